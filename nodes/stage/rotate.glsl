void fg_stage_rotate(vec3 z, vec3 axis, float angle_deg, OUT(vec3) rotated)
{
    float len = length(axis);
    vec3 a = len > FG_TINY ? axis / len : vec3(0.0, 1.0, 0.0);
    rotated = fg_rotate_axis(z, a, angle_deg * FG_PI / 180.0);
}

void fg_stage_rotate_tangent(vec3 z, vec3 axis, float angle_deg, vec3 d_z, OUT(vec3) d_rotated)
{
    // A rotation is linear: the tangent turns with the point.
    fg_stage_rotate(d_z, axis, angle_deg, d_rotated);
}
