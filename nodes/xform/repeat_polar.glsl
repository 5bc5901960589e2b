void fg_xform_repeat_polar(vec3 p, int count, OUT(vec3) p_out)
{
    float sector = 2.0 * FG_PI / float(max(count, 1));
    float r = length(vec2(p.x, p.z));
    float a = fg_safe_atan(p.z, p.x) + 0.5 * sector;
    a = a - sector * floor(a / sector) - 0.5 * sector;
    p_out = vec3(cos(a) * r, p.y, sin(a) * r);
}
