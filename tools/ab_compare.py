#!/usr/bin/env python3
"""Alternating A/B runs of two vkrt builds, or of one build with two kernel directories: the
measurement behind the before -> after figures in docs/lab/ and the commit messages.

    # renders: the GPU render time vkrt prints, per scene (--device cpu: the CPU reference's)
    tools/ab_compare.py renders --a /tmp/old/build/vkrt --b build/vkrt [--pairs 4] [--size 400] [--rpp 16] \\
        ../shared/scenes/upstream/pt_objects.xml ../shared/scenes/upstream/threeEggs.xml
    # the same binary, two copies of shaders/ (edit B, keep A): --a-args / --b-args go to each run
    tools/ab_compare.py renders --a build/vkrt --a-args "--shader-dir /tmp/A" \\
        --b build/vkrt --b-args "--shader-dir shaders" SCENE.xml...
    # rays: vkrt-bench gpu rays, GPU/CPU ratios measured inside each process
    tools/ab_compare.py rays --a /tmp/old/build/vkrt-bench --b build/vkrt-bench [--pairs 5] sphere:64 MESH.obj...

Why alternate: this machine's speed drifts by 10-50% over minutes (other tenants), so A's runs and
B's runs must interleave (A B A B ...) for their medians to be comparable. Renders report seconds
(lower is better); rays report GPU/CPU throughput ratios from one process each (higher is better),
which also cancels drift within a run. Every line gives each side's median and range and B/A of
the medians; only a difference well outside both ranges is worth quoting.
"""
import argparse
import re
import shlex
import statistics
import subprocess
import sys
import tempfile

# The GPU summary puts the kernel's compile before the render ("compile 0.412s, render ...").
RENDER_TIME = re.compile(r": (?:compile [0-9.]+s, )?render ([0-9.]+)s, total")
RAY_RATIOS = re.compile(r"ratio_gpu_over_cpu rounds \d+ primary ([0-9.]+) shadow ([0-9.]+) diffuse ([0-9.]+)")
MISMATCHES = re.compile(r"gpu_cpu_mismatches primary (\d+) of \d+ shadow (\d+) of \d+ diffuse (\d+) of \d+")


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"ab_compare: {shlex.join(command)} failed ({done.returncode}):\n{done.stderr.strip()[-2000:]}")
    return done.stdout + done.stderr


def render_seconds(binary, extra, scene, args, output):
    # --device gpu by default: auto renders on the CPU reference where lavapipe is the only device.
    command = [binary, scene, "-w", str(args.size), "-h", str(args.size), "-r", str(args.rpp), "--device", args.device,
               "-o", output] + extra
    text = run(command)
    m = RENDER_TIME.search(text)
    if not m:
        sys.exit(f"ab_compare: no 'render N.NNNs' in the output of {shlex.join(command)}")
    return [float(m.group(1))]


def ray_ratios(binary, extra, source, args, _output):
    command = [binary, "gpu", "rays", source] + [str(v) for v in args.rays_size] + ["--rounds", str(args.rounds), "--no-peer"] + extra
    text = run(command)
    m, w = RAY_RATIOS.search(text), MISMATCHES.search(text)
    if not m or not w:
        sys.exit(f"ab_compare: no ratio_gpu_over_cpu / gpu_cpu_mismatches line from {shlex.join(command)}")
    if any(int(x) for x in w.groups()):
        print(f"  note: {shlex.join(command)}: GPU and CPU disagree ({w.group(0)})")
    return [float(x) for x in m.groups()]


def summary(values):
    return f"{statistics.median(values):.3f} ({min(values):.3f}-{max(values):.3f})"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["renders", "rays"])
    parser.add_argument("inputs", nargs="+", help="scene files (renders) or vkrt-bench sources (rays)")
    parser.add_argument("--a", required=True, help="baseline binary (vkrt for renders, vkrt-bench for rays)")
    parser.add_argument("--b", required=True, help="binary under test")
    parser.add_argument("--a-args", default="", help="extra arguments for A's runs, e.g. \"--shader-dir /tmp/A\"")
    parser.add_argument("--b-args", default="", help="extra arguments for B's runs")
    parser.add_argument("--pairs", type=int, default=4, help="A/B pairs per input (default 4)")
    parser.add_argument("--size", type=int, default=400, help="renders: image width and height (default 400)")
    parser.add_argument("--rpp", type=int, default=16, help="renders: samples per pixel (default 16)")
    parser.add_argument("--device", choices=["gpu", "cpu"], default="gpu",
                        help="renders: the device rendering (default gpu; cpu times the CPU reference)")
    parser.add_argument("--rounds", type=int, default=4, help="rays: timed rounds per run (default 4)")
    parser.add_argument("--rays-size", type=int, nargs=3, default=[512, 512, 4], metavar=("W", "H", "SPP"),
                        help="rays: the camera's image and samples per pixel (default 512 512 4, the peer's)")
    args = parser.parse_args()
    if args.pairs < 1:
        parser.error("--pairs must be at least 1")

    measure = render_seconds if args.mode == "renders" else ray_ratios
    names = ["seconds"] if args.mode == "renders" else ["primary", "shadow", "diffuse"]
    better = "lower" if args.mode == "renders" else "higher"
    sides = [("A", args.a, shlex.split(args.a_args)), ("B", args.b, shlex.split(args.b_args))]
    print(f"# {args.mode}: {args.pairs} alternating pairs per input; A = {shlex.join([args.a] + sides[0][2])}, "
          f"B = {shlex.join([args.b] + sides[1][2])}; {better} is better; median (range), B/A of the medians")
    with tempfile.TemporaryDirectory() as scratch:
        for source in args.inputs:
            results = {"A": [], "B": []}
            for _ in range(args.pairs):
                for label, binary, extra in sides:
                    results[label].append(measure(binary, extra, source, args, f"{scratch}/{label}.png"))
            for k, name in enumerate(names):
                a = [r[k] for r in results["A"]]
                b = [r[k] for r in results["B"]]
                base = statistics.median(a)
                ratio = f"{statistics.median(b) / base:.3f}" if base > 0 else "n/a (A's median is 0: give the runs more work)"
                print(f"{source} {name}: A {summary(a)}  B {summary(b)}  B/A {ratio}")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
