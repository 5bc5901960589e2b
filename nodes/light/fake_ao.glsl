void fg_light_fake_ao(vec3 position, vec3 direction, float radius, float strength, OUT(float) ao)
{
    float free_space = clamp(fg_scene_distance(position + direction * radius) / radius, 0.0, 1.0);
    ao = clamp(1.0 - strength * (1.0 - free_space), 0.0, 1.0);
}
