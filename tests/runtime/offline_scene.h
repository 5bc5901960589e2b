#pragma once
// A scene that surrounds the camera, for panoramas: a floor under the whole lower half of the
// image, a ball ahead, a box behind (across the equirectangular seam) and a ring to the right.

namespace fg::test {

inline const char* kRoomGraph = R"({
  "format": "fractograph-graph", "version": 1, "name": "room",
  "nodes": [
    {"id": "floor", "type": "prim.plane", "inputs": {"offset": 1.0}},
    {"id": "front", "type": "xform.translate", "inputs": {"offset": [0.0, 0.0, -2.0]}},
    {"id": "ball", "type": "prim.sphere", "inputs": {"p": "front.p", "radius": 0.6}},
    {"id": "back", "type": "xform.translate", "inputs": {"offset": [0.3, -0.2, 2.2]}},
    {"id": "box", "type": "prim.box", "inputs": {"p": "back.p", "size": [0.8, 0.6, 0.4], "rounding": 0.05}},
    {"id": "side", "type": "xform.translate", "inputs": {"offset": [2.0, 0.0, 0.0]}},
    {"id": "ring", "type": "prim.torus", "inputs": {"p": "side.p", "major": 0.6, "minor": 0.2}},
    {"id": "u1", "type": "op.union", "inputs": {"a": "floor", "b": "ball"}},
    {"id": "u2", "type": "op.union", "inputs": {"a": "u1", "b": "box"}},
    {"id": "all", "type": "op.union", "inputs": {"a": "u2", "b": "ring"}}
  ],
  "outputs": {"distance": "all"},
  "scene": {"camera": {"position": [0, 0, 0], "target": [0, 0, -1], "fov_deg": 90}, "bounds": {"radius": 6.0}}
})";

}  // namespace fg::test
