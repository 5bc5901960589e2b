void fg_stage_quaternion_square_3d(vec3 z, OUT(vec3) squared, OUT(float) gain)
{
    gain = 2.0 * length(z);
    squared = vec3(z.x * z.x - z.y * z.y - z.z * z.z, 2.0 * z.x * z.y, 2.0 * z.x * z.z);
}
