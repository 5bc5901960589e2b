// Fractograph Studio: the node editor beside the live preview. The graph document is the state;
// the canvas, the parameter sliders and the preview are views of it. Every edit goes to the server's
// compiler; diagnostics come back to the node and port their JSON pointer names.
import { useCallback, useEffect, useMemo, useRef, useState } from "react";
import {
  Background,
  Controls,
  ReactFlow,
  ReactFlowProvider,
  applyEdgeChanges,
  applyNodeChanges,
  useReactFlow,
  useUpdateNodeInternals,
  type Connection,
  type Edge,
  type EdgeChange,
  type FinalConnectionState,
  type NodeChange,
} from "@xyflow/react";
import { api, REFINED_SAMPLES, type CalibrationStatus, type CompileState, type Diagnostic, type FrameInfo, type GraphDoc, type GraphNodeDoc, type Json, type NodeDef, type ProbeInfo } from "./api";
import { addNode, nodesOf, pasteNodes, placeOf, portsOf, removeNodes, setBinding, setNodeField, uniqueId, wiresOf } from "./graph";
import { bodyView, groupNames, placeInBody, withBody, type OpenBody } from "./body";
import { autoLayout, editorPositions, type Positions } from "./layout";
import { History } from "./history";
import { GraphNode, type GraphFlowNode } from "./GraphNode";
import { Palette } from "./Palette";
import { ParamPanel, paramDefaults } from "./ParamPanel";
import { Preview } from "./Preview";
import type { Camera, Vec3 } from "./camera";
import { OUTPUT_NODE_ID, graphOutputs, typeColour } from "./types";

const nodeTypes = { graph: GraphNode };

interface Snapshot {
  doc: GraphDoc;
  positions: Positions;
}

function sceneCamera(doc: GraphDoc): Camera {
  const camera = ((doc.scene as Record<string, Json> | undefined)?.camera ?? {}) as Record<string, Json>;
  const v = (x: Json, d: Vec3): Vec3 => (Array.isArray(x) && x.length === 3 ? (x as Vec3) : d);
  return { position: v(camera.position, [0, 0, 3]), target: v(camera.target, [0, 0, 0]) };
}

// The document without the studio's own block: what the compiler gets.
function compiledDoc(doc: GraphDoc): GraphDoc {
  const { editor: _editor, ...rest } = doc;
  return rest as GraphDoc;
}

function Studio() {
  const flow = useReactFlow();
  const [catalog, setCatalog] = useState<NodeDef[]>([]);
  const catalogMap = useMemo(() => new Map(catalog.map((d) => [d.type, d])), [catalog]);
  const [graphs, setGraphs] = useState<string[]>([]);
  const [path, setPath] = useState("");
  const [doc, setDoc] = useState<GraphDoc | null>(null);
  const [positions, setPositions] = useState<Positions>({});
  const [layoutDirty, setLayoutDirty] = useState(false);
  const [nodes, setNodes] = useState<GraphFlowNode[]>([]);
  const [edges, setEdges] = useState<Edge[]>([]);
  const [compile, setCompile] = useState<CompileState | null>(null);
  const [compiling, setCompiling] = useState(false);
  const [params, setParams] = useState<Record<string, Json>>({});
  const [camera, setCamera] = useState<Camera>({ position: [0, 0, 3], target: [0, 0, 0] });
  const [stereo, setStereo] = useState(false);
  const [frame, setFrame] = useState<FrameInfo | null>(null);
  const [probe, setProbe] = useState<ProbeInfo | null>(null);
  const [previews, setPreviews] = useState<Record<string, string>>({});
  const [toast, setToast] = useState("");
  const [calibration, setCalibration] = useState<CalibrationStatus | null>(null);
  // A formula's body opened on the canvas (its group's stages), or null for the graph itself.
  const [openBody, setOpenBody] = useState<OpenBody | null>(null);
  const [bodyPositions, setBodyPositions] = useState<Positions>({});
  const openRef = useRef(openBody);
  openRef.current = openBody;
  const viewDoc = useMemo(() => (doc && openBody ? bodyView(doc, openBody) : doc), [doc, openBody]);

  const history = useRef(new History<Snapshot>());
  const snapshot = useRef<Snapshot>({ doc: {}, positions: {} });
  snapshot.current = { doc: doc ?? {}, positions };
  // What the canvas shows of a document (the open body, or all of it), and a document with an edit
  // of that view written back.
  const viewOf = (d: GraphDoc): GraphDoc => (openRef.current ? bodyView(d, openRef.current) : d);
  const fromView = (d: GraphDoc, view: GraphDoc): GraphDoc => (openRef.current ? withBody(d, openRef.current, view) : view);
  const clipboard = useRef<GraphNodeDoc[]>([]);
  const latestRevision = useRef(0);

  const say = useCallback((text: string) => {
    setToast(text);
    window.setTimeout(() => setToast((t) => (t === text ? "" : t)), 6000);
  }, []);

  // --- preview frames: one request in flight, the newest view wins -------------------------------
  const view = useRef({ camera, params, stereo });
  view.current = { camera, params, stereo };
  const frameState = useRef({ inFlight: false, again: false });
  // Until a graph has compiled there is no frame to ask for (the server would answer 409).
  const compiledOnce = useRef(false);
  const requestFrame = useCallback(() => {
    if (!compiledOnce.current) return;
    const s = frameState.current;
    if (s.inFlight) {
      s.again = true;
      return;
    }
    s.inFlight = true;
    s.again = false;
    const v = view.current;
    // The device pixels one eye is shown across: the renderer hits by them, whatever its own size.
    const shown = document.querySelector('[data-testid="preview-frame"]')?.clientWidth ?? 0;
    const displayWidth = (shown * window.devicePixelRatio) / (v.stereo ? 2 : 1);
    let refine = false;
    api
      .frame({ camera: v.camera, params: v.params, stereo: v.stereo ? "side-by-side" : "mono", display_width: displayWidth })
      .then((f) => {
        // A still view keeps refining: each frame adds a sample per pixel until REFINED_SAMPLES.
        const now = view.current;
        refine = f.samples < REFINED_SAMPLES && now.camera === v.camera && now.params === v.params && now.stereo === v.stereo;
        setFrame((old) => {
          if (old) URL.revokeObjectURL(old.url);
          return f;
        });
      })
      .catch(() => undefined)
      .finally(() => {
        s.inFlight = false;
        if (s.again || refine) requestFrame();
      });
  }, []);
  useEffect(requestFrame, [camera, params, stereo, requestFrame]);

  // --- opening a graph ---------------------------------------------------------------------------
  // Edits since the graph was opened or saved: switching graphs or closing the tab asks first.
  const unsaved = useRef(false);
  useEffect(() => {
    const warn = (e: BeforeUnloadEvent) => {
      if (!unsaved.current) return;
      e.preventDefault();
      e.returnValue = "";
    };
    window.addEventListener("beforeunload", warn);
    return () => window.removeEventListener("beforeunload", warn);
  }, []);
  const show = useCallback(
    (p: string, graph: GraphDoc, saved: boolean) => {
        const placed = editorPositions(graph);
        setPath(p);
        setDoc(graph);
        unsaved.current = !saved;
        setPositions(placed ?? autoLayout(graph, catalogMap));
        setLayoutDirty(false);
        setParams(paramDefaults(graph));
        setCamera(sceneCamera(graph));
        setProbe(null);
        setOpenBody(null);
        history.current.clear();
        window.history.replaceState(null, "", `?graph=${encodeURIComponent(p)}`);
        window.setTimeout(() => flow.fitView({ padding: 0.1 }), 50);
    },
    [catalogMap, flow],
  );
  const open = useCallback(
    async (p: string) => {
      try {
        const { graph } = await api.graph(p);
        show(p, graph, true);
      } catch (e) {
        say(String(e));
      }
    },
    [show, say],
  );
  // A new graph to start from (a sphere, lit), unsaved until Save: what an empty folder offers.
  const newGraph = () => {
    if (unsaved.current && !window.confirm(`Discard the unsaved edits of ${path}?`)) return;
    let name = "new.json";
    for (let i = 2; graphs.includes(name); ++i) name = `new_${i}.json`;
    show(name, {
      format: "fractograph-graph",
      version: 1,
      name: "New graph",
      nodes: [
        { id: "shape", type: "prim.sphere" },
        { id: "light", type: "light.fake_diffuse" },
      ],
      outputs: { distance: "shape.distance", diffuse: "light.diffuse" },
      scene: { camera: { position: [0, 0.6, 3], target: [0, 0, 0], fov_deg: 60 }, bounds: { radius: 2 } },
    } as GraphDoc, false);
  };

  useEffect(() => {
    api.nodes().then((r) => setCatalog(r.nodes)).catch((e) => say(String(e)));
    api.graphs().then((r) => setGraphs(r.graphs)).catch((e) => say(String(e)));
  }, [say]);
  useEffect(() => {
    if (catalog.length === 0 || doc) return;
    const asked = new URLSearchParams(window.location.search).get("graph");
    api.graphs().then((r) => {
      const first = asked ?? (r.opened || r.graphs[0]);
      // An empty folder starts a new graph rather than showing nothing.
      if (first) open(first);
      else newGraph();
    });
  }, [catalog, doc, open]);

  // --- every edit is compiled; the outcome of the newest one is shown ----------------------------
  const refreshPreviews = useCallback(
    async (graph: GraphDoc, revision: number) => {
      const distanceNodes = nodesOf(graph).filter((n) => portsOf(n, catalogMap).outputs.some((o) => o.name === "distance"));
      for (const n of distanceNodes) {
        if (latestRevision.current !== revision) return;
        const url = await api.nodePreview(graph, n.id, view.current.params);
        setPreviews((old) => {
          if (old[n.id]) URL.revokeObjectURL(old[n.id]);
          const next = { ...old };
          if (url) next[n.id] = url;
          else delete next[n.id];
          return next;
        });
      }
    },
    [catalogMap],
  );
  useEffect(() => {
    if (!doc) return;
    const graph = compiledDoc(doc);
    const timer = window.setTimeout(async () => {
      setCompiling(true);
      try {
        const { revision } = await api.edit(graph);
        latestRevision.current = revision;
        let state = await api.state(revision, 10000);
        while (state.revision < revision && latestRevision.current === revision) state = await api.state(revision, 10000);
        if (latestRevision.current !== revision) return;
        setCompile(state);
        setCompiling(false);
        if (state.ok) {
          compiledOnce.current = true;
          requestFrame();
          refreshPreviews(graph, revision);
        }
      } catch (e) {
        setCompiling(false);
        say(String(e));
      }
    }, 120);
    return () => window.clearTimeout(timer);
  }, [doc, requestFrame, refreshPreviews, say]);

  // --- edits, with undo ----------------------------------------------------------------------------
  const commit = useCallback((next: GraphDoc, nextPositions?: Positions) => {
    history.current.push(snapshot.current);
    unsaved.current = true;
    setDoc(next);
    if (nextPositions) {
      setPositions(nextPositions);
      setLayoutDirty(true);
    }
  }, []);
  const restore = (s: Snapshot | null) => {
    if (!s) return;
    unsaved.current = true;
    setDoc(s.doc);
    setPositions(s.positions);
  };
  const undo = () => restore(history.current.undo(snapshot.current));
  const redo = () => restore(history.current.redo(snapshot.current));

  const onBinding = useCallback(
    (id: string, port: string, value: Json | undefined) => {
      const d = snapshot.current.doc;
      commit(fromView(d, setBinding(viewOf(d), id, port, value)));
    },
    [commit],
  );
  const onCode = useCallback((id: string, code: string[]) => commit(setNodeField(snapshot.current.doc, id, "code", code)), [commit]);
  const openFormula = useCallback(
    (id: string, group: number) => {
      const open = { node: id, group };
      setOpenBody(open);
      setBodyPositions(autoLayout(bodyView(snapshot.current.doc, open), catalogMap));
      window.setTimeout(() => flow.fitView({ padding: 0.15 }), 50);
    },
    [catalogMap, flow],
  );
  const closeFormula = () => {
    setOpenBody(null);
    window.setTimeout(() => flow.fitView({ padding: 0.1 }), 50);
  };

  const addType = useCallback(
    (type: string) => {
      const current = snapshot.current.doc;
      const centre = flow.screenToFlowPosition({ x: window.innerWidth * 0.4, y: window.innerHeight * 0.45 });
      if (openRef.current) {
        // Inside a body: a stage, its z left to the point entering the group until it is wired.
        const view = viewOf(current);
        const id = uniqueId(view, type.split(".").pop() ?? "stage");
        setBodyPositions((p) => ({ ...p, [id]: [Math.round(centre.x), Math.round(centre.y)] }));
        commit(fromView(current, addNode(view, { id, type })));
        return;
      }
      const id = uniqueId(current, type.split(".").pop() ?? "node");
      const node: GraphNodeDoc =
        type === "custom.glsl"
          ? { id, type, ports: { inputs: [{ name: "p", type: "vec3", default: "position" }], outputs: [{ name: "distance", type: "float" }] }, lipschitz: 1.0, code: ["distance = length(p) - 0.5;"] }
          : type === "fractal.formula"
            ? { id, type, ...(structuredClone(catalog.find((d) => d.type === type)?.example ?? {}) as object) }
            : { id, type };
      commit(addNode(current, node), { ...snapshot.current.positions, [id]: [Math.round(centre.x), Math.round(centre.y)] });
    },
    [commit, flow, catalog],
  );

  // A wire the compiler would refuse is not drawn: its reason is shown instead. The check is a round
  // trip to the server, so the wire is bound into the document as it is when the answer comes (an
  // edit made meanwhile is kept), and a check that fails says so rather than drop the wire silently.
  const onConnect = useCallback(
    async (c: Connection) => {
      if (!c.source || !c.target || !c.sourceHandle || !c.targetHandle || c.source === OUTPUT_NODE_ID) return;
      const open = openRef.current;
      const bind = (doc: GraphDoc) => fromView(doc, setBinding(viewOf(doc), c.target, c.targetHandle!, `${c.source}.${c.sourceHandle}`));
      try {
        const candidate = bind(snapshot.current.doc);
        const check = await api.validate(compiledDoc(candidate));
        const reason = check.diagnostics.find((d) => {
          const place = open ? placeInBody(candidate, open, d.pointer) : placeOf(candidate, d.pointer, d.node);
          return d.severity === "error" && place?.node === c.target && (place.port === c.targetHandle || !place.port);
        });
        if (reason) say(`wire refused: ${reason.message}`);
        else commit(bind(snapshot.current.doc));
      } catch (e) {
        say(`wire not made: it could not be checked (${e})`);
      }
    },
    [commit, say],
  );

  // A wire dropped on an input's row (its name, its type, its field) goes to that input: the
  // handle itself is a few pixels wide at the zoom a whole graph is seen at.
  const onConnectEnd = useCallback(
    (event: MouseEvent | TouchEvent, state: FinalConnectionState) => {
      if (state.isValid || !state.fromNode || state.fromHandle?.type !== "source" || !state.fromHandle.id) return;
      const at = "changedTouches" in event ? event.changedTouches[0] : event;
      const row = document.elementFromPoint(at.clientX, at.clientY)?.closest<HTMLElement>("[data-port-node]");
      if (!row?.dataset.portNode || !row.dataset.portName) return;
      onConnect({ source: state.fromNode.id, sourceHandle: state.fromHandle.id, target: row.dataset.portNode, targetHandle: row.dataset.portName });
    },
    [onConnect],
  );

  const deleteSelection = useCallback(
    (nodeIds: string[], edgeList: Edge[]) => {
      const view = viewOf(snapshot.current.doc);
      let next = view;
      for (const e of edgeList) next = setBinding(next, e.target, e.targetHandle ?? "", undefined);
      const ids = new Set(nodeIds.filter((id) => id !== OUTPUT_NODE_ID));
      if (ids.size) next = removeNodes(next, ids);
      if (next !== view) commit(fromView(snapshot.current.doc, next));
    },
    [commit],
  );

  // --- canvas nodes and wires from the document ------------------------------------------------------
  const diagnostics = compile?.diagnostics ?? [];
  useEffect(() => {
    if (!doc || !viewDoc) return;
    const placed = new Map<string, { port?: string; diagnostic: Diagnostic }[]>();
    for (const d of diagnostics) {
      const place = openBody ? placeInBody(doc, openBody, d.pointer) : placeOf(doc, d.pointer, d.node);
      if (place) placed.set(place.node, [...(placed.get(place.node) ?? []), { port: place.port, diagnostic: d }]);
    }
    const where = openBody ? bodyPositions : positions;
    const wires = wiresOf(viewDoc, catalogMap);
    const wired = (id: string) => new Set(wires.filter((w) => w.target === id).map((w) => w.targetHandle));
    setNodes((old) => {
      const before = new Map(old.map((n) => [n.id, n]));
      const make = (id: string, data: GraphFlowNode["data"]): GraphFlowNode => {
        const o = before.get(id);
        const p = where[id] ?? [0, 0];
        return { ...(o ?? {}), id, type: "graph", position: { x: p[0], y: p[1] }, data } as GraphFlowNode;
      };
      const list = nodesOf(viewDoc).map((n) => {
        const ports = portsOf(n, catalogMap);
        const groups = n.type === "fractal.formula" && !openBody ? groupNames(doc, n.id) : [];
        return make(n.id, {
          doc: n,
          title: n.id,
          summary: catalogMap.get(n.type)?.summary ?? (n.type === "custom.glsl" ? "custom GLSL" : `unknown type ${n.type}`),
          inputs: ports.inputs,
          outputs: ports.outputs,
          wired: wired(n.id),
          diagnostics: placed.get(n.id) ?? [],
          preview: previews[n.id],
          onBinding: (port, value) => onBinding(n.id, port, value),
          onCode: (code) => onCode(n.id, code),
          bodyGroups: groups,
          onOpenBody: (group) => openFormula(n.id, group),
        });
      });
      list.push(
        make(OUTPUT_NODE_ID, {
          doc: null,
          title: openBody ? "z leaving the group" : "outputs",
          summary: openBody ? "the stage whose z the next group (or the next iteration) takes" : "what the scene shows: the distance, and how the surface is shaded",
          inputs: openBody ? [{ name: "z", type: "vec3", doc: "the orbit point leaving the group" }] : graphOutputs.map((o) => ({ name: o.name, type: o.type, doc: o.name })),
          outputs: [],
          wired: wired(OUTPUT_NODE_ID),
          diagnostics: placed.get(OUTPUT_NODE_ID) ?? [],
          onBinding: (port, value) => onBinding(OUTPUT_NODE_ID, port, value),
          onCode: () => undefined,
        }),
      );
      return list;
    });
    setEdges((old) => {
      const selected = new Set(old.filter((e) => e.selected).map((e) => e.id));
      return wires.map((w) => {
        const sourceNode = nodesOf(viewDoc).find((n) => n.id === w.source);
        const type = sourceNode ? portsOf(sourceNode, catalogMap).outputs.find((o) => o.name === w.sourceHandle)?.type ?? "float" : "float";
        return { ...w, selected: selected.has(w.id), style: { stroke: typeColour(type), strokeWidth: 2 } };
      });
    });
  }, [doc, viewDoc, openBody, positions, bodyPositions, diagnostics, previews, catalogMap, onBinding, onCode, openFormula]);

  // React Flow starts a wire from the bounds of the handles it measured in each node. On a loaded
  // machine it sometimes holds a node's measured size but no handle bounds after the page loads,
  // and measures again only when the size changes, so every drag from that node started no wire
  // (stop 31's CI: all of the gallery graph's nodes, in 5 of 28 runs here under load). Such a node
  // is measured again.
  const updateNodeInternals = useUpdateNodeInternals();
  useEffect(() => {
    const lost = nodes.filter((n) => n.measured && !flow.getInternalNode(n.id)?.internals.handleBounds).map((n) => n.id);
    if (lost.length) updateNodeInternals(lost);
  }, [nodes, flow, updateNodeInternals]);

  const onNodesChange = useCallback((changes: NodeChange<GraphFlowNode>[]) => {
    setNodes((nds) => applyNodeChanges(changes, nds));
  }, []);
  const onEdgesChange = useCallback((changes: EdgeChange[]) => setEdges((eds) => applyEdgeChanges(changes, eds)), []);

  // --- saving, exporting, calibrating -----------------------------------------------------------------
  const savedDoc = (): GraphDoc => {
    if (!doc) return {};
    if (!layoutDirty) return doc;
    const rounded: Positions = {};
    for (const n of nodes) rounded[n.id] = [Math.round(n.position.x), Math.round(n.position.y)];
    return { ...doc, editor: { version: 1, nodes: rounded as unknown as Json } };
  };
  const save = async (target: string) => {
    try {
      const r = await api.save(target, savedDoc(), path);
      unsaved.current = false;
      say(`saved ${r.path} (${r.bytes} bytes)`);
      if (target !== path) {
        setPath(target);
        api.graphs().then((g) => setGraphs(g.graphs));
      }
    } catch (e) {
      say(`save failed: ${e}`);
    }
  };
  const exportPack = async () => {
    const target = window.prompt("shader pack to write (inside the studio's folder)", path.replace(/\.json$/, ".fgpack"));
    if (!target || !doc) return;
    try {
      const r = await api.exportPack(target, compiledDoc(doc));
      say(`exported ${target} (${r.bytes} bytes)`);
    } catch (e) {
      say(`export failed: ${e}`);
    }
  };
  const calibrate = async () => {
    if (!doc) return;
    try {
      setCalibration(await api.calibrate(compiledDoc(doc), 2000));
      const poll = async () => {
        const s = await api.calibration();
        setCalibration(s);
        if (s.state === "running") window.setTimeout(poll, 400);
        else if (s.state === "done" && s.graph) {
          const calibrated = JSON.parse(s.graph) as GraphDoc;
          if (doc.editor) calibrated.editor = doc.editor;
          commit(calibrated);
          say("calibrated: the bias fgc measured is in the graph (undo to drop it)");
        } else if (s.state === "failed") say(`calibration failed:\n${s.log}`);
      };
      poll();
    } catch (e) {
      say(String(e));
    }
  };

  // --- keyboard -----------------------------------------------------------------------------------------
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      const typing = (e.target as HTMLElement).closest("input, textarea");
      if (!(e.ctrlKey || e.metaKey) || typing) return;
      const key = e.key.toLowerCase();
      if (key === "z" && !e.shiftKey) undo();
      else if (key === "y" || (key === "z" && e.shiftKey)) redo();
      else if (key === "s") save(path);
      else if (key === "c") {
        const ids = new Set(nodes.filter((n) => n.selected).map((n) => n.id));
        clipboard.current = nodesOf(viewOf(snapshot.current.doc)).filter((n) => ids.has(n.id));
      } else if (key === "v" && clipboard.current.length) {
        const { doc: next, ids } = pasteNodes(viewOf(snapshot.current.doc), clipboard.current);
        const moved = { ...(openRef.current ? bodyPositions : snapshot.current.positions) };
        for (const [from, to] of ids) {
          const p = moved[from] ?? [0, 0];
          moved[to] = [p[0] + 40, p[1] + 40];
        }
        if (openRef.current) {
          setBodyPositions(moved);
          commit(fromView(snapshot.current.doc, next));
        } else commit(next, moved);
      } else return;
      e.preventDefault();
    };
    window.addEventListener("keydown", onKey);
    return () => window.removeEventListener("keydown", onKey);
  });

  const errors = diagnostics.filter((d) => d.severity === "error");
  const status = compiling
    ? "compiling…"
    : compile
      ? compile.ok
        ? `revision ${compile.revision}: compiled in ${compile.compile_ms.toFixed(0)} ms + pipelines ${compile.pipelines_ms.toFixed(0)} ms`
        : `${errors.length} error${errors.length === 1 ? "" : "s"}: the preview keeps the last good pack`
      : "";

  return (
    <div className="studio">
      <header>
        <b>Fractograph Studio</b>
        <select value={path} onChange={(e) => {
            if (unsaved.current && !window.confirm(`Discard the unsaved edits of ${path}?`)) return;
            open(e.target.value);
          }} data-testid="graph-select">
          {!graphs.includes(path) && <option value={path}>{path}</option>}
          {graphs.map((g) => (
            <option key={g} value={g}>{g}</option>
          ))}
        </select>
        <button onClick={newGraph} data-testid="new-graph">New</button>
        <button onClick={() => save(path)} data-testid="save">Save</button>
        <button
          data-testid="save-as"
          onClick={() => {
            const target = window.prompt("save as (inside the studio's folder)", path);
            if (target) save(target);
          }}
        >
          Save as…
        </button>
        <button onClick={exportPack}>Export pack…</button>
        <button onClick={calibrate} disabled={calibration?.state === "running"} data-testid="calibrate">Calibrate</button>
        {calibration?.state === "running" && (
          <progress max={calibration.total || 1} value={calibration.done} title="fgc calibrate: bubble search" />
        )}
        <button onClick={undo} title="Ctrl+Z">Undo</button>
        <button onClick={redo} title="Ctrl+Shift+Z">Redo</button>
        <span className="hint">Ctrl+C / Ctrl+V copy and paste, Delete removes, Ctrl+S saves</span>
      </header>
      <Palette nodes={catalog} onAdd={addType} stages={openBody !== null} />
      <main className="canvas">
        {openBody && doc && (
          <div className="body-bar" data-testid="body-bar">
            <span>
              body of <b>{openBody.node}</b>:
            </span>
            {groupNames(doc, openBody.node).map((name, i) => (
              <button key={i} className={i === openBody.group ? "active" : ""} data-testid={`body-group-${i}`} onClick={() => openFormula(openBody.node, i)}>
                {name}
              </button>
            ))}
            <button onClick={closeFormula} data-testid="close-body">Close</button>
          </div>
        )}
        <ReactFlow
          nodes={nodes}
          edges={edges}
          nodeTypes={nodeTypes}
          onNodesChange={onNodesChange}
          onEdgesChange={onEdgesChange}
          onConnect={onConnect}
          onConnectEnd={onConnectEnd}
          onDelete={({ nodes: gone, edges: cut }) => deleteSelection(gone.map((n) => n.id), cut)}
          onNodeDragStop={(_, __, moved) => {
            if (openRef.current) {
              // A body's layout is the page's own: it is not saved with the graph.
              setBodyPositions((p) => {
                const next = { ...p };
                for (const n of moved) next[n.id] = [Math.round(n.position.x), Math.round(n.position.y)];
                return next;
              });
              return;
            }
            const next = { ...snapshot.current.positions };
            for (const n of moved) next[n.id] = [Math.round(n.position.x), Math.round(n.position.y)];
            history.current.push(snapshot.current);
            setPositions(next);
            setLayoutDirty(true);
            unsaved.current = true;
          }}
          deleteKeyCode={["Delete", "Backspace"]}
          minZoom={0.2}
          fitView
          colorMode="dark"
        >
          <Background />
          <Controls />
        </ReactFlow>
        {toast && <div className="toast" data-testid="toast">{toast}</div>}
      </main>
      <aside className="side">
        <Preview
          frame={frame}
          camera={camera}
          onCamera={setCamera}
          stereo={stereo}
          onStereo={setStereo}
          probe={probe}
          onProbe={(x, y) => api.probe(x, y).then(setProbe).catch((e) => say(String(e)))}
          status={status}
        />
        <h3>Parameters</h3>
        {doc && <ParamPanel doc={doc} values={params} onChange={(name, value) => setParams((p) => ({ ...p, [name]: value }))} />}
        {diagnostics.length > 0 && (
          <>
            <h3>Diagnostics</h3>
            <ul className="diagnostics" data-testid="diagnostics">
              {diagnostics.map((d, i) => (
                <li key={i} className={d.severity}>{d.text}</li>
              ))}
            </ul>
          </>
        )}
      </aside>
    </div>
  );
}

export function App() {
  return (
    <ReactFlowProvider>
      <Studio />
    </ReactFlowProvider>
  );
}
