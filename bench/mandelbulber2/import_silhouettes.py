#!/usr/bin/env python3
"""fgc import against Mandelbulber2 itself: each scene rendered headless by Mandelbulber2 (2.20,
Debian's package) and, imported, by fgplay, both SIZE x SIZE; the silhouettes (Mandelbulber2's
alpha, fgplay's depth) compared as intersection over union. With --coverage, first imports every
example scene Mandelbulber2 ships and counts what imports and why the rest does not.

With --far D, both render the scene from Mandelbulber2's default view direction at distance D
from the origin instead of the scene's camera: the whole shape against the sky, which tests the
formula's conventions where a close camera fills the frame.

usage: import_silhouettes.py BUILD OUT_DIR [--size 256] [--coverage] [--far D] [SCENE.fract ...]
Writes OUT_DIR/silhouettes.md (the table), OUT_DIR/silhouettes.png (per scene, three to a row in the
table's order: Mandelbulber2's mask, fgplay's, their difference; silhouettes_far.* with --far) and,
with --coverage, OUT_DIR/coverage.md.
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

import numpy
from PIL import Image

EXAMPLES = "/usr/share/mandelbulber2/examples"
# The effects that change the look and not the silhouette, off for Mandelbulber2's render (time).
LOOK_OFF = "#".join(f"{k}=false" for k in (
    "ambient_occlusion_enabled", "DOF_enabled", "shadows_enabled", "raytraced_reflections", "volumetric_fog_enabled",
    "glow_enabled", "iteration_fog_enable", "main_light_volumetric_enabled", "fake_lights_enabled", "basic_fog_enabled",
    "DOF_monte_carlo", "antialiasing_enabled", "stereo_enabled", *(f"aux_light_volumetric_enabled_{i}" for i in range(1, 5))))


def run(argv, **kw):
    return subprocess.run(argv, capture_output=True, text=True, **kw)


def coverage(build, out):
    scenes = sorted(os.path.join(d, f) for d, _, fs in os.walk(EXAMPLES) for f in fs if f.endswith(".fract"))
    imported, reasons = [], collections.Counter()
    with tempfile.TemporaryDirectory() as work:
        for i, scene in enumerate(scenes):
            r = run([f"{build}/compiler/fgc", "import", scene, "-o", os.path.join(work, "x.json")])
            if r.returncode == 0:
                imported.append(scene)
            else:
                first = next((l for l in r.stderr.splitlines() if "error:" in l), r.stderr.strip()[:100])
                reason = re.sub(r"^.*?error: (line \d+: )?", "", first)
                reason = re.sub(r"formula_\d (\d+): this formula.*", r"formula \1 is not imported", reason)
                reason = re.sub(r"^(\w+?)_?\d*: .*? is not imported \((.*)\)$", r"\1: \2", reason)
                reasons[reason[:110]] += 1
            if (i + 1) % 50 == 0 or i + 1 == len(scenes):
                print(f"{i + 1}/{len(scenes)} scenes, {len(imported)} imported", file=sys.stderr)
    print(file=sys.stderr)
    with open(os.path.join(out, "coverage.md"), "w") as f:
        f.write(f"{len(imported)} of {len(scenes)} example scenes imported ({100 * len(imported) / len(scenes):.1f} %).\n\n")
        f.write("| scenes | first reason the rest are refused |\n|---:|---|\n")
        for reason, n in reasons.most_common():
            f.write(f"| {n} | {reason} |\n")
    print(f"{len(imported)} of {len(scenes)} imported")
    return imported


CAMERA_KEYS = ("camera", "target", "camera_top", "camera_rotation", "camera_distance_to_target", "fov", "perspective_type",
               "view_distance_max", "legacy_coordinate_system")


def far_view(scene, distance, path):
    """The scene seen from Mandelbulber2's default direction, (3, -6, 2) / 7, at `distance` from
    the origin (its default camera rotation looks along that line)."""
    text = open(scene, encoding="latin-1").read()
    text = re.sub(rf"^({'|'.join(CAMERA_KEYS)}) .*\n", "", text, flags=re.M)
    s = distance / 7.0
    camera = (f"camera {3 * s:.6f} {-6 * s:.6f} {2 * s:.6f};\ntarget 0 0 0;\ncamera_rotation 26.565 -16.60154 0;\n"
              f"camera_distance_to_target {distance:.6f};\n")
    with open(path, "w", encoding="latin-1") as f:
        f.write(text.replace("[main_parameters]\n", "[main_parameters]\n" + camera, 1))
    return path


def silhouettes(build, out, scenes, size, far=None):
    rows, tiles = [], []
    home = tempfile.mkdtemp()   # Mandelbulber2 writes its settings folder into HOME
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        with tempfile.TemporaryDirectory() as work:
            if far:
                scene = far_view(scene, far, os.path.join(work, "far.fract"))
            mb = os.path.join(work, "mb.png")
            try:
                r = run(["mandelbulber2", "-n", "-r", f"{size}x{size}", "-f", "png16alpha", "-O", LOOK_OFF, "-o", mb, scene],
                        env={**os.environ, "HOME": home}, timeout=300)
            except subprocess.TimeoutExpired:
                print(f"{name}: skipped (Mandelbulber2 took over 5 minutes)")
                continue
            graph, pack = os.path.join(work, "scene.json"), os.path.join(work, "scene.fgpack")
            imp = run([f"{build}/compiler/fgc", "import", scene, "-o", graph])
            if r.returncode or not os.path.exists(mb) or imp.returncode:
                print(f"{name}: skipped ({'mandelbulber2' if r.returncode else 'import'} failed)")
                continue
            run([f"{build}/compiler/fgc", "compile", graph, "-o", pack], check=True)
            run([f"{build}/runtime/fgplay", "render", pack, "--out", work, "--size", f"{size}x{size}", "--ipd", "0",
                 "--depth"], check=True)
            theirs = numpy.array(Image.open(mb))[..., 3] > 127
            ours = numpy.array(Image.open(os.path.join(work, "depth_left.png"))) > 0
            if theirs.shape != ours.shape:
                print(f"{name}: skipped (Mandelbulber2 drew {theirs.shape[1]}x{theirs.shape[0]})")
                continue
            union = numpy.count_nonzero(theirs | ours)
            iou = numpy.count_nonzero(theirs & ours) / union if union else 1.0
            rows.append((name, iou, theirs.mean(), ours.mean(), imp.stdout.strip().split(": ")[-1]))
            tiles.append(numpy.concatenate([theirs, ours, theirs ^ ours], axis=1))
            print(f"{name}: IoU {iou:.3f}")
    stem = "silhouettes_far" if far else "silhouettes"
    with open(os.path.join(out, f"{stem}.md"), "w") as f:
        f.write(f"| scene | IoU | Mandelbulber2 coverage | fgplay coverage | imported as |\n|---|---:|---:|---:|---|\n")
        for name, iou, a, b, what in rows:
            f.write(f"| {name} | {iou:.3f} | {100 * a:.1f} % | {100 * b:.1f} % | {what} |\n")
    if tiles:
        sheet(tiles).save(os.path.join(out, f"{stem}.png"))


def sheet(tiles, across=3):
    """The scenes' triplets (Mandelbulber2's mask, fgplay's, their difference) at half size,
    `across` to a row, in the table's order."""
    half = [Image.fromarray((t * 255).astype(numpy.uint8)).reduce(2) for t in tiles]
    w, h = half[0].size
    out = Image.new("L", (across * w + (across - 1) * 8, (len(half) + across - 1) // across * (h + 8) - 8), 128)
    for i, tile in enumerate(half):
        out.paste(tile, ((i % across) * (w + 8), (i // across) * (h + 8)))
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("build")
    p.add_argument("out")
    p.add_argument("scenes", nargs="*")
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--coverage", action="store_true")
    p.add_argument("--far", type=float)
    a = p.parse_intermixed_args()
    os.makedirs(a.out, exist_ok=True)
    scenes = a.scenes
    if a.coverage:
        imported = coverage(a.build, a.out)
        scenes = scenes or imported
    silhouettes(a.build, a.out, scenes, a.size, a.far)


if __name__ == "__main__":
    main()
