void fg_op_union(float a, float b, OUT(float) distance)
{
    distance = min(a, b);
}
