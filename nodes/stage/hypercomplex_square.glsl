void fg_stage_hypercomplex_square(vec4 z, OUT(vec4) squared, OUT(float) gain)
{
    squared = vec4(z.x * z.x - z.y * z.y - z.z * z.z - z.w * z.w, 2.0 * (z.x * z.y + z.z * z.w), 2.0 * (z.x * z.z + z.y * z.w),
                   2.0 * (z.x * z.w + z.y * z.z));
    gain = 2.0 * fg_safe_div(length(squared), length(z));
}

void fg_stage_hypercomplex_square_tangent(vec4 z, vec4 d_z, OUT(vec4) d_squared)
{
    vec4 d = d_z;
    d_squared = 2.0 * vec4(z.x * d.x - z.y * d.y - z.z * d.z - z.w * d.w, d.x * z.y + z.x * d.y + d.z * z.w + z.z * d.w,
                           d.x * z.z + z.x * d.z + d.y * z.w + z.y * d.w, d.x * z.w + z.x * d.w + d.y * z.z + z.y * d.z);
}
