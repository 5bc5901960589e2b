// Fractograph Studio driven as a person would, in headless Chromium (Debian's, through
// puppeteer-core): open the gallery Mandelbulb, move a slider, add and wire a node, make a type
// error, save, reopen an untouched graph and save it byte-identical. Run by ctest with FGPLAY,
// FGC, CHROMIUM, FG_SOURCE_DIR and STUDIO_WORK set; FG_STUDIO_SCREENSHOTS (optional) is where the
// screenshots docs/studio.md shows are written.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { spawn, execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import puppeteer from "puppeteer-core";

const env = (name) => {
  const v = process.env[name];
  if (!v) throw new Error(`${name} is not set (ctest sets it)`);
  return v;
};
const work = env("STUDIO_WORK");
const folder = path.join(work, "folder");
const shots = process.env.FG_STUDIO_SCREENSHOTS || path.join(work, "screenshots");
let server, browser, page, base;

// What the page is doing, for a failed step's message: the requests it sent and what it printed.
const pageLog = [];
const note = (line) => pageLog.push(`${new Date().toISOString().slice(11, 23)} ${line}`);

// Requests the page has sent and not yet had answered, but for its long poll of the compile state.
const inFlight = new Set();
const busy = () => [...inFlight].filter((r) => !r.url().includes("/api/state")).length;

before(async () => {
  fs.rmSync(work, { recursive: true, force: true });
  fs.mkdirSync(folder, { recursive: true });
  fs.mkdirSync(shots, { recursive: true });
  for (const name of ["mandelbulb.json", "menger.json", "mandelbox.json"])
    fs.copyFileSync(path.join(env("FG_SOURCE_DIR"), "graphs/gallery", name), path.join(folder, name));
  fs.copyFileSync(path.join(env("FG_SOURCE_DIR"), "graphs/formulas/mandelbox.json"), path.join(folder, "formula_box.json"));
  server = spawn(env("FGPLAY"), ["studio", path.join(folder, "mandelbulb.json"), "--port", "0", "--fgc", env("FGC")], {
    stdio: ["ignore", "pipe", "inherit"],
  });
  base = await new Promise((resolve, reject) => {
    let out = "";
    server.stdout.on("data", (d) => {
      out += d;
      const m = out.match(/http:\/\/127\.0\.0\.1:\d+\/\S*/);
      if (m) resolve(m[0]);
    });
    server.on("exit", (code) => reject(new Error(`fgplay studio exited with ${code}: ${out}`)));
    // unref: a pending timer would keep node running for its full minute after the tests end.
    setTimeout(() => reject(new Error(`no URL from fgplay studio: ${out}`)), 60000).unref();
  });
  browser = await puppeteer.launch({
    executablePath: env("CHROMIUM"),
    headless: true,
    args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"],
  });
  page = await browser.newPage();
  await page.setViewport({ width: 1600, height: 900 });
  page.on("pageerror", (e) => console.error("page error:", e.message));
  page.on("console", (m) => note(`console ${m.type()}: ${m.text()}`));
  page.on("request", (r) => inFlight.add(r));
  page.on("requestfinished", (r) => {
    inFlight.delete(r);
    note(`${r.method()} ${r.url().replace(/^\w+:\/\/[^/]+/, "")} ${r.response()?.status()}`);
  });
  page.on("requestfailed", (r) => {
    inFlight.delete(r);
    note(`${r.method()} ${r.url().replace(/^\w+:\/\/[^/]+/, "")} failed: ${r.failure()?.errorText}`);
  });
});

after(async () => {
  await browser?.close();
  server?.kill("SIGTERM");
});

const origin = () => new URL(base).origin;
async function serverState() {
  const r = await fetch(`${origin()}/api/state`);
  return r.json();
}

// A digest of the preview's pixels and how much they vary (a blank frame does not).
async function previewPixels() {
  return page.evaluate(async () => {
    const img = document.querySelector('[data-testid="preview-image"]');
    if (!img || !img.complete || !img.naturalWidth) return null;
    const c = document.createElement("canvas");
    c.width = img.naturalWidth;
    c.height = img.naturalHeight;
    const g = c.getContext("2d");
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let sum = 0, sum2 = 0, hash = 0;
    for (let i = 0; i < d.length; i += 4) {
      const y = d[i] + d[i + 1] + d[i + 2];
      sum += y;
      sum2 += y * y;
      hash = (hash * 31 + y) | 0;
    }
    const n = d.length / 4;
    return { hash, variance: sum2 / n - (sum / n) ** 2, src: img.src, width: c.width };
  });
}

async function waitForPreview(differentFrom, timeout = 120000) {
  const start = Date.now();
  while (Date.now() - start < timeout) {
    const p = await previewPixels();
    if (p && p.variance > 10 && (!differentFrom || p.hash !== differentFrom.hash)) return p;
    await new Promise((r) => setTimeout(r, 200));
  }
  throw new Error("the preview did not show the expected frame");
}

async function idle() {
  // Compiles done, the newest frame and every node's preview shown: a preview arriving re-renders
  // its node, and on a loaded machine each takes seconds (a new shader for every subgraph).
  await page.waitForFunction(() => !document.querySelector('[data-testid="status"]')?.textContent?.includes("compiling"), { timeout: 120000 });
  for (const start = Date.now(); busy() > 0 && Date.now() - start < 120000; ) await new Promise((r) => setTimeout(r, 100));
  await new Promise((r) => setTimeout(r, 800));
}

// The preview once a still view has refined to 16 samples per pixel: its frames change until then.
async function refined() {
  await page.waitForFunction(() => document.querySelector('[data-testid="samples"]')?.textContent?.includes("16 samples/pixel"), {
    timeout: 120000,
  });
  await idle();
  return previewPixels();
}

// Where an element settles: a node grows when its preview image or diagnostics arrive, which moves
// its handles, so a drag starts only once both ends have held still for a moment.
async function settledBox(selector) {
  const element = await page.waitForSelector(selector);
  let last = await element.boundingBox();
  for (let i = 0; i < 50; ++i) {
    await new Promise((r) => setTimeout(r, 150));
    const box = await element.boundingBox();
    if (box && last && box.x === last.x && box.y === last.y) return box;
    last = box;
  }
  throw new Error(`${selector} kept moving`);
}

// The element a point lands on, described briefly (a handle by its node and port).
async function under(x, y) {
  return page.evaluate((px, py) => {
    const e = document.elementFromPoint(px, py);
    if (!e) return "nothing";
    if (e.classList.contains("react-flow__handle")) return `handle ${e.dataset.nodeid}.${e.dataset.handleid}`;
    return `${e.tagName.toLowerCase()}.${[...e.classList].join(".")}`;
  }, x, y);
}

// A drag from one handle to another as a person makes it: press, move, hold over the target until
// React Flow has drawn its connection line there, release. Reports what each end landed on and
// whether the line was drawn and judged valid, so a failed wire says which part failed.
async function drag(from, to) {
  const a = await settledBox(from);
  const b = await settledBox(to);
  const [ax, ay, bx, by] = [a.x + a.width / 2, a.y + a.height / 2, b.x + b.width / 2, b.y + b.height / 2];
  const report = { from: await under(ax, ay), to: await under(bx, by) };
  // What the page receives of the drag (where the press and the release land, how many moves).
  await page.evaluate(() => {
    const seen = (window.__fgSeen = { down: null, moves: 0, up: null });
    const name = (e) => (e.target?.dataset?.handleid ? `handle ${e.target.dataset.nodeid}.${e.target.dataset.handleid}` : `${e.target?.tagName}.${e.target?.className}`);
    const done = new AbortController();
    const options = { capture: true, signal: done.signal };
    document.addEventListener("mousedown", (e) => (seen.down = name(e)), options);
    document.addEventListener("mousemove", () => ++seen.moves, options);
    document.addEventListener("mouseup", (e) => ((seen.up = name(e)), done.abort()), options);
  });
  await page.mouse.move(ax, ay);
  await page.mouse.down();
  await page.mouse.move((ax + bx) / 2, (ay + by) / 2, { steps: 8 });
  await page.mouse.move(bx, by, { steps: 8 });
  const line = await page
    .waitForFunction(() => document.querySelector(".react-flow__connection")?.getAttribute("class"), { timeout: 5000 })
    .then((h) => h.jsonValue())
    .catch(() => "no connection line");
  report.line = line;
  await page.mouse.up();
  report.events = await page.evaluate(() => window.__fgSeen);
  return report;
}

// A wire drawn by dragging; on a loaded machine a late re-layout can still move a handle under the
// mouse, so a drag that left no wire is made again when the page is idle (three drags in all).
async function wire(fromNode, fromPort, toNode, toPort) {
  const edge = `.react-flow__edge[data-testid="rf__edge-${fromNode}.${fromPort}->${toNode}.${toPort}"]`;
  const reports = [];
  for (let attempt = 0; attempt < 3; ++attempt) {
    await idle();
    reports.push(await drag(handle(fromNode, "source", fromPort), handle(toNode, "target", toPort)));
    if (await page.waitForSelector(edge, { timeout: 15000 }).catch(() => null)) return;
  }
  await page.screenshot({ path: path.join(shots, "wire_failed.png") });
  throw new Error(`no wire ${fromNode}.${fromPort} -> ${toNode}.${toPort} after three drags: ${JSON.stringify(reports)}\npage:\n${pageLog.slice(-40).join("\n")}`);
}

const handle = (node, side, port) => `[data-testid="node-${node}"] .react-flow__handle.${side}[data-handleid="${port}"]`;

async function setLiteral(node, port, text) {
  const field = await page.waitForSelector(`[data-testid="literal-${node}-${port}"]`);
  await field.click({ clickCount: 3 });
  await field.type(text);
  await field.press("Enter");
}

async function saveAs(name) {
  const accept = (d) => d.accept(name);
  page.once("dialog", accept);
  await page.click('[data-testid="save-as"]');
  await page.waitForFunction((n) => document.querySelector('[data-testid="toast"]')?.textContent?.includes(`saved ${n}`), { timeout: 30000 }, name);
}

test("the studio edits a graph with a live preview", async (t) => {
  await page.goto(base);
  let frame;
  await t.test("it opens the gallery Mandelbulb and shows a non-blank preview", async () => {
    await page.waitForSelector('[data-testid="node-bulb"]', { timeout: 60000 });
    frame = await waitForPreview();
    await idle();
    // The page asks for a frame only once a graph has compiled: no request was refused on the way.
    const refused = pageLog.filter((line) => / (4\d\d|5\d\d)$/.test(line));
    assert.deepEqual(refused, [], "requests refused while the page opened");
    await page.screenshot({ path: path.join(shots, "overview.png") });
  });

  await t.test("a still preview refines to 16 samples per pixel, shown smoothly at the page's size", async () => {
    await page.waitForFunction(() => document.querySelector('[data-testid="samples"]')?.textContent?.includes("16 samples/pixel"), {
      timeout: 120000,
    });
    const refined = await previewPixels();
    const box = await (await page.$('[data-testid="preview-image"]')).boundingBox();
    await page.screenshot({ path: path.join(shots, "preview_refined.png"), clip: box });
    // What the preview showed before: one sample per pixel of the render size, blown up with
    // nearest-neighbour. A camera a hair away restarts the server's refinement: one sample.
    const one = await page.evaluate(async () => {
      const r = await fetch("/api/frame", {
        method: "POST",
        headers: { "Content-Type": "application/json" },
        body: JSON.stringify({ camera: { position: [0.0, 0.6001, 2.6], target: [0, 0, 0] }, stereo: "mono" }),
      });
      const samples = Number(r.headers.get("X-Fg-Samples"));
      const img = document.createElement("img");
      img.src = URL.createObjectURL(await r.blob());
      await img.decode();
      const shown = document.querySelector('[data-testid="preview-image"]').getBoundingClientRect();
      Object.assign(img.style, { position: "fixed", left: `${shown.left}px`, top: `${shown.top}px`, width: `${shown.width}px`,
                                 height: `${shown.height}px`, imageRendering: "pixelated", zIndex: 1000 });
      img.id = "one-sample";
      document.body.appendChild(img);
      return { samples, width: img.naturalWidth };
    });
    await page.screenshot({ path: path.join(shots, "preview_one_sample.png"), clip: box });
    await page.evaluate(() => document.getElementById("one-sample").remove());
    assert.equal(one.samples, 1, "a new view starts from one sample");
    assert.ok(refined.width === one.width && refined.variance > 10, "the refined frame is a picture of the render size");
  });

  await t.test("the power slider changes the preview without a recompile", async () => {
    const compiles = (await serverState()).compiles;
    const slider = await page.$('[data-testid="param-power"]');
    const box = await slider.boundingBox();
    await page.mouse.click(box.x + box.width * 0.2, box.y + box.height / 2);
    frame = await waitForPreview(frame);
    assert.equal((await serverState()).compiles, compiles, "a slider move must not recompile");
  });

  await t.test("clicking the preview probes the surface", async () => {
    const img = await (await page.$('[data-testid="preview-image"]')).boundingBox();
    await page.mouse.click(img.x + img.width / 2, img.y + img.height / 2);
    const text = await page.waitForSelector('[data-testid="probe"]').then((e) => e.evaluate((x) => x.textContent));
    assert.match(text, /hit at|no surface/);
  });

  await t.test("a new node wired in changes the picture", async () => {
    await page.type('[data-testid="palette-search"]', "round");
    await page.click('[data-testid="palette-op.round"]');
    await page.waitForSelector('[data-testid="node-round"]');
    await new Promise((r) => setTimeout(r, 500));
    await wire("bulb", "distance", "round", "d");
    await wire("round", "distance", "__outputs__", "distance");
    await setLiteral("round", "radius", "0.08");
    frame = await waitForPreview(frame);
    await idle();
    frame = await refined();
    await page.waitForSelector('[data-testid="preview-round"]', { timeout: 60000 });
    await page.screenshot({ path: path.join(shots, "node_added.png") });
  });

  await t.test("a wire between incompatible types is refused with the compiler's reason", async () => {
    // A node preview arriving mid-drag (slow shader compiles on a loaded machine) moves the handles
    // under the mouse: if no answer comes, another drag once the page is idle again.
    let toast = null;
    const reports = [];
    for (let attempt = 0; attempt < 3 && !toast; ++attempt) {
      if (attempt > 0) await idle();
      // Dropped on the input's name, not its handle: the whole row takes a wire.
      reports.push(await drag(handle("bulb", "source", "trap"), '[data-testid="port-round-radius"] .port-name'));
      toast = await page
        .waitForSelector('[data-testid="toast"]', { timeout: 20000 })
        .then((e) => e.evaluate((x) => x.textContent))
        .catch(() => null);
    }
    assert.ok(toast, `no answer to the refused wire after three drags: ${JSON.stringify(reports)}\npage:\n${pageLog.slice(-40).join("\n")}`);
    assert.match(toast, /wire refused: .*type mismatch/);
  });

  await t.test("a type error shows its message on that node, and the preview keeps the last good pack", async () => {
    await setLiteral("round", "radius", "[1, 2, 3]");
    const diag = await page.waitForSelector('[data-testid="diag-round"]', { timeout: 60000 });
    const text = await diag.evaluate((x) => x.textContent);
    assert.match(text, /radius/);
    assert.equal(await page.$eval('[data-testid="node-round"]', (n) => n.classList.contains("has-error")), true);
    await page.waitForSelector('[data-testid="port-round-radius"].port-error');
    await page.screenshot({ path: path.join(shots, "type_error.png") });
    assert.equal((await previewPixels()).hash, frame.hash);
    await setLiteral("round", "radius", "0.08");
    await page.waitForFunction(() => !document.querySelector('[data-testid="diag-round"]'), { timeout: 60000 });
  });

  await t.test("saving writes a graph that fgc check accepts", async () => {
    await saveAs("saved/edited.json");
    const saved = path.join(folder, "saved/edited.json");
    const graph = JSON.parse(fs.readFileSync(saved, "utf8"));
    assert.equal(graph.editor.version, 1);
    assert.ok(graph.editor.nodes.round);
    assert.equal(graph.outputs.distance, "round.distance");
    execFileSync(env("FGC"), ["check", saved], { stdio: "inherit" });
  });

  await t.test("switching graphs with unsaved edits asks first, and keeps them when told to", async () => {
    await setLiteral("round", "radius", "0.09");
    let asked = "";
    page.once("dialog", (d) => {
      asked = d.message();
      d.dismiss();
    });
    await page.select('[data-testid="graph-select"]', "menger.json");
    await new Promise((r) => setTimeout(r, 500));
    assert.match(asked, /unsaved edits of saved\/edited\.json/);
    assert.equal(await page.$eval('[data-testid="graph-select"]', (s) => s.value), "saved/edited.json");
    assert.ok(await page.$('[data-testid="node-round"]'), "the edited graph is still open");
    await saveAs("saved/edited.json");
  });

  await t.test("side-by-side stereo shows both eyes", async () => {
    await page.click('[data-testid="stereo"]');
    await page.waitForFunction(() => {
      const img = document.querySelector('[data-testid="preview-image"]');
      return img && img.naturalWidth === 2 * img.naturalHeight;
    }, { timeout: 60000 });
    await idle();
    await page.screenshot({ path: path.join(shots, "stereo.png") });
    await page.click('[data-testid="mono"]');
  });

  await t.test("an untouched gallery graph reopens and saves byte-identical", async () => {
    await page.select('[data-testid="graph-select"]', "menger.json");
    await page.waitForFunction(() => new URLSearchParams(location.search).get("graph") === "menger.json");
    await idle();
    await saveAs("copy/menger.json");
    assert.ok(fs.readFileSync(path.join(folder, "copy/menger.json")).equals(fs.readFileSync(path.join(folder, "menger.json"))));
  });

  await t.test("a formula's body opens on the canvas, and a number edited there reshapes the preview without a compile", async () => {
    await page.select('[data-testid="graph-select"]', "formula_box.json");
    await page.waitForSelector('[data-testid="node-box"]', { timeout: 60000 });
    let before = await waitForPreview();
    await idle();
    await page.click('[data-testid="open-body-box-0"]');
    await page.waitForSelector('[data-testid="node-sphere"]', { timeout: 30000 });
    const search = await page.$('[data-testid="palette-search"]');
    await search.click({ clickCount: 3 });
    await search.type("fold");
    assert.ok(await page.$('[data-testid="palette-stage.plane_fold"]'), "inside a body the palette offers the stages");
    assert.equal(await page.$('[data-testid="palette-op.round"]'), null, "and nothing a body cannot hold");
    await search.click({ clickCount: 3 });
    await search.type("multiply");
    assert.ok(await page.$('[data-testid="palette-math.multiply"]'), "and the maths nodes with a tangent rule");
    assert.equal(await page.$('[data-testid="node-trap"]'), null, "the graph's other nodes are not shown inside the body");
    await setLiteral("sphere", "min_radius", "0.3");
    const after = await waitForPreview(before);
    await idle();
    const state = await serverState();
    assert.equal(state.passes_compiled, 0, "a body's number is a uniform: editing it compiles no pass");
    await page.screenshot({ path: path.join(shots, "formula_body.png") });
    await page.click('[data-testid="close-body"]');
    await page.waitForSelector('[data-testid="node-trap"]', { timeout: 30000 });
    assert.notEqual(after.hash, before.hash);
    await saveAs("saved/formula_box.json");
    const saved = JSON.parse(fs.readFileSync(path.join(folder, "saved/formula_box.json"), "utf8"));
    assert.equal(saved.nodes[0].formula.groups[0].nodes[1].inputs.min_radius, 0.3);
    execFileSync(env("FGC"), ["check", path.join(folder, "saved/formula_box.json")], { stdio: "inherit" });
  });

  await t.test("New starts a graph that compiles and previews, unsaved until saved", async () => {
    await page.click('[data-testid="new-graph"]');
    await page.waitForSelector('[data-testid="node-shape"]', { timeout: 30000 });
    assert.equal(await page.$eval('[data-testid="graph-select"]', (s) => s.value), "new.json");
    await waitForPreview();
    await saveAs("new.json");
    execFileSync(env("FGC"), ["check", path.join(folder, "new.json")], { stdio: "inherit" });
  });
});
