void fg_op_onion(float d, float thickness, OUT(float) distance)
{
    distance = abs(d) - thickness;
}
