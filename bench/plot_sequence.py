#!/usr/bin/env python3
"""Plots for `fgplay bench --sequence`: per trace, GPU time of every frame for each setting (one
panel per scene); the median and p99 speed-up of every setting over naive sphere tracing on all
pixels, per trace (one panel per scene); and what each setting's time buys, its median GPU time
against its picture's median PSNR from the ground truth, per trace (the axes of the governor's
front). Reads sequence.csv and sequence_frames.csv, writes PNGs beside them."""
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = [r for r in csv.DictReader(open(folder / "sequence.csv")) if not r["error"]]
frames = list(csv.DictReader(open(folder / "sequence_frames.csv")))
scenes = list(dict.fromkeys(r["scene"] for r in rows))
traces = list(dict.fromkeys(r["trace"] for r in rows))
settings = list(dict.fromkeys(r["setting"] for r in rows))
methods = list(dict.fromkeys(r["method"] for r in rows))
colour = {m: plt.get_cmap("tab10")(i) for i, m in enumerate(methods)}
method_of = {r["setting"]: r["method"] for r in rows}
masked = {r["setting"]: r["lens_mask"] == "1" for r in rows}
baseline = "naive"   # the setting every bar is measured against: naive on all pixels
written = []

for trace in traces:
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.2), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for setting in settings:
            sel = [f for f in frames if f["scene"] == scene and f["trace"] == trace and f["setting"] == setting]
            if not sel:
                continue
            # A dark frame (a snap turn's black) renders nothing: a gap in the line.
            ms = [math.nan if f["dark"] == "1" else float(f["frame_ms"]) for f in sel]
            ax.plot([int(f["frame"]) for f in sel], ms, ls="--" if masked[setting] else "-", lw=1.1,
                    c=colour[method_of[setting]], label=setting)
        dark = sorted({int(f["frame"]) for f in frames
                       if f["scene"] == scene and f["trace"] == trace and f["dark"] == "1"})
        for k, i in enumerate(dark):
            ax.axvspan(i - 0.5, i + 0.5, color="black", alpha=0.15, label="black frame (not rendered)" if k == 0 else None)
        ax.set_xlabel("frame (90 Hz)")
        ax.set_ylabel("GPU time per stereo frame (ms)")
        ax.set_title(f"{scene}: {trace}")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=6, loc="upper left")
    fig.tight_layout()
    name = f"sequence_frame_time_{trace}.png"
    fig.savefig(folder / name, dpi=100)
    plt.close(fig)
    written.append(name)

# Bars: median speed-up solid, p99 speed-up hatched beside it, per setting, grouped by trace.
others = [s for s in settings if s != baseline]
fig, axes = plt.subplots(len(scenes), 1, figsize=(max(8.0, 0.32 * len(traces) * len(others)) + 3.5, 3.4 * len(scenes)),
                         squeeze=False)
for ax, scene in zip(axes[:, 0], scenes):
    base = {r["trace"]: r for r in rows if r["scene"] == scene and r["setting"] == baseline}
    width = 0.8 / max(1, 2 * len(others))
    for k, setting in enumerate(others):
        med, p99 = [], []
        for trace in traces:
            r = next((r for r in rows if r["scene"] == scene and r["trace"] == trace and r["setting"] == setting), None)
            b = base.get(trace)
            ok = r and b and float(r["frame_ms_median"]) > 0 and float(r["frame_ms_p99"]) > 0
            med.append(float(b["frame_ms_median"]) / float(r["frame_ms_median"]) if ok else 0.0)
            p99.append(float(b["frame_ms_p99"]) / float(r["frame_ms_p99"]) if ok else 0.0)
        x = [t - 0.4 + width * (2 * k + 0.5) for t in range(len(traces))]
        c = colour[method_of[setting]]
        ax.bar(x, med, width, color=c, alpha=0.55 if masked[setting] else 1.0, label=f"{setting}: median")
        ax.bar([v + width for v in x], p99, width, color=c, alpha=0.55 if masked[setting] else 1.0, hatch="///",
               edgecolor="white", label=f"{setting}: p99")
    ax.axhline(1.0, c="black", lw=0.8)
    ax.set_xticks(range(len(traces)))
    ax.set_xticklabels(traces, fontsize=8)
    ax.set_ylabel("speed-up over naive on all pixels (×)")
    ax.set_title(scene)
    ax.grid(axis="y", alpha=0.3)
axes[0][0].legend(fontsize=6.5, loc="upper left", bbox_to_anchor=(1.01, 1.0))
fig.tight_layout()
fig.savefig(folder / "sequence_speedups.png", dpi=100)
written.append("sequence_speedups.png")
plt.close(fig)

# Time against the picture: each setting a marker per trace, up and to the left is better.
if all("picture_psnr_db_median" in r for r in rows):
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.6), squeeze=False)
    markers = "osD^vP*Xh"
    for ax, scene in zip(axes[0], scenes):
        for setting in settings:
            for k, trace in enumerate(traces):
                r = next((r for r in rows if r["scene"] == scene and r["trace"] == trace and r["setting"] == setting), None)
                if not r or float(r["frame_ms_median"]) <= 0:
                    continue
                ax.scatter(float(r["frame_ms_median"]), float(r["picture_psnr_db_median"]), s=28,
                           marker=markers[k % len(markers)], facecolors="none" if masked[setting] else colour[method_of[setting]],
                           edgecolors=colour[method_of[setting]], label=setting if k == 0 else None)
        ax.set_xlabel("median GPU time per stereo frame (ms)")
        ax.set_ylabel("picture PSNR against 16 samples per pixel (dB)")
        ax.set_title(f"{scene}: " + ", ".join(f"{markers[k % len(markers)]} {t}" for k, t in enumerate(traces)), fontsize=8)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=6, loc="lower right")
    fig.tight_layout()
    fig.savefig(folder / "sequence_time_vs_picture.png", dpi=100)
    written.append("sequence_time_vs_picture.png")
print("plots: " + ", ".join(str(folder / n) for n in written))
