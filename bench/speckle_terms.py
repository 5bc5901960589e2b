#!/usr/bin/env python3
"""Which term makes a sampled picture grainy: renders a graph at N samples and at a reference count,
once whole and once without each sampled shading output (the graph's binding removed), and measures
the 8x8 tiles' RMS error in 8-bit levels for each. The term whose removal takes the most noise away
is the one to sample better. The picture without all of them keeps only the pixel's own jitter.

    speckle_terms.py FGPLAY FGC GRAPH OUT [--size 480x270] [--samples 16] [--reference 64]

Writes OUT/speckle_terms.md (the table and the commands).
"""
import argparse
import json
import os
import subprocess
import time

import numpy as np
from PIL import Image

ARGS = argparse.ArgumentParser()
ARGS.add_argument("fgplay"), ARGS.add_argument("fgc"), ARGS.add_argument("graph"), ARGS.add_argument("out")
ARGS.add_argument("--size", default="480x270")
ARGS.add_argument("--samples", type=int, default=16)
ARGS.add_argument("--reference", type=int, default=64)
ARGS = ARGS.parse_args()
os.makedirs(ARGS.out, exist_ok=True)
GRAPH = json.load(open(ARGS.graph))
FOLDER = os.path.dirname(os.path.abspath(ARGS.graph))
# The outputs whose shading draws a sample of its own while samples accumulate.
SAMPLED = [name for name in ("shadow", "ao", "reflection", "specular") if name in GRAPH["outputs"]]


def render(pack, name, n):
    out = os.path.join(ARGS.out, f"{name}_{n}")
    subprocess.run([ARGS.fgplay, "render", pack, "--size", ARGS.size, "--stereo", "naive", "--samples", str(n),
                    "--no-progress", "--out", out], check=True, capture_output=True)
    return np.asarray(Image.open(os.path.join(out, "left.png")).convert("RGB")).astype(np.float64)


def tiles(name, drop):
    graph = json.loads(json.dumps(GRAPH))
    for output in drop:
        del graph["outputs"][output]
    # Beside the original, so that relative paths (an environment image) still resolve.
    path = os.path.join(FOLDER, f".speckle_{name}.json")
    json.dump(graph, open(path, "w"))
    pack = os.path.join(ARGS.out, f"{name}.fgpack")
    try:
        subprocess.run([ARGS.fgc, "compile", path, "-o", pack], check=True, capture_output=True)
    finally:
        os.remove(path)
    start = time.monotonic()
    picture, reference = render(pack, name, ARGS.samples), render(pack, name, ARGS.reference)
    h, w = picture.shape[0] // 8 * 8, picture.shape[1] // 8 * 8
    error = ((picture[:h, :w] - reference[:h, :w]) ** 2).mean(axis=2)
    t = np.sqrt(error.reshape(h // 8, 8, w // 8, 8).mean(axis=(1, 3)))
    print(f"{name}: median {np.median(t):.2f}, 99th {np.percentile(t, 99):.2f} ({time.monotonic() - start:.0f} s)", flush=True)
    return np.median(t), np.percentile(t, 99), np.sqrt(error.mean())


variants = [("whole", [])] + [(f"without_{o}", [o]) for o in SAMPLED] + [("jitter_only", SAMPLED)]
rows = [(name, drop, *tiles(name, drop)) for name, drop in variants]
lines = [
    f"{ARGS.graph} at {ARGS.size}: RMS error of {ARGS.samples} samples against {ARGS.reference}, 8-bit levels, "
    "each picture against its own reference:",
    "",
    "| picture | whole | median 8x8 tile | 99th percentile tile |",
    "|---|---:|---:|---:|",
]
for name, drop, median, p99, whole in rows:
    label = "whole graph" if not drop else ("pixel jitter only (without " + ", ".join(drop) + ")" if len(drop) > 1 else f"without `{drop[0]}`")
    lines.append(f"| {label} | {whole:.2f} | {median:.2f} | {p99:.2f} |")
lines += ["", f"bench/speckle_terms.py FGPLAY FGC {ARGS.graph} OUT --size {ARGS.size} --samples {ARGS.samples} "
          f"--reference {ARGS.reference}"]
open(os.path.join(ARGS.out, "speckle_terms.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
