void fg_prim_box(vec3 p, vec3 size, float rounding, OUT(float) distance)
{
    vec3 q = abs(p) - size + vec3(rounding);
    distance = length(max(q, vec3(0.0))) + min(max(q.x, max(q.y, q.z)), 0.0) - rounding;
}
