#!/usr/bin/env python3
"""GPU and CPU render times of the course scenes that use path tracing (issue 20): every scene with
a Diffuse surface, a shape emitter or an environment map, from ../shared/scenes (the 13 Diffuse
JSON files, the two emitter files, the environment-map files and the two XML files that name the
2018 reef faces). The figures docs/BENCHMARKS.md quotes.

    tools/path_tracing_timings.py [--vkrt build/vkrt] [--shared ../shared] [--size 160 120] [--rpp 16]
                                  [--runs 3] [--estimator mis]

Runs alternate GPU and CPU (the machine's speed drifts); each line gives the median render time
vkrt prints per device, their ratio and the kernel variant the GPU ran (its summary line), which
must name the features the scene has ('diffuse', 'emitters', 'environment').
"""
import argparse
import json
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def path_traced_features(scene):
    """The path-tracing features a scene file uses (read from its text, not through vkrt)."""
    text = scene.read_text()
    features = []
    if scene.suffix == ".json":
        if re.search(r'"_?type"\s*:\s*"Diffuse"', text):
            features.append("diffuse")
        if re.search(r'"_?type"\s*:\s*"shape"', text):
            features.append("emitters")
        if re.search(r'"envMap(Prefix|VertCross)"\s*:\s*"[^"]+"', text):
            features.append("environment")
    else:
        uncommented = re.sub(r"<!--.*?-->", "", text, flags=re.S)
        if re.search(r'envmapPrefix|envMapPrefix', uncommented, flags=re.I):
            features.append("environment")
    return features


def render(vkrt, scene, device, size, rpp, estimator):
    with tempfile.TemporaryDirectory() as out:
        cmd = [vkrt, str(scene), "-w", str(size[0]), "-h", str(size[1]), "-r", str(rpp), "--device", device,
               "--estimator", estimator, "-o", str(Path(out) / "x.png")]
        run = subprocess.run(cmd, capture_output=True, text=True)
        text = run.stdout + run.stderr
        if run.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed:\n{run.stderr}")
        found = re.search(r"render ([0-9.]+)s", text)
        if not found:
            sys.exit(f"no render time in the output of {' '.join(cmd)}:\n{text}")
        kernel = re.search(r"\[kernel: ([^;\]]*)", text)
        return float(found.group(1)), (kernel.group(1) if kernel else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--vkrt", default=str(ROOT / "build" / "vkrt"))
    parser.add_argument("--shared", default=str(ROOT.parent / "shared"))
    parser.add_argument("--size", type=int, nargs=2, default=[160, 120], metavar=("W", "H"))
    parser.add_argument("--rpp", type=int, default=16)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--estimator", default="mis")
    args = parser.parse_args()

    shared = Path(args.shared) / "scenes"
    scenes = sorted((shared / "json").glob("*.json")) + sorted((shared / "upstream").glob("*.xml"))
    chosen = [(s, path_traced_features(s)) for s in scenes]
    chosen = [(s, f) for s, f in chosen if f]
    if not chosen:
        sys.exit(f"no path-traced scene under {shared}")
    print(f"{args.size[0]}x{args.size[1]}, {args.rpp} rpp, estimator {args.estimator}, median of {args.runs} "
          f"alternating runs per device")
    print(f"| scene | features | GPU s | CPU s | GPU/CPU | kernel |")
    print(f"|---|---|---:|---:|---:|---|")
    for scene, features in chosen:
        times = {"gpu": [], "cpu": []}
        kernel = ""
        for _ in range(args.runs):
            for device in ("gpu", "cpu"):
                seconds, summary = render(args.vkrt, scene, device, args.size, args.rpp, args.estimator)
                times[device].append(seconds)
                if device == "gpu":
                    kernel = summary
        missing = [f for f in features if f not in kernel.split()]
        if missing:
            sys.exit(f"{scene.name}: the GPU kernel lacks {missing}: [{kernel}]")
        gpu, cpu = statistics.median(times["gpu"]), statistics.median(times["cpu"])
        print(f"| {scene.name} | {' '.join(features)} | {gpu:.3f} | {cpu:.3f} | {gpu / cpu:.2f} | {kernel} |",
              flush=True)


if __name__ == "__main__":
    main()
