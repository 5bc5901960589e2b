void fg_light_fake_sss(vec3 position, vec3 direction, float depth, float strength, OUT(float) sss)
{
    float h = max(depth, FG_TINY);
    float inside = -fg_scene_distance(position - direction * h);
    sss = strength * (1.0 - clamp(inside / h, 0.0, 1.0));
}
