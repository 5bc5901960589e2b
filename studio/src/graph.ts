// The graph document the page edits: bindings read and written in the graph format's own forms
// (docs/graph-format.md), so untouched parts stay exactly as they were loaded.
import type { GraphDoc, GraphNodeDoc, Json, NodeDef, PortDef } from "./api";
import { OUTPUT_NODE_ID } from "./types";

export type Binding =
  | { kind: "node"; node: string; port?: string }
  | { kind: "param"; name: string }
  | { kind: "literal"; value: Json };

export function parseBinding(value: Json): Binding {
  if (typeof value === "string") {
    if (value.startsWith("$")) return { kind: "param", name: value.slice(1) };
    const dot = value.indexOf(".");
    return dot < 0 ? { kind: "node", node: value } : { kind: "node", node: value.slice(0, dot), port: value.slice(dot + 1) };
  }
  if (value && typeof value === "object" && !Array.isArray(value)) {
    if (typeof value.node === "string") return { kind: "node", node: value.node, port: typeof value.port === "string" ? value.port : undefined };
    if (typeof value.param === "string") return { kind: "param", name: value.param };
    if ("value" in value) return { kind: "literal", value: value.value };
  }
  return { kind: "literal", value };
}

export function nodesOf(doc: GraphDoc): GraphNodeDoc[] {
  return Array.isArray(doc.nodes) ? (doc.nodes as GraphNodeDoc[]) : [];
}

function customPorts(node: GraphNodeDoc, side: "inputs" | "outputs"): PortDef[] {
  const ports = node.ports as { [k: string]: Json } | undefined;
  const list = ports && Array.isArray(ports[side]) ? (ports[side] as { [k: string]: Json }[]) : [];
  return list.map((p) => ({
    name: String(p.name ?? ""),
    type: String(p.type ?? "float"),
    doc: String(p.doc ?? ""),
    implicit: typeof p.default === "string" ? p.default : undefined,
    default: typeof p.default === "number" || Array.isArray(p.default) ? (p.default as number | number[]) : undefined,
  }));
}

// A node's ports: from the library, or declared on the node for custom GLSL.
export function portsOf(node: GraphNodeDoc, catalog: Map<string, NodeDef>): { inputs: PortDef[]; outputs: PortDef[] } {
  if (node.type === "custom.glsl") return { inputs: customPorts(node, "inputs"), outputs: customPorts(node, "outputs") };
  const def = catalog.get(node.type);
  return def ? { inputs: def.inputs, outputs: def.outputs } : { inputs: [], outputs: [] };
}

export interface Wire {
  id: string;
  source: string;
  sourceHandle: string;
  target: string;
  targetHandle: string;
}

// Every node-to-node binding, and the graph outputs, as wires (the outputs as inputs of one node).
export function wiresOf(doc: GraphDoc, catalog: Map<string, NodeDef>): Wire[] {
  const nodes = nodesOf(doc);
  const firstOutput = new Map(nodes.map((n) => [n.id, portsOf(n, catalog).outputs[0]?.name ?? "out"]));
  const wires: Wire[] = [];
  const add = (target: string, targetHandle: string, value: Json) => {
    const b = parseBinding(value);
    if (b.kind !== "node" || !firstOutput.has(b.node)) return;
    const sourceHandle = b.port ?? firstOutput.get(b.node)!;
    wires.push({ id: `${b.node}.${sourceHandle}->${target}.${targetHandle}`, source: b.node, sourceHandle, target, targetHandle });
  };
  for (const n of nodes) for (const [port, value] of Object.entries(n.inputs ?? {})) add(n.id, port, value as Json);
  const outputs = (doc.outputs ?? {}) as Record<string, Json>;
  for (const [name, value] of Object.entries(outputs)) add(OUTPUT_NODE_ID, name, value);
  return wires;
}

function clone<T>(x: T): T {
  return JSON.parse(JSON.stringify(x)) as T;
}

// Sets (or with undefined, removes) input `port` of node `id`, or graph output `port`.
export function setBinding(doc: GraphDoc, id: string, port: string, value: Json | undefined): GraphDoc {
  const next = clone(doc);
  if (id === OUTPUT_NODE_ID) {
    const outputs = ((next.outputs as Record<string, Json>) ??= {});
    if (value === undefined) delete outputs[port];
    else outputs[port] = value;
    return next;
  }
  const node = nodesOf(next).find((n) => n.id === id);
  if (!node) return doc;
  if (value === undefined) {
    if (node.inputs) {
      delete node.inputs[port];
      if (Object.keys(node.inputs).length === 0) delete node.inputs;
    }
  } else {
    node.inputs = { ...(node.inputs ?? {}), [port]: value };
  }
  return next;
}

export function setNodeField(doc: GraphDoc, id: string, key: string, value: Json): GraphDoc {
  const next = clone(doc);
  const node = nodesOf(next).find((n) => n.id === id);
  if (node) node[key] = value;
  return next;
}

export function uniqueId(doc: GraphDoc, base: string): string {
  const taken = new Set(nodesOf(doc).map((n) => n.id));
  const stem = base.replace(/[^A-Za-z0-9_-]/g, "_");
  if (!taken.has(stem)) return stem;
  for (let i = 2; ; ++i) if (!taken.has(`${stem}${i}`)) return `${stem}${i}`;
}

export function addNode(doc: GraphDoc, node: GraphNodeDoc): GraphDoc {
  const next = clone(doc);
  next.nodes = [...nodesOf(next), node];
  return next;
}

// Removes nodes and every binding that read from them (those inputs fall back to their defaults).
export function removeNodes(doc: GraphDoc, ids: Set<string>): GraphDoc {
  const next = clone(doc);
  next.nodes = nodesOf(next).filter((n) => !ids.has(n.id));
  const reads = (v: Json) => {
    const b = parseBinding(v);
    return b.kind === "node" && ids.has(b.node);
  };
  for (const n of nodesOf(next)) {
    for (const [port, v] of Object.entries(n.inputs ?? {})) if (reads(v as Json)) delete n.inputs![port];
    if (n.inputs && Object.keys(n.inputs).length === 0) delete n.inputs;
  }
  const outputs = (next.outputs ?? {}) as Record<string, Json>;
  for (const [name, v] of Object.entries(outputs)) if (reads(v)) delete outputs[name];
  return next;
}

// Copies of `nodes` with fresh ids; bindings among them follow the new ids.
export function pasteNodes(doc: GraphDoc, nodes: GraphNodeDoc[]): { doc: GraphDoc; ids: Map<string, string> } {
  let next = clone(doc);
  const ids = new Map<string, string>();
  for (const n of nodes) {
    const id = uniqueId(next, n.id);
    ids.set(n.id, id);
    next = addNode(next, { ...clone(n), id });
  }
  for (const n of nodesOf(next)) {
    if (![...ids.values()].includes(n.id)) continue;
    for (const [port, v] of Object.entries(n.inputs ?? {})) {
      const b = parseBinding(v as Json);
      if (b.kind === "node" && ids.has(b.node)) n.inputs![port] = `${ids.get(b.node)}${b.port ? "." + b.port : ""}`;
    }
  }
  return { doc: next, ids };
}

// Which node and port a diagnostic's JSON pointer names ("/nodes/3/inputs/t", "/outputs/albedo").
export function placeOf(doc: GraphDoc, pointer: string, nodeId: string): { node: string; port?: string } | null {
  const parts = pointer.split("/").slice(1);
  if (parts[0] === "outputs") return { node: OUTPUT_NODE_ID, port: parts[1] };
  if (parts[0] === "nodes" && parts.length >= 2) {
    const n = nodesOf(doc)[Number(parts[1])];
    const port = parts[2] === "inputs" ? parts[3] : parts[2] === "code" ? "code" : undefined;
    if (n) return { node: n.id, port };
  }
  return nodeId ? { node: nodeId } : null;
}
