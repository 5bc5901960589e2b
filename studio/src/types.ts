// Port types and their colours: the same colour on both ends of a wire that the compiler accepts.
export const typeColours: Record<string, string> = {
  float: "#a3a3a3",
  int: "#6fbf73",
  bool: "#d86c6c",
  vec2: "#5fb3d9",
  vec3: "#c9a13b",
  vec4: "#b37ad9",
  T: "#e0e0e0",
};

export function typeColour(type: string): string {
  return typeColours[type] ?? "#888";
}

// The graph's outputs (docs/graph-format.md) and their types.
export const graphOutputs: { name: string; type: string }[] = [
  { name: "distance", type: "float" },
  { name: "albedo", type: "vec3" },
  { name: "diffuse", type: "float" },
  { name: "ao", type: "float" },
  { name: "sss", type: "float" },
  { name: "rim", type: "float" },
  { name: "emission", type: "vec3" },
];

export const OUTPUT_NODE_ID = "__outputs__";
