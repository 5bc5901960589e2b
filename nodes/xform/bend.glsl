void fg_xform_bend(vec3 p, float rate, OUT(vec3) p_out)
{
    float c = cos(rate * p.x);
    float s = sin(rate * p.x);
    p_out = vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
}
