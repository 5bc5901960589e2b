#version 450
// Burns a known amount of time so a timed pass is measurably long.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0) buffer Values { float values[]; };

layout(push_constant) uniform Push { uint iterations; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    float x = float(i);
    for (uint k = 0u; k < push.iterations; ++k) x = sin(x) * 0.5 + cos(x + float(k));
    values[i] = x;
}
