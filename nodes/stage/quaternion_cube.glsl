void fg_stage_quaternion_cube(vec4 z, OUT(vec4) cubed, OUT(float) gain)
{
    float a2 = z.x * z.x;
    float v2 = z.y * z.y + z.z * z.z + z.w * z.w;
    gain = 3.0 * (a2 + v2);
    float k = 3.0 * a2 - v2;
    cubed = vec4(z.x * (a2 - 3.0 * v2), k * z.y, k * z.z, k * z.w);
}

void fg_stage_quaternion_cube_tangent(vec4 z, vec4 d_z, OUT(vec4) d_cubed)
{
    float a2 = z.x * z.x;
    float v2 = z.y * z.y + z.z * z.z + z.w * z.w;
    float d_a2 = 2.0 * z.x * d_z.x;
    float d_v2 = 2.0 * (z.y * d_z.y + z.z * d_z.z + z.w * d_z.w);
    float k = 3.0 * a2 - v2;
    float d_k = 3.0 * d_a2 - d_v2;
    d_cubed = vec4(d_z.x * (a2 - 3.0 * v2) + z.x * (d_a2 - 3.0 * d_v2), d_k * z.y + k * d_z.y, d_k * z.z + k * d_z.z,
                   d_k * z.w + k * d_z.w);
}
