void fg_xform_twist(vec3 p, float rate, OUT(vec3) p_out)
{
    float c = cos(rate * p.y);
    float s = sin(rate * p.y);
    p_out = vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}
