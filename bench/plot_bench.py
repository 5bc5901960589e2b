#!/usr/bin/env python3
"""Plots for `fgplay bench`: time versus error with the Pareto front marked (one panel per view),
and GPU time per pass stacked for every setting. Reads results.json, writes PNGs beside it."""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = pathlib.Path(sys.argv[1])
data = json.loads((folder / "results.json").read_text())
rows = [r for r in data["rows"] if not r["error"]]
views = list(dict.fromkeys(r["view"] for r in rows))


def pareto(points):
    """Points (time, error, row) not beaten on both time and error by another."""
    front = []
    for p in sorted(points, key=lambda p: (p[0], p[1])):
        if not front or p[1] < front[-1][1]:
            front.append(p)
    return front


fig, axes = plt.subplots(1, len(views), figsize=(5.5 * len(views), 4.6), squeeze=False)
for ax, view in zip(axes[0], views):
    pts = [(r["pass_ms"].get("frame", 0.0), r["wrong_pct"], r) for r in rows if r["view"] == view]
    for t, e, r in pts:
        colour = "black" if r["baseline"] else ("tab:orange" if r["group"] == "grid" else "tab:blue")
        ax.scatter(t, max(e, 1e-3), s=40 if r["baseline"] else 18, c=colour, zorder=3)
    front = pareto(pts)
    ax.plot([p[0] for p in front], [max(p[1], 1e-3) for p in front], "-", c="tab:red", lw=1.5,
            label="Pareto front", zorder=2)
    for t, e, r in front:
        ax.annotate(r["setting"], (t, max(e, 1e-3)), fontsize=6, xytext=(3, 3), textcoords="offset points")
    base = [p for p in pts if p[2]["baseline"]]
    for t, e, r in base:
        ax.annotate("naive baseline", (t, max(e, 1e-3)), fontsize=7, weight="bold", xytext=(3, -9),
                    textcoords="offset points")
    ax.axhline(0.5, ls=":", c="grey", lw=1)
    ax.set_yscale("log")
    ax.set_xlabel("GPU time per stereo frame (ms)")
    ax.set_ylabel("misclassified pixels (%)")
    ax.set_title(f"{data['scene']}: view '{view}'")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
fig.suptitle(f"Accuracy versus time on {data['device']}, {data['size']}x{data['size']} per eye "
             "(blue: one knob, orange: grid)", fontsize=9)
fig.tight_layout()
fig.savefig(folder / "time_vs_error.png", dpi=110)

# Time per pass, stacked, per setting (first view that has them all, preferring 'filled').
view = "filled" if "filled" in views else views[0]
sel = [r for r in rows if r["view"] == view]
passes = ["march", "tail", "reproject", "shade", "fovea"]
fig, ax = plt.subplots(figsize=(9, 0.28 * len(sel) + 1.5))
left = [0.0] * len(sel)
for p in passes:
    vals = [r["pass_ms"].get(p, 0.0) for r in sel]
    if not any(vals):
        continue
    ax.barh(range(len(sel)), vals, left=left, label=p)
    left = [a + b for a, b in zip(left, vals)]
ax.set_yticks(range(len(sel)))
ax.set_yticklabels([r["setting"] for r in sel], fontsize=7)
ax.invert_yaxis()
ax.set_xlabel("GPU time (ms), median")
ax.set_title(f"Time per pass, view '{view}'")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(folder / "time_per_pass.png", dpi=110)
print(f"plots: {folder / 'time_vs_error.png'}, {folder / 'time_per_pass.png'}")
