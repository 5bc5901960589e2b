void fg_op_subtract(float a, float b, OUT(float) distance)
{
    distance = max(a, -b);
}
