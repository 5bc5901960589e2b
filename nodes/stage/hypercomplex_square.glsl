void fg_stage_hypercomplex_square(vec4 z, OUT(vec4) squared, OUT(float) gain)
{
    squared = vec4(z.x * z.x - z.y * z.y - z.z * z.z - z.w * z.w, 2.0 * (z.x * z.y + z.z * z.w), 2.0 * (z.x * z.z + z.y * z.w),
                   2.0 * (z.x * z.w + z.y * z.z));
    gain = 2.0 * fg_safe_div(length(squared), length(z));
}
