// How long the studio takes to answer what a person does, over its HTTP API (what the page does):
//   slider move -> new preview frame (a uniform changes, nothing recompiles)
//   graph edit  -> compile + pipelines + first frame (warm: the server is already running), three
//                  kinds: a literal changed, a wire moved, a node added
// A benchmark, not a test: prints a Markdown table for docs/studio.md.
//   node studio/bench/latency.mjs FGPLAY GRAPH [--size 256] [--moves 60] [--edits 20]
// The graph must have the gallery Mandelbulb's nodes `tone` (math.scale), `shift` (math.add) and
// `palette` (palette.cosine); a graph with a formula node (graphs/formulas/mandelbox.json) also
// times an edit of a number in its body. Every edit leaves a graph not seen before, in this run or an earlier
// one: each round of three edits starts with a new value of tone's literal, counted from a random
// start, so neither the server's caches nor Mesa's shader cache can answer for the pass it changes.
import { spawn } from "node:child_process";

const [fgplay, graphPath, ...rest] = process.argv.slice(2);
if (!fgplay || !graphPath) {
  console.error("usage: node latency.mjs FGPLAY GRAPH [--size N] [--moves N] [--edits N]");
  process.exit(2);
}
const option = (name, fallback) => {
  const i = rest.indexOf(name);
  return i >= 0 ? Number(rest[i + 1]) : fallback;
};
const size = option("--size", 256), moves = option("--moves", 60), edits = option("--edits", 20);

const server = spawn(fgplay, ["studio", graphPath, "--port", "0", "--size", String(size)], { stdio: ["ignore", "pipe", "inherit"] });
const base = await new Promise((resolve, reject) => {
  let out = "";
  server.stdout.on("data", (d) => {
    out += d;
    const m = out.match(/http:\/\/127\.0\.0\.1:\d+/);
    if (m) resolve(m[0]);
  });
  server.on("exit", (code) => reject(new Error(`fgplay studio exited with ${code}`)));
});

const post = (path, body) => fetch(base + path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
const now = () => performance.now();
async function frame(params) {
  const r = await post("/api/frame", { params });
  if (!r.ok) throw new Error(await r.text());
  await r.arrayBuffer();
  return { gpu: Number(r.headers.get("X-Fg-Gpu-Ms")), cpu: Number(r.headers.get("X-Fg-Cpu-Ms")), compiles: Number(r.headers.get("X-Fg-Compiles")) };
}
async function compile(graph) {
  const { revision } = await (await post("/api/edit", { graph })).json();
  for (;;) {
    const state = await (await fetch(`${base}/api/state?after=${revision}&wait_ms=10000`)).json();
    if (state.revision >= revision) {
      if (!state.ok) throw new Error(JSON.stringify(state.diagnostics));
      return state;
    }
  }
}
const stats = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const at = (q) => s[Math.min(s.length - 1, Math.floor(q * s.length))];
  return { median: at(0.5), p95: at(0.95), n: s.length };
};

const graph = (await (await fetch(`${base}/api/graph?path=${encodeURIComponent(graphPath.split("/").pop())}`)).json()).graph;
await compile(graph);
await frame({});

const slider = [], sliderGpu = [], sliderServer = [];
const compilesBefore = (await frame({})).compiles;
for (let i = 0; i < moves; ++i) {
  const t = now();
  const f = await frame({ power: 8 + 3 * Math.sin(i) });
  slider.push(now() - t);
  sliderGpu.push(f.gpu);
  sliderServer.push(f.cpu);
}
const compilesAfter = (await frame({})).compiles;

// One round: a literal (baked into the code, so it recompiles), a wire moved (shift.b between the
// hue parameter and the trap's x), a node added in front of the palette.
const node = (g, id) => g.nodes.find((n) => n.id === id);
const start = 0.3 + Math.round(Math.random() * 100000) / 500000;
const kinds = {
  literal: (g, round) => { node(g, "tone").inputs.s = start + 0.001 * (round + 1); },
  wire: (g) => { const shift = node(g, "shift"); shift.inputs.b = shift.inputs.b === "$hue" ? "trap.x" : "$hue"; },
  "node added": (g, round) => {
    const palette = node(g, "palette");
    g.nodes.push({ id: `added${round}`, type: "math.add", inputs: { a: palette.inputs.t, b: 0.01 } });
    palette.inputs.t = `added${round}`;
  },
};
// A graph with a formula node gets a fourth kind: a number of its body (the sphere fold's radius,
// or its first stage's first number), which the preview holds as a uniform.
const formula = graph.nodes.find((n) => n.formula);
if (formula) {
  const stages = formula.formula.groups[0].nodes;
  const stage = stages.find((n) => n.type === "stage.sphere_fold") ?? stages[0];
  const key = stage.type === "stage.sphere_fold" ? "min_radius" : Object.keys(stage.inputs ?? {}).find((k) => typeof stage.inputs[k] === "number");
  if (key) {
    const base = stage.inputs[key];
    kinds["formula number"] = (g, round) => {
      const s = node(g, formula.id).formula.groups[0].nodes.find((n) => n.id === stage.id);
      s.inputs[key] = base * (1 + 0.01 * Math.sin(start * 1000 + round));
    };
  }
}
const measured = Object.fromEntries(Object.keys(kinds).map((k) => [k, { total: [], compile: [], glslang: [], optimize: [], pipelines: [], frame: [], passes: [] }]));
const current = JSON.parse(JSON.stringify(graph));
for (let round = 0; round < edits; ++round) {
  for (const [kind, edit] of Object.entries(kinds)) {
    edit(current, round);
    const t = now();
    const state = await compile(current);
    const compiled = now();
    await frame({});
    const m = measured[kind];
    m.total.push(now() - t);
    m.frame.push(now() - compiled);
    m.compile.push(state.compile_ms);
    m.glslang.push(state.glslang_ms ?? NaN);
    m.optimize.push(state.optimize_ms ?? NaN);
    m.pipelines.push(state.pipelines_ms);
    m.passes.push(state.passes_compiled ?? NaN);
  }
}
server.kill("SIGTERM");

const ms = (x) => (Number.isNaN(x) ? "n/a" : `${x.toFixed(0)} ms`);
const row = (what, s, extra) => `| ${what} | ${s.median.toFixed(0)} ms | ${s.p95.toFixed(0)} ms | ${s.n} | ${extra} |`;
const g = stats(sliderGpu), sv = stats(sliderServer);
console.log(`| step | median | p95 | runs | of which (medians) |`);
console.log(`|---|---|---|---|---|`);
console.log(row(`slider move -> new frame (${size}² per eye)`, stats(slider),
  `render + read back + PNG on the server ${sv.median.toFixed(0)} ms${g.median >= 0 ? `, GPU ${g.median.toFixed(0)} ms` : ""}; compiles during the moves: ${compilesAfter - compilesBefore}`));
for (const [kind, m] of Object.entries(measured)) {
  const median = (xs) => stats(xs).median;
  console.log(row(`graph edit (${kind}) -> first new frame`, stats(m.total),
    `compile ${ms(median(m.compile))} (glslang ${ms(median(m.glslang))}, spirv-opt and validation ${ms(median(m.optimize))} CPU over ` +
    `${Number.isNaN(median(m.passes)) ? "all" : median(m.passes)} passes compiled), pipelines ${ms(median(m.pipelines))}, first frame ${ms(median(m.frame))}`));
}
