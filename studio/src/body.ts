// A fractal.formula's body opened on the canvas: one stage group seen as a graph of its own, its
// stages as nodes and the z that leaves the group as its one output. Edits made there are written
// back into the formula node, so the document stays the one source of truth.
import type { GraphDoc, GraphNodeDoc, Json } from "./api";
import { nodesOf } from "./graph";

export interface OpenBody {
  node: string; // the fractal.formula node's id
  group: number; // which of its groups
}

interface GroupDoc {
  name?: string;
  nodes?: GraphNodeDoc[];
  z?: string;
  [key: string]: Json | GraphNodeDoc[] | undefined;
}

function groupsOf(doc: GraphDoc, node: string): GroupDoc[] {
  const n = nodesOf(doc).find((x) => x.id === node);
  const formula = n?.formula as { groups?: GroupDoc[] } | undefined;
  return Array.isArray(formula?.groups) ? formula!.groups! : [];
}

export function groupNames(doc: GraphDoc, node: string): string[] {
  return groupsOf(doc, node).map((g, i) => String(g.name ?? `group ${i + 1}`));
}

// The group as a document: its stages, and the z leaving it (named, or the last stage's) as output.
export function bodyView(doc: GraphDoc, open: OpenBody): GraphDoc {
  const group = groupsOf(doc, open.node)[open.group];
  const stages = Array.isArray(group?.nodes) ? group!.nodes! : [];
  const leaving = group?.z ?? stages[stages.length - 1]?.id;
  return { nodes: stages, outputs: leaving ? { z: leaving } : {} };
}

// The document with the group replaced by an edited view of it. The group names its z only where
// that is not simply its last stage, as the file had it.
export function withBody(doc: GraphDoc, open: OpenBody, view: GraphDoc): GraphDoc {
  const next = JSON.parse(JSON.stringify(doc)) as GraphDoc;
  const group = groupsOf(next, open.node)[open.group];
  if (!group) return doc;
  const stages = nodesOf(view);
  group.nodes = stages;
  const leaving = (view.outputs as Record<string, Json> | undefined)?.z;
  if (typeof leaving === "string" && (group.z !== undefined || leaving !== stages[stages.length - 1]?.id)) group.z = leaving.split(".")[0];
  else if (leaving === undefined || leaving === stages[stages.length - 1]?.id) delete group.z;
  return next;
}

// Which stage and port a diagnostic inside the open group names
// ("/nodes/0/formula/groups/1/nodes/2/inputs/limit"); null when it is elsewhere.
export function placeInBody(doc: GraphDoc, open: OpenBody, pointer: string): { node: string; port?: string } | null {
  const parts = pointer.split("/").slice(1);
  const index = nodesOf(doc).findIndex((n) => n.id === open.node);
  if (parts[0] !== "nodes" || Number(parts[1]) !== index || parts[2] !== "formula" || parts[3] !== "groups" || Number(parts[4]) !== open.group)
    return null;
  if (parts[5] !== "nodes" || parts[6] === undefined) return null;
  const stage = bodyView(doc, open).nodes?.[Number(parts[6])];
  return stage ? { node: stage.id, port: parts[7] === "inputs" ? parts[8] : undefined } : null;
}
