//! pass: probe
//! needs: distance
//! when: always
// Distance and normal at a list of points: collision probes at the head and its predicted
// position, and the GPU side of the tests that compare the scene with its CPU twin.

layout(local_size_x = 64) in;
layout(set = 0, binding = 3, std430) readonly buffer FgProbePoints { vec4 points[]; } fg_points;
layout(set = 0, binding = 4, std430) writeonly buffer FgProbeResults { vec4 results[]; } fg_results;
layout(push_constant) uniform FgProbePush { ProbePush pc; };

void main()
{
    int i = int(gl_GlobalInvocationID.x);
    if (i >= pc.count) return;
    vec3 p = fg_points.points[i].xyz;
    float d = fg_scene_distance(p);
    float h = pc.normal_step;
    vec3 n = vec3(fg_scene_distance(p + vec3(h, 0.0, 0.0)) - fg_scene_distance(p - vec3(h, 0.0, 0.0)),
                  fg_scene_distance(p + vec3(0.0, h, 0.0)) - fg_scene_distance(p - vec3(0.0, h, 0.0)),
                  fg_scene_distance(p + vec3(0.0, 0.0, h)) - fg_scene_distance(p - vec3(0.0, 0.0, h)));
    float len = length(n);
    fg_results.results[i] = vec4(d, len > 1e-20 ? n / len : vec3(0.0, 1.0, 0.0));
}
