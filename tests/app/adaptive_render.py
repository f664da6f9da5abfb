#!/usr/bin/env python3
"""vkrt --target-error / --time (issue 36), end to end: the image, the error map and the sample-count
map are byte-identical across runs and thread counts; the summary says why the rounds stopped;
--progressive writes each round; the GPU device and bad values are refused with their reason.

    adaptive_render.py VKRT SCENE WORKDIR
"""
import filecmp
import os
import subprocess
import sys


def run(argv, expect_code=0):
    p = subprocess.run(argv, capture_output=True, text=True)
    if p.returncode != expect_code:
        sys.exit("%s: exit %d (expected %d):\n%s" % (" ".join(argv), p.returncode, expect_code, p.stderr))
    return p.stderr


def main():
    vkrt, scene, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    out = lambda name: os.path.join(work, name)
    base = [vkrt, scene, "-w", "48", "-h", "40", "--target-error", "0.01", "--device", "cpu"]
    outputs = {}
    for name, threads in (("a", "2"), ("b", "2"), ("c", "1")):
        files = [out("%s.exr" % name), out("%s_error.exr" % name), out("%s_samples.png" % name), out("%s_samples.exr" % name)]
        err = run(base + ["-n", threads, "-o", files[0], "--error-map", files[1], "--sample-map", files[2]])
        run(base + ["-n", threads, "-q", "-o", out("%s_again.png" % name), "--sample-map", files[3]])
        if "(target met) after" not in err or "adaptive sobol2 on cpu" not in err:
            sys.exit("summary without the stop reason or the sampler:\n" + err)
        outputs[name] = files
    for i in range(4):
        if not (filecmp.cmp(outputs["a"][i], outputs["b"][i], shallow=False) and
                filecmp.cmp(outputs["a"][i], outputs["c"][i], shallow=False)):
            sys.exit("%s differs between runs or thread counts" % os.path.basename(outputs["a"][i]))
    print("image, error map and sample maps identical across runs and threads")

    err = run(base + ["--progressive", "2", "-o", out("progressive.png")])
    rounds = [line for line in err.splitlines() if line.startswith("round ") and line.endswith("progressive.png")]
    if len(rounds) < 2:
        sys.exit("--progressive did not write each round:\n" + err)
    print("progressive writes each of %d rounds" % len(rounds))

    refusals = [
        ([vkrt, scene, "--target-error", "0.01", "--device", "gpu", "--sampler", "jittered"], 2, "adaptive sampling needs sobol2"),
        ([vkrt, scene, "--target-error", "-1"], 2, "--target-error -1: must be a relative RMSE of at least 0.0001"),
        ([vkrt, scene, "--time", "0"], 2, "--time 0: must be a number of seconds above 0"),
        ([vkrt, scene, "--time", "1", "--sampler", "sobol"], 2, "adaptive sampling needs sobol2"),
        ([vkrt, scene, "--time", "1", "-o", out("same.png"), "--sample-map", out("same.png")], 1, "is also the image (-o)"),
    ]
    for argv, code, text in refusals:
        err = run(argv, code)
        if text not in err:
            sys.exit("%s: the message does not say '%s':\n%s" % (" ".join(argv[1:]), text, err))
    print("adaptive refusals name their reason")


if __name__ == "__main__":
    main()
