// A node on the canvas: typed, coloured ports; literals edited in place; custom GLSL in a code box;
// the compiler's diagnostics on the node and on the port their JSON pointer names; a small preview
// of the node's distance when it has one.
import { memo, useEffect, useState } from "react";
import { Handle, Position, type NodeProps, type Node } from "@xyflow/react";
import type { Diagnostic, GraphNodeDoc, Json, PortDef } from "./api";
import { parseBinding } from "./graph";
import { typeColour } from "./types";

export interface GraphNodeData extends Record<string, unknown> {
  doc: GraphNodeDoc | null; // null: the graph's outputs
  title: string;
  summary: string;
  inputs: PortDef[];
  outputs: PortDef[];
  wired: Set<string>; // inputs fed by a wire
  diagnostics: { port?: string; diagnostic: Diagnostic }[];
  preview?: string;
  onBinding: (port: string, value: Json | undefined) => void;
  onCode: (code: string[]) => void;
  bodyGroups?: string[]; // a formula node's stage groups, each opened on the canvas by a button
  onOpenBody?: (group: number) => void;
}

export type GraphFlowNode = Node<GraphNodeData, "graph">;

function bindingText(value: Json | undefined): string {
  if (value === undefined) return "";
  const b = parseBinding(value);
  if (b.kind === "param") return "$" + b.name;
  return JSON.stringify(b.kind === "literal" ? b.value : value);
}

// What the page turns typed text into: nothing (the default), a parameter, or a JSON literal.
function textBinding(text: string): Json | undefined {
  const t = text.trim();
  if (t === "") return undefined;
  if (t.startsWith("$")) return t;
  try {
    return JSON.parse(t) as Json;
  } catch {
    return t;
  }
}

function placeholderOf(p: PortDef): string {
  if (p.implicit) return p.implicit;
  if (p.default !== undefined) return JSON.stringify(p.default);
  return "required";
}

function LiteralField({ nodeId, port, value, onCommit }: { nodeId: string; port: PortDef; value: Json | undefined; onCommit: (v: Json | undefined) => void }) {
  const [text, setText] = useState(bindingText(value));
  useEffect(() => setText(bindingText(value)), [value]);
  const commit = () => {
    if (text !== bindingText(value)) onCommit(textBinding(text));
  };
  return (
    <input
      className="literal nodrag"
      data-testid={`literal-${nodeId}-${port.name}`}
      value={text}
      placeholder={placeholderOf(port)}
      title={`${port.doc}${port.min !== undefined ? ` (min ${port.min})` : ""}${port.max !== undefined ? ` (max ${port.max})` : ""}`}
      onChange={(e) => setText(e.target.value)}
      onBlur={commit}
      onKeyDown={(e) => {
        if (e.key === "Enter") (e.target as HTMLInputElement).blur();
        e.stopPropagation();
      }}
    />
  );
}

function CodeBox({ nodeId, code, onCommit }: { nodeId: string; code: string[]; onCommit: (code: string[]) => void }) {
  const joined = code.join("\n");
  const [text, setText] = useState(joined);
  useEffect(() => setText(joined), [joined]);
  return (
    <textarea
      className="code nodrag nowheel"
      data-testid={`code-${nodeId}`}
      spellCheck={false}
      value={text}
      rows={Math.max(3, text.split("\n").length)}
      onChange={(e) => setText(e.target.value)}
      onBlur={() => text !== joined && onCommit(text.split("\n"))}
      onKeyDown={(e) => e.stopPropagation()}
    />
  );
}

function GraphNodeView({ id: flowId, data, selected }: NodeProps<GraphFlowNode>) {
  // The outputs node has no document: it goes by its flow id, which no graph node can take.
  const id = data.doc?.id ?? flowId;
  const portErrors = new Map<string, string>();
  for (const d of data.diagnostics) if (d.port && d.diagnostic.severity === "error") portErrors.set(d.port, d.diagnostic.message);
  const hasError = data.diagnostics.some((d) => d.diagnostic.severity === "error");
  const inputs = data.doc?.inputs ?? {};
  // A node with a distance keeps room for its preview before the picture arrives: nothing moves under a drag.
  const hasPreview = data.outputs.some((p) => p.name === "distance");
  const code = data.doc?.type === "custom.glsl" ? (Array.isArray(data.doc.code) ? (data.doc.code as string[]) : [String(data.doc.code ?? "")]) : null;
  return (
    <div className={`graph-node${hasError ? " has-error" : ""}${selected ? " selected" : ""}${data.doc ? "" : " outputs-node"}`} data-testid={`node-${id}`}>
      <div className="node-header" title={data.summary}>
        <span className="node-id">{data.title}</span>
        {data.doc && <span className="node-type">{data.doc.type}</span>}
      </div>
      {data.preview ? (
        <img className="node-preview" src={data.preview} alt={`preview of ${id}`} data-testid={`preview-${id}`} />
      ) : (
        hasPreview && <div className="node-preview pending" aria-hidden="true" />
      )}
      <div className="ports">
        {data.outputs.map((p) => (
          <div className="port-row output" key={`o-${p.name}`} title={`${p.type}: ${p.doc}`}>
            <span className="port-name">{p.name}</span>
            <span className="port-type" style={{ color: typeColour(p.type) }}>{p.type}</span>
            <Handle type="source" position={Position.Right} id={p.name} style={{ background: typeColour(p.type) }} />
          </div>
        ))}
        {data.inputs.map((p) => (
          <div className={`port-row input${portErrors.has(p.name) ? " port-error" : ""}`} key={`i-${p.name}`} title={portErrors.get(p.name) ?? `${p.type}: ${p.doc}`} data-testid={`port-${id}-${p.name}`} data-port-node={id} data-port-name={p.name}>
            <Handle type="target" position={Position.Left} id={p.name} style={{ background: typeColour(p.type) }} />
            <span className="port-name">{p.name}</span>
            <span className="port-type" style={{ color: typeColour(p.type) }}>{p.type}</span>
            {data.doc && !data.wired.has(p.name) && (
              <LiteralField nodeId={id} port={p} value={inputs[p.name] as Json | undefined} onCommit={(v) => data.onBinding(p.name, v)} />
            )}
          </div>
        ))}
      </div>
      {code && <CodeBox nodeId={id} code={code} onCommit={data.onCode} />}
      {data.bodyGroups && data.bodyGroups.length > 0 && (
        <div className="body-groups">
          {data.bodyGroups.map((name, i) => (
            <button key={i} className="nodrag" data-testid={`open-body-${id}-${i}`} title="open this group of the formula's body on the canvas" onClick={() => data.onOpenBody?.(i)}>
              open {name}
            </button>
          ))}
        </div>
      )}
      {data.diagnostics.length > 0 && (
        <ul className="node-diagnostics" data-testid={`diag-${id}`}>
          {data.diagnostics.map((d, i) => (
            <li key={i} className={d.diagnostic.severity}>
              {d.port ? <b>{d.port}: </b> : null}
              {d.diagnostic.message}
              {d.diagnostic.context && <pre>{d.diagnostic.context}</pre>}
            </li>
          ))}
        </ul>
      )}
    </div>
  );
}

export const GraphNode = memo(GraphNodeView);
