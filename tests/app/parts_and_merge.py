#!/usr/bin/env python3
"""vkrt --part I/N and vkrt merge (issue 23), end to end: on each device, a scene rendered as 1, 2
and 3 parts (given to merge in shuffled order) gives the single process's PNG and EXR byte for byte;
merge refuses a missing part, a part given twice, parts of different renders (another rpp, another
device), a file that is no part, and --part refuses an output that is not EXR.

    parts_and_merge.py VKRT SCENE WORKDIR
"""
import filecmp
import os
import subprocess
import sys


def run(argv, expect_ok=True):
    p = subprocess.run(argv, capture_output=True, text=True)
    if (p.returncode == 0) != expect_ok:
        sys.exit("%s: exit %d (expected %s):\n%s" % (" ".join(argv), p.returncode, "0" if expect_ok else "non-zero", p.stderr))
    return p.stderr


def main():
    vkrt, scene, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    size = ["-w", "64", "-h", "45", "-r", "4", "-q"]
    out = lambda name: os.path.join(work, name)
    for device in ("gpu", "cpu"):
        for ext in ("png", "exr"):
            run([vkrt, scene, *size, "--device", device, "-o", out("whole_%s.%s" % (device, ext))])
        for parts in (1, 2, 3):
            files = [out("part%d_of%d_%s.exr" % (i, parts, device)) for i in range(1, parts + 1)]
            for i, f in enumerate(files, 1):
                run([vkrt, scene, *size, "--device", device, "--part", "%d/%d" % (i, parts), "-o", f])
            shuffled = files[::-1]
            for ext in ("png", "exr"):
                merged = out("merged%d_%s.%s" % (parts, device, ext))
                run([vkrt, "merge", *shuffled, "-q", "-o", merged])
                if not filecmp.cmp(merged, out("whole_%s.%s" % (device, ext)), shallow=False):
                    sys.exit("%s: %d parts merged differ from the whole %s" % (device, parts, ext))
        print("%s: 1, 2 and 3 parts merge into the whole image's PNG and EXR bytes" % device)

    p = lambda i, n, d="gpu": out("part%d_of%d_%s.exr" % (i, n, d))
    checks = [
        ([p(1, 3), p(3, 3)], "part(s) 2 of 3 missing"),
        ([p(1, 2), p(1, 2), p(2, 2)], "is given twice"),
        ([p(1, 2, "gpu"), p(2, 2, "cpu")], "a part of another render"),
        ([p(1, 2), out("whole_gpu.exr")], "not a part of a render"),
    ]
    run([vkrt, scene, "-w", "64", "-h", "45", "-r", "8", "-q", "--device", "gpu", "--part", "2/2", "-o", out("other_rpp.exr")])
    checks.append(([p(1, 2), out("other_rpp.exr")], "rpp 8"))
    for inputs, expected in checks:
        err = run([vkrt, "merge", *inputs, "-o", out("refused.png")], expect_ok=False)
        if expected not in err:
            sys.exit("merge %s: expected '%s' in:\n%s" % (" ".join(inputs), expected, err))
    err = run([vkrt, scene, *size, "--part", "1/2", "-o", out("part.png")], expect_ok=False)
    if "a part is written as EXR" not in err:
        sys.exit("--part with a PNG output: " + err)
    err = run([vkrt, scene, *size, "--part", "3/2", "-o", out("part.exr")], expect_ok=False)
    if "expected I/N with 1 <= I <= N" not in err:
        sys.exit("--part 3/2: " + err)
    print("merge refuses missing, repeated, foreign and non-part files")


if __name__ == "__main__":
    main()
