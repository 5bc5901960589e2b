#!/usr/bin/env python3
"""What an integer knob of an effect costs and buys: a graph's frame rendered by fgplay at several
values of the knob, in turns (so that load on a shared machine hits all alike), against the same
graph without the effect's outputs and against a reference at a high value.

    bench/knob_sweep.py BUILD GRAPH.json --knob volume_steps --without volume_ [--values 8,16,32,64,128]
                        [--reference 1024] [--size 384] [--runs 3]

`--without P` leaves out the graph's outputs whose names start with P for the baseline (volume_:
the medium; reflection: the mirror bounce). Prints a Markdown table: the median frame and shade
pass times, their ratios to the baseline, and the left eye's error against the reference (RMS in
8-bit levels, PSNR). Each run renders 2 frames and keeps the second (lavapipe compiles a pipeline on
its first dispatch)."""
import argparse
import json
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("graph")
    ap.add_argument("--size", type=int, default=384)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--knob", required=True)
    ap.add_argument("--without", required=True)
    ap.add_argument("--values", default="8,16,32,64,128")
    ap.add_argument("--reference", type=int, default=1024)
    a = ap.parse_args()
    values = [int(v) for v in a.values.split(",")]
    work = pathlib.Path(tempfile.mkdtemp())
    graph = json.loads(pathlib.Path(a.graph).read_text())
    bare = dict(graph, outputs={k: v for k, v in graph["outputs"].items() if not k.startswith(a.without)})
    # The baseline's graph sits in a temporary folder: its environment image, if any, by full path.
    environment = bare.get("scene", {}).get("environment", {})
    if "image" in environment:
        environment["image"] = str((pathlib.Path(a.graph).parent / environment["image"]).resolve())
    (work / "bare.json").write_text(json.dumps(bare))
    for name, path in (("effect", a.graph), ("bare", work / "bare.json")):
        subprocess.run([f"{a.build}/compiler/fgc", "compile", str(path), "-o", str(work / f"{name}.fgpack")],
                       check=True, capture_output=True)

    def shade_ms(pack, value, out):
        result = subprocess.run(
            [f"{a.build}/runtime/fgplay", "render", str(pack), "--out", str(out), "--size", f"{a.size}x{a.size}",
             "--frames", "2"] + (["--knob", f"{a.knob}={value}"] if value else []),
            check=True, capture_output=True, text=True)
        found = re.findall(r"^frame 1:.*GPU frame ([0-9.]+) ms.*shade ([0-9.]+) ms", result.stdout + result.stderr, re.M)
        return float(found[-1][0]), float(found[-1][1])

    cases = [("without the effect", "bare", 0)] + [(f"{a.knob} {v}", "effect", v) for v in values]
    times = {label: [] for label, _, _ in cases}
    for run in range(a.runs):
        for label, pack, s in cases:
            times[label].append(shade_ms(work / f"{pack}.fgpack", s, work / label.replace(" ", "_")))
        print(f"\r  run {run + 1} of {a.runs}", end="", file=sys.stderr)
    print(file=sys.stderr)
    shade_ms(work / "effect.fgpack", a.reference, work / "reference")
    def second_frame(folder):
        return np.asarray(Image.open(folder / "left_0001.png").convert("RGB"), dtype=float)

    reference = second_frame(work / "reference")

    def error(label):
        rms = float(np.sqrt(np.mean((second_frame(work / label.replace(" ", "_")) - reference) ** 2)))
        return rms, 99.0 if rms == 0 else 20 * np.log10(255.0 / rms)

    def median(label, k):
        return statistics.median(t[k] for t in times[label])

    frame0, shade0 = median("without the effect", 0), median("without the effect", 1)
    print(f"| {pathlib.Path(a.graph).name}, {a.size}² per eye | frame ms | against without | shade ms | against without "
          f"| RMS against {a.knob} {a.reference} | PSNR |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for label, _, _ in cases:
        frame, shade = median(label, 0), median(label, 1)
        rms, psnr = error(label)
        print(f"| {label} | {frame:.1f} | {frame / frame0:.2f} | {shade:.1f} | {shade / shade0:.2f} | {rms:.2f} | {psnr:.1f} dB |")


if __name__ == "__main__":
    main()
