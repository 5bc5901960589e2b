void fg_stage_slab_fold(vec3 z, vec3 upper, vec3 lower, float limit, OUT(vec3) folded)
{
    float lu = length(upper), ll = length(lower);
    vec3 u = lu > FG_TINY ? upper / lu : vec3(1.0, 0.0, 0.0);
    vec3 l = ll > FG_TINY ? lower / ll : vec3(1.0, 0.0, 0.0);
    float above = max(dot(z, u) - limit, 0.0);
    float below = above > 0.0 ? 0.0 : min(dot(z, l) + limit, 0.0);
    folded = z - 2.0 * above * u - 2.0 * below * l;
}

void fg_stage_slab_fold_tangent(vec3 z, vec3 upper, vec3 lower, float limit, vec3 d_z, OUT(vec3) d_folded)
{
    float lu = length(upper), ll = length(lower);
    vec3 u = lu > FG_TINY ? upper / lu : vec3(1.0, 0.0, 0.0);
    vec3 l = ll > FG_TINY ? lower / ll : vec3(1.0, 0.0, 0.0);
    bool above = dot(z, u) - limit > 0.0;
    bool below = !above && dot(z, l) + limit < 0.0;
    d_folded = above ? d_z - 2.0 * dot(d_z, u) * u : below ? d_z - 2.0 * dot(d_z, l) * l : d_z;
}
