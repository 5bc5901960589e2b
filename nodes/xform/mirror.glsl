void fg_xform_mirror(vec3 p, vec3 normal, float offset, OUT(vec3) p_out)
{
    float len = length(normal);
    vec3 n = len > FG_TINY ? normal / len : vec3(1.0, 0.0, 0.0);
    float side = dot(p, n) - offset;
    p_out = p - 2.0 * min(side, 0.0) * n;
}
