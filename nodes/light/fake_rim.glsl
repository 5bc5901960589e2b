void fg_light_fake_rim(vec3 position, vec3 to_camera, float eps, float power, float strength, OUT(float) rim)
{
    float h = max(eps, FG_TINY);
    float facing = clamp(fg_scene_distance(position + to_camera * h) / h, 0.0, 1.0);
    rim = strength * pow(1.0 - facing, power);
}
