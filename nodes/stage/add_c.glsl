void fg_stage_add_c(T z, T c, float weight, OUT(T) added)
{
    added = z + c * weight;
}

void fg_stage_add_c_tangent(T z, T c, float weight, T d_z, T d_c, OUT(T) d_added)
{
    d_added = d_z + d_c * weight;
}
