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
