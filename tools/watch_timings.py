#!/usr/bin/env python3
"""What one edit costs in `vkrt --watch`: the measurement behind docs/WATCH.md.

    tools/watch_timings.py [--vkrt build/vkrt] [--scene scenes/glass_and_instances.xml]
                           [--size 320x240] [--rpp 16] [--edits 5]

Starts one `vkrt --watch` on the GPU (lavapipe here) with --shader-dir pointing at a copy of
shaders/, then alternates a scene edit (the file rewritten) and a shader edit (a comment appended to
render.comp), --edits of each, and prints vkrt's own figures for each render (load, kernel compile,
pipeline, render, total), the median per kind of edit, and the wall time from the edit to the new
image on disk (which includes the 50 ms that ends a save). For comparison it also times a one-shot
`vkrt` of the same scene (a new process: instance, device, kernel, pipeline, load, render).
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
LINE = re.compile(r"\] render (\d+): .*?: (?:kernel ([\d.]+)s, )?(?:load ([\d.]+)s, )?pipeline ([\d.]+)s, render ([\d.]+)s, total ([\d.]+)s")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--vkrt", default=str(ROOT / "build" / "vkrt"))
    ap.add_argument("--scene", default=str(ROOT / "scenes" / "glass_and_instances.xml"))
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--rpp", type=int, default=16)
    ap.add_argument("--edits", type=int, default=5)
    a = ap.parse_args()
    w, h = a.size.split("x")
    work = Path(tempfile.mkdtemp(prefix="vkrt_watch_"))
    shaders = work / "shaders"
    shutil.copytree(ROOT / "shaders", shaders)
    # The scene beside its own assets: copied into the scene's folder would need them too, so edit
    # it where it is through a copy made next to it.
    scene = Path(a.scene).resolve()
    edited = scene.with_name(".watch_timings_" + scene.name)
    shutil.copyfile(scene, edited)
    out = work / "out.png"
    args = ["-w", w, "-h", h, "-r", str(a.rpp), "--device", "gpu", "--shader-dir", str(shaders)]
    try:
        start = time.monotonic()
        subprocess.run([a.vkrt, str(edited), *args, "-q", "-o", str(work / "once.png")], check=True)
        once = time.monotonic() - start
        log = []
        proc = subprocess.Popen([a.vkrt, "--watch", str(edited), *args, "-o", str(out)], stderr=subprocess.PIPE, text=True)
        threading.Thread(target=lambda: [log.append(line) for line in proc.stderr], daemon=True).start()

        def wait_render(n):
            while True:
                for line in list(log):
                    m = LINE.search(line)
                    if m and int(m.group(1)) == n:
                        return m
                if proc.poll() is not None:
                    raise SystemExit("vkrt --watch exited:\n" + "".join(log))
                time.sleep(0.005)

        wait_render(1)
        text, comp = edited.read_text(), (shaders / "render.comp").read_text()
        rows = {"scene": [], "shader": []}
        n = 1
        for i in range(a.edits):
            for kind in ("scene", "shader"):
                n += 1
                time.sleep(0.3)
                t0 = time.monotonic()
                if kind == "scene":
                    edited.write_text(text + "<!-- edit %d -->\n" % i)
                else:
                    (shaders / "render.comp").write_text(comp + "// edit %d\n" % i)
                m = wait_render(n)
                wall = time.monotonic() - t0
                kernel, load, pipeline, render, total = (float(g) if g else 0.0 for g in m.groups()[1:])
                rows[kind].append((kernel, load, pipeline, render, total, wall))
        proc.terminate()
        proc.wait()
    finally:
        edited.unlink(missing_ok=True)
        shutil.rmtree(work, ignore_errors=True)
    print("%s %sx%s, %d rpp, lavapipe; medians of %d edits (seconds)" % (Path(a.scene).name, w, h, a.rpp, a.edits))
    print("%-8s %8s %8s %8s %8s %8s %14s" % ("edit", "kernel", "load", "pipeline", "render", "total", "edit->image"))
    for kind, values in rows.items():
        med = [statistics.median(v[k] for v in values) for k in range(6)]
        print("%-8s %8.3f %8.3f %8.3f %8.3f %8.3f %14.3f" % (kind, *med))
    print("one-shot vkrt process (wall): %.3f s" % once)


if __name__ == "__main__":
    main()
