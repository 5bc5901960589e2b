void fg_stage_triplex_power_elevation(vec3 z, float power, float theta_offset_deg, float phi_offset_deg, OUT(vec3) raised,
                                      OUT(float) gain)
{
    float r = length(z);
    float rn = pow(max(r, FG_TINY), power);
    // At the origin and on the y axis the angles are 0/0: the safe forms answer 0.
    float theta = (asin(clamp(fg_safe_div(z.y, r), -1.0, 1.0)) + theta_offset_deg * (FG_PI / 180.0)) * power;
    float phi = (fg_safe_atan(z.z, z.x) + phi_offset_deg * (FG_PI / 180.0)) * power;
    gain = power * pow(max(r, FG_TINY), power - 1.0);
    raised = rn * vec3(cos(theta) * cos(phi), sin(theta), cos(theta) * sin(phi));
}

void fg_stage_triplex_power_elevation_tangent(vec3 z, float power, float theta_offset_deg, float phi_offset_deg,
                                              vec3 d_z, OUT(vec3) d_raised)
{
    // z = r (cos t cos f, sin t, cos t sin f) with t = asin(y / r), f = atan(z, x), each plus its
    // offset: the elevation falls as the colatitude grows, and this longitude turns the other way.
    vec3 d = fg_polar_tangent(z, d_z);
    float r = max(length(z), FG_TINY);
    float t = (asin(clamp(fg_safe_div(z.y, r), -1.0, 1.0)) + theta_offset_deg * (FG_PI / 180.0)) * power;
    float f = (fg_safe_atan(z.z, z.x) + phi_offset_deg * (FG_PI / 180.0)) * power;
    vec3 dir = vec3(cos(t) * cos(f), sin(t), cos(t) * sin(f));
    vec3 along_t = vec3(-sin(t) * cos(f), cos(t), -sin(t) * sin(f));
    vec3 along_f = vec3(-cos(t) * sin(f), 0.0, cos(t) * cos(f));
    d_raised = power * pow(r, power) * (d.x / r * dir - d.y * along_t - d.z * along_f);
}
