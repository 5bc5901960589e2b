void fg_op_round(float d, float radius, OUT(float) distance)
{
    distance = d - radius;
}
