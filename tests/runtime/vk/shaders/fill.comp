#version 450
// values[i] = i * scale + offset for the first `count` elements; the rest are left alone.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0) buffer Values { uint values[]; };

layout(push_constant) uniform Push {
    uint count;
    uint scale;
    uint offset;
} push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    values[i] = i * push.scale + push.offset;
}
