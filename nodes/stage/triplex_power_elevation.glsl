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
