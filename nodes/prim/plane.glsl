void fg_prim_plane(vec3 p, vec3 normal, float offset, OUT(float) distance)
{
    float len = length(normal);
    vec3 n = len > FG_TINY ? normal / len : vec3(0.0, 1.0, 0.0);
    distance = dot(p, n) + offset;
}
