#!/usr/bin/env python3
"""GPU and CPU render times of Cook's distribution effects, each on and off on the same scene:
the figures docs/RENDERING.md quotes for depth of field, glossy translucency and motion blur.

    tools/effect_timings.py [--vkrt build/vkrt] [--size 320 240] [--rpp 64] [--runs 5]

"Off" is the same scene with the effect removed, so the kernel is the one a scene without it gets:
depth of field with --aperture 0 (the pinhole), translucency with every Dielectric's roughness set to
0 in a copy of the scene, motion blur with the <transformEnd> elements deleted from a copy. Runs
alternate on and off (the machine's speed drifts); each line gives the median render time vkrt
prints and the on/off ratio, per device.
"""
import argparse
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def render_seconds(vkrt, scene, device, size, rpp, extra, feature, present):
    """The render time vkrt reports; on the GPU the kernel summary must (not) name `feature`."""
    with tempfile.TemporaryDirectory() as out:
        cmd = [vkrt, str(scene), "-w", str(size[0]), "-h", str(size[1]), "-r", str(rpp), "--device", device,
               "-o", str(Path(out) / "x.png")] + extra
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed:\n{run.stderr}")
        found = re.search(r"render ([0-9.]+)s", run.stdout + run.stderr)
        if not found:
            sys.exit(f"no render time in the output of {' '.join(cmd)}:\n{run.stdout}{run.stderr}")
        kernel = re.search(r"\[(?:general )?kernel[^]]*\]", run.stdout + run.stderr)
        if device == "gpu" and (kernel is None or (f" {feature} " in kernel.group(0) + " ") != present):
            sys.exit(f"{' '.join(cmd)}: the kernel should {'' if present else 'not '}have '{feature}': "
                     f"{kernel.group(0) if kernel else run.stdout}")
        return float(found.group(1))


def copy_without(scene, pattern, replacement, made):
    """The scene's text with `pattern` replaced, written beside the original (so its relative paths
    still hold) under a hidden name; the path is added to `made` for removal."""
    text = re.sub(pattern, replacement, scene.read_text(), flags=re.S)
    path = scene.parent / f".{scene.stem}.effect_off{scene.suffix}"
    path.write_text(text)
    made.append(path)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--vkrt", default=str(ROOT / "build" / "vkrt"))
    parser.add_argument("--size", type=int, nargs=2, default=[320, 240], metavar=("W", "H"))
    parser.add_argument("--rpp", type=int, default=64)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()

    scenes = ROOT / "scenes"
    made = []
    try:
        cases = [
            ("depth of field", "thin-lens", scenes / "depth_of_field.xml", [], scenes / "depth_of_field.xml", ["--aperture", "0"]),
            ("glossy translucency", "translucency", scenes / "translucency.xml", [],
             copy_without(scenes / "translucency.xml", r"<roughness>[^<]*</roughness>", "<roughness>0</roughness>", made), []),
            ("motion blur", "motion", scenes / "motion_blur.xml", [],
             copy_without(scenes / "motion_blur.xml", r"<transformEnd\b[^>]*>(?:(?!<transformEnd).)*?</transformEnd>", "", made), []),
        ]
        print(f"# {args.size[0]}x{args.size[1]}, {args.rpp} rpp, median of {args.runs} alternating runs; "
              "seconds of the render vkrt reports")
        print("| effect | device | on (s) | off (s) | on/off |")
        print("|---|---|---:|---:|---:|")
        for name, feature, on_scene, on_args, off_scene, off_args in cases:
            for device in ("gpu", "cpu"):
                on, off = [], []
                for _ in range(args.runs):
                    on.append(render_seconds(args.vkrt, on_scene, device, args.size, args.rpp, on_args, feature, True))
                    off.append(render_seconds(args.vkrt, off_scene, device, args.size, args.rpp, off_args, feature, False))
                a, b = statistics.median(on), statistics.median(off)
                ratio = f"{a / b:.2f}" if b > 0 else "-"  # a tiny render can report 0.000 s
                print(f"| {name} | {device} | {a:.3f} | {b:.3f} | {ratio} |", flush=True)
    finally:
        for path in made:
            path.unlink(missing_ok=True)


if __name__ == "__main__":
    main()
