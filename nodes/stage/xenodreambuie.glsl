void fg_stage_xenodreambuie(vec3 z, float power, float theta_offset_deg, float phi_offset_deg, OUT(vec3) raised, OUT(float) gain)
{
    float r = length(z);
    float rn = pow(max(r, FG_TINY), power);
    float theta = fg_safe_acos(fg_safe_div(z.y, r)) + theta_offset_deg * (FG_PI / 180.0);
    // Folded into [-90, 90] degrees: the lower half mirrored onto the upper one.
    if (abs(theta) > 0.5 * FG_PI) theta = (theta > 0.0 ? FG_PI : -FG_PI) - theta;
    float phi = fg_safe_atan(-z.z, z.x) + phi_offset_deg * (FG_PI / 180.0);
    gain = power * pow(max(r, FG_TINY), power - 1.0);
    raised = rn * vec3(cos(phi * power) * sin(theta * power), cos(theta * power), -sin(phi * power) * sin(theta * power));
}

void fg_stage_xenodreambuie_tangent(vec3 z, float power, float theta_offset_deg, float phi_offset_deg, vec3 d_z,
                                    OUT(vec3) d_raised)
{
    // As the triplex power, with t = acos(y / r) folded into [-90, 90] degrees (the fold mirrors
    // t, so its change turns sign) and f = atan(-z, x).
    vec3 d = fg_polar_tangent(z, d_z);
    float d_t = d.y;
    float r = max(length(z), FG_TINY);
    float t = fg_safe_acos(fg_safe_div(z.y, r)) + theta_offset_deg * (FG_PI / 180.0);
    if (abs(t) > 0.5 * FG_PI) {
        t = (t > 0.0 ? FG_PI : -FG_PI) - t;
        d_t = -d_t;
    }
    float f = fg_safe_atan(-z.z, z.x) + phi_offset_deg * (FG_PI / 180.0);
    t *= power;
    f *= power;
    vec3 dir = vec3(cos(f) * sin(t), cos(t), -sin(f) * sin(t));
    vec3 along_t = vec3(cos(f) * cos(t), -sin(t), -sin(f) * cos(t));
    vec3 along_f = vec3(-sin(f) * sin(t), 0.0, -cos(f) * sin(t));
    d_raised = power * pow(r, power) * (d.x / r * dir + d_t * along_t + d.z * along_f);
}
