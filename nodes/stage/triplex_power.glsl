void fg_stage_triplex_power(vec3 z, float power, OUT(vec3) raised, OUT(float) gain)
{
    float r = length(z);
    float rn = pow(max(r, FG_TINY), power);
    // At the origin and on the y axis the angles are 0/0: the safe forms answer 0.
    float theta = fg_safe_acos(fg_safe_div(z.y, r)) * power;
    float phi = fg_safe_atan(z.x, z.z) * power;
    gain = power * pow(max(r, FG_TINY), power - 1.0);
    raised = rn * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
}

void fg_stage_triplex_power_tangent(vec3 z, float power, vec3 d_z, OUT(vec3) d_raised)
{
    // z = r (sin t sin f, cos t, sin t cos f) with t = acos(y / r), f = atan(x, z); the power
    // multiplies both angles: the tangent moves r, t and f, then the point.
    float r = max(length(z), FG_TINY);
    float rho2 = z.x * z.x + z.z * z.z;
    float rho = sqrt(rho2);
    float d_r = dot(z, d_z) / r;
    float d_t = -fg_safe_div(d_z.y * r - z.y * d_r, r * rho);
    float d_f = fg_safe_div(z.z * d_z.x - z.x * d_z.z, rho2);
    float t = fg_safe_acos(fg_safe_div(z.y, r)) * power, f = fg_safe_atan(z.x, z.z) * power;
    float rn = pow(r, power);
    vec3 dir = vec3(sin(t) * sin(f), cos(t), sin(t) * cos(f));
    vec3 along_t = vec3(cos(t) * sin(f), -sin(t), cos(t) * cos(f));
    vec3 along_f = vec3(sin(t) * cos(f), 0.0, -sin(t) * sin(f));
    d_raised = power * (rn / r * d_r * dir + rn * (d_t * along_t + d_f * along_f));
}
