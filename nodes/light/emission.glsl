void fg_light_emission(vec3 color, float intensity, float mask, OUT(vec3) emission)
{
    emission = color * (intensity * mask);
}
