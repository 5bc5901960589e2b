#version 450
// Reads what an earlier dispatch wrote, so it only sees the right values after a barrier.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0) buffer Values { uint values[]; };

layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    values[i] = values[i] * 2u;
}
