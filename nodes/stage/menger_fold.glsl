void fg_stage_menger_fold(vec3 z, OUT(vec3) folded)
{
    folded = z;
    if (folded.x < folded.y) folded = vec3(folded.y, folded.x, folded.z);
    if (folded.x < folded.z) folded = vec3(folded.z, folded.y, folded.x);
    if (folded.y < folded.z) folded = vec3(folded.x, folded.z, folded.y);
}
