void fg_op_displace(float d, vec3 p, float amplitude, float frequency, float phase, OUT(float) distance)
{
    vec3 w = sin(p * frequency + vec3(phase));
    distance = d + amplitude * w.x * w.y * w.z;
}
