#!/usr/bin/env python3
"""Temporal anti-aliasing and upsampling against one sample per pixel, on head traces at 90 Hz, judged against 16
jittered samples per pixel of every frame (the picture each frame would converge to). Renders with
fgplay as a user does: `fgplay render --path P` (1 spp), `--taa` (history carried from frame to
frame), `--taa --taa-upscale 1.5` and `2` (temporal upsampling: 44 % and 25 % of the rays) and
`--samples 16` (the reference), then compares the left eyes frame by frame:

- PSNR and SSIM (scikit-image) against the reference;
- flicker: the mean over pixels of |(I_t - I_t-1) - (R_t - R_t-1)| in 8-bit levels, the change
  from one frame to the next that the reference does not have;
- detail: the picture's gradient energy (mean squared difference of neighbouring pixels' luma)
  over the reference's. Below 1 is blur; noise and aliasing push 1 spp above 1.

    taa_quality.py FGPLAY FGC SIZE FRAMES OUT GRAPH.json [GRAPH.json ...] [--traces a,b] [--methods "1 spp,TAA"]
                   [--no-timing]

Writes OUT/taa_frames.csv (every frame), OUT/taa_quality.md (medians from frame 16 on, worst
frames) and OUT/taa_quality.png (PSNR per frame). Traces start at the graph's camera: look_around
(the gaze circling 15 degrees at 60 deg/s), fast_turn (yaw +-30 degrees at up to 150 deg/s), walk (sideways at
0.3 scene units/s, looking ahead), still (the first pose held), and the slow ones where resampling blur
shows: slow_orbit (the camera circling the target at 20 deg/s, 0.2-0.5 px a frame at 256²) and
slow_walk (sideways at 0.05 units/s); burst (flying forward at 0.3 units/s with a 90 deg/s turn
from frame 18 to 36).
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import skimage.io  # noqa: E402
from skimage.metrics import structural_similarity  # noqa: E402

ARGS = argparse.ArgumentParser()
ARGS.add_argument("fgplay"), ARGS.add_argument("fgc"), ARGS.add_argument("size", type=int)
ARGS.add_argument("frames", type=int), ARGS.add_argument("out"), ARGS.add_argument("graphs", nargs="+")
ARGS.add_argument("--traces", default="look_around,fast_turn,walk,still")
ARGS.add_argument("--methods", default="1 spp,TAA,TAAU 1.5,TAAU 2")
ARGS.add_argument("--no-timing", action="store_true", help="leave out the frame times (a quality run only)")
ARGS = ARGS.parse_args()
FGPLAY, FGC, SIZE, FRAMES, OUT, GRAPHS = ARGS.fgplay, ARGS.fgc, ARGS.size, ARGS.frames, ARGS.out, ARGS.graphs
TRACES = ARGS.traces.split(",")
HZ = 90.0
SETTLED = 16   # statistics from this frame on: TAA's history has filled
os.makedirs(OUT, exist_ok=True)


def rotate_y(v, angle):
    c, s = math.cos(angle), math.sin(angle)
    return [c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2]]


def trace(name, camera):
    """Keyframes, one per frame, for a trace from the graph's camera."""
    eye, target = camera["position"], camera["target"]
    ahead = [t - e for t, e in zip(target, eye)]
    keys = []
    for i in range(FRAMES):
        t = i / HZ
        if name == "look_around":
            yaw = math.radians(15.0) * math.sin(math.radians(60.0) / math.radians(15.0) * t)
            pitch = math.radians(15.0) * (1 - math.cos(math.radians(60.0) / math.radians(15.0) * t))
            d = rotate_y(ahead, yaw)
            d[1] -= pitch * math.hypot(d[0], d[2])
            keys.append({"time": t, "position": eye, "target": [e + x for e, x in zip(eye, d)]})
        elif name == "fast_turn":
            # +-30 degrees, passing the start at 150 deg/s: the fractal stays in view.
            d = rotate_y(ahead, math.radians(30.0) * math.sin(150.0 / 30.0 * t))
            keys.append({"time": t, "position": eye, "target": [e + x for e, x in zip(eye, d)]})
        elif name in ("walk", "slow_walk"):
            speed = 0.3 if name == "walk" else 0.05
            side = rotate_y([ahead[0], 0.0, ahead[2]], math.pi / 2)
            n = math.hypot(side[0], side[2])
            p = [e + speed * t * s / n for e, s in zip(eye, side)]
            keys.append({"time": t, "position": p, "target": [q + a for q, a in zip(p, ahead)]})
        elif name == "burst":
            # Flying forward at 0.3 units/s, turning at 90 deg/s from 0.2 to 0.4 s (frames 18-36).
            yaw = math.radians(90.0) * min(max(t - 0.2, 0.0), 0.2)
            p = [e + 0.3 * t * a / math.sqrt(sum(x * x for x in ahead)) for e, a in zip(eye, ahead)]
            d = rotate_y(ahead, yaw)
            keys.append({"time": t, "position": p, "target": [q + x for q, x in zip(p, d)]})
        elif name == "slow_orbit":
            back = rotate_y([-x for x in ahead], math.radians(20.0) * t)
            keys.append({"time": t, "position": [c + b for c, b in zip(target, back)], "target": target})
        else:
            keys.append({"time": t, "position": eye, "target": target})
    return {"format": "fractograph-camera-path", "version": 1, "fps": HZ, "interpolation": "linear", "keyframes": keys}


def render(pack, path, out, *extra):
    subprocess.run([FGPLAY, "render", pack, "--path", path, "--projection", "perspective", "--size", f"{SIZE}x{SIZE}",
                    "--out", out, "--no-progress", *extra], check=True, capture_output=True)
    return [skimage.io.imread(os.path.join(out, f"frame_{i:06}.png"))[:, :SIZE, :3].astype(float) for i in range(FRAMES)]


def gradient_energy(image):
    luma = image @ np.array([0.2126, 0.7152, 0.0722])
    return float(np.mean(np.diff(luma, axis=0) ** 2) + np.mean(np.diff(luma, axis=1) ** 2))


def psnr(a, b):
    mse = np.mean((a - b) ** 2)
    return 99.0 if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)


# What each method adds to `fgplay render --path`.
METHODS = {"1 spp": [], "TAA": ["--taa"], "TAAU 1.5": ["--taa", "--taa-upscale", "1.5"],
           "TAAU 2": ["--taa", "--taa-upscale", "2"]}
METHODS = {m: METHODS[m] for m in ARGS.methods.split(",")}


def frame_times(pack, extra):
    """The taa pass's and the frame's GPU time, medians of frames 4-7 of a still view (after warm-up)."""
    out = subprocess.run([FGPLAY, "render", pack, *extra, "--frames", "8", "--size", f"{SIZE}x{SIZE}",
                          "--out", os.path.join(OUT, "taa_timing")], check=True, capture_output=True, text=True).stdout
    taa, frame = [], []
    for line in out.splitlines():
        found = re.match(r"frame (\d+):.*GPU (.*)$", line)
        if found and int(found.group(1)) >= 4:
            ms = {k: float(v) for k, v in re.findall(r"(\w+) ([0-9.]+) ms", found.group(2))}
            taa.append(ms.get("taa", 0.0))
            frame.append(ms["frame"])
    return float(np.median(taa)), float(np.median(frame))


rows, summary, curves = [], [], {}
for graph in GRAPHS:
    scene = os.path.splitext(os.path.basename(graph))[0]
    pack = os.path.join(OUT, scene + ".fgpack")
    subprocess.run([FGC, "compile", graph, "-o", pack], check=True, capture_output=True)
    times = {} if ARGS.no_timing else {method: frame_times(pack, extra) for method, extra in METHODS.items()}
    if times:
        summary.append(f"{scene}: frame " + ", ".join(f"{m} {t[1]:.2f} ms" for m, t in times.items()) +
                       "; the taa pass " + ", ".join(f"{100 * t[0] / t[1]:.1f} %" for m, t in times.items() if t[0] > 0) +
                       " of its frame")
    camera = json.load(open(graph))["scene"]["camera"]
    for name in TRACES:
        path = os.path.join(OUT, f"{scene}_{name}.json")
        json.dump(trace(name, camera), open(path, "w"))
        base = os.path.join(OUT, f"{scene}_{name}")
        frames = {method: render(pack, path, base + "_" + re.sub(r"\W+", "_", method.lower()), *extra)
                  for method, extra in METHODS.items()}
        reference = render(pack, path, base + "_ref", "--samples", "16")
        reference_detail = [gradient_energy(ref) for ref in reference]
        for method, images in frames.items():
            stats = []
            for i, (image, ref) in enumerate(zip(images, reference)):
                p = psnr(image, ref)
                s = structural_similarity(image, ref, channel_axis=2, data_range=255)
                f = float(np.mean(np.abs((image - images[i - 1]) - (ref - reference[i - 1])))) if i else float("nan")
                d = gradient_energy(image) / reference_detail[i]
                rows.append([scene, name, method, i, f"{p:.3f}", f"{s:.5f}", f"{f:.3f}", f"{d:.4f}"])
                stats.append((p, s, f, d))
            curves[(scene, name, method)] = [x[0] for x in stats]
            if name == "burst":
                turn = [x[2] for x in stats[19:37]]
                straight = [x[2] for x in stats[8:18] + stats[38:]]
                summary.append(f"{scene}, burst, {method}: flicker {np.median(straight):.2f} flying straight "
                               f"(frames 8-17, 38-), {np.median(turn):.2f} in the turn (frames 19-36)")
            settled = stats[SETTLED:]
            med = lambda k: float(np.median([x[k] for x in settled]))
            summary.append(f"| {scene} | {name} | {method} | {med(0):.2f} | {min(x[0] for x in settled):.2f} | "
                           f"{med(1):.4f} | {med(2):.2f} | {max(x[2] for x in settled):.2f} | {med(3):.3f} |")
        print("\n".join(summary[-len(METHODS):]), flush=True)

with open(os.path.join(OUT, "taa_frames.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["scene", "trace", "method", "frame", "psnr_db", "ssim", "flicker_levels", "detail"])
    w.writerows(rows)
with open(os.path.join(OUT, "taa_quality.md"), "w") as f:
    f.write(f"{SIZE}² per eye, {FRAMES} frames at 90 Hz, left eye against 16 jittered samples per pixel; "
            f"medians and worst of frames {SETTLED}-{FRAMES - 1}.\n\n")
    f.write("\n".join(s for s in summary if not s.startswith("|")) + "\n\n")
    f.write("| scene | trace | method | PSNR median | PSNR worst | SSIM median | flicker median | flicker worst | detail median |\n")
    f.write("|---|---|---|---:|---:|---:|---:|---:|---:|\n")
    f.write("\n".join(s for s in summary if s.startswith("|")) + "\n")

scenes = sorted({k[0] for k in curves})
traces = TRACES
fig, axes = plt.subplots(len(scenes), len(traces), figsize=(4 * len(traces), 2.8 * len(scenes)), squeeze=False)
for r, scene in enumerate(scenes):
    for c, name in enumerate(traces):
        ax = axes[r][c]
        for method in METHODS:
            if (scene, name, method) in curves:
                ax.plot(curves[(scene, name, method)], label=method)
        ax.axvspan(0, SETTLED, color="0.9")
        ax.set_title(f"{scene}: {name}", fontsize=9)
        ax.set_xlabel("frame (90 Hz)", fontsize=8)
        ax.set_ylabel("PSNR against 16 spp (dB)", fontsize=8)
        ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(OUT, "taa_quality.png"), dpi=80)
