void fg_xform_repeat_finite(vec3 p, vec3 period, vec3 count, OUT(vec3) p_out)
{
    vec3 n = floor(count + vec3(0.5));
    p_out = p - period * clamp(floor(p / period + vec3(0.5)), -n, n);
}
