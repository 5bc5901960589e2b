void fg_stage_quaternion_square_3d(vec3 z, OUT(vec3) squared, OUT(float) gain)
{
    gain = 2.0 * length(z);
    squared = vec3(z.x * z.x - z.y * z.y - z.z * z.z, 2.0 * z.x * z.y, 2.0 * z.x * z.z);
}

void fg_stage_quaternion_square_3d_tangent(vec3 z, vec3 d_z, OUT(vec3) d_squared)
{
    vec3 d = d_z;
    d_squared = 2.0 * vec3(z.x * d.x - z.y * d.y - z.z * d.z, d.x * z.y + z.x * d.y, d.x * z.z + z.x * d.z);
}
