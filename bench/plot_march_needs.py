#!/usr/bin/env python3
"""How much faster than naive's the march must be for issue 19's whole-frame targets, against what
per-eye conemarch gives and the last-mile spike's ceiling. Shading and post cost both tracers the
same, so with s naive's share after the march a frame is 1 / ((1 - s) / m + s) times faster for a
march m times faster. Reads sequence.csv files of `fgplay bench --sequence` runs (all five traces,
plain and masked rows) and writes OUT.png.

    plot_march_needs.py OUT.png CEILING SEQUENCE.csv [SEQUENCE.csv ...]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out, ceiling, files = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
MASKED = " with lens mask + foveation 0.5"
rows = {}
for name in files:
    for r in csv.DictReader(open(name)):
        rows[(r["scene"], r["trace"], r["setting"])] = r


def time_split(scene, trace, setting):
    """(frame ms, march ms, after-march ms) of a row."""
    r = rows[(scene, trace, setting)]
    frame, share = float(r["frame_ms_median"]), float(r["after_march_share"])
    return frame, frame * (1 - share), frame * share


labels, now_all, need_all, now_masked, need_masked = [], [], [], [], []
for scene, trace, setting in rows:
    if setting != "naive":
        continue
    naive, naive_march, naive_after = time_split(scene, trace, "naive")
    _, eye_march, _ = time_split(scene, trace, "per-eye")
    _, masked_naive_march, _ = time_split(scene, trace, "naive" + MASKED)
    _, masked_eye_march, masked_eye_after = time_split(scene, trace, "per-eye" + MASKED)
    labels.append(f"{scene}\n{trace}")
    now_all.append(naive_march / eye_march)
    need_all.append(naive_march / (naive / 2 - naive_after))
    now_masked.append(masked_naive_march / masked_eye_march)
    need_masked.append(masked_naive_march / (naive / 3 - masked_eye_after))

fig, axes = plt.subplots(1, 2, figsize=(15, 4.8), sharey=True)
x = range(len(labels))
for ax, now, need, title in ((axes[0], now_all, need_all, "all pixels: 2x the naive frame"),
                             (axes[1], now_masked, need_masked, "lens mask + foveation 0.5: 3x the all-pixel naive frame")):
    ax.bar([i - 0.2 for i in x], now, 0.4, label="per-eye's march now")
    ax.bar([i + 0.2 for i in x], need, 0.4, label="march needed for the target")
    ax.axhline(ceiling, c="k", ls="--", lw=1, label=f"spike's ceiling: still head, free reuse, lane refill ({ceiling}x)")
    ax.set_xticks(list(x), labels, rotation=90, fontsize=7)
    ax.set_title(title, fontsize=10)
    ax.grid(axis="y", alpha=0.3)
axes[0].set_ylabel("march time: naive's / per-eye's")
axes[0].legend(fontsize=8, loc="upper left")
fig.suptitle("Lavapipe, 512² per eye, head traces at 90 Hz: the march a whole-frame target needs", fontsize=11)
fig.tight_layout()
fig.savefig(out, dpi=110)
print(out)
