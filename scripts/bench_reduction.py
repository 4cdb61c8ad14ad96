#!/usr/bin/python3
"""Benchmark of "Irregular Vertices: Automatic Reduction" against its peer, MeshLab's own
"Remeshing: Isotropic Explicit Remeshing", in one go on this machine, through the staged
meshlabserver: each corpus model is remeshed by the peer to the edge length that gives about N
vertices, and our filter runs on the same input with the same edge length (its optional first
step is the same vcglib remesher) and then reduces. Every measure is taken here, independently
of both filters: valences and angles with numpy from the written faces, the symmetric
Hausdorff distance to the input with numpy/scipy (mlpy.hausdorff), wall-clock time of the
meshlabserver run (loading and saving included).

    /usr/bin/python3 scripts/bench_reduction.py [--vertices 20000] [--out out/bench_reduction.md] [model ...]
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "meshlabserver"))
from mlpy import (DATA, AbsPerc, Enum, Filter, diagonal, edge_length_for, euler_characteristic,  # noqa: E402
                  hausdorff, irregular_mask, read_mesh, run, shape_measures, valences)

MODELS = ["bunny00.off", "armadillo.off", "fandisk.off", "camel.off", "homer.off", "elephant.off", "knot1.off"]


def peer(diag, length):
    return Filter("Remeshing: Isotropic Explicit Remeshing", Iterations=10, Adaptive=False, SelectedOnly=False,
                  TargetLen=AbsPerc(length, 0.0, diag), FeatureDeg=30.0, CheckSurfDist=False,
                  MaxSurfDist=AbsPerc(length / 10, 0.0, diag), SplitFlag=True, CollapseFlag=True, SwapFlag=True,
                  SmoothFlag=True, ReprojectFlag=True)


def ours(diag, length, budget):
    return Filter("Irregular Vertices: Automatic Reduction", remeshEdgeLength=AbsPerc(length, 0.0, diag),
                  targetCount=0, hausdorffBudget=budget, minAngle=30.0, maxTravel=12,
                  protect=Enum(0, ["Nothing", "Selected region untouched", "Selected irregular vertices kept"]),
                  relaxation=Enum(0, ["Local", "Global"]), timeLimit=0.0, colorize=True)


def measure(src, path, seconds):
    m = read_mesh(path)
    val = valences(m)
    irr = irregular_mask(m)
    hist = {int(k): int(c) for k, c in zip(*np.unique(val[val > 0], return_counts=True))}
    ab, ba = hausdorff(src, m)
    diag = diagonal(src)
    s = shape_measures(m)
    return {"V": int((val > 0).sum()), "chi": euler_characteristic(m), "irr": int(irr.sum()),
            "share": 100.0 * irr.sum() / max(1, (val > 0).sum()), "hist": hist, "H": 100 * max(ab, ba) / diag,
            "minang": s["min_angle"], "below30": 100 * s["share_below_30"], "time": seconds}


def row(model, who, r):
    hist = " ".join("v%d:%d" % kv for kv in sorted(r["hist"].items()) if kv[0] != 6)
    return "| %s | %s | %d | %d | %d | %.2f%% | %s | %.3f%% | %.1f | %.2f%% | %.1f s |" % (
        model, who, r["V"], r["chi"], r["irr"], r["share"], hist, r["H"], r["minang"], r["below30"], r["time"])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--vertices", type=int, default=20000)
    ap.add_argument("--budget", type=float, default=0.5, help="Hausdorff budget of our filter, %% of the diagonal")
    ap.add_argument("--out", default=os.path.join(HERE, "..", "out", "bench_reduction.md"))
    ap.add_argument("models", nargs="*", default=MODELS)
    a = ap.parse_args()
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    work = os.path.join(os.path.dirname(os.path.abspath(a.out)), "bench_reduction")
    os.makedirs(work, exist_ok=True)
    lines = ["| model | method | V | chi | irregular | share | irregular valences | Hausdorff (% diag) | "
             "min angle | < 30 deg | time |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    print("\n".join(lines), flush=True)
    for name in a.models:
        srcpath = os.path.join(DATA, name)
        src = read_mesh(srcpath)
        diag = diagonal(src)
        length = edge_length_for(src, a.vertices)
        base = os.path.splitext(name)[0]
        for who, flt in [("MeshLab isotropic remeshing", peer(diag, length)),
                         ("filter_irregular (remesh + reduce)", ours(diag, length, a.budget))]:
            out = os.path.join(work, "%s_%s.ply" % (base, "peer" if who.startswith("MeshLab") else "ours"))
            t = time.time()
            r = run(srcpath, out, [flt], timeout=1800)
            seconds = time.time() - t
            if not r.ok:
                line = "| %s | %s | failed (exit %d) |" % (base, who, r.returncode)
            else:
                line = row(base, who, measure(src, out, seconds))
            lines.append(line)
            print(line, flush=True)
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", a.out)


if __name__ == "__main__":
    main()
