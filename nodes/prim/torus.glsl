void fg_prim_torus(vec3 p, float major, float minor, OUT(float) distance)
{
    float ring = length(vec2(p.x, p.z)) - major;
    distance = length(vec2(ring, p.y)) - minor;
}
