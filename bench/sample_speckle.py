#!/usr/bin/env python3
"""Speckle: where a picture of few samples is still grainy, tile by tile. Renders a scene at N samples
a pixel and at many (the reference, its own converged picture), measures each 8x8 tile's RMS error in
8-bit levels, and saves the worst tile's neighbourhood from both pictures at 100 % and enlarged 3x,
so a reader sees what a viewer sees.

    sample_speckle.py FGPLAY FGC GRAPH OUT [--size 480x270] [--samples 16] [--reference 256] [--terms]

Writes OUT/speckle.md (the tile figures and the commands) and OUT/speckle_crop.png. With --terms it
measures which term makes the grain instead: the same figures for the graph whole, without each
sampled shading output in turn (its binding removed), and without all of them (the pixel's own
jitter alone), each against its own reference, into OUT/speckle_terms.md.
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
ARGS.add_argument("--reference", type=int, default=256)
ARGS.add_argument("--terms", action="store_true", help="which sampled output makes the grain")
ARGS = ARGS.parse_args()
os.makedirs(ARGS.out, exist_ok=True)
# The outputs whose shading draws random numbers of its own while samples accumulate.
SAMPLED_OUTPUTS = ("shadow", "ao", "reflection", "specular")


def compile_without(name, dropped):
    """The graph compiled without the bindings of `dropped`, written beside the original so that its
    relative paths (an environment image) still resolve."""
    graph = json.load(open(ARGS.graph))
    for output in dropped:
        del graph["outputs"][output]
    path = os.path.join(os.path.dirname(os.path.abspath(ARGS.graph)), f".speckle_{name}.json")
    json.dump(graph, open(path, "w"))
    pack = os.path.join(ARGS.out, f"{name}.fgpack")
    try:
        subprocess.run([ARGS.fgc, "compile", path, "-o", pack], check=True, capture_output=True)
    finally:
        os.remove(path)
    return pack


def render(pack, name, n):
    out = os.path.join(ARGS.out, f"{name}_{n}")
    start = time.monotonic()
    subprocess.run([ARGS.fgplay, "render", pack, "--size", ARGS.size, "--stereo", "naive", "--samples", str(n),
                    "--no-progress", "--out", out], check=True, capture_output=True)
    return np.asarray(Image.open(os.path.join(out, "left.png")).convert("RGB")).astype(np.float64), time.monotonic() - start


def seen(picture):
    """The picture as an eye resolves it at 100 %: a Gaussian of 1 pixel's sigma (about one minute of
    arc at a desktop viewing distance), so that grain finer than that, blue noise, counts for less."""
    weights = np.exp(-0.5 * np.arange(-3, 4) ** 2)
    weights /= weights.sum()
    padded = np.pad(picture, ((3, 3), (3, 3), (0, 0)), mode="edge")
    rows = sum(w * padded[:, i:i + picture.shape[1]] for i, w in enumerate(weights))
    return sum(w * rows[i:i + picture.shape[0]] for i, w in enumerate(weights))


def tile_errors(picture, reference):
    """Each pixel's squared error (mean over the channels) and each 8x8 tile's RMS error."""
    h, w = picture.shape[0] // 8 * 8, picture.shape[1] // 8 * 8
    error = ((picture[:h, :w] - reference[:h, :w]) ** 2).mean(axis=2)
    return error, np.sqrt(error.reshape(h // 8, 8, w // 8, 8).mean(axis=(1, 3)))


def crop_report():
    pack = compile_without("scene", [])
    picture, seconds = render(pack, "samples", ARGS.samples)
    reference, reference_seconds = render(pack, "samples", ARGS.reference)
    error, tiles = tile_errors(picture, reference)
    seen_error, seen_tiles = tile_errors(seen(picture), seen(reference))
    worst = np.unravel_index(np.argmax(tiles), tiles.shape)
    # 64x64 pixels around the worst tile, both pictures side by side, then 3x larger without smoothing.
    cy = min(max(worst[0] * 8 + 4 - 32, 0), picture.shape[0] - 64)
    cx = min(max(worst[1] * 8 + 4 - 32, 0), picture.shape[1] - 64)
    crop = np.concatenate([picture[cy:cy + 64, cx:cx + 64], np.full((64, 4, 3), 255.0), reference[cy:cy + 64, cx:cx + 64]], axis=1)
    image = Image.fromarray(crop.astype(np.uint8))
    image.resize((image.width * 3, image.height * 3), Image.NEAREST).save(os.path.join(ARGS.out, "speckle_crop.png"))
    return "speckle.md", [
        f"{ARGS.graph} at {ARGS.size}, {ARGS.samples} samples against {ARGS.reference} ({seconds:.0f} s and "
        f"{reference_seconds:.0f} s for the stereo pair on this machine):",
        "",
        "| RMS error, 8-bit levels | pixels | as seen at 100 % (Gaussian, sigma 1 pixel) |",
        "|---|---:|---:|",
        f"| whole picture | {np.sqrt(error.mean()):.2f} | {np.sqrt(seen_error.mean()):.2f} |",
        f"| median 8x8 tile | {np.median(tiles):.2f} | {np.median(seen_tiles):.2f} |",
        f"| 99th percentile tile | {np.percentile(tiles, 99):.2f} | {np.percentile(seen_tiles, 99):.2f} |",
        f"| worst tile (at x {worst[1] * 8}, y {worst[0] * 8}) | {tiles.max():.2f} | {seen_tiles.max():.2f} |",
        "",
        f"speckle_crop.png: 64x64 pixels around the worst tile, {ARGS.samples} samples (left) and {ARGS.reference}, 3x.",
    ]


def terms_report():
    sampled = [name for name in SAMPLED_OUTPUTS if name in json.load(open(ARGS.graph))["outputs"]]
    variants = [("whole", [])] + [(f"without_{o}", [o]) for o in sampled] + [("jitter_only", sampled)]
    lines = [
        f"{ARGS.graph} at {ARGS.size}: RMS error of {ARGS.samples} samples against {ARGS.reference}, 8-bit levels, "
        "each picture against its own reference:",
        "",
        "| picture | whole | median 8x8 tile | 99th percentile tile |",
        "|---|---:|---:|---:|",
    ]
    for name, dropped in variants:
        pack = compile_without(name, dropped)
        error, tiles = tile_errors(render(pack, name, ARGS.samples)[0], render(pack, name, ARGS.reference)[0])
        label = ("whole graph" if not dropped else f"without `{dropped[0]}`" if len(dropped) == 1
                 else "pixel jitter only (without " + ", ".join(dropped) + ")")
        lines.append(f"| {label} | {np.sqrt(error.mean()):.2f} | {np.median(tiles):.2f} | {np.percentile(tiles, 99):.2f} |")
        print(lines[-1], flush=True)
    return "speckle_terms.md", lines


name, lines = terms_report() if ARGS.terms else crop_report()
open(os.path.join(ARGS.out, name), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
