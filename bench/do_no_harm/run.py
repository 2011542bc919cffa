#!/usr/bin/env python3
"""Runs holefill binaries over the do-no-harm set with default options and prints, per mesh and
per kind, what each did: loops found, holes kept although their patch cuts the mesh (the
report's count), holes left open (the report's count and the open loops of
the output by position, from holefill-check-fill), intersecting pairs (patch/mesh and
patch/patch, by the checker's exact test), the harm the checker found otherwise (input faces or
vertices missing, non-manifold edges or vertices), the exit code and the user time.

usage: run.py CHECKER SETDIR OUTDIR NAME=BINARY [NAME=BINARY ...]
Writes OUTDIR/NAME/MESH.obj and .json; prints Markdown tables; --reasons also lists each hole
left open with the reason the last binary's report gives."""

import json
import os
import subprocess
import sys
import time

KINDS = {"k1": "1 touching duplicates", "k2": "2 open surfaces", "k3": "3 every cap cuts",
         "k4": "4 doubtful islands"}


def run_one(binary, checker, mesh, out_mesh, report):
    start = os.times()
    wall = time.time()
    rc = subprocess.run([binary, "fill", mesh, "-o", out_mesh, "--report", report, "-q"],
                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    end = os.times()
    row = {"rc": rc, "user": end.children_user - start.children_user, "wall": time.time() - wall}
    if not os.path.exists(out_mesh) or rc not in (0, 1, 5):
        return row
    with open(report) as f:
        data = json.load(f)
    row["loops"] = data["before"]["holes"]
    row["open"] = data["after"]["holes"]
    row["cutting"] = sum(1 for h in data["holes"] if h["filled"] and h.get("self_intersections", 0) > 0)
    row["reasons"] = [(h["hole"], h.get("failure", "")) for h in data["holes"] if not h["filled"]]
    check = subprocess.run([checker, mesh, out_mesh], capture_output=True, text=True)
    row.update({k: int(v) for k, v in (w.split("=") for w in check.stdout.split())})
    return row


def cell(row):
    if "loops" not in row:
        return "crash rc %d" % row["rc"]
    harm = row["faces_changed"] + row["vertices_moved"] + row["nonmanifold_edges"] + row["nonmanifold_vertices"]
    text = "%d/%d open (%d by pos.), %d+%d pairs, rc %d" % (
        row["open"], row["loops"], row["boundary_loops"], row["patch_mesh_pairs"], row["patch_patch_pairs"], row["rc"])
    if harm:
        text += ", changed %d/%d nm %d/%d" % (row["faces_changed"], row["vertices_moved"],
                                             row["nonmanifold_edges"], row["nonmanifold_vertices"])
    return text


def main():
    args = [a for a in sys.argv[1:] if a != "--reasons"]
    if len(args) < 4:
        sys.exit(__doc__)
    checker, setdir, outdir = args[:3]
    binaries = [a.split("=", 1) for a in args[3:]]
    meshes = sorted(f for f in os.listdir(setdir) if f.endswith(".obj"))
    results = {}
    for name, binary in binaries:
        os.makedirs(os.path.join(outdir, name), exist_ok=True)
    for mesh in meshes:  # the binaries alternate mesh by mesh, so that a slow minute hits both
        for name, binary in binaries:
            base = os.path.join(outdir, name, mesh[:-4])
            results[(name, mesh)] = run_one(binary, checker, os.path.join(setdir, mesh), base + ".out.obj",
                                            base + ".json")
    names = [n for n, _ in binaries]
    print("| mesh | " + " | ".join(names) + " |")
    print("|---|" + "---|" * len(names))
    for mesh in meshes:
        print("| %s | %s |" % (mesh[:-4], " | ".join(cell(results[(n, mesh)]) for n in names)))
    print()
    print("| kind | binary | meshes | loops | closed | left open | open loops by position "
          "| holes kept cutting (report) | patch/mesh pairs | patch/patch pairs | meshes with pairs | input faces lost / vertices moved "
          "| non-manifold edges / vertices | exit codes (meshes) | user s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for kind, title in KINDS.items():
        for name in names:
            rows = [results[(name, m)] for m in meshes if m.startswith(kind)]
            ok = [r for r in rows if "loops" in r]
            total = lambda key: sum(r[key] for r in ok)
            codes = {}
            for r in rows:
                codes[r["rc"]] = codes.get(r["rc"], 0) + 1
            print("| %s | %s | %d | %d | %d | %d | %d | %d | %d | %d | %d | %d / %d | %d / %d | %s | %.2f |" % (
                title, name, len(rows), total("loops"), total("loops") - total("open"), total("open"),
                total("boundary_loops"), total("cutting"), total("patch_mesh_pairs"), total("patch_patch_pairs"),
                sum(1 for r in ok if r["patch_mesh_pairs"] + r["patch_patch_pairs"]),
                total("faces_changed"), total("vertices_moved"), total("nonmanifold_edges"),
                total("nonmanifold_vertices"), ", ".join("%d (%d)" % (c, n) for c, n in sorted(codes.items())),
                sum(r["user"] for r in rows)))
    if "--reasons" in sys.argv:
        name = names[-1]
        print()
        print("Holes %s leaves open, with the report's reason:" % name)
        print()
        for mesh in meshes:
            for hole, reason in results[(name, mesh)].get("reasons", []):
                print("- %s, hole %d: %s" % (mesh[:-4], hole, reason))


if __name__ == "__main__":
    main()
