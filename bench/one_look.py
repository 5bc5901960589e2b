#!/usr/bin/env python3
"""One look at every resolution, measured with fgplay as a user runs it: for each scene in its own
view (the graph's camera), at SIZE per eye on the device fgplay picks,

- the linear mean of a 1 spp frame against its 4x4 supersampled frame, hit by the output pixel
  (the default) and by the marched pixel (`--detail 4`, a threshold four times finer);
- foveation 0.4 against the unfoveated frame: each ring's linear mean, and the SDF evaluations;
- `--samples 16` against `--supersample 4` (the same rays) in PSNR, with the default per-eye
  conemarch and with naive sphere tracing.

    one_look.py FGPLAY FGC SIZE GRAPH.json [GRAPH.json ...] > table.md

Prints markdown tables (docs/accuracy.md quotes them). Needs numpy and scikit-image.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
import skimage.io

FGPLAY, FGC, SIZE, GRAPHS = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
RINGS = [(0.0, 0.4), (0.4, 0.55), (0.55, 0.8), (0.8, 10.0)]   # half image heights from the centre
work = tempfile.mkdtemp(prefix="one_look_")


def linear(path, eye_width):
    """The left eye of a PNG in linear light, per pixel (mean of RGB)."""
    srgb = skimage.io.imread(path)[:, :eye_width, :3] / 255.0
    return np.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4).mean(axis=2)


def psnr(a, b):
    """PSNR of two 8-bit sRGB pictures (the left eyes)."""
    a = skimage.io.imread(a)[:, :SIZE, :3].astype(float)
    b = skimage.io.imread(b)[:, :SIZE, :3].astype(float)
    mse = np.mean((a - b) ** 2)
    return float("inf") if mse == 0 else 10 * np.log10(255.0 ** 2 / mse)


def ring_means(image):
    h, w = image.shape
    y, x = np.mgrid[0:h, 0:w]
    r = np.hypot(x + 0.5 - w / 2, y + 0.5 - h / 2) / (h / 2)
    return [image[(r >= lo) & (r < hi)].mean() for lo, hi in RINGS]


def fgplay(*args):
    out = subprocess.run([FGPLAY, "render", *args], capture_output=True, text=True, check=True).stdout
    found = re.search(r"SDF evaluations per output pixel: ([0-9.]+)", out)
    return float(found.group(1)) if found else None


def path_frame(pack, path, name, *extra):
    out = os.path.join(work, name)
    fgplay(pack, "--path", path, "--frames", "0:1", "--projection", "perspective", "--size", f"{SIZE}x{SIZE}",
           "--out", out, "--no-progress", *extra)
    return os.path.join(out, "frame_000000.png")


means, rings, samples = [], [], []
for graph in GRAPHS:
    scene = os.path.splitext(os.path.basename(graph))[0]
    pack = os.path.join(work, scene + ".fgpack")
    subprocess.run([FGC, "compile", graph, "-o", pack], check=True, capture_output=True)
    camera = json.load(open(graph))["scene"]["camera"]
    path = os.path.join(work, scene + ".path.json")
    json.dump({"format": "fractograph-camera-path", "version": 1, "fps": 30, "interpolation": "linear",
               "keyframes": [{"time": t, "position": camera["position"], "target": camera["target"]} for t in (0, 1)]},
              open(path, "w"))

    one = linear(path_frame(pack, path, scene + "_1"), SIZE).mean()
    output = linear(path_frame(pack, path, scene + "_ss4", "--supersample", "4"), SIZE).mean()
    marched = linear(path_frame(pack, path, scene + "_ss4_d4", "--supersample", "4", "--detail", "4"), SIZE).mean()
    means.append(f"| {scene} | {100 * (one / output - 1):+.1f} % | {100 * (one / marched - 1):+.1f} % |")

    stills = {}
    for fovea in (0, 0.4):
        out = os.path.join(work, f"{scene}_fovea{fovea}")
        evaluations = fgplay(pack, "--size", f"{SIZE}x{SIZE}", "--foveation", str(fovea), "--out", out)
        stills[fovea] = (evaluations, ring_means(linear(os.path.join(out, "left.png"), SIZE)))
    ratios = " | ".join(f"{100 * (f / u - 1):+.1f} %" for f, u in zip(stills[0.4][1], stills[0][1]))
    rings.append(f"| {scene} | {ratios} | {stills[0][0]:.2f} → {stills[0.4][0]:.2f} |")

    cells = []
    for stereo in ("per-eye", "naive"):
        ss = path_frame(pack, path, f"{scene}_{stereo}_ss4", "--supersample", "4", "--stereo", stereo)
        s16 = path_frame(pack, path, f"{scene}_{stereo}_s16", "--samples", "16", "--stereo", stereo)
        s1 = path_frame(pack, path, f"{scene}_{stereo}_s1", "--stereo", stereo)
        cells.append(f"{psnr(ss, s16):.1f} dB | {psnr(ss, s1):.1f} dB")
    samples.append(f"| {scene} | " + " | ".join(cells) + " |")

print(f"1 spp against 4x4 supersampling, {SIZE}² per eye, linear mean of the left eye:\n")
print("| scene | hit by the output pixel | hit by the marched pixel (`--detail 4`) |\n|---|---:|---:|")
print("\n".join(means))
print(f"\nFoveation 0.4 against the unfoveated frame, {SIZE}² per eye, linear mean of each ring:\n")
print("| scene | " + " | ".join(f"{lo}–{hi if hi < 10 else '…'}" for lo, hi in RINGS) +
      " | SDF evaluations per pixel, off → 0.4 |\n|---|" + "---:|" * (len(RINGS) + 1))
print("\n".join(rings))
print(f"\n`--samples 16` and 1 spp against `--supersample 4`, {SIZE}² per eye, PSNR:\n")
print("| scene | per-eye: 16 samples | per-eye: 1 spp | naive: 16 samples | naive: 1 spp |\n|---|---:|---:|---:|---:|")
print("\n".join(samples))
