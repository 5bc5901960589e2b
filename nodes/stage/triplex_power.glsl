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
