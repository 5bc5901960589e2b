void fg_light_iteration_fog(float escape, float start, float full, float opacity, vec3 outer, vec3 inner,
                            OUT(float) density, OUT(vec3) color)
{
    // 0 where the fog starts, 1 where it is full: it thickens towards the set.
    float ramp = clamp((escape - start) / max(full - start, FG_TINY), 0.0, 1.0);
    density = opacity * ramp;
    color = mix(outer, inner, ramp);
}
