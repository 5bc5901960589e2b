void fg_op_smooth_union(float a, float b, float k, OUT(float) distance)
{
    float h = k > 0.0 ? max(k - abs(a - b), 0.0) / k : 0.0;
    distance = min(a, b) - h * h * k * 0.25;
}
