#!/usr/bin/env python3
"""Speckle: where a picture of few samples is still grainy, tile by tile. Renders a scene at N samples
a pixel and at many (the reference, its own converged picture), measures each 8x8 tile's RMS error in
8-bit levels, and saves the worst tile's neighbourhood from both pictures at 100 % and enlarged 3x,
so a reader sees what a viewer sees.

    sample_speckle.py FGPLAY FGC GRAPH OUT [--size 480x270] [--samples 16] [--reference 256]

Writes OUT/speckle.md (the tile figures and the commands) and OUT/speckle_crop.png.
"""
import argparse
import os
import subprocess
import time

import numpy as np
from PIL import Image

ARGS = argparse.ArgumentParser()
ARGS.add_argument("fgplay"), ARGS.add_argument("fgc"), ARGS.add_argument("graph"), ARGS.add_argument("out")
ARGS.add_argument("--size", default="480x270")
ARGS.add_argument("--samples", type=int, default=16)
ARGS.add_argument("--reference", type=int, default=256)
ARGS = ARGS.parse_args()
os.makedirs(ARGS.out, exist_ok=True)
PACK = os.path.join(ARGS.out, "scene.fgpack")
subprocess.run([ARGS.fgc, "compile", ARGS.graph, "-o", PACK], check=True, capture_output=True)


def render(n):
    out = os.path.join(ARGS.out, f"samples_{n}")
    start = time.monotonic()
    subprocess.run([ARGS.fgplay, "render", PACK, "--size", ARGS.size, "--stereo", "naive", "--samples", str(n),
                    "--no-progress", "--out", out], check=True, capture_output=True)
    return np.asarray(Image.open(os.path.join(out, "left.png")).convert("RGB")).astype(np.float64), time.monotonic() - start


picture, seconds = render(ARGS.samples)
reference, reference_seconds = render(ARGS.reference)
h, w = picture.shape[0] // 8 * 8, picture.shape[1] // 8 * 8
error = ((picture[:h, :w] - reference[:h, :w]) ** 2).mean(axis=2)
tiles = np.sqrt(error.reshape(h // 8, 8, w // 8, 8).mean(axis=(1, 3)))
worst = np.unravel_index(np.argmax(tiles), tiles.shape)
# 64x64 pixels around the worst tile, both pictures side by side, then 3x larger without smoothing.
cy = min(max(worst[0] * 8 + 4 - 32, 0), picture.shape[0] - 64)
cx = min(max(worst[1] * 8 + 4 - 32, 0), picture.shape[1] - 64)
crop = np.concatenate([picture[cy:cy + 64, cx:cx + 64], np.full((64, 4, 3), 255.0), reference[cy:cy + 64, cx:cx + 64]], axis=1)
image = Image.fromarray(crop.astype(np.uint8))
image.resize((image.width * 3, image.height * 3), Image.NEAREST).save(os.path.join(ARGS.out, "speckle_crop.png"))
rms = np.sqrt(error.mean())
lines = [
    f"{ARGS.graph} at {ARGS.size}, {ARGS.samples} samples against {ARGS.reference} ({seconds:.0f} s and "
    f"{reference_seconds:.0f} s for the stereo pair on this machine):",
    "",
    "| RMS error, 8-bit levels | value |",
    "|---|---:|",
    f"| whole picture | {rms:.2f} |",
    f"| median 8x8 tile | {np.median(tiles):.2f} |",
    f"| 99th percentile tile | {np.percentile(tiles, 99):.2f} |",
    f"| worst tile (at x {worst[1] * 8}, y {worst[0] * 8}) | {tiles.max():.2f} |",
    "",
    f"speckle_crop.png: 64x64 pixels around the worst tile, {ARGS.samples} samples (left) and {ARGS.reference}, 3x.",
]
open(os.path.join(ARGS.out, "speckle.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
