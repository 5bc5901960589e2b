// Where nodes go when the graph has no `editor` block: in columns by how far each is from the
// outputs (the outputs on the right), in the order the graph lists them.
import type { GraphDoc, Json, NodeDef } from "./api";
import { nodesOf, wiresOf } from "./graph";
import { OUTPUT_NODE_ID } from "./types";

export type Positions = Record<string, [number, number]>;

export function editorPositions(doc: GraphDoc): Positions | null {
  const editor = doc.editor as { [k: string]: Json } | undefined;
  if (!editor || editor.version !== 1 || typeof editor.nodes !== "object" || editor.nodes === null) return null;
  return editor.nodes as unknown as Positions;
}

export function autoLayout(doc: GraphDoc, catalog: Map<string, NodeDef>): Positions {
  const wires = wiresOf(doc, catalog);
  const depth = new Map<string, number>([[OUTPUT_NODE_ID, 0]]);
  const ids = nodesOf(doc).map((n) => n.id);
  // Longest distance to the outputs; a node nothing reads sits in the first column.
  for (let pass = 0; pass < ids.length + 1; ++pass)
    for (const w of wires) {
      const d = depth.get(w.target);
      if (d !== undefined && (depth.get(w.source) ?? -1) < d + 1) depth.set(w.source, d + 1);
    }
  const columns = Math.max(1, ...[...depth.values()]) + 1;
  const rows = new Map<number, number>();
  const positions: Positions = {};
  for (const id of [...ids, OUTPUT_NODE_ID]) {
    const d = depth.get(id) ?? columns - 1;
    const row = rows.get(d) ?? 0;
    rows.set(d, row + 1);
    positions[id] = [(columns - 1 - d) * 280, row * 230];
  }
  return positions;
}
