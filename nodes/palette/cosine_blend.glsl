void fg_palette_cosine_blend(float t, float blend, vec3 a1, vec3 b1, vec3 c1, vec3 d1, vec3 a2, vec3 b2, vec3 c2,
                             vec3 d2, OUT(vec3) color)
{
    vec3 first = a1 + b1 * cos(2.0 * FG_PI * (c1 * t + d1));
    vec3 second = a2 + b2 * cos(2.0 * FG_PI * (c2 * t + d2));
    color = mix(first, second, blend);
}
