void fg_prim_octahedron(vec3 p, float size, OUT(float) distance)
{
    vec3 a = abs(p);
    float m = a.x + a.y + a.z - size;
    vec3 q;
    // Which face region the point projects into decides the nearest feature (face, edge, vertex).
    if (3.0 * a.x < m) q = a;
    else if (3.0 * a.y < m) q = vec3(a.y, a.z, a.x);
    else if (3.0 * a.z < m) q = vec3(a.z, a.x, a.y);
    else {
        distance = m * 0.57735026918962576;
        return;
    }
    float k = clamp(0.5 * (q.z - q.y + size), 0.0, size);
    distance = length(vec3(q.x, q.y - size + k, q.z - k));
}
