void fg_xform_octant_fold(vec3 p, vec3 axes, vec3 center, OUT(vec3) p_out)
{
    vec3 q = p - center;
    p_out = mix(q, abs(q), clamp(axes, 0.0, 1.0)) + center;
}
