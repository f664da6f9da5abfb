#!/usr/bin/env python3
"""Which up vector a camera looking straight down needs: the evidence table of docs/RENDERING.md §1.

    tools/camera_up_evidence.py --vkrt build/vkrt --scenes ../shared/scenes/json [--size 64]

The only renders of the course's straight-down scenes (StanfordBunny.json, kv_StanfordDragon.json,
kv_buddha.json, all "position 0 5 0, viewDir 0 -1 0") are the 2022 student renders in
github.com/kvatsaas/renderer output/ (StanfordBunny.png, StanfordDragon.png, buddha.png). They are
not in shared/, so they are stood in for by the camera of the code that made them, written out
here from that repository: renderer/CoordSys.cpp builds the basis with up (0,1,0) and switches to
(1,0,0) when the gaze is parallel to it; renderer/PerspectiveCamera.h maps pixel (i, j) to
u = l + (r-l)(i+0.5)/nx, v = b + (t-b)(j+0.5)/ny; renderer/Framebuffer.cpp writes column j to PNG row
ny-1-j. Every mesh triangle is projected through that camera and the pixels whose centres it
covers form the student's silhouette; each candidate rule's vkrt render (one ray through each pixel
centre; background pixels out, the rest in) is scored against it by intersection over union: 1 is
the student's image, a rotated one scores low.

The second column says where each mesh's top (the end of its long axis where its cross-sections
narrow: the bunny's ears at +x, the buddha's head at +z) lands in the image, measured from the
render's silhouette: the side of the image holding the silhouette pixels that project from the
top's vertices.

Pure Python (no numpy): reads the binary PPMs vkrt writes.
"""
import argparse
import os
import subprocess
import sys
import tempfile

SCENES = {  # scene -> (mesh, the mesh's top end as (axis, sign), from its cross-sections)
    "StanfordBunny.json": ("objFiles/bunny.obj", (0, +1)),
    "kv_StanfordDragon.json": ("objFiles/dragon.obj", (0, +1)),
    "kv_buddha.json": ("objFiles/buddha.obj", (2, +1)),
}
EYE, GAZE, FOCAL, PLANE = (0.0, 5.0, 0.0), (0.0, -1.0, 0.0), 1.0, 0.5  # the three scenes' camera
CANDIDATES = [  # label, vkrt arguments
    ("vkrt before issue 39 (fallback 0,0,-1)", ["--up", "0,0,-1"]),
    ("vkrt default now (fallback 1,0,0)", []),
    ("fallback 0,0,1 (the 2026 cheat sheet)", ["--up", "0,0,1"]),
    ("fallback -1,0,0", ["--up", "-1,0,0"]),
]


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = dot(a, a) ** 0.5
    return tuple(x / n for x in a)


def student_basis(gaze):
    """renderer/CoordSys.cpp of kvatsaas/renderer: tempUp (0,1,0), (1,0,0) when the gaze is parallel."""
    w = unit(tuple(-x for x in gaze))
    up = (0.0, 1.0, 0.0)
    if abs(dot(unit(gaze), up)) == 1.0:
        up = (1.0, 0.0, 0.0)
    u = unit(cross(up, w))
    return u, unit(cross(w, u)), w


def project(p, n):
    """Continuous pixel position (x right, y down from the top edge) of point p through the
    student's camera, or None behind it."""
    u, v, w = student_basis(GAZE)
    d = sub(p, EYE)
    depth = -dot(d, w)
    if depth <= 0:
        return None
    a, b = dot(d, u) * FOCAL / depth, dot(d, v) * FOCAL / depth
    # square image: the plane's height is its width; j counts up from the bottom row, written to
    # PNG row ny-1-j, so the top edge is b = +PLANE/2
    return (a + PLANE / 2) / PLANE * n, (PLANE / 2 - b) / PLANE * n


def read_mesh(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append(tuple(map(float, line.split()[1:4])))
            elif line.startswith("f "):
                ids = [int(t.split("/")[0]) - 1 for t in line.split()[1:]]
                faces += [(ids[0], ids[k], ids[k + 1]) for k in range(1, len(ids) - 1)]
    return vertices, faces


def silhouette(vertices, faces, n):
    """The pixels whose centres the student's camera sees a triangle through."""
    xy = [project(p, n) for p in vertices]
    mask = set()
    for a, b, c in faces:
        if not (xy[a] and xy[b] and xy[c]):
            continue
        (ax, ay), (bx, by), (cx, cy) = xy[a], xy[b], xy[c]
        area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if area == 0:
            continue
        for j in range(max(0, int(min(ay, by, cy) - 0.5)), min(n, int(max(ay, by, cy) + 0.5) + 1)):
            for i in range(max(0, int(min(ax, bx, cx) - 0.5)), min(n, int(max(ax, bx, cx) + 0.5) + 1)):
                px, py = i + 0.5, j + 0.5
                e0 = ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / area
                e1 = ((cx - bx) * (py - by) - (cy - by) * (px - bx)) / area
                e2 = ((ax - cx) * (py - cy) - (ay - cy) * (px - cx)) / area
                if e0 >= 0 and e1 >= 0 and e2 >= 0:
                    mask.add((i, j))
    return mask


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # P6, width, height, maxval (vkrt writes no comments)
        while data[pos:pos + 1].isspace():
            pos += 1
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    width, height = int(fields[1]), int(fields[2])
    pixels = data[pos + 1:]
    return width, height, [tuple(pixels[3 * k:3 * k + 3]) for k in range(width * height)]


def render_mask(vkrt, scene, args, n, work):
    out = os.path.join(work, "render.ppm")
    cmd = [vkrt, scene, "--device", "cpu", "-w", str(n), "-h", str(n), "-r", "1", "--sampler", "regular",
           "--bg", "1,0,1", "-q", "-o", out] + args
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    width, height, pixels = read_ppm(out)
    return {(k % width, k // width) for k, p in enumerate(pixels) if p != (255, 0, 255)}


def side_of(points, n):
    """Which side of the image the centroid of `points` lies towards."""
    cx = sum(p[0] for p in points) / len(points) - (n - 1) / 2
    cy = sum(p[1] for p in points) / len(points) - (n - 1) / 2
    if abs(cy) >= abs(cx):
        return "top" if cy < 0 else "bottom"
    return "left" if cx < 0 else "right"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--vkrt", default="build/vkrt")
    parser.add_argument("--scenes", default="../shared/scenes/json")
    parser.add_argument("--size", type=int, default=64)
    o = parser.parse_args()
    n = o.size
    print("| scene | rule | IoU with the student's camera | mesh top appears at |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for scene, (mesh, (axis, sign)) in SCENES.items():
            vertices, faces = read_mesh(os.path.join(o.scenes, mesh))
            student = silhouette(vertices, faces, n)
            top_value = max(sign * v[axis] for v in vertices)
            top = [v for v in vertices if sign * v[axis] > top_value - 0.3]  # the last 15% of a [-1, 1] axis
            top_pixels = [(int(x), int(y)) for x, y in filter(None, (project(p, n) for p in top))]
            for label, args in CANDIDATES:
                mask = render_mask(o.vkrt, os.path.join(o.scenes, scene), args, n, work)
                iou = len(mask & student) / max(1, len(mask | student))
                side = top_side(student, mask, top_pixels, n)
                print(f"| {scene} | {label} | {iou:.3f} | {side} |")
    return 0


def rotate(points, quarter_turns, n):
    out = set(points)
    for _ in range(quarter_turns):
        out = {(n - 1 - y, x) for x, y in out}  # 90 degrees clockwise in image coordinates
    return out


def top_side(student, mask, top, n):
    """The candidate's image is the student's turned by a multiple of 90 degrees (every candidate
    up lies in the image plane); find the turn that matches best and carry the top's side along."""
    best = max(range(4), key=lambda k: len(rotate(student, k, n) & mask) / max(1, len(rotate(student, k, n) | mask)))
    return side_of(list(rotate(top, best, n)), n)


if __name__ == "__main__":
    sys.exit(main())
