#!/usr/bin/env python3
"""Measures distributed rendering on this machine (docs/distributed.md, docs/performance.md).

1. Strong scaling: the built-in Cornell box on 1 rank of 1 thread against 2 ranks of 1 thread each (whole
   mpirun runs, median of --runs).
2. A simulated 64-rank job: each of the 64 shares of one render (`illum render --share R/64`) runs as its
   own process, one by one, giving each rank's start-up (process start to the first sample: wall time less
   render time) and its render time; the reduction of the film onto rank 0 is measured on 2 real ranks and
   scaled to the log2(64) = 6 steps of a binomial-tree reduction.

Usage: scripts/mpi_scaling.py [--build build] [--spp 16] [--res 1024x1024] ...
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import tempfile
import time


def wall(cmd, cwd):
    t0 = time.perf_counter()
    subprocess.run(cmd, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--res", default="1024x1024")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--shares", type=int, default=64)
    ap.add_argument("--share-spp", type=int, default=4096)
    ap.add_argument("--share-res", default="1024x768")
    ap.add_argument("--share-threads", type=int, default=2)
    ap.add_argument("--every", type=int, default=1,
                    help="time every k-th share only (the shares' work differs by at most one sample a pixel)")
    a = ap.parse_args()
    illum = os.path.realpath(os.path.join(a.build, "illum"))
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with tempfile.TemporaryDirectory() as d:
        print(f"== strong scaling: built-in Cornell box, {a.res}, {a.spp} spp, 1 thread per rank, "
              f"median of {a.runs}")
        t = {}
        for ranks in (1, 2):
            cmd = [a.mpirun, "-np", str(ranks), illum, "render", "--resolution", a.res, "--spp", str(a.spp),
                   "--threads", "1", "-q", "-o", "out.exr"]
            t[ranks] = statistics.median(wall(cmd, d) for _ in range(a.runs))
            print(f"{ranks} rank(s): {t[ranks]:.2f} s")
        print(f"speed-up: {t[1] / t[2]:.3f}x")

        print(f"== simulated {a.shares}-rank job: {a.share_res}, {a.share_spp} spp, {a.share_threads} threads "
              f"per rank, each share timed as its own process"
              + (f" (every {a.every}th)" if a.every > 1 else ""))
        walls, renders, setups = [], [], []
        for r in range(0, a.shares, a.every):
            cmd = [illum, "render", "--resolution", a.share_res, "--spp", str(a.share_spp), "--threads",
                   str(a.share_threads), "-q", "--share", f"{r}/{a.shares}", "-o", "share.pfm", "--stats",
                   "share.json"]
            walls.append(wall(cmd, d))
            s = json.load(open(os.path.join(d, "share.json")))
            renders.append(s["seconds"])
            setups.append(s["setup_seconds"])
        # The reduction: 2 real ranks of balanced, tiny work; their communication time is one tree step.
        subprocess.run([a.mpirun, "-np", "2", illum, "render", "--resolution", a.share_res, "--spp", "2",
                        "--threads", "1", "-q", "-o", "red.exr", "--stats", "red.json"], cwd=d, check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        step = json.load(open(os.path.join(d, "red.json")))["communication_seconds"]
        steps = math.ceil(math.log2(a.shares))
        # The launcher's own start-up (mpirun and MPI_Init): a tiny render under mpirun less the same alone.
        tiny = [illum, "render", "--resolution", "8x8", "--spp", "1", "--threads", "1", "-q", "-o", "t.exr"]
        launch = max(0.0, statistics.median(wall([a.mpirun, "-np", "2"] + tiny, d) for _ in range(5)) -
                     statistics.median(wall(tiny, d) for _ in range(5)))
        w, rnd, st = statistics.mean(walls), statistics.mean(renders), statistics.mean(setups)
        overhead = (w - rnd) + launch + steps * step
        print(f"per rank: wall {w:.3f} s, render {rnd:.3f} s (slowest {max(renders):.3f} s), scene setup {st:.3f} s")
        print(f"launcher start-up (mpirun, MPI_Init): {launch:.3f} s")
        print(f"reduction: {step:.4f} s a tree step (2 ranks), {steps * step:.4f} s for {steps} steps")
        print(f"start-up + reduction: {overhead:.3f} s = {100 * overhead / rnd:.2f}% of the render "
              f"(process {w - rnd:.3f} s, launcher {launch:.3f} s, reduction {steps * step:.3f} s)")


if __name__ == "__main__":
    main()
