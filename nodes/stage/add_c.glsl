void fg_stage_add_c(T z, T c, float weight, OUT(T) added)
{
    added = z + c * weight;
}
