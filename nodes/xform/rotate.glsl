void fg_xform_rotate(vec3 p, vec3 axis, float angle_deg, OUT(vec3) p_out)
{
    float len = length(axis);
    vec3 a = len > FG_TINY ? axis / len : vec3(0.0, 1.0, 0.0);
    p_out = fg_rotate_axis(p, a, -angle_deg * FG_PI / 180.0);
}
