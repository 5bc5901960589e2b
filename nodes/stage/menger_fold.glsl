void fg_stage_menger_fold(vec3 z, OUT(vec3) folded)
{
    folded = z;
    if (folded.x < folded.y) folded = vec3(folded.y, folded.x, folded.z);
    if (folded.x < folded.z) folded = vec3(folded.z, folded.y, folded.x);
    if (folded.y < folded.z) folded = vec3(folded.x, folded.z, folded.y);
}

void fg_stage_menger_fold_tangent(vec3 z, vec3 d_z, OUT(vec3) d_folded)
{
    // The same swaps as the fold, made on the tangent too.
    vec3 f = z;
    vec3 d = d_z;
    if (f.x < f.y) { f = vec3(f.y, f.x, f.z); d = vec3(d.y, d.x, d.z); }
    if (f.x < f.z) { f = vec3(f.z, f.y, f.x); d = vec3(d.z, d.y, d.x); }
    if (f.y < f.z) { f = vec3(f.x, f.z, f.y); d = vec3(d.x, d.z, d.y); }
    d_folded = d;
}
