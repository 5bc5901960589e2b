void fg_stage_quaternion_cube(vec4 z, OUT(vec4) cubed, OUT(float) gain)
{
    float a2 = z.x * z.x;
    float v2 = z.y * z.y + z.z * z.z + z.w * z.w;
    gain = 3.0 * (a2 + v2);
    float k = 3.0 * a2 - v2;
    cubed = vec4(z.x * (a2 - 3.0 * v2), k * z.y, k * z.z, k * z.w);
}
