#!/usr/bin/env python3
"""fgc export end to end, every file read back by another program: the .vdb by OpenVDB's own
Python reader (pyopenvdb), the meshes by VTK's PLY, OBJ and STL readers (volume, area, boundary
and non-manifold edges) and the STL by admesh, the mesh checker slicers' users know.

usage: check_export.py CASE --fgc FGC --source SOURCE_DIR --work WORK_DIR (the test's own folder)
CASE: shapes | gallery | mixed | shards | bad_input
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import time

import pyopenvdb
import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


def fgc(args, *extra):
    result = subprocess.run([args.fgc, "export", *extra], capture_output=True, text=True)
    return result


def export_ok(args, *extra):
    result = fgc(args, *extra)
    if result.returncode != 0:
        raise SystemExit(f"fgc export {' '.join(extra)} failed ({result.returncode}):\n{result.stdout}{result.stderr}")
    return result.stdout


def read_mesh(path):
    reader = {".ply": vtk.vtkPLYReader, ".obj": vtk.vtkOBJReader, ".stl": vtk.vtkSTLReader}[os.path.splitext(path)[1]]()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def edges(mesh, boundary, non_manifold):
    f = vtk.vtkFeatureEdges()
    f.SetInputData(mesh)
    f.SetBoundaryEdges(boundary)
    f.SetNonManifoldEdges(non_manifold)
    f.FeatureEdgesOff()
    f.ManifoldEdgesOff()
    f.Update()
    return f.GetOutput().GetNumberOfLines()


def check_mesh(path, stdout):
    """Watertight and manifold by VTK; the triangle count fgc reported; (volume, area)."""
    mesh = read_mesh(path)
    m = re.search(re.escape(path) + r": (\d+) vertices, (\d+) triangles", stdout)
    if not m:
        fail(f"{path}: fgc did not report it")
        return 0.0, 0.0
    if mesh.GetNumberOfCells() != int(m.group(2)) or mesh.GetNumberOfCells() == 0:
        fail(f"{path}: VTK reads {mesh.GetNumberOfCells()} triangles, fgc wrote {m.group(2)}")
    # Every vertex a PLY or OBJ holds is used by a triangle (STL has no shared vertices).
    if not path.endswith(".stl"):
        used = len(numpy.unique(vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())))
        if used != mesh.GetNumberOfPoints():
            fail(f"{path}: {mesh.GetNumberOfPoints() - used} of {mesh.GetNumberOfPoints()} vertices in no triangle")
    # Debian's VTK 9.1 vtkFeatureEdges fails to allocate on meshes of millions of triangles (the
    # sponge's at the default resolution): those are checked by admesh on their STL alone.
    if mesh.GetNumberOfCells() <= 1000000:
        holes, bad = edges(mesh, True, False), edges(mesh, False, True)
        if holes or bad:
            fail(f"{path}: {holes} boundary edges (holes), {bad} non-manifold edges")
    mass = vtk.vtkMassProperties()
    mass.SetInputData(mesh)
    mass.Update()
    return mass.GetVolume(), mass.GetSurfaceArea()


def check_admesh(path):
    """admesh's own check: every facet connected on all three edges, nothing to fix."""
    out = subprocess.run(["admesh", path], capture_output=True, text=True).stdout
    numbers = dict((k.strip(), int(v)) for k, v in re.findall(r"^([A-Za-z ]+?)\s*:\s+(\d+)", out, re.M))
    for key in ("Total disconnected facets", "Degenerate facets", "Edges fixed", "Facets removed", "Facets added",
                "Facets reversed", "Backwards edges", "Normals fixed"):
        if key not in numbers:
            fail(f"{path}: admesh printed no '{key}':\n{out}")
        elif numbers[key] != 0:
            fail(f"{path}: admesh: {key} {numbers[key]}")


def check_vdb(path, stdout):
    """OpenVDB's reader finds the level set fgc said it wrote: same active voxels and bounds."""
    m = re.search(re.escape(path) + r": (\d+) active voxels, index bounds (-?\d+) (-?\d+) (-?\d+) to (-?\d+) (-?\d+) (-?\d+)", stdout)
    if not m:
        fail(f"{path}: fgc did not report it")
        return None
    grid = pyopenvdb.read(path, "surface")
    said = int(m.group(1)), tuple(int(x) for x in m.group(2, 3, 4)), tuple(int(x) for x in m.group(5, 6, 7))
    read = grid.activeVoxelCount(), *grid.evalActiveVoxelBoundingBox()
    if said != read or grid.gridClass != pyopenvdb.GridClass.LEVEL_SET or said[0] == 0:
        fail(f"{path}: fgc wrote {said}, OpenVDB reads {read} ({grid.gridClass})")
    return grid


def check_signed_band(path, grid, width=3.0):
    """A true signed band on both sides: active values reach below -1 voxel inside and above +1
    outside, and none beyond the band's half-width."""
    h = grid.transform.voxelSize()[0]
    values = numpy.array([item.value for item in grid.citerOnValues()]) / h
    inside = numpy.count_nonzero(values < 0.0)
    print(f"{path}: active values {values.min():+.2f} to {values.max():+.2f} voxels, {inside} of {len(values)} inside")
    if values.min() > -1.5 or values.max() < 1.5 or numpy.abs(values).max() >= width:
        fail(f"{path}: active values {values.min():+.2f} to {values.max():+.2f} voxels: not a signed band of {width} voxels")


def near(what, value, expected, tolerance=0.01):
    error = value / expected - 1.0
    print(f"{what}: {value:.6f}, closed form {expected:.6f}, error {100 * error:+.3f} %")
    if abs(error) > tolerance:
        fail(f"{what}: {value:.6f} is {100 * error:+.2f} % off {expected:.6f}")


def shapes(args):
    """Meshes at the default resolution against closed forms, within 1 %."""
    g = os.path.join(args.source, "tests/export/graphs")
    sphere = 4.0 / 3.0 * math.pi, 4.0 * math.pi
    big = 4.0 / 3.0 * math.pi * 1.1 ** 3, 4.0 * math.pi * 1.1 ** 2
    torus = 2 * math.pi ** 2 * 0.75 * 0.25 ** 2, 4 * math.pi ** 2 * 0.75 * 0.25
    cases = [
        ("sphere", [], sphere, (".ply", ".obj", ".stl")),
        ("torus", [], torus, (".ply", ".stl")),
        # The distance moved out by 0.1: a sphere of radius 1.1.
        ("sphere", ["--offset", "0.1"], big, (".stl",)),
        # A box close around the sponge, as for a print: the level-3 holes are 8 voxels wide.
        ("menger3", ["--box", "-1.1,-1.1,-1.1,1.1,1.1,1.1"], (8.0 * (20.0 / 27.0) ** 3, None), (".stl",)),
    ]
    for i, (name, extra, (volume, area), formats) in enumerate(cases):
        out = os.path.join(args.work, f"{name}{i}")
        meshes = [a for ext in formats for a in ("--mesh", out + ext)]
        stdout = export_ok(args, os.path.join(g, name + ".json"), "-o", out + ".vdb", "--quiet", *meshes, *extra)
        grid = check_vdb(out + ".vdb", stdout)
        if grid is not None and name == "sphere":
            check_signed_band(out + ".vdb", grid)
        for ext in formats:
            v, a = check_mesh(out + ext, stdout)
            near(f"{name} {' '.join(extra)} {ext} volume", v, volume)
            if area:
                near(f"{name} {' '.join(extra)} {ext} area", a, area)
            if ext == ".stl":
                check_admesh(out + ext)


# The gallery's graphs without /scene/bounds (endless scenes), with a box around their camera's view.
BOXES = {"apollonian": "-1,-1,-1,1,1,1", "julia_pool": "-1.5,-1,-1.5,1.5,1,1.5", "kleinian": "-1,-1,-1,1,1,1"}


# The gallery's shapes with an interior more than a voxel deep at 48 voxels across (the sheets,
# sponges and thin sets have none that deep to band).
SOLID = {"apollonian", "box_menger_hybrid", "bulb_box_hybrid", "julia_pool", "kleinian", "mandelbox", "mandelbox_halls",
         "mandelbulb", "mandelbulb_power5"}


def gallery(args):
    """Every gallery fractal's mesh is watertight and manifold (VTK and admesh), its .vdb reads back
    (the hybrid formulas among them)."""
    folder = os.path.join(args.source, "graphs/gallery")
    names = sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".json"))
    if len(names) < 10:
        fail(f"only {len(names)} gallery graphs found in {folder}")
    if len([n for n in names if n.endswith("_hybrid")]) < 2:
        fail(f"fewer than two hybrid formulas in {folder}")
    for name in names:
        out = os.path.join(args.work, name)
        extra = ["--box", BOXES[name]] if name in BOXES else []
        if name == "mandelbulb":
            extra.append("--colors")
        if name == "menger_twisted":
            extra += ["--adaptivity", "0.3"]   # merged polygons close as well
        stdout = export_ok(args, os.path.join(folder, name + ".json"), "--resolution", "48", "-o", out + ".vdb",
                           "--mesh", out + ".stl", "--mesh", out + ".ply", "--quiet", *extra)
        grid = check_vdb(out + ".vdb", stdout)
        if grid is not None and name in SOLID:
            check_signed_band(out + ".vdb", grid)
        for ext in (".stl", ".ply"):
            volume, _ = check_mesh(out + ext, stdout)
            if volume <= 0.0:
                fail(f"{out + ext}: volume {volume}: no solid")
        check_admesh(out + ".stl")
        print(f"{name}: watertight and manifold")
    # Vertex colours from the graph's albedo: the bulb's palette varies over its surface.
    colours = read_mesh(os.path.join(args.work, "mandelbulb.ply")).GetPointData().GetScalars()
    if colours is None or colours.GetNumberOfComponents() != 3:
        fail("mandelbulb.ply: no RGB vertex colours")
    else:
        reds = {int(colours.GetTuple3(i)[0]) for i in range(colours.GetNumberOfTuples())}
        if len(reds) < 10:
            fail(f"mandelbulb.ply: only {len(reds)} shades of red: the albedo is not sampled per vertex")


def mixed(args):
    """A bulb (an estimate with an inside) smooth-unioned with a Mandelbox (one without): both kept,
    the box out to its faces at 2.0 on every axis; a signed band of the --band asked for. And the
    memory estimate errs high."""
    out = os.path.join(args.work, "bulb_box")
    stdout = export_ok(args, os.path.join(args.source, "tests/export/graphs/bulb_box_union.json"), "--resolution", "64",
                       "--band", "5", "-o", out + ".vdb", "--mesh", out + ".stl", "--quiet")
    if 'node "box" has no inside' not in stdout or 'node "bulb" has no inside' in stdout:
        fail(f"the surface rules named are not the box's alone:\n{stdout}")
    grid = check_vdb(out + ".vdb", stdout)
    if grid is not None:
        check_signed_band(out + ".vdb", grid, width=5.0)
    check_mesh(out + ".stl", stdout)
    check_admesh(out + ".stl")
    bounds = read_mesh(out + ".stl").GetBounds()
    print(f"bulb_box.stl bounds {bounds}")
    if min(-bounds[0], bounds[1], -bounds[2], bounds[3], -bounds[4], bounds[5]) < 1.95:
        fail(f"bulb_box.stl bounds {bounds}: the Mandelbox (faces at 2.0) is not whole")
    estimate_errs_high(args)


def estimate_errs_high(args):
    """The memory estimate printed before the work is not below the process's measured peak."""
    if "ASAN_OPTIONS" in os.environ:
        print("memory: not compared under AddressSanitizer, whose shadow memory and quarantine the estimate leaves out")
        return
    out = os.path.join(args.work, "bulb192")
    argv = [args.fgc, "export", os.path.join(args.source, "graphs/gallery/mandelbulb.json"), "--resolution", "192",
            "-o", out + ".vdb", "--mesh", out + ".stl", "--quiet"]
    # GNU time reports the peak of the process it starts; a child of this Python would count its
    # (VTK's) pages from before the exec.
    result = subprocess.run(["/usr/bin/time", "-f", "peak %M KiB", *argv], capture_output=True, text=True)
    stdout = result.stdout
    peak_line = re.search(r"peak (\d+) KiB", result.stderr)
    m = re.search(r"([\d.]+) (MiB|GiB) peak memory", stdout)
    if result.returncode != 0 or not m or not peak_line:
        fail(f"fgc export at 192 voxels: exit {result.returncode}:\n{stdout}{result.stderr}")
        return
    estimate = float(m.group(1)) * (1024 if m.group(2) == "GiB" else 1)
    peak = int(peak_line.group(1)) / 1024.0
    print(f"memory: estimate {estimate:.0f} MiB, measured peak {peak:.0f} MiB")
    if estimate < peak:
        fail(f"the memory estimate {estimate:.0f} MiB is below the measured peak {peak:.0f} MiB")


def shards(args):
    """Three slabs exported apart and merged are the whole run, voxel for voxel (read by OpenVDB)."""
    graph = os.path.join(args.source, "graphs/gallery/mandelbulb.json")
    whole = os.path.join(args.work, "whole.vdb")
    common = ["--resolution", "80", "--quiet"]
    check_vdb(whole, export_ok(args, graph, "-o", whole, *common))
    parts = []
    for i in range(3):
        parts.append(os.path.join(args.work, f"shard{i}.vdb"))
        grid = check_vdb(parts[-1], export_ok(args, graph, "-o", parts[-1], "--shard", f"{i}/3", *common))
        if grid is not None and grid.metadata.get("fractograph.shard") != f"{i}/3":
            fail(f"{parts[-1]}: metadata fractograph.shard is {grid.metadata.get('fractograph.shard')}")
    merged = os.path.join(args.work, "merged.vdb")
    stdout = export_ok(args, "--merge", *parts, "-o", merged, "--mesh", merged[:-4] + ".stl")
    check_vdb(merged, stdout)
    check_mesh(merged[:-4] + ".stl", stdout)
    check_admesh(merged[:-4] + ".stl")
    a, b = pyopenvdb.read(whole, "surface"), pyopenvdb.read(merged, "surface")
    values = {}
    for item in a.citerOnValues():
        values[item.min] = item.value
    same = sum(1 for item in b.citerOnValues() if values.get(item.min) == item.value)
    print(f"merged: {b.activeVoxelCount()} active voxels, {same} equal to the whole run's {a.activeVoxelCount()}")
    if not (same == a.activeVoxelCount() == b.activeVoxelCount()) or a.evalActiveVoxelBoundingBox() != b.evalActiveVoxelBoundingBox():
        fail("the merged shards differ from the whole run")
    if b.metadata.get("fractograph.graph") != "Mandelbulb" or "fractograph.shard" in b.metadata:
        fail(f"merged metadata: {b.metadata}")


def bad_input(args):
    """Each mistake is an error naming its option, field or path, before any work; nothing written."""
    g = os.path.join(args.source, "tests/export/graphs")
    unbounded = os.path.join(args.work, "unbounded.json")
    with open(os.path.join(g, "sphere.json")) as f:
        text = f.read()
    with open(unbounded, "w") as f:
        f.write(text.replace('"scene": {"bounds": {"radius": 1.2}}', '"scene": {}'))
    out = os.path.join(args.work, "out.vdb")
    sphere = os.path.join(g, "sphere.json")
    cases = [
        ([unbounded, "-o", out], "/scene/bounds"),
        ([unbounded, "-o", out, "--box", "1,0,0,0,1,1"], "--box 1,0,0,0,1,1"),
        ([sphere, "-o", out, "--voxel-size", "0.00001", "--max-memory", "2G"], "--voxel-size 1e-05"),
        ([sphere, "-o", out, "--resolution", "100000", "--max-memory", "2G"], "over --max-memory 2.0 GiB"),
        ([sphere, "-o", out, "--voxel-size", "1e-10", "--max-memory", "1000T"], "beyond OpenVDB's 32-bit coordinates"),
        ([sphere, "-o", "/etc/hostname/out.vdb"], "-o /etc/hostname/out.vdb: cannot write there"),
        ([sphere, "-o", out, "--mesh", os.path.join(args.work, "no_such_folder/out.stl")], "no_such_folder/out.stl: cannot write there"),
        ([sphere, "-o", out, "--mesh", os.path.join(args.work, "out.fbx")], "--mesh " + os.path.join(args.work, "out.fbx") + ": unknown mesh format"),
        ([sphere, "-o", out, "--shard", "3/3"], "--shard 3/3: expected I/N"),
        ([sphere, "-o", os.path.join(args.work, "out.txt")], "out.txt: a level set is written as .vdb"),
        ([sphere, "-o", out, "--param", "radius=2"], "--param radius=2"),
        (["--merge", os.path.join(args.work, "missing.vdb"), "-o", out], "missing.vdb"),
    ]
    for argv, needle in cases:
        start = time.monotonic()
        result = fgc(args, *argv)
        seconds = time.monotonic() - start
        said = result.stdout + result.stderr
        errors = [line for line in said.splitlines() if "error" in line]
        print(f"fgc export {' '.join(argv)}: exit {result.returncode} in {seconds:.2f} s: {errors[0] if errors else said.strip()}")
        if result.returncode == 0 or needle not in said:
            fail(f"fgc export {' '.join(argv)}: exit {result.returncode}, expected an error with '{needle}':\n{said}")
        if os.path.exists(out) or seconds > 5.0:
            fail(f"fgc export {' '.join(argv)}: wrote {out} or worked {seconds:.1f} s before the error")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case", choices=["shapes", "gallery", "mixed", "shards", "bad_input"])
    parser.add_argument("--fgc", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    if not shutil.which("admesh"):
        raise SystemExit("admesh not found (Debian: admesh; scripts/fractograph.sh installs the test packages)")
    # The test's own folder, emptied at the start; removed when it passes unless
    # FG_KEEP_TEST_FILES=1 (docs/testing.md), kept to look at when it fails.
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    globals()[args.case](args)
    if failures:
        print(f"{len(failures)} failure(s); the files are in {args.work}")
        sys.exit(1)
    if os.environ.get("FG_KEEP_TEST_FILES") != "1":
        shutil.rmtree(args.work)
    print("ok")


if __name__ == "__main__":
    main()
