void fg_palette_cosine(float t, vec3 a, vec3 b, vec3 c, vec3 d, OUT(vec3) color)
{
    color = a + b * cos(2.0 * FG_PI * (c * t + d));
}
