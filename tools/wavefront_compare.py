#!/usr/bin/env python3
"""The wavefront renderer against the megakernel on scene files: renders each with
`vkrt --device gpu --gpu-kernel megakernel` and `--gpu-kernel wavefront` (same size, samples and
seed) into OpenEXR files and prints, per scene, how many of the float values are identical and the
largest difference. On lavapipe every course file renders bit for bit the same (docs/BENCHMARKS.md).

    tools/wavefront_compare.py [--vkrt build/vkrt] [-w 64] [-H 48] [-r 8] SCENE_OR_DIR...

Exit status 1 when any scene differs or fails to render.
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_peer import read_exr  # noqa: E402  (the repository's own OpenEXR reader)


def scene_files(inputs):
    for item in inputs:
        if os.path.isdir(item):
            for name in sorted(os.listdir(item)):
                if name.endswith((".xml", ".json")):
                    yield os.path.join(item, name)
        else:
            yield item


def render(vkrt, scene, kernel, out, args):
    cmd = [vkrt, scene, "--device", "gpu", "--gpu-kernel", kernel, "-w", str(args.w), "-h", str(args.H),
           "-r", str(args.r), "-q", "-o", out]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{kernel}: exit {done.returncode}: {done.stderr.strip().splitlines()[-1:]}")
    _, _, planes = read_exr(out)
    return [v for plane in planes for v in plane]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("inputs", nargs="+")
    parser.add_argument("--vkrt", default="build/vkrt")
    parser.add_argument("-w", type=int, default=64)
    parser.add_argument("-H", type=int, default=48)
    parser.add_argument("-r", type=int, default=8)
    args = parser.parse_args()
    failed = 0
    same_scenes = 0
    with tempfile.TemporaryDirectory() as tmp:
        files = list(scene_files(args.inputs))
        for scene in files:
            name = os.path.basename(scene)
            try:
                a = render(args.vkrt, scene, "megakernel", os.path.join(tmp, "m.exr"), args)
                b = render(args.vkrt, scene, "wavefront", os.path.join(tmp, "w.exr"), args)
            except RuntimeError as e:
                print(f"{name}: {e}")
                failed += 1
                continue
            same = sum(1 for x, y in zip(a, b) if x == y)
            diff = max(abs(x - y) for x, y in zip(a, b))
            print(f"{name}: {same} of {len(a)} values identical, max |difference| {diff:.3g}", flush=True)
            if same == len(a):
                same_scenes += 1
            else:
                failed += 1
    print(f"{same_scenes} of {len(files)} scenes bit for bit the same")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
