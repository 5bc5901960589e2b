#version 450
// Each pixel gets its own coordinates, so a misplaced row or column shows in the readback.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform writeonly image2D target;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(target)))) return;
    imageStore(target, p, vec4(float(p.x), float(p.y), float(p.x * 1000 + p.y), 1.0));
}
