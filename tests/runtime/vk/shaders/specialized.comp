#version 450
// One constant of each 4-byte type a specialization value can carry.
layout(local_size_x = 64) in;

layout(constant_id = 0) const uint MULTIPLIER = 1u;
layout(constant_id = 1) const int OFFSET = 0;
layout(constant_id = 2) const float SCALE = 1.0;

layout(set = 0, binding = 0) buffer Values { float values[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    values[i] = float(int(i * MULTIPLIER) + OFFSET) * SCALE;
}
