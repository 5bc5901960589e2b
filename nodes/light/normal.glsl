void fg_light_normal(vec3 position, int taps, float eps, OUT(vec3) normal)
{
    float h = max(eps, FG_TINY);
    vec3 g;
    if (taps >= 6) {
        g = vec3(fg_scene_distance(position + vec3(h, 0.0, 0.0)) - fg_scene_distance(position - vec3(h, 0.0, 0.0)),
                 fg_scene_distance(position + vec3(0.0, h, 0.0)) - fg_scene_distance(position - vec3(0.0, h, 0.0)),
                 fg_scene_distance(position + vec3(0.0, 0.0, h)) - fg_scene_distance(position - vec3(0.0, 0.0, h)));
    } else {
        // Tetrahedral taps: the four corners (1,-1,-1), (-1,-1,1), (-1,1,-1), (1,1,1).
        g = vec3(1.0, -1.0, -1.0) * fg_scene_distance(position + vec3(1.0, -1.0, -1.0) * h) +
            vec3(-1.0, -1.0, 1.0) * fg_scene_distance(position + vec3(-1.0, -1.0, 1.0) * h) +
            vec3(-1.0, 1.0, -1.0) * fg_scene_distance(position + vec3(-1.0, 1.0, -1.0) * h) +
            vec3(1.0, 1.0, 1.0) * fg_scene_distance(position + vec3(1.0, 1.0, 1.0) * h);
    }
    float len = length(g);
    normal = len > FG_TINY ? g / len : vec3(0.0, 1.0, 0.0);
}
