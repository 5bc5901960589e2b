void fg_stage_quaternion_square(vec4 z, OUT(vec4) squared, OUT(float) gain)
{
    gain = 2.0 * sqrt(dot(z, z));
    squared = vec4(z.x * z.x - z.y * z.y - z.z * z.z - z.w * z.w, 2.0 * z.x * z.y, 2.0 * z.x * z.z, 2.0 * z.x * z.w);
}
