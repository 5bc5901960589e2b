void fg_prim_sphere(vec3 p, float radius, OUT(float) distance)
{
    distance = length(p) - radius;
}
