#!/usr/bin/env python3
"""Peer benchmark of vkrt's CPU renderer against Blender's Cycles (issue 37).

Builds matched scenes in Cycles from vkrt JSON scenes (perspective camera; triangle, sphere and box
shapes; Diffuse shaders; shape emitters; a constant background colour), renders both with the same
settings and prints, per scene:
  (a) agreement: the image mean per channel of each renderer at a high sample count, with its
      standard error over independent seeds, and the ratio vkrt / Cycles;
  (b) time to error: render time and RMSE against a high-spp Cycles reference at 16/64/256 samples
      per pixel for both, and the time vkrt needs to reach Cycles' 256-spp error (t * e^2 scaling),
      as a ratio to Cycles' time.
Standard library only. See docs/PEER_CYCLES.md.

  tools/cycles_peer.py                       # both built-in scenes, 96x96, -k 4
  tools/cycles_peer.py --install             # first apt-get install blender (Debian's 3.4.1)
  tools/cycles_peer.py --depth 1             # direct light only: vkrt -k 1 against Cycles bounces 0
"""
import argparse
import array
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# --------------------------------------------------------------------------------------------
# Images: a tiny OpenEXR reader (scan lines; NONE, ZIPS, ZIP; HALF and FLOAT) -> (w, h, [r, g, b])


def _exr_attrs(data):
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError("not an OpenEXR file")
    flags = data[5]
    if data[4] != 2 or flags & 0x02:
        raise ValueError("only single-part scan-line OpenEXR files are supported")
    pos = 8
    attrs = {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        pos = end + 1
        end = data.index(b"\0", pos)
        typ = data[pos:end].decode()
        pos = end + 1
        (size,) = struct.unpack_from("<i", data, pos)
        pos += 4
        attrs[name] = (typ, data[pos:pos + size])
        pos += size
    return attrs, pos + 1


def read_exr(path):
    with open(path, "rb") as f:
        data = f.read()
    attrs, pos = _exr_attrs(data)
    chl = attrs["channels"][1]
    channels = []
    p = 0
    while chl[p] != 0:
        end = chl.index(b"\0", p)
        name = chl[p:end].decode()
        ptype, _lin, _xs, _ys = struct.unpack_from("<iBxxxii", chl, end + 1)
        channels.append((name, ptype))
        p = end + 1 + 16
    comp = attrs["compression"][1][0]
    if comp not in (0, 2, 3):
        raise ValueError("%s: EXR compression %d not supported (NONE, ZIPS, ZIP are)" % (path, comp))
    xmin, ymin, xmax, ymax = struct.unpack("<iiii", attrs["dataWindow"][1])
    w, h = xmax - xmin + 1, ymax - ymin + 1
    lpc = 16 if comp == 3 else 1
    nchunks = (h + lpc - 1) // lpc
    offsets = struct.unpack_from("<%dQ" % nchunks, data, pos)
    size_of = {0: 4, 1: 2, 2: 4}
    planes = {name: array.array("f", bytes(4 * w * h)) for name, _ in channels}
    for off in offsets:
        y, n = struct.unpack_from("<ii", data, off)
        raw = data[off + 8:off + 8 + n]
        lines = min(lpc, ymax + 1 - y)
        expect = lines * w * sum(size_of[t] for _, t in channels)
        if comp != 0 and n < expect:
            tmp = bytearray(zlib.decompress(raw))
            for i in range(1, len(tmp)):  # undo the predictor
                tmp[i] = (tmp[i - 1] + tmp[i] - 128) & 0xFF
            half = (len(tmp) + 1) // 2
            out = bytearray(len(tmp))
            out[0::2] = tmp[:half]
            out[1::2] = tmp[half:]
            raw = bytes(out)
        q = 0
        for line in range(lines):
            row = (y - ymin) + line
            for name, t in channels:
                nb = size_of[t] * w
                chunk = raw[q:q + nb]
                q += nb
                if t == 2:
                    vals = array.array("f")
                    vals.frombytes(chunk)
                elif t == 1:
                    vals = struct.unpack("<%de" % w, chunk)
                else:
                    vals = struct.unpack("<%dI" % w, chunk)
                planes[name][row * w:(row + 1) * w] = array.array("f", vals)
    try:
        rgb = [planes[c] for c in ("R", "G", "B")]
    except KeyError:
        raise ValueError("%s: no R, G, B channels (has %s)" % (path, [c for c, _ in channels]))
    return w, h, rgb


def exr_time_attr(path, name):
    """A string attribute of Cycles' EXR metadata holding a time, 'MM:SS.cc' or 'HH:MM:SS.cc', in s."""
    with open(path, "rb") as f:
        attrs, _ = _exr_attrs(f.read())
    if name not in attrs:
        return float("nan")
    text = attrs[name][1].decode()
    secs = 0.0
    for part in text.split(":"):
        secs = secs * 60 + float(part)
    return secs


def write_png(path, w, h, rgb, scale=1.0):
    """Linear -> sRGB-ish 8-bit PNG (for looking at, not for measuring)."""
    def enc(x):
        x = max(0.0, min(1.0, x * scale))
        x = 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
        return int(x * 255 + 0.5)
    rows = bytearray()
    for j in range(h):
        rows.append(0)
        for i in range(w):
            k = j * w + i
            rows += bytes((enc(rgb[0][k]), enc(rgb[1][k]), enc(rgb[2][k])))

    def chunk(tag, body):
        c = struct.pack(">I", len(body)) + tag + body
        return c + struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


# --------------------------------------------------------------------------------------------
# Statistics


def channel_means(rgb):
    return [sum(p) / len(p) for p in rgb]


def mean_images(imgs):
    n = len(imgs)
    return [array.array("f", [sum(v) / n for v in zip(*[im[c] for im in imgs])]) for c in range(3)]


def pixel_var_of_mean(imgs):
    """Per-pixel variance of the mean of independent images (sample variance / n), averaged over
    pixels and channels: what the mean image's own noise adds to a squared error against it."""
    n = len(imgs)
    if n < 2:
        return 0.0
    tot = 0.0
    cnt = 0
    for c in range(3):
        for vals in zip(*[im[c] for im in imgs]):
            m = sum(vals) / n
            tot += sum((v - m) ** 2 for v in vals) / (n - 1) / n
            cnt += 1
    return tot / cnt


def mse(a, b):
    tot = 0.0
    cnt = 0
    for c in range(3):
        for x, y in zip(a[c], b[c]):
            tot += (x - y) ** 2
        cnt += len(a[c])
    return tot / cnt


def mean_se(values):
    n = len(values)
    m = sum(values) / n
    if n < 2:
        return m, float("nan")
    var = sum((v - m) ** 2 for v in values) / (n - 1)
    return m, math.sqrt(var / n)


# --------------------------------------------------------------------------------------------
# Scenes


def vec(s):
    if isinstance(s, (int, float)):
        return [float(s)] * 3
    v = [float(x) for x in str(s).replace(",", " ").split()]
    if len(v) != 3:
        raise ValueError("not a 3-vector: %r" % (s,))
    return v


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    l = math.sqrt(sum(x * x for x in a))
    return [x / l for x in a]


def get(d, key, default=None):
    """The course's keys come with and without a leading underscore; the plain one wins."""
    if key in d:
        return d[key]
    return d.get("_" + key, default)


def sphere_mesh(center, r, nseg=128, nring=64):
    verts = [[center[0], center[1] + r, center[2]]]
    for j in range(1, nring):
        th = math.pi * j / nring
        for i in range(nseg):
            ph = 2 * math.pi * i / nseg
            verts.append([center[0] + r * math.sin(th) * math.cos(ph), center[1] + r * math.cos(th),
                          center[2] + r * math.sin(th) * math.sin(ph)])
    verts.append([center[0], center[1] - r, center[2]])
    faces = []
    for i in range(nseg):
        faces.append([0, 1 + (i + 1) % nseg, 1 + i])
    for j in range(nring - 2):
        a0 = 1 + j * nseg
        b0 = a0 + nseg
        for i in range(nseg):
            i1 = (i + 1) % nseg
            faces.append([a0 + i, a0 + i1, b0 + i1, b0 + i])
    last = len(verts) - 1
    base = 1 + (nring - 2) * nseg
    for i in range(nseg):
        faces.append([base + i, base + (i + 1) % nseg, last])
    return verts, faces


def box_mesh(lo, hi):
    verts = [[(hi if i & 1 else lo)[0], (hi if i & 2 else lo)[1], (hi if i & 4 else lo)[2]]
             for i in range(8)]
    faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return verts, faces


class Untranslatable(Exception):
    pass


def translate(scene_path, cam_index=0, nseg=128):
    """vkrt JSON scene -> the Cycles job description the Blender script builds (or Untranslatable)."""
    with open(scene_path) as f:
        doc = json.load(f)
    sc = doc.get("scene", doc)
    for key in ("texture", "instance"):
        if sc.get(key):
            raise Untranslatable("'%s' is not translated" % key)
    params = sc.get("sceneParameters") or {}
    if isinstance(params, list):
        params = params[0] if params else {}
    if get(params, "envMapPrefix") or get(params, "envMapVertCross"):
        raise Untranslatable("environment maps are not translated")
    bg = get(sc, "bgColor") or get(params, "bgColor") or "0 0 0"
    cams = sc["camera"]
    cams = cams if isinstance(cams, list) else [cams]
    cam = cams[cam_index]
    if get(cam, "type", "perspective") != "perspective":
        raise Untranslatable("camera type %s" % get(cam, "type"))
    if float(cam.get("aperture", 0) or 0) > 0 and float(cam.get("focusDistance", 0) or 0) > 0:
        raise Untranslatable("depth of field is not translated")
    pos = vec(cam["position"])
    gaze = sub(vec(cam["lookatPoint"]), pos) if "lookatPoint" in cam else vec(cam["viewDir"])
    gn = norm(gaze)
    up = vec(cam["up"]) if "up" in cam else ([1.0, 0.0, 0.0] if abs(gn[1]) > 0.9999 else [0.0, 1.0, 0.0])
    w = [-x for x in gn]
    u = norm(cross(up, w))
    v = cross(w, u)
    f = float(cam.get("focalLength", 1.0))
    ipw = float(cam.get("imagePlaneWidth", 0.5))
    # Blender's camera looks down its local -Z with local +Y up: local X, Y, Z = u, v, w.
    matrix = [[u[0], v[0], w[0], pos[0]], [u[1], v[1], w[1], pos[1]],
              [u[2], v[2], w[2], pos[2]], [0.0, 0.0, 0.0, 1.0]]
    shaders = {}
    for s in sc.get("shader", []) or []:
        shaders[get(s, "name")] = s

    def material(shape):
        ref = shape.get("shader")
        if ref is None:
            raise Untranslatable("shape %s has no shader" % get(shape, "name"))
        s = shaders.get(get(ref, "ref")) if get(ref, "ref") is not None else ref
        if s is None:
            raise Untranslatable("shader %r not found" % (get(ref, "ref"),))
        if get(s, "type") != "Diffuse":
            raise Untranslatable("shader type %s (only Diffuse is translated)" % get(s, "type"))
        if get(s, "tex") or s.get("texture"):
            raise Untranslatable("textured shader")
        return {"type": "diffuse", "color": vec(s.get("diffuse", "1 1 1"))}

    def geometry(shape):
        t = get(shape, "type")
        if shape.get("xform") or shape.get("transform"):
            raise Untranslatable("transformed shape")
        if t == "triangle":
            return [vec(shape["v0"]), vec(shape["v1"]), vec(shape["v2"])], [[0, 1, 2]], False
        if t == "sphere":
            verts, faces = sphere_mesh(vec(shape.get("center", "0 0 0")), float(shape.get("radius", 1.0)),
                                       nseg, max(2, nseg // 2))
            return verts, faces, True
        if t == "box":
            verts, faces = box_mesh(vec(shape.get("minPt", "-1 -1 -1")), vec(shape.get("maxPt", "1 1 1")))
            return verts, faces, False
        raise Untranslatable("shape type %s" % t)

    objects = []
    for i, shape in enumerate(sc.get("shape", []) or []):
        verts, faces, smooth = geometry(shape)
        objects.append({"name": "s%d_%s" % (i, get(shape, "name", "")), "verts": verts, "faces": faces,
                        "smooth": smooth, "material": material(shape)})
    for i, light in enumerate(sc.get("light", []) or []):
        if get(light, "type") != "shape":
            raise Untranslatable("light type %s (only shape emitters are translated)" % get(light, "type"))
        verts, faces, smooth = geometry(light["shape"])
        objects.append({"name": "e%d" % i, "verts": verts, "faces": faces, "smooth": smooth,
                        "material": {"type": "emission", "color": vec(light["intensity"])}})
    return {"camera": {"matrix": matrix, "angle": 2 * math.atan(ipw / (2 * f))},
            "background": vec(bg), "objects": objects}


def write_sphere_scene(path):
    """The second matched scene: an open Diffuse floor with three spheres and a box, lit by a
    sphere emitter, black background, camera given by lookatPoint."""
    def tri(name, a, b, c, ref):
        return {"v0": a, "v1": b, "v2": c, "shader": {"_ref": ref}, "_name": name, "_type": "triangle"}
    scene = {"scene": {
        "camera": [{"position": "0 1.6 4.5", "lookatPoint": "0 0.5 0", "focalLength": 1.0,
                    "imagePlaneWidth": 1.0, "_name": "main", "_type": "perspective"}],
        "light": [{"_type": "shape", "intensity": "60 54 48",
                   "shape": {"center": "-1.0 3.0 2.5", "radius": 0.3, "_name": "lamp", "_type": "sphere"}}],
        "shader": [{"diffuse": "0.7 0.7 0.7", "_name": "grey", "_type": "Diffuse"},
                   {"diffuse": "0.8 0.3 0.2", "_name": "orange", "_type": "Diffuse"},
                   {"diffuse": "0.2 0.4 0.8", "_name": "blue", "_type": "Diffuse"},
                   {"diffuse": "0.9 0.9 0.85", "_name": "white", "_type": "Diffuse"}],
        "shape": [tri("floor0", "-3 0 -3", "3 0 3", "3 0 -3", "grey"),
                  tri("floor1", "-3 0 -3", "-3 0 3", "3 0 3", "grey"),
                  {"center": "-0.9 0.5 0", "radius": 0.5, "shader": {"_ref": "orange"}, "_name": "ball0", "_type": "sphere"},
                  {"center": "0.4 0.35 0.6", "radius": 0.35, "shader": {"_ref": "white"}, "_name": "ball1", "_type": "sphere"},
                  {"center": "1.1 0.6 -0.8", "radius": 0.6, "shader": {"_ref": "blue"}, "_name": "ball2", "_type": "sphere"},
                  {"minPt": "-0.3 0 -1.2", "maxPt": "0.3 0.8 -0.6", "shader": {"_ref": "white"}, "_name": "block", "_type": "box"}],
        "bgColor": "0 0 0"}}
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)


# --------------------------------------------------------------------------------------------
# Cycles (runs inside Blender: blender -b --factory-startup --python-exit-code 1 --python S -- JOB)

BLENDER_SCRIPT = r'''
import bpy, json, sys, time
job = json.load(open(sys.argv[sys.argv.index("--") + 1]))
for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.cameras, bpy.data.lights, bpy.data.materials):
    for item in list(coll):
        coll.remove(item)
scene = bpy.context.scene
r = scene.render
r.engine = "CYCLES"
r.resolution_x, r.resolution_y, r.resolution_percentage = job["width"], job["height"], 100
r.pixel_aspect_x = r.pixel_aspect_y = 1.0
r.threads_mode, r.threads = "FIXED", job["threads"]
r.use_persistent_data = False
r.film_transparent = False
c = scene.cycles
c.device = "CPU"
c.feature_set = "SUPPORTED"
c.use_denoising = False
c.use_adaptive_sampling = False
c.use_guiding = False
c.light_sampling_threshold = 0.0
c.sample_clamp_direct = 0.0
c.sample_clamp_indirect = 0.0
c.blur_glossy = 0.0
c.caustics_reflective = True
c.caustics_refractive = True
c.use_fast_gi = False
c.min_light_bounces = 0
c.min_transparent_bounces = 0
b = job["bounces"]
c.max_bounces = b
c.diffuse_bounces = b
c.glossy_bounces = b
c.transmission_bounces = b
c.volume_bounces = 0
c.transparent_max_bounces = b
c.pixel_filter_type = "BOX"
c.filter_width = 1.0
c.film_exposure = 1.0
c.use_animated_seed = False
c.sample_offset = 0
c.use_layer_samples = "IGNORE"
vs = scene.view_settings
scene.display_settings.display_device = "sRGB"
vs.view_transform = "Standard"
vs.look = "None"
vs.exposure = 0.0
vs.gamma = 1.0
vs.use_curve_mapping = False
im = r.image_settings
im.file_format = "OPEN_EXR"
im.color_mode = "RGB"
im.color_depth = "32"
im.exr_codec = "ZIP"
world = bpy.data.worlds.new("peer_world")
world.use_nodes = True
bgn = world.node_tree.nodes["Background"]
bgn.inputs["Color"].default_value = tuple(job["background"]) + (1.0,)
bgn.inputs["Strength"].default_value = 1.0
scene.world = world
cam_data = bpy.data.cameras.new("peer_cam")
cam_data.type = "PERSP"
cam_data.sensor_fit = "HORIZONTAL"
cam_data.angle = job["camera"]["angle"]
cam_data.shift_x = cam_data.shift_y = 0.0
cam_data.clip_start, cam_data.clip_end = 1e-4, 1e6
cam_data.dof.use_dof = False
cam = bpy.data.objects.new("peer_cam", cam_data)
scene.collection.objects.link(cam)
from mathutils import Matrix
cam.matrix_world = Matrix(job["camera"]["matrix"])
scene.camera = cam
mats = {}
def material(m):
    key = json.dumps(m, sort_keys=True)
    if key in mats:
        return mats[key]
    mat = bpy.data.materials.new("peer_mat%d" % len(mats))
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    if m["type"] == "diffuse":
        n = nt.nodes.new("ShaderNodeBsdfDiffuse")
        n.inputs["Color"].default_value = tuple(m["color"]) + (1.0,)
        n.inputs["Roughness"].default_value = 0.0
        nt.links.new(n.outputs["BSDF"], out.inputs["Surface"])
    else:
        n = nt.nodes.new("ShaderNodeEmission")
        n.inputs["Color"].default_value = tuple(m["color"]) + (1.0,)
        n.inputs["Strength"].default_value = 1.0
        nt.links.new(n.outputs["Emission"], out.inputs["Surface"])
        mat.cycles.sample_as_light = True
    mats[key] = mat
    return mat
for o in job["objects"]:
    me = bpy.data.meshes.new(o["name"])
    me.from_pydata(o["verts"], [], o["faces"])
    me.update()
    for p in me.polygons:
        p.use_smooth = o["smooth"]
    me.materials.append(material(o["material"]))
    ob = bpy.data.objects.new(o["name"], me)
    scene.collection.objects.link(ob)
results = []
def render(spp, seed, path):
    c.samples = spp
    c.seed = seed
    r.filepath = path
    t0 = time.perf_counter()
    bpy.ops.render.render()
    t = time.perf_counter() - t0
    if path:
        bpy.data.images["Render Result"].save_render(path)
    return t
render(1, 0, "")  # warm-up: not timed (first-render set-up of Cycles)
for job_r in job["renders"]:
    t = render(job_r["spp"], job_r["seed"], job_r["out"])
    results.append({"out": job_r["out"], "spp": job_r["spp"], "seed": job_r["seed"], "seconds": t})
    print("cycles_peer: %d spp seed %d: %.3f s" % (job_r["spp"], job_r["seed"], t), flush=True)
json.dump({"blender": bpy.app.version_string, "results": results}, open(job["results"], "w"), indent=1)
'''


def run_cycles(blender, job, renders, workdir, tag, width, height, threads, bounces, log):
    job = dict(job, width=width, height=height, threads=threads, bounces=bounces, renders=renders,
               results=os.path.join(workdir, tag + "_cycles_results.json"))
    jpath = os.path.join(workdir, tag + "_cycles_job.json")
    spath = os.path.join(workdir, "cycles_peer_blender.py")
    with open(jpath, "w") as f:
        json.dump(job, f)
    with open(spath, "w") as f:
        f.write(BLENDER_SCRIPT)
    cmd = [blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code", "1", "--python", spath, "--", jpath]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(workdir, tag + "_blender.log"), "w") as f:
        f.write(p.stdout)
    if p.returncode != 0 or not os.path.exists(job["results"]):
        sys.exit("cycles_peer: Blender failed (exit %d); its log is %s_blender.log in %s:\n%s"
                 % (p.returncode, tag, workdir, p.stdout[-3000:]))
    with open(job["results"]) as f:
        res = json.load(f)
    log("  Cycles: Blender %s, %d renders" % (res["blender"], len(res["results"])))
    return {(x["spp"], x["seed"]): x for x in res["results"]}


TIME_RE = re.compile(r"render ([0-9.]+)s")


def run_vkrt(vkrt, scene, out, width, height, spp, depth, seed, threads):
    cmd = [vkrt, scene, "--device", "cpu", "-w", str(width), "-h", str(height), "-r", str(spp),
           "-k", str(depth), "--seed", str(seed), "-n", str(threads), "-o", out]
    t0 = time.perf_counter()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit("cycles_peer: %s failed (exit %d):\n%s" % (" ".join(cmd), p.returncode, p.stdout))
    m = TIME_RE.search(p.stdout)
    if not m:
        sys.exit("cycles_peer: no 'render Ns' in vkrt's summary line:\n%s" % p.stdout)
    return float(m.group(1)), wall


# --------------------------------------------------------------------------------------------


def ensure_blender(args):
    found = shutil.which(args.blender)
    if found:
        return found
    if not args.install:
        sys.exit("cycles_peer: '%s' not found. Install Debian's Blender (3.4.1) with\n"
                 "  tools/cycles_peer.py --install ...   (runs apt-get install -y --no-install-recommends blender)\n"
                 "or pass --blender PATH." % args.blender)
    cmd = ["apt-get", "install", "-y", "--no-install-recommends", "blender"]
    if os.geteuid() != 0:
        cmd = ["sudo"] + cmd
    print("cycles_peer: " + " ".join(cmd), flush=True)
    if subprocess.run(cmd).returncode != 0:
        sys.exit("cycles_peer: apt-get install blender failed")
    found = shutil.which(args.blender)
    if not found:
        sys.exit("cycles_peer: blender still not found after installing it")
    return found


def fmt3(v, digits=4):
    return " ".join("%.*f" % (digits, x) for x in v)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenes", nargs="*", help="vkrt JSON scenes (default: scenes/quad_lit_room.json and "
                    "the generated sphere scene)")
    ap.add_argument("--vkrt", default=os.path.join(ROOT, "build", "vkrt"))
    ap.add_argument("--blender", default="blender")
    ap.add_argument("--install", action="store_true", help="apt-get install Debian's blender if missing")
    ap.add_argument("-W", "--width", type=int, default=96)
    ap.add_argument("-H", "--height", type=int, default=96)
    ap.add_argument("-k", "--depth", type=int, default=4,
                    help="vkrt -k K (max depth); Cycles gets max_bounces = diffuse_bounces = K-1")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--seeds", type=int, default=4, help="independent seeds of the high-spp images")
    ap.add_argument("--high-spp", type=int, default=512,
                    help="spp of each high-spp image (agreement; Cycles' reference = their mean)")
    ap.add_argument("--spp", default="16,64,256", help="time-to-error sample counts")
    ap.add_argument("--repeats", type=int, default=3,
                    help="time-to-error renders per sample count (seeds 100, 101, ...); times and e^2 averaged")
    ap.add_argument("--sphere-segments", type=int, default=128,
                    help="a sphere becomes a smooth-shaded UV-sphere mesh of N segments and N/2 rings")
    ap.add_argument("--out", help="keep images and logs here (default: a temporary folder, removed)")
    ap.add_argument("--png", action="store_true", help="also write side-by-side PNGs of the high-spp means")
    args = ap.parse_args()
    if args.depth < 1:
        sys.exit("cycles_peer: --depth must be >= 1 (vkrt -k 0 shows emitters only; Cycles has no such setting)")
    blender = ensure_blender(args)
    if not os.path.exists(args.vkrt):
        sys.exit("cycles_peer: vkrt binary %s not found (build it, or pass --vkrt)" % args.vkrt)
    workdir = args.out or tempfile.mkdtemp(prefix="cycles_peer_")
    os.makedirs(workdir, exist_ok=True)
    spps = [int(x) for x in args.spp.split(",")]
    scenes = args.scenes
    if not scenes:
        gen = os.path.join(workdir, "sphere_lamp.json")
        write_sphere_scene(gen)
        scenes = [os.path.join(ROOT, "scenes", "quad_lit_room.json"), gen]

    def log(msg):
        print(msg, file=sys.stderr, flush=True)

    W, H, K = args.width, args.height, args.depth
    load0 = os.getloadavg()[0]
    agree_rows, tte_rows, tte_summary = [], [], []
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        try:
            job = translate(scene, nseg=args.sphere_segments)
        except Untranslatable as e:
            log("cycles_peer: skipping %s: %s" % (scene, e))
            continue
        log("%s: %d objects" % (name, len(job["objects"])))
        seeds = list(range(1, args.seeds + 1))
        tseeds = list(range(100, 100 + args.repeats))

        def cycles(n, seed_list, tag):
            renders = [{"spp": n, "seed": sd, "out": os.path.join(workdir, "%s_cy_%s_%d.exr" % (name, tag, sd))}
                       for sd in seed_list]
            res = run_cycles(blender, job, renders, workdir, "%s_%s" % (name, tag), W, H, args.threads, K - 1, log)
            return [(res[(n, sd)]["seconds"], exr_time_attr(r["out"], "cycles.ViewLayer.render_time"),
                     read_exr(r["out"])[2]) for sd, r in zip(seed_list, renders)]

        def vkrt(n, sd, tag):
            out = os.path.join(workdir, "%s_vk_%s_%d.exr" % (name, tag, sd))
            t, wall = run_vkrt(args.vkrt, scene, out, W, H, n, K, sd, args.threads)
            return t, wall, read_exr(out)[2]

        # High-spp images, the two renderers alternating seed by seed (a shared machine's load
        # then falls on both alike).
        cy_hi, vk_hi = [], []
        for sd in seeds:
            cy_hi.append(cycles(args.high_spp, [sd], "hi")[0][2])
            vk_hi.append(vkrt(args.high_spp, sd, "hi")[2])
        # (a) agreement
        cm = [channel_means(im) for im in cy_hi]
        vm = [channel_means(im) for im in vk_hi]
        for c, ch in enumerate("RGB"):
            cmean, cse = mean_se([m[c] for m in cm])
            vmean, vse = mean_se([m[c] for m in vm])
            ratio = vmean / cmean if cmean else float("nan")
            rse = abs(ratio) * math.sqrt((vse / vmean) ** 2 + (cse / cmean) ** 2) if cmean and vmean else float("nan")
            agree_rows.append((name, ch, vmean, vse, cmean, cse, ratio, rse))
        # (b) time to error against Cycles' reference (the mean of its high-spp images)
        ref = mean_images(cy_hi)
        ref_var = pixel_var_of_mean(cy_hi)
        vref = mean_images(vk_hi)
        vref_var = pixel_var_of_mean(vk_hi)
        bias2 = max(0.0, mse(vref, ref) - ref_var - vref_var)
        if args.png:
            both = [array.array("f", [x for j in range(H) for x in (list(a[j * W:(j + 1) * W]) + list(b[j * W:(j + 1) * W]))])
                    for a, b in zip(vref, ref)]
            write_png(os.path.join(workdir, "%s_vkrt_left_cycles_right.png" % name), 2 * W, H, [both[0], both[1], both[2]])

        def measure_vkrt(n, tag):
            vt, ve2, vwall = 0.0, 0.0, 0.0
            for sd in tseeds:
                t, wall, im = vkrt(n, sd, tag)
                vt += t
                vwall += wall
                ve2 += mse(im, ref) - ref_var
            r = len(tseeds)
            return vt / r, max(ve2 / r, 0.0), vwall / r

        per = {}
        for n in spps:
            ct, cown, ce2, vt, ve2, vwall = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
            for sd in tseeds:  # alternate: one Cycles render, then vkrt's with the same seed
                call_s, own_s, im = cycles(n, [sd], str(n))[0]
                ct += call_s
                cown += own_s
                ce2 += mse(im, ref) - ref_var
                t, wall, im = vkrt(n, sd, str(n))
                vt += t
                vwall += wall
                ve2 += mse(im, ref) - ref_var
            r = len(tseeds)
            per[n] = (ct / r, cown / r, max(ce2 / r, 0.0), vt / r, max(ve2 / r, 0.0), vwall / r)
            tte_rows.append((name, n) + per[n])
        nmax = max(spps)
        ct, cown, ce2 = per[nmax][0], per[nmax][1], per[nmax][2]
        for n in spps:
            vt, ve2, vwall = per[n][3], per[n][4], per[n][5]
            t_reach = vt * ve2 / ce2 if ce2 > 0 else float("nan")
            w_reach = vwall * ve2 / ce2 if ce2 > 0 else float("nan")
            tte_summary.append((name, str(n), t_reach, cown, t_reach / cown if cown else float("nan"),
                                w_reach, ct, w_reach / ct if ct else float("nan")))
        # Check the extrapolation near the target: from the measured row whose error is nearest E,
        # predict the rpp that reaches E (e^2 ~ 1/rpp), render it, and once more from that render
        # if its error is still more than 10% off; then the same t * (e/E)^2 from the last render.
        # (vkrt's jittered samples and Cycles' Sobol/PMJ converge faster than 1/rpp on smooth
        # integrands, so extrapolating over a long way is only approximate.)
        if ce2 > 0 and all(per[n][4] > 0 for n in spps):
            n0 = min(spps, key=lambda n: abs(math.log(per[n][4] / ce2)))
            n_pred, ve2_0 = n0, per[n0][4]
            for _ in range(2):
                n_pred = max(1, int(round(n_pred * ve2_0 / ce2)))
                vt, ve2, vwall = measure_vkrt(n_pred, "check%d" % n_pred)
                tte_rows.append((name, n_pred, float("nan"), float("nan"), float("nan"), vt, ve2, vwall))
                if abs(math.sqrt(ve2 / ce2) - 1) <= 0.1:
                    break
                ve2_0 = ve2
            t_reach = vt * ve2 / ce2
            w_reach = vwall * ve2 / ce2
            tte_summary.append((name, "%d (check)" % n_pred, t_reach, cown, t_reach / cown if cown else float("nan"),
                                w_reach, ct, w_reach / ct if ct else float("nan")))
        log("  bias^2 between the two high-spp means (noise removed): %.3g (RMS %.3g)" % (bias2, math.sqrt(bias2)))
        tte_summary.append((name, "bias", math.sqrt(bias2), math.sqrt(ref_var), math.sqrt(vref_var), 0, 0, 0))

    print("## cycles_peer: load average %.2f at the start, %.2f at the end (%d CPUs)"
          % (load0, os.getloadavg()[0], os.cpu_count()))
    print()
    print("## cycles_peer: %dx%d, vkrt -k %d = Cycles max_bounces %d, %d threads, CPU" % (W, H, K, K - 1, args.threads))
    print()
    print("### (a) Agreement: image mean per channel, %d seeds x %d spp each, standard error over seeds"
          % (args.seeds, args.high_spp))
    print()
    print("| scene | ch | vkrt mean | ± se | Cycles mean | ± se | vkrt/Cycles | ± se |")
    print("|---|---|---|---|---|---|---|---|")
    for row in agree_rows:
        print("| %s | %s | %.5f | %.5f | %.5f | %.5f | %.4f | %.4f |" % row)
    print()
    print("### (b) Time to error: RMSE against Cycles' reference (mean of its %d x %d-spp images, its own "
          "noise subtracted), %d render(s) averaged per row" % (args.seeds, args.high_spp, args.repeats))
    print()
    print("Cycles render_time: Cycles' own figure from the EXR metadata (excludes synchronisation; 10 ms "
          "resolution); Cycles call: render.render() timed in the script (the whole render). "
          "vkrt render: its summary line's 'render' figure; vkrt wall: the whole vkrt process.")
    print()
    print("| scene | spp | Cycles render_time s | Cycles call s | Cycles RMSE | vkrt render s | vkrt wall s | vkrt RMSE |")
    print("|---|---|---|---|---|---|---|---|")
    for (name, n, ct, cown, ce2, vt, ve2, vwall) in tte_rows:
        cy_cells = "| %.2f | %.3f | %.5f " % (cown, ct, math.sqrt(ce2)) if ct == ct else "| - | - | - "
        print("| %s | %d %s| %.3f | %.3f | %.5f |" % (name, n, cy_cells, vt, vwall, math.sqrt(ve2)))
    print()
    print("### vkrt's time to reach Cycles' %d-spp RMSE E: t * (e/E)^2 from vkrt's render at each rpp; "
          "'check': vkrt rendered near E (the rpp predicted from the row nearest E, iterated once if "
          "more than 10%% off), then the same rule" % max(spps))
    print()
    print("| scene | from vkrt rpp | vkrt render s to E | Cycles render_time s | **ratio** | vkrt wall s to E | Cycles call s | ratio (wall/call) |")
    print("|---|---|---|---|---|---|---|---|")
    for row in tte_summary:
        if row[1] == "bias":
            continue
        print("| %s | %s | %.3f | %.2f | **%.3f** | %.3f | %.3f | %.3f |" % row)
    print()
    print("RMS difference between the two renderers' high-spp mean images, noise of both removed "
          "(vkrt's RMSE cannot fall below it): " + ", ".join(
              "%s %.5f (reference noise %.5f, vkrt high-spp noise %.5f)" % (r[0], r[2], r[3], r[4])
              for r in tte_summary if r[1] == "bias"))
    if not args.out:
        shutil.rmtree(workdir, ignore_errors=True)
    else:
        log("images and logs kept in %s" % workdir)


if __name__ == "__main__":
    main()
