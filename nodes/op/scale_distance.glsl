void fg_op_scale_distance(float d, float s, OUT(float) distance)
{
    distance = d * s;
}
