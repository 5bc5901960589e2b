// Cross-frame reuse: a cone of this frame walks the conemarch levels of the same eye in the frame
// before, as stereo reprojection walks the centre eye's (reproject.comp), but for a whole cone, so
// that what it proves empty is a cone bound again and the next frame can reuse it in turn.
//
// What an old level proves: every point of an old cell's cone closer to the old eye than the cell's
// bound D is empty (the bound's cone covers every ray through the cell). The new cone's cross-section
// at axial distance t is a disc of radius c t around the axis point q. The disc is empty if it lies
// in the old cells' cones (its directions seen from the old eye stay inside the cell's rectangle on
// the old tangent plane) and |q - o| + c t < D. Its directions lie within the angle
// alpha = asin(c t / |q - o|) of q's, and the tangent plane stretches an angle by at most
// 1 + tan^2 of the direction's angle from the view axis, so shrinking the rectangle by
// alpha (1 + tan^2(theta + alpha)), theta the cell's widest angle, keeps the disc inside. Segments
// proven so are contiguous from where the walk starts.

layout(set = 0, binding = 15, rg32f) uniform readonly image2D fg_previous_levels;

struct FgConeWalk {
    GpuView C;       // the old eye
    vec3 b;          // the new cone's apex relative to the old eye
    vec3 r;          // the cone's axis, unit
    float c;         // its radius per unit of axial distance
    ivec2 size;      // the old eye's full-resolution size
};

// Where the cone's axis point at t lies on the old tangent plane (xy) and in front of the old eye (z).
vec3 fg_walk_tan(FgConeWalk w, float t)
{
    vec3 q = w.b + w.r * t;
    float f = dot(q, w.C.forward.xyz);
    return vec3(dot(q, w.C.right.xyz) / f, dot(q, w.C.up.xyz) / f, f);
}

// The axial distance (after `after`) where the axis crosses the old tangent-plane line of value X
// along `axis` (right or up); 1e30 if never.
float fg_walk_crossing(FgConeWalk w, vec3 axis, float X, float after)
{
    float den = dot(w.r, axis) - X * dot(w.r, w.C.forward.xyz);
    if (abs(den) < 1e-20) return 1e30;
    float t = (X * dot(w.b, w.C.forward.xyz) - dot(w.b, axis)) / den;
    return t > after ? t : 1e30;
}

// The largest t with |b + r t| + c t <= D: where the cone's discs leave the old eye's ball of
// radius D ((1 - c^2) t^2 + 2 (b.r + D c) t + |b|^2 - D^2 = 0); -1e30 if nowhere.
float fg_walk_ball_exit(FgConeWalk w, float D)
{
    float a = 1.0 - w.c * w.c;
    float h = dot(w.b, w.r) + D * w.c;
    float disc = h * h - a * (dot(w.b, w.b) - D * D);
    return disc < 0.0 ? -1e30 : (-h + sqrt(disc)) / a;
}

// The largest angle the disc subtends from the old eye over [t0, t1]: c t / |b + r t| peaks at
// most once, at t = -|b|^2 / (b.r).
float fg_walk_alpha(FgConeWalk w, float t0, float t1)
{
    float bb = dot(w.b, w.b), br = dot(w.b, w.r);
    float ratio = max(t0 / max(length(w.b + w.r * t0), 1e-30), t1 / max(length(w.b + w.r * t1), 1e-30));
    if (br < 0.0) {
        float peak = -bb / br;
        if (peak > t0 && peak < t1) ratio = max(ratio, peak / max(length(w.b + w.r * peak), 1e-30));
    }
    return asin(min(w.c * ratio, 1.0));
}

// The largest tangent of the angle from the old view's axis over a rectangle of pixels.
float fg_walk_widest(FgConeWalk w, vec2 tan0, vec2 tan_per_pixel, vec2 px_min, vec2 px_max)
{
    vec2 a = tan0 + px_min * tan_per_pixel, b = tan0 + px_max * tan_per_pixel;
    return max(max(length(a), length(b)), max(length(vec2(a.x, b.y)), length(vec2(b.x, a.y))));
}

// Advance t through the cells of one old level while the cone is provably empty; returns the new
// proven distance (t itself if nothing more is proven). Where the disc straddles cells, every cell
// it touches (at most 3 x 3) must prove it empty.
float fg_walk_level(FgConeWalk w, int level, float t, float t_max)
{
    ivec4 rect = fg_level_rect(level, w.size);
    float cell = float(1 << level);
    vec2 tan0 = vec2(w.C.tan_fov.x, w.C.tan_fov.w);
    vec2 tan_per_pixel = vec2(w.C.tan_fov.y - w.C.tan_fov.x, w.C.tan_fov.z - w.C.tan_fov.w) / vec2(w.size);
    for (int i = 0; i < FG_REPROJECT_STEPS && t < t_max; ++i) {
        vec3 ct = fg_walk_tan(w, t);
        if (ct.z <= 0.0) return t;                       // beside or behind the old eye
        vec2 px = (ct.xy - tan0) / tan_per_pixel;
        // The cells the disc may touch, judged with the widest it gets up to the far side of the
        // 3 x 3 block of cells around it: a cone as wide as the old cells (the same level) spills
        // into its neighbours wherever the new pixel's centre is off the old one's.
        ivec2 c0 = ivec2(floor(px / cell)) - 1;
        vec2 block_min = vec2(c0) * cell, block_max = vec2(c0 + 3) * cell;
        float far = min(min(fg_walk_crossing(w, w.C.right.xyz, tan0.x + block_min.x * tan_per_pixel.x, t),
                            fg_walk_crossing(w, w.C.right.xyz, tan0.x + block_max.x * tan_per_pixel.x, t)),
                        min(fg_walk_crossing(w, w.C.up.xyz, tan0.y + block_min.y * tan_per_pixel.y, t),
                            fg_walk_crossing(w, w.C.up.xyz, tan0.y + block_max.y * tan_per_pixel.y, t)));
        float alpha = fg_walk_alpha(w, t, min(far, t_max));
        float widest = atan(fg_walk_widest(w, tan0, tan_per_pixel, block_min, block_max));
        if (widest + alpha >= 1.5) return t;
        float tw = tan(widest + alpha);
        vec2 margin = vec2(alpha * (1.0 + tw * tw) * 1.001) / abs(tan_per_pixel);   // in pixels
        // The cells under the disc's footprint; all must lie in the image and the block.
        ivec2 lo = ivec2(floor((px - margin) / cell)), hi = ivec2(floor((px + margin) / cell));
        if (any(lessThan(lo, c0)) || any(greaterThan(hi, c0 + 2))) return t;
        if (any(lessThan(lo, ivec2(0))) || any(greaterThanEqual(hi, rect.zw))) return t;
        if ((px.x - margin.x) < 0.0 || (px.y - margin.y) < 0.0) return t;
        float D = 1e30;
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) D = min(D, imageLoad(fg_previous_levels, rect.xy + ivec2(x, y)).y);
        vec3 q = w.b + w.r * t;
        if (length(q) + w.c * t >= D) return t;         // a surface may be here, seen from the old eye
        // The disc stays over these cells while the axis stays inside them shrunk by the margin.
        vec2 keep_min = vec2(lo) * cell + margin, keep_max = vec2(hi + 1) * cell - margin;
        float exit_t = min(min(fg_walk_crossing(w, w.C.right.xyz, tan0.x + keep_min.x * tan_per_pixel.x, t),
                               fg_walk_crossing(w, w.C.right.xyz, tan0.x + keep_max.x * tan_per_pixel.x, t)),
                           min(fg_walk_crossing(w, w.C.up.xyz, tan0.y + keep_min.y * tan_per_pixel.y, t),
                               fg_walk_crossing(w, w.C.up.xyz, tan0.y + keep_max.y * tan_per_pixel.y, t)));
        exit_t = min(exit_t, far);
        float ball = fg_walk_ball_exit(w, D);
        // Short of the ball's edge; just past a cell's edge, so the next step sees the next cells
        // (the sliver between is a millionth of the distance, far under any hit threshold).
        if (ball <= exit_t) return max(t, ball * (1.0 - 1e-5));
        if (exit_t >= 1e29) return min(t_max, ball * (1.0 - 1e-5));
        t = exit_t * (1.0 + 1e-6) + 1e-9;
    }
    return min(t, t_max);
}

// How far the previous frame proves a cone of this frame's level `level` empty, from `t` (already
// proven) on: the same eye's old cells of that level. Coarser old levels would add nothing: this
// frame's coarser levels walked them already, and their bound is where this cone starts.
float fg_reused_bound(int view, int level, vec3 ro, vec3 rd, float cone, float t, float t_max)
{
    if (!FG_REUSE || fg_frame.reuse == 0u || view == FG_VIEW_CENTRE) return t;
    FgConeWalk w;
    w.C = fg_frame.previous[view];
    w.b = ro - w.C.origin.xyz;
    w.r = rd;
    w.c = cone;
    w.size = fg_view_size(view);
    // Foveation leaves the odd pixels of the periphery unmarched at level 0: their old values are
    // stale, so a foveated frame's level 0 walks the old level 1.
    return fg_walk_level(w, max(level, fg_frame.fovea_radius > 0.0 ? 1 : 0), t, t_max);
}
