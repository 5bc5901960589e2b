void fg_stage_plane_fold(vec3 z, vec3 normal, float distance, OUT(vec3) folded)
{
    float len = length(normal);
    vec3 n = len > FG_TINY ? normal / len : vec3(1.0, 0.0, 0.0);
    float below = min(dot(z, n) - distance, 0.0);
    folded = z - 2.0 * below * n;
}

void fg_stage_plane_fold_tangent(vec3 z, vec3 normal, float distance, vec3 d_z, OUT(vec3) d_folded)
{
    float len = length(normal);
    vec3 n = len > FG_TINY ? normal / len : vec3(1.0, 0.0, 0.0);
    d_folded = dot(z, n) - distance < 0.0 ? d_z - 2.0 * dot(d_z, n) * n : d_z;
}
