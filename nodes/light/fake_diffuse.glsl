void fg_light_fake_diffuse(vec3 position, vec3 light_dir, float eps, float contrast, OUT(float) diffuse)
{
    float h = eps * 2.25;
    float d = fg_scene_distance(position + light_dir * h) / h;
    diffuse = fg_gain(d, contrast);
}
