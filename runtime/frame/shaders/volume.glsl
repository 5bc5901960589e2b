#ifdef FG_HAS_VOLUME
// A glowing medium drawn as nodes (the graph's volume_density and volume_color, such as
// light.iteration_fog): emission and absorption along the eye's ray from ro along the unit rd,
// inside the scene bounds and up to the hit at t (t < 0, a miss: the far limit).
//
// The ray's stretch is cut into at most FG_VOLUME_STEPS segments, each taken as uniform at one
// point of its own. A segment is as long as the scene's distance at the point before it, between a
// quarter and twice the even share of the stretch: iteration fog thickens towards the surface, so
// the segments shorten where it does; the last takes what is left. The point's place in its segment
// is a fixed offset per pixel in a frame (interleaved gradient noise, so the error dithers instead
// of banding) and a new one each sample while samples accumulate. A segment of density s and length
// h absorbs 1 - e^(-s h) of what lies behind it and gives as much of its colour: exact for a medium
// uniform along each segment.
vec3 fg_through_volume(vec3 color, vec3 ro, vec3 rd, float t)
{
    vec2 span = fg_bounds_interval(ro, rd, 0.0);
    if (t >= 0.0) span.y = min(span.y, t);
    if (span.y <= span.x) return color;
    float even = (span.y - span.x) / float(FG_VOLUME_STEPS);
    vec2 q = vec2(fg_shading_pixel);
    float offset = fg_frame.area_light.z == 0.0 ? fract(52.9829189 * fract(dot(q, vec2(0.06711056, 0.00583715))))
                                                : fg_sample_square(2u).y;
    vec3 light = vec3(0.0);
    float through = 1.0, start = span.x, h = even;
    for (int i = 0; i < FG_VOLUME_STEPS && start < span.y; i++) {
        h = i == FG_VOLUME_STEPS - 1 ? span.y - start : min(h, span.y - start);
        float distance;
        vec4 medium = fg_scene_volume(ro + rd * (start + offset * h), distance);
        float absorbed = 1.0 - exp(-max(medium.a, 0.0) * h);
        light += through * absorbed * medium.rgb;
        through -= through * absorbed;
        start += h;
        h = clamp(abs(distance) * FG_STEP_SCALE, 0.25 * even, 2.0 * even);
    }
    return color * through + light;
}
#endif
