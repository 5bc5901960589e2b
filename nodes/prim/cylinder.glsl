void fg_prim_cylinder(vec3 p, float radius, float half_height, OUT(float) distance)
{
    vec2 d = abs(vec2(length(vec2(p.x, p.z)), p.y)) - vec2(radius, half_height);
    distance = min(max(d.x, d.y), 0.0) + length(max(d, vec2(0.0)));
}
