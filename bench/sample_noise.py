#!/usr/bin/env python3
"""Noise against samples per pixel, for each stochastic term of the offline picture: how far the
picture of N samples is from the same setting's picture of many (PSNR, so each setting is judged by
how close it comes to its own converged image). The terms are switched on one after another on the
lit Mandelbulb (graphs/examples/lit_mandelbulb.json):

- pixel: the sub-pixel jitter alone (anti-aliasing), the soft shadow's cone-angle penumbra (area off);
- + area light: the soft shadow marches one sharp ray a sample to a point of the light's disc;
- + lens: depth of field (--aperture), a point of the lens a sample.

    sample_noise.py FGPLAY FGC SIZE OUT [--samples 1,2,4,8,16,32,64] [--reference 256] [--aperture 0.05]

Writes OUT/sample_noise.md (a table) and OUT/sample_noise.png (PSNR against samples, log scale).
"""
import argparse
import json
import math
import os
import subprocess
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import skimage.io  # noqa: E402

ARGS = argparse.ArgumentParser()
ARGS.add_argument("fgplay"), ARGS.add_argument("fgc"), ARGS.add_argument("size", type=int), ARGS.add_argument("out")
ARGS.add_argument("--samples", default="1,2,4,8,16,32,64")
ARGS.add_argument("--reference", type=int, default=256)
ARGS.add_argument("--aperture", type=float, default=0.05)
ARGS = ARGS.parse_args()
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.makedirs(ARGS.out, exist_ok=True)
COUNTS = [int(n) for n in ARGS.samples.split(",")]


def pack(area):
    graph = json.load(open(os.path.join(ROOT, "graphs/examples/lit_mandelbulb.json")))
    for node in graph["nodes"]:
        if node["type"] == "light.soft_shadow":
            node["inputs"]["area"] = area
    path = os.path.join(ARGS.out, f"lit_area_{area}.json")
    json.dump(graph, open(path, "w"))
    out = path.replace(".json", ".fgpack")
    subprocess.run([ARGS.fgc, "compile", path, "-o", out], check=True, capture_output=True)
    return out


SETTINGS = {"pixel": (pack(False), []), "+ area light": (pack(True), []),
            "+ lens": (pack(True), ["--aperture", str(ARGS.aperture)])}


def render(fgpack, extra, n):
    out = os.path.join(ARGS.out, "frames")
    start = time.monotonic()
    subprocess.run([ARGS.fgplay, "render", fgpack, "--size", f"{ARGS.size}x{ARGS.size}", "--samples", str(n),
                    "--out", out, *extra], check=True, capture_output=True)
    seconds = time.monotonic() - start
    return skimage.io.imread(os.path.join(out, "left.png"))[..., :3].astype(float), seconds


def psnr(a, b):
    mse = np.mean((a - b) ** 2)
    return 99.0 if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)


rows = {}
for name, (fgpack, extra) in SETTINGS.items():
    reference, _ = render(fgpack, extra, ARGS.reference)
    rows[name] = []
    for n in COUNTS:
        if extra and n < 2:   # depth of field averages samples through the lens: 2 at least
            rows[name].append((float("nan"), 0.0))
            continue
        image, seconds = render(fgpack, extra, n)
        rows[name].append((psnr(image, reference), seconds))
        print(f"{name}, {n} samples: {rows[name][-1][0]:.2f} dB ({seconds:.1f} s)", flush=True)

with open(os.path.join(ARGS.out, "sample_noise.md"), "w") as f:
    f.write(f"Lit Mandelbulb, {ARGS.size}² (left eye), PSNR against the same setting's {ARGS.reference} samples "
            f"(lens: aperture {ARGS.aperture}).\n\n")
    f.write("| setting | " + " | ".join(f"{n}" for n in COUNTS) + " |\n|---|" + "---:|" * len(COUNTS) + "\n")
    for name, values in rows.items():
        f.write(f"| {name} | " + " | ".join("" if p != p else f"{p:.1f}" for p, _ in values) + " |\n")
fig, ax = plt.subplots(figsize=(6, 4))
for name, values in rows.items():
    ax.plot(COUNTS, [p for p, _ in values], marker="o", label=name)
ax.set_xscale("log", base=2)
ax.set_xlabel("samples per pixel")
ax.set_ylabel(f"PSNR against {ARGS.reference} samples (dB)")
ax.grid(True, alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(ARGS.out, "sample_noise.png"), dpi=90)
