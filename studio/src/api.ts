// The studio server's JSON API (runtime/studio/studio_routes.h), typed.
export type Json = null | boolean | number | string | Json[] | { [key: string]: Json };
// eslint-disable-next-line @typescript-eslint/no-explicit-any -- a graph document is open-ended JSON
export type GraphDoc = { nodes?: GraphNodeDoc[]; [key: string]: any };
export type GraphNodeDoc = { id: string; type: string; inputs?: Record<string, Json>; [key: string]: Json | undefined };

export interface PortDef {
  name: string;
  type: string; // "float", "vec3", ... or "T" (generic)
  doc: string;
  default?: number | number[];
  implicit?: string;
  min?: number;
  max?: number;
  knob?: string;
}

export interface NodeDef {
  type: string;
  category: string;
  summary: string;
  doc: string;
  shade_only: boolean;
  inputs: PortDef[];
  outputs: PortDef[];
  generic: string[];
  stage: boolean;
  in_body: boolean;
  example: { inputs?: Record<string, unknown>; formula?: unknown };
}

export interface Diagnostic {
  severity: "error" | "warning" | "note";
  message: string;
  pointer: string;
  node: string;
  context: string;
  text: string;
}

export interface CompileState {
  revision: number;
  ok: boolean;
  diagnostics: Diagnostic[];
  compile_ms: number;
  pipelines_ms: number;
  compiles: number;
  submitted: number;
  skipped: number;
  busy: boolean;
}

export interface FrameInfo {
  url: string;
  gpuMs: number;
  cpuMs: number;
  evaluationsPerPixel: number;
  revision: number;
  compiles: number;
  width: number;
  height: number;
  samples: number; // samples per pixel the picture holds: a still view refines to REFINED_SAMPLES
}

// A still preview refines until each pixel holds this many samples (the runtime's kRefinedFrames).
export const REFINED_SAMPLES = 16;

export interface ProbeInfo {
  hit: boolean;
  point: [number, number, number];
  depth: number;
  distance: number;
}

async function json<T>(response: Response): Promise<T> {
  const body = await response.json().catch(() => ({ error: `HTTP ${response.status}` }));
  if (!response.ok) throw new Error(body.error ?? `HTTP ${response.status}`);
  return body as T;
}

function post(path: string, body: unknown): Promise<Response> {
  return fetch(path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
}

export const api = {
  nodes: () => fetch("/api/nodes").then((r) => json<{ nodes: NodeDef[] }>(r)),
  graphs: () => fetch("/api/graphs").then((r) => json<{ folder: string; graphs: string[]; opened: string }>(r)),
  graph: (path: string) =>
    fetch(`/api/graph?path=${encodeURIComponent(path)}`).then((r) => json<{ path: string; graph: GraphDoc }>(r)),
  validate: (graph: GraphDoc) => post("/api/validate", { graph }).then((r) => json<{ ok: boolean; diagnostics: Diagnostic[] }>(r)),
  edit: (graph: GraphDoc) => post("/api/edit", { graph }).then((r) => json<{ revision: number }>(r)),
  state: (after: number, waitMs: number) =>
    fetch(`/api/state?after=${after}&wait_ms=${waitMs}`).then((r) => json<CompileState>(r)),
  save: (path: string, graph: GraphDoc, basedOn: string) =>
    post("/api/save", { path, graph, based_on: basedOn }).then((r) =>
      json<{ path: string; bytes: number; diagnostics: Diagnostic[] }>(r),
    ),
  exportPack: (path: string, graph: GraphDoc) => post("/api/export", { path, graph }).then((r) => json<{ bytes: number }>(r)),
  calibrate: (graph: GraphDoc, samples: number) => post("/api/calibrate", { graph, samples }).then((r) => json<CalibrationStatus>(r)),
  calibration: () => fetch("/api/calibrate").then((r) => json<CalibrationStatus>(r)),
  probe: (x: number, y: number) => post("/api/probe", { x, y }).then((r) => json<ProbeInfo>(r)),

  async frame(body: unknown): Promise<FrameInfo> {
    const r = await post("/api/frame", body);
    if (!r.ok) await json(r);
    const header = (name: string) => Number(r.headers.get(name) ?? "0");
    const blob = await r.blob();
    const bitmap = await createImageBitmap(blob);
    const info: FrameInfo = {
      url: URL.createObjectURL(blob),
      gpuMs: header("X-Fg-Gpu-Ms"),
      cpuMs: header("X-Fg-Cpu-Ms"),
      evaluationsPerPixel: header("X-Fg-Evaluations-Per-Pixel"),
      revision: header("X-Fg-Revision"),
      compiles: header("X-Fg-Compiles"),
      samples: header("X-Fg-Samples") || 1,
      width: bitmap.width,
      height: bitmap.height,
    };
    bitmap.close();
    return info;
  },

  async nodePreview(graph: GraphDoc, node: string, params: Record<string, Json>): Promise<string | null> {
    const r = await post("/api/node-preview", { graph, node, port: "distance", params });
    if (!r.ok) return null;
    return URL.createObjectURL(await r.blob());
  },
};

export interface CalibrationStatus {
  state: "idle" | "running" | "done" | "failed";
  done: number;
  total: number;
  log: string;
  graph?: string;
}
