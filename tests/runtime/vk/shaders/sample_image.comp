#version 450
// Copies every texel of a sampled image into a buffer, row by row.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D source;
layout(set = 0, binding = 1) writeonly buffer Texels { vec4 texels[]; };

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(source, 0);
    if (any(greaterThanEqual(p, size))) return;
    texels[p.y * size.x + p.x] = texelFetch(source, p, 0);
}
