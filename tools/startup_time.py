#!/usr/bin/env python3
"""Where a small render's process time goes, and what it costs in all: the measurement behind
docs/STARTUP.md.

    tools/startup_time.py [--vkrt build/vkrt] [--runs 5]

For each command it prints the median whole-process CPU time (user + sys, from os.wait4's rusage,
children included) over --runs runs, the wall time, and how many shared libraries the process
mapped (LD_DEBUG=files, one extra run): `vkrt --help`, a 1x1 render on the CPU device and on the
GPU (lavapipe here) to PNG, and the same CPU render to EXR (which loads the OpenImageIO module).
The GPU render's own phases (Vulkan instance and device, kernel compile, first dispatch) are what
vkrt prints with -v after the render line, where it prints them.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def run_once(argv, env=None):
    start = time.monotonic()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    stderr = proc.stderr.read().decode(errors="replace")  # to EOF first: LD_DEBUG fills a pipe
    proc.stderr.close()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{' '.join(argv)} failed:\n{stderr}")
    return usage.ru_utime + usage.ru_stime, wall, stderr


def libraries(argv):
    env = dict(os.environ, LD_DEBUG="files")
    _, _, stderr = run_once(argv, env)
    return len(set(re.findall(r"file=(\S+)\s+\[0\];  generating link map", stderr)))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--vkrt", default=str(ROOT / "build" / "vkrt"))
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    scene = str(ROOT / "scenes" / "soft_shadows.xml")
    with tempfile.TemporaryDirectory() as out:
        tiny = ["-w", "1", "-h", "1", "-r", "1", "-q"]
        commands = [
            ("vkrt --help", [args.vkrt, "--help"]),
            ("1x1 render, --device cpu, PNG", [args.vkrt, scene, *tiny, "--device", "cpu", "-o", f"{out}/x.png"]),
            ("1x1 render, --device gpu, PNG", [args.vkrt, scene, *tiny, "--device", "gpu", "-o", f"{out}/x.png"]),
            ("1x1 render, --device cpu, EXR", [args.vkrt, scene, *tiny, "--device", "cpu", "-o", f"{out}/x.exr"]),
        ]
        print(f"# median of {args.runs} runs; CPU = user + sys of the whole process")
        print("| command | CPU (s) | wall (s) | shared libraries |")
        print("|---|---:|---:|---:|")
        for name, argv in commands:
            runs = [run_once(argv) for _ in range(args.runs)]
            cpu = statistics.median(r[0] for r in runs)
            wall = statistics.median(r[1] for r in runs)
            print(f"| {name} | {cpu:.3f} | {wall:.3f} | {libraries(argv)} |", flush=True)


if __name__ == "__main__":
    main()
