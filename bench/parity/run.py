"""Cost of a filter run through pymeshlab 2025.7 against the same run through MeshLab
2020.09's meshlabserver (issue: performance parity, at most 10% above): Automatic Reduction of
bunny00 without remeshing (the two vcglib versions remesh differently) and without time limit,
load and save included, the two alternated A B A B ... so drifts of the machine's speed hit both.
Prints each run's wall and CPU (user + sys) seconds, the medians and the ratios
pymeshlab / meshlabserver.

    .deps/venv/bin/python bench/parity/run.py [runs=3] [mesh]
"""
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def timed(cmd, env):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stdout[-3000:]))
    return wall, cpu, p.stdout


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    mesh = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, ".deps", "data", "meshes", "bunny00.off")
    tmp = tempfile.mkdtemp()
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_RUNTIME_DIR=tmp)
    a = [os.path.join(here, ".deps", "venv", "bin", "python"), os.path.join(here, "bench", "parity", "reduce_pymeshlab.py"),
         mesh, os.path.join(tmp, "a.ply")]
    # meshlabserver needs an X display: one Xvfb for all runs, started before timing.
    xvfb = subprocess.Popen(["Xvfb", ":87", "-screen", "0", "1024x768x24"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    time.sleep(1)
    env_b = dict(env, DISPLAY=":87")
    env_b.pop("QT_QPA_PLATFORM")
    b = [os.path.join(here, "build", "stage", "bin", "meshlabserver"), "-i", mesh, "-o", os.path.join(tmp, "b.ply"),
         "-m", "vc", "vq", "-s", os.path.join(here, "bench", "parity", "reduce_bunny.mlx")]
    rows = {"pymeshlab": [], "meshlabserver": []}
    try:
        for i in range(runs):
            for name, cmd, e in (("pymeshlab", a, env), ("meshlabserver", b, env_b)):
                wall, cpu, text = timed(cmd, e)
                rows[name].append((wall, cpu))
                line = [l for l in text.splitlines() if "pymeshlab:" in l or "Automatic reduction:" in l]
                print("run %d %-13s wall %7.2f s  cpu %7.2f s  %s" % (i + 1, name, wall, cpu, line[-1] if line else ""))
                sys.stdout.flush()
    finally:
        xvfb.terminate()
    med = {k: (statistics.median(w for w, _ in v), statistics.median(c for _, c in v)) for k, v in rows.items()}
    for k, (w, c) in med.items():
        print("median %-13s wall %7.2f s  cpu %7.2f s" % (k, w, c))
    print("ratio pymeshlab / meshlabserver: wall %.3f, cpu %.3f (medians of %d runs)"
          % (med["pymeshlab"][0] / med["meshlabserver"][0], med["pymeshlab"][1] / med["meshlabserver"][1], runs))
    pairs = [pa[1] / pb[1] for pa, pb in zip(rows["pymeshlab"], rows["meshlabserver"])]
    print("cpu ratio per pair: " + " ".join("%.3f" % r for r in pairs))


if __name__ == "__main__":
    main()
