#!/usr/bin/env python3
"""Checks that a build needs nothing scripts/fractograph.sh does not install.

Every system header the build included (ninja's dependency log) and every shared library its
programs load (ldd) must belong to a Debian package that the script's lists name, or to one those
depend on (Depends and Pre-Depends, recursively, never Recommends), or to a minimal Debian 12
(Essential and required packages, and apt). The tools may use only the demo's lists; the tests and
benchmark programs the test command's. A reused machine cannot fool it: what is installed by hand
is not in the closure of the lists.

    python3 scripts/check_packages.py BUILD_DIR [--lists-from SCRIPT] [--without PACKAGE...]
(--without leaves packages out of the lists: what the check says when one is forgotten.)
Exit 0 when all is covered; 1 naming each missing package, what needs it and which command lacks it.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def listed_packages(script, command):
    out = subprocess.run(["bash", script, "packages", command], check=True, capture_output=True, text=True)
    return set(out.stdout.split())


def read_dpkg_status(path="/var/lib/dpkg/status"):
    """Installed packages: name -> fields, and virtual name -> packages that provide it."""
    packages, provides = {}, {}
    with open(path, encoding="utf-8") as f:
        for stanza in f.read().split("\n\n"):
            fields, key = {}, None
            for line in stanza.splitlines():
                if line.startswith((" ", "\t")) and key:
                    fields[key] += " " + line.strip()
                elif ":" in line:
                    key, value = line.split(":", 1)
                    fields[key] = value.strip()
            if "installed" not in fields.get("Status", "").split() or "Package" not in fields:
                continue
            packages[fields["Package"]] = fields
            for p in split_relations(fields.get("Provides", "")):
                provides.setdefault(p[0], set()).add(fields["Package"])
    return packages, provides


def split_relations(text):
    """'a (>= 1) | b:any, c' -> [['a', 'b'], ['c']]"""
    clauses = []
    for clause in text.split(","):
        names = [re.sub(r"\(.*?\)|\[.*?\]|<.*?>", "", alt).strip().split(":")[0] for alt in clause.split("|")]
        names = [n for n in names if n]
        if names:
            clauses.append(names)
    return clauses


def closure(roots, packages, provides):
    """Every package apt would install for roots on a fresh machine: for 'a | b' the first choice."""
    seen, todo = set(), list(roots)
    while todo:
        name = todo.pop()
        for real in ([name] if name in packages else sorted(provides.get(name, ()))):
            if real in seen:
                continue
            seen.add(real)
            fields = packages[real]
            for clause in split_relations(fields.get("Depends", "") + "," + fields.get("Pre-Depends", "")):
                todo.append(clause[0])
    return seen


def minimal_debian(packages):
    return {n for n, f in packages.items()
            if f.get("Essential") == "yes" or f.get("Priority") == "required"} | {"apt"}


def path_variants(path):
    """The names dpkg may know a file by on a merged-/usr system."""
    variants = {path, os.path.realpath(path)}
    for p in list(variants):
        for a, b in (("/usr/lib/", "/lib/"), ("/usr/bin/", "/bin/"), ("/usr/sbin/", "/sbin/"), ("/usr/lib64/", "/lib64/")):
            if p.startswith(a):
                variants.add(b + p[len(a):])
            elif p.startswith(b):
                variants.add(a + p[len(b):])
    return variants


def owners(paths):
    """path -> owning package, read from dpkg's file lists (one pass, no dpkg -S per file)."""
    wanted = {}
    for p in paths:
        for v in path_variants(p):
            wanted.setdefault(v, set()).add(p)
    found = {}
    for lst in glob.glob("/var/lib/dpkg/info/*.list"):
        package = os.path.basename(lst)[:-len(".list")].split(":")[0]
        with open(lst, encoding="utf-8", errors="replace") as f:
            for line in f:
                for p in wanted.get(line.rstrip("\n"), ()):
                    found.setdefault(p, package)
    return found


FUZZ_BUILD = False   # a fuzz build (FG_FUZZ) is all test code: scripts/fuzz.sh, with clang


def is_test_only(relative):
    return FUZZ_BUILD or relative.startswith(("tests/", "bench/"))


def headers_by_user(build):
    """System headers -> the first object file (relative to build) that includes each, split by tools / tests."""
    out = subprocess.run(["ninja", "-C", build, "-t", "deps"], check=True, capture_output=True, text=True).stdout
    used, target = {}, None
    source_dirs = (ROOT + "/", os.path.abspath(build) + "/")
    for line in out.splitlines():
        if line and not line[0].isspace():
            target = line.split(":")[0]
        elif line.strip() and target:
            path = os.path.normpath(line.strip())
            if path.startswith("/") and not path.startswith(source_dirs):
                used.setdefault((path, is_test_only(target)), target)
    return used


def libraries_by_user(build):
    """Shared libraries -> the first program in the build that loads each, split by tools / tests."""
    used = {}
    for dirpath, dirnames, filenames in os.walk(build):
        dirnames[:] = [d for d in dirnames if d != "CMakeFiles" and not d.startswith(".")]
        for name in filenames:
            path = os.path.join(dirpath, name)
            if os.path.islink(path) or not (os.access(path, os.X_OK) or ".so" in name):
                continue
            with open(path, "rb") as f:
                if f.read(4) != b"\x7fELF":
                    continue
            relative = os.path.relpath(path, build)
            ldd = subprocess.run(["ldd", path], capture_output=True, text=True).stdout
            for lib in re.findall(r"=> (/\S+)|^\s+(/\S+)", ldd, re.M):
                lib = os.path.normpath(lib[0] or lib[1])
                if not lib.startswith(os.path.abspath(build) + "/"):
                    used.setdefault((lib, is_test_only(relative)), relative)
    return used


def shown(path):
    return os.path.relpath(path, ROOT) if os.path.abspath(path).startswith(ROOT + "/") else path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--lists-from", default=os.path.join(ROOT, "scripts", "fractograph.sh"))
    parser.add_argument("--without", nargs="*", default=[], help="leave these packages out of the lists")
    args = parser.parse_args()

    global FUZZ_BUILD
    cache = os.path.join(args.build, "CMakeCache.txt")
    FUZZ_BUILD = os.path.exists(cache) and "FG_FUZZ:BOOL=ON" in open(cache, encoding="utf-8").read()
    packages, provides = read_dpkg_status()
    base = minimal_debian(packages)
    demo_lists = listed_packages(args.lists_from, "demo") - set(args.without)
    test_lists = listed_packages(args.lists_from, "test") - set(args.without)
    allowed = {False: closure(base | demo_lists, packages, provides),
               True: closure(base | test_lists, packages, provides)}

    used = headers_by_user(args.build)
    used.update(libraries_by_user(args.build))
    owner = owners({path for path, _ in used})

    problems = {}
    for (path, test_only), user in sorted(used.items()):
        package = owner.get(path)
        if package is None:
            problems.setdefault(("(no Debian package)", test_only), (path, user))
        elif package not in allowed[test_only]:
            problems.setdefault((package, test_only), (path, user))
    # A package the tools need is reported for the demo, even when a test needs it too.
    problems = {k: v for k, v in problems.items() if not (k[1] and (k[0], False) in problems)}

    files = len({path for path, _ in used})
    if not problems:
        print(f"check_packages: all {files} system headers and libraries the build uses come from packages "
              f"that '{shown(args.lists_from)} demo|test' install")
        return 0
    print(f"check_packages: {len(problems)} package(s) used by the build but not installed by "
          f"{shown(args.lists_from)}'s lists nor by what they depend on:")
    for (package, test_only), (path, user) in sorted(problems.items()):
        command = "test" if test_only else "demo"
        print(f"  {package}: {path}, used by {user}; add it to the packages of '{command}'")
    return 1


if __name__ == "__main__":
    sys.exit(main())
