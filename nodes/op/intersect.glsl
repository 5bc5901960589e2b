void fg_op_intersect(float a, float b, OUT(float) distance)
{
    distance = max(a, b);
}
