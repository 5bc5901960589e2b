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
    vec3 d = fg_polar_tangent(z, d_z);
    float r = max(length(z), FG_TINY);
    float t = fg_safe_acos(fg_safe_div(z.y, r)) * power, f = fg_safe_atan(z.x, z.z) * power;
    vec3 dir = vec3(sin(t) * sin(f), cos(t), sin(t) * cos(f));
    vec3 along_t = vec3(cos(t) * sin(f), -sin(t), cos(t) * cos(f));
    vec3 along_f = vec3(sin(t) * cos(f), 0.0, -sin(t) * sin(f));
    d_raised = power * pow(r, power) * (d.x / r * dir + d.y * along_t + d.z * along_f);
}
