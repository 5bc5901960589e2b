// Where a marching pass with persistent lanes leaves its results: one vec4 per pixel (the depth or
// FG_MISS, the pixel's cone bound, the closest approach, unused), written as each ray ends, in
// whatever order the lanes finish. The resolve pass (resolve.comp) moves them into the images.
// Stores into a buffer cost little wherever they fall; image stores scattered over a subgroup's
// lanes cost far more (on llvmpipe, the whole subgroup pays each one).
layout(set = 0, binding = 14, std430) buffer FgRays { vec4 rays[]; } fg_rays;

void fg_ray_result(ivec2 pixel, int width, vec4 result)
{
    fg_rays.rays[pixel.y * width + pixel.x] = result;
}
