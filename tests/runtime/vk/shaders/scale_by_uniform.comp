#version 450
// outputs[i] = inputs[i] * factor + bias, with factor and bias from a uniform buffer.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Params {
    float factor;
    float bias;
} params;
layout(set = 0, binding = 1) readonly buffer Inputs { float inputs[]; };
layout(set = 0, binding = 2) writeonly buffer Outputs { float outputs[]; };

layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    outputs[i] = inputs[i] * params.factor + params.bias;
}
