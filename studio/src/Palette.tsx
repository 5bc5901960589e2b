// Every node type of the library by category, with a search box; hovering shows the node's doc,
// a click adds it to the graph.
import { useMemo, useState } from "react";
import type { NodeDef } from "./api";
import { typeColour } from "./types";

// Inside an open formula body (`stages`) it offers what a body holds: the stages, which belong there
// and nowhere else, and the maths nodes with a tangent rule.
export function Palette({ nodes, onAdd, stages }: { nodes: NodeDef[]; onAdd: (type: string) => void; stages: boolean }) {
  const [query, setQuery] = useState("");
  const [hover, setHover] = useState<NodeDef | null>(null);
  const groups = useMemo(() => {
    const q = query.trim().toLowerCase();
    const found = nodes.filter((n) => (stages ? n.in_body : !n.stage) && (!q || n.type.includes(q) || n.summary.toLowerCase().includes(q)));
    const byCategory = new Map<string, NodeDef[]>();
    for (const n of found) byCategory.set(n.category, [...(byCategory.get(n.category) ?? []), n]);
    return [...byCategory.entries()];
  }, [nodes, query, stages]);
  return (
    <aside className="palette">
      <input className="search" placeholder="search nodes" value={query} data-testid="palette-search" onChange={(e) => setQuery(e.target.value)} />
      <div className="palette-list">
        {groups.map(([category, defs]) => (
          <details key={category} open={query !== "" || stages || category === "fractal" || category === "op"}>
            <summary>{category}</summary>
            {defs.map((d) => (
              <button
                key={d.type}
                className="palette-item"
                data-testid={`palette-${d.type}`}
                onClick={() => onAdd(d.type)}
                onMouseEnter={() => setHover(d)}
                onMouseLeave={() => setHover(null)}
              >
                {d.type.slice(d.category.length + 1)}
                {d.outputs.map((o) => (
                  <span key={o.name} className="dot" style={{ background: typeColour(o.type) }} />
                ))}
              </button>
            ))}
          </details>
        ))}
        {!stages && <details open={query !== ""}>
          <summary>custom</summary>
          <button className="palette-item" data-testid="palette-custom.glsl" onClick={() => onAdd("custom.glsl")}>
            glsl
          </button>
        </details>}
      </div>
      {hover && (
        <div className="node-doc" data-testid="node-doc">
          <b>{hover.type}</b>
          <p>{hover.summary}</p>
          <p className="doc">{hover.doc}</p>
          <table>
            <tbody>
              {hover.inputs.map((p) => (
                <tr key={p.name}>
                  <td>{p.name}</td>
                  <td style={{ color: typeColour(p.type) }}>{p.type}</td>
                  <td>{p.doc}</td>
                </tr>
              ))}
            </tbody>
          </table>
        </div>
      )}
    </aside>
  );
}
