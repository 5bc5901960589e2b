#version 450
// Needs the shaderFloat64 device feature.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0) buffer Values { float values[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    double x = double(i) / 3.0lf;
    values[i] = float(x * 3.0lf);
}
