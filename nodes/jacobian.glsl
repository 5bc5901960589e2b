// Helpers of formulas that carry a running Jacobian (compiler/ir/formula_program.h); emitted only
// into scenes that have one.

// The largest stretch of any direction by a map whose Jacobian has columns a, b, c: the square root
// of the largest eigenvalue of J^T J, bounded above by both its trace and its largest Gershgorin row
// sum, so never too small, and exact for a rotation times a scale (J^T J is then diagonal).
float fg_gram_norm(float aa, float bb, float cc, float ab, float ac, float bc)
{
    float rows = max(aa + abs(ab) + abs(ac), max(bb + abs(ab) + abs(bc), cc + abs(ac) + abs(bc)));
    return sqrt(min(aa + bb + cc, rows));
}

float fg_jacobian_norm(vec3 a, vec3 b, vec3 c)
{
    return fg_gram_norm(dot(a, a), dot(b, b), dot(c, c), dot(a, b), dot(a, c), dot(b, c));
}

float fg_jacobian_norm(vec4 a, vec4 b, vec4 c)
{
    return fg_gram_norm(dot(a, a), dot(b, b), dot(c, c), dot(a, b), dot(a, c), dot(b, c));
}

// How r = |z|, z's colatitude acos(y / r) and its longitude atan(x, z) move along d_z: the
// tangents of the power maps' spherical coordinates (0 for the angles on the y axis, where they
// are undefined).
vec3 fg_polar_tangent(vec3 z, vec3 d_z)
{
    float r = max(length(z), FG_TINY);
    float rho2 = z.x * z.x + z.z * z.z;
    float d_r = dot(z, d_z) / r;
    return vec3(d_r, -fg_safe_div(d_z.y * r - z.y * d_r, r * sqrt(rho2)), fg_safe_div(z.z * d_z.x - z.x * d_z.z, rho2));
}
