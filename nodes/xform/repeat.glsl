void fg_xform_repeat(vec3 p, vec3 period, OUT(vec3) p_out)
{
    // floor(x + 0.5) rather than round(): GLSL leaves the direction of round(0.5) open, and the GPU
    // and the CPU twin must pick the same cell.
    p_out = p - period * floor(p / period + vec3(0.5));
}
