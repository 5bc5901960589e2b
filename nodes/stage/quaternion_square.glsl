void fg_stage_quaternion_square(vec4 z, OUT(vec4) squared, OUT(float) gain)
{
    gain = 2.0 * sqrt(dot(z, z));
    squared = vec4(z.x * z.x - z.y * z.y - z.z * z.z - z.w * z.w, 2.0 * z.x * z.y, 2.0 * z.x * z.z, 2.0 * z.x * z.w);
}

void fg_stage_quaternion_square_tangent(vec4 z, vec4 d_z, OUT(vec4) d_squared)
{
    vec4 d = d_z;
    d_squared = 2.0 * vec4(z.x * d.x - z.y * d.y - z.z * d.z - z.w * d.w, d.x * z.y + z.x * d.y, d.x * z.z + z.x * d.z,
                           d.x * z.w + z.x * d.w);
}
