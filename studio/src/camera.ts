// The preview's camera, moved with the mouse: orbit turns the eye around the target, fly turns the
// target around the eye and moves both with the keys.
export type Vec3 = [number, number, number];
export interface Camera {
  position: Vec3;
  target: Vec3;
}

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
const length = (a: Vec3) => Math.hypot(a[0], a[1], a[2]);

function toSpherical(v: Vec3) {
  const r = Math.max(1e-9, length(v));
  return { r, yaw: Math.atan2(v[0], v[2]), pitch: Math.asin(Math.max(-1, Math.min(1, v[1] / r))) };
}
function fromSpherical(r: number, yaw: number, pitch: number): Vec3 {
  const p = Math.max(-1.55, Math.min(1.55, pitch));
  return [r * Math.cos(p) * Math.sin(yaw), r * Math.sin(p), r * Math.cos(p) * Math.cos(yaw)];
}

export function orbit(c: Camera, dx: number, dy: number): Camera {
  const s = toSpherical(sub(c.position, c.target));
  return { ...c, position: add(c.target, fromSpherical(s.r, s.yaw - dx * 0.01, s.pitch + dy * 0.01)) };
}

export function dolly(c: Camera, factor: number): Camera {
  return { ...c, position: add(c.target, scale(sub(c.position, c.target), factor)) };
}

export function look(c: Camera, dx: number, dy: number): Camera {
  const s = toSpherical(sub(c.target, c.position));
  return { ...c, target: add(c.position, fromSpherical(s.r, s.yaw - dx * 0.005, s.pitch - dy * 0.005)) };
}

// Moves eye and target together: forward along the view, right across it.
export function fly(c: Camera, forward: number, right: number, up: number): Camera {
  const f = sub(c.target, c.position);
  const r = length(f);
  const fw = scale(f, 1 / r);
  const rt: Vec3 = [-fw[2], 0, fw[0]];
  const rl = Math.max(1e-9, length(rt));
  const step = add(add(scale(fw, forward * r * 0.05), scale(rt, (right * r * 0.05) / rl)), [0, up * r * 0.05, 0]);
  return { position: add(c.position, step), target: add(c.target, step) };
}
