#!/usr/bin/env python3
"""Every graph in graphs/ validates against docs/graph.schema.json, so editors that use the schema
agree with fgc; and a few broken graphs do not, so the schema is not vacuous."""
import json
import pathlib
import sys

import jsonschema

root = pathlib.Path(sys.argv[1])
schema = json.loads((root / "docs/graph.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
graphs = sorted((root / "graphs").rglob("*.json"))
failures = 0
for g in graphs:
    errors = list(validator.iter_errors(json.loads(g.read_text())))
    for e in errors:
        print(f"{g.relative_to(root)}: {'/'.join(map(str, e.absolute_path))}: {e.message}")
    failures += bool(errors)
broken = [
    {"format": "fractograph-graph", "version": 1, "nodes": []},                         # no outputs
    {"format": "fractograph-graph", "version": 2, "nodes": [], "outputs": {"distance": 1}},
    {"format": "fractograph-graph", "version": 1, "nodes": [{"id": "a b", "type": "prim.sphere"}],
     "outputs": {"distance": "a"}},
    {"format": "fractograph-graph", "version": 1, "nodes": [], "outputs": {"distance": "x", "colour": "y"}},
    {"format": "fractograph-graph", "version": 1, "outputs": {"distance": "f"},                 # a body of no group
     "nodes": [{"id": "f", "type": "fractal.formula", "formula": {"groups": []}}]},
]
for b in broken:
    if validator.is_valid(b):
        print(f"schema accepts a broken graph: {json.dumps(b)}")
        failures += 1
print(f"{len(graphs)} graphs checked, {failures} problems")
sys.exit(1 if failures else 0)
