#!/usr/bin/env python3
"""Time to reach an error, two vkrt builds (or two option sets) against one converged reference:
the measurement behind issue 37's "time to reach a given RMSE" figures.

    tools/time_to_error.py --a /tmp/base/vkrt --b build/vkrt [--pairs 2] [--size 96] [--rpp 16,64] \\
        [--seeds 2] [--estimator mis] [--sampler sobol] [--device cpu] [--reference-rpp 2048] SCENE...
    # one build, two option sets
    tools/time_to_error.py --a build/vkrt --a-args "--light-samples 1" --b build/vkrt --b-args "--light-samples 4" SCENE

Each side runs `vkrt sweep` (one sampler, one estimator, the given rpps and seeds) on every scene,
A and B alternating (this machine's speed drifts), with one --cache directory, so both measure
their RMSE against the same reference (`vkrt sweep` renders it once, with the build that runs
first: A; its own noise, from its two halves, is taken out of every RMSE, docs/SAMPLING.md).

An unbiased renderer's squared error falls as 1/time, so a render of t seconds with error e needs
t (e / E)^2 seconds to reach error E: the product t e^2 is a render's cost per unit of accuracy,
and B/A's ratio of it is B's speed-up at any target error (> 1: B reaches it sooner). Each line
gives, per scene, each side's median of t e^2 over its renders (every rpp, seed and pair), B's
speed-up, and each side's RMSE at the highest rpp (a biased side shows as an RMSE that stops
falling with rpp; compare the rows of the largest rpps).
"""
import argparse
import csv
import shlex
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path


def sweep(vkrt, extra, scene, args, cache, out):
    command = [vkrt, "sweep", str(scene), "--out", str(out), "--cache", str(cache), "--device", args.device,
               "--samplers", args.sampler, "--estimators", args.estimator, "--rpp", args.rpp,
               "--seeds", str(args.seeds), "--reference-rpp", str(args.reference_rpp),
               "--reference-device", args.device, "-w", str(args.size), "-h", str(args.size)] + shlex.split(extra)
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"time_to_error: {shlex.join(command)} failed ({done.returncode}):\n{done.stderr.strip()[-2000:]}")
    with open(Path(out) / "sweep.csv") as f:
        return [(int(r["rpp"]), float(r["time_s"]), float(r["rmse"])) for r in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenes", nargs="+", type=Path)
    parser.add_argument("--a", required=True, help="the baseline vkrt")
    parser.add_argument("--b", required=True, help="the vkrt measured against it")
    parser.add_argument("--a-args", default="", help="extra options for A's sweeps")
    parser.add_argument("--b-args", default="", help="extra options for B's sweeps")
    parser.add_argument("--pairs", type=int, default=2, help="alternating A, B rounds")
    parser.add_argument("--size", type=int, default=96, help="image width and height")
    parser.add_argument("--rpp", default="16,64", help="rays per pixel, comma-separated")
    parser.add_argument("--seeds", type=int, default=2)
    parser.add_argument("--estimator", default="mis")
    parser.add_argument("--sampler", default="sobol")
    parser.add_argument("--device", default="cpu", choices=["cpu", "gpu"])
    parser.add_argument("--reference-rpp", type=int, default=2048)
    parser.add_argument("--cache", help="reference cache (default: a temporary directory)")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        cache = Path(args.cache) if args.cache else Path(tmp) / "cache"
        print(f"# {args.device}, {args.size}x{args.size}, rpp {args.rpp} x {args.seeds} seeds, {args.sampler}, "
              f"{args.estimator}, reference {args.reference_rpp} rpp, {args.pairs} pairs")
        print(f"# A: {args.a} {args.a_args}\n# B: {args.b} {args.b_args}")
        print("scene | A median t*e^2 | B median t*e^2 | B speed-up | A rmse | B rmse (highest rpp)")
        for scene in args.scenes:
            rows = {"a": [], "b": []}
            for pair in range(args.pairs):
                for side, vkrt, extra in (("a", args.a, args.a_args), ("b", args.b, args.b_args)):
                    rows[side] += sweep(vkrt, extra, scene, args, cache, Path(tmp) / f"{side}{pair}")
            cost = {s: statistics.median(t * e * e for _, t, e in rows[s]) for s in rows}
            top = max(r for r, _, _ in rows["a"])
            final = {s: statistics.median(e for r, _, e in rows[s] if r == top) for s in rows}
            print(f"{scene.name} | {cost['a']:.4g} | {cost['b']:.4g} | {cost['a'] / cost['b']:.2f} | "
                  f"{final['a']:.4g} | {final['b']:.4g}", flush=True)


if __name__ == "__main__":
    main()
