// The graph's parameters as sliders within their min and max: they are uniforms, so moving one
// renders a new frame without a recompile.
import type { GraphDoc, Json } from "./api";

interface ParamDoc {
  type: string;
  default: Json;
  min?: number;
  max?: number;
  doc?: string;
}

const components: Record<string, number> = { float: 1, int: 1, bool: 1, vec2: 2, vec3: 3, vec4: 4 };

export function paramDefaults(doc: GraphDoc): Record<string, Json> {
  const out: Record<string, Json> = {};
  for (const [name, p] of Object.entries((doc.params ?? {}) as Record<string, ParamDoc>)) out[name] = p.default;
  return out;
}

export function ParamPanel({ doc, values, onChange }: { doc: GraphDoc; values: Record<string, Json>; onChange: (name: string, value: Json) => void }) {
  const params = Object.entries((doc.params ?? {}) as Record<string, ParamDoc>);
  if (params.length === 0) return <p className="muted">No parameters.</p>;
  return (
    <div className="params">
      {params.map(([name, p]) => {
        const n = components[p.type] ?? 1;
        const value = values[name] ?? p.default;
        const list: number[] = Array.isArray(value) ? (value as number[]) : [Number(value)];
        const base = typeof p.default === "number" ? Math.abs(p.default) : 1;
        const min = p.min ?? (p.type === "bool" ? 0 : -Math.max(1, base * 2));
        const max = p.max ?? (p.type === "bool" ? 1 : Math.max(1, base * 2));
        const step = p.type === "int" || p.type === "bool" ? 1 : (max - min) / 1000;
        return (
          <div className="param" key={name} title={p.doc}>
            <label>
              {name} <span className="muted">{p.type}</span>
            </label>
            {Array.from({ length: n }, (_, i) => (
              <div className="slider" key={i}>
                <input
                  type="range"
                  data-testid={`param-${name}${n > 1 ? "-" + i : ""}`}
                  min={min}
                  max={max}
                  step={step}
                  value={list[i] ?? 0}
                  onChange={(e) => {
                    const x = Number(e.target.value);
                    if (n === 1) onChange(name, p.type === "bool" ? x !== 0 : x);
                    else onChange(name, list.map((v, j) => (j === i ? x : v)));
                  }}
                />
                <span className="value">{Number(list[i] ?? 0).toFixed(p.type === "int" ? 0 : 3)}</span>
              </div>
            ))}
          </div>
        );
      })}
    </div>
  );
}
