#!/usr/bin/env python3
"""vkrt --watch (issue 23), end to end on lavapipe with a --shader-dir copy of the kernel's GLSL:

1. the first image is a one-shot `vkrt` render's bytes;
2. a scene edit (the sphere's colour), a mesh edit (the OBJ's triangle moved) and a shader edit
   (render.comp storing black) each give one new image, the bytes a one-shot render of the edited
   inputs gives (a separate process: an independent computation of the expected image);
3. a broken shader and a broken scene each print their error (file and line) and the process goes on;
   the next good edit renders again;
4. a reader polling the output all along never sees a partial file (every read is a whole PPM), and
   --progressive 2 writes a half-sampled pass before each image;
5. Ctrl-C while waiting stops it with exit 0;
6. an edit during a long render (CPU, 65,536 rpp, ~1.5 s) stops that render at once and renders the
   edited scene, whose image is the one-shot bytes; Ctrl-C during a render exits 130.

    watch_mode.py VKRT SHADERS WORKDIR
"""
import os
import shutil
import signal
import subprocess
import sys
import threading
import time

W, H, RPP = 40, 30, 4
SCENE = """<?xml version="1.0"?>
<scene bgColor="0.1 0.1 0.1">
  <camera name="main" type="perspective"><position>0 0 4</position><viewDir>0 0 -1</viewDir>
    <focalLength>1</focalLength><imagePlaneWidth>1</imagePlaneWidth></camera>
  <light type="point"><position>2 3 4</position><intensity>1 1 1</intensity></light>
  <shader name="s" type="Lambertian"><diffuse>COLOUR</diffuse></shader>
  <shader name="m" type="Lambertian"><diffuse>0.8 0.8 0.8</diffuse></shader>
  <shape name="ball" type="sphere"><shader ref="s"/><center>-0.4 0 0</center><radius>0.5</radius></shape>
  <shape name="tri" type="mesh"><shader ref="m"/><file>tri.obj</file></shape>
</scene>
"""
OBJ = "v 0.2 -0.5 0\nv 1.2 -0.5 0\nv X 0.6 0\nf 1 2 3\n"
STORE = "storePixelSum(key.pixel, sum);"


def fail(message, log=None):
    sys.exit(message + ("\n--- watch log ---\n" + "".join(log) if log is not None else ""))


def write(path, text):
    # Written in place (IN_CLOSE_WRITE), as most editors do; the scene edits below rename instead.
    with open(path, "w") as f:
        f.write(text)


def write_by_rename(path, text):
    with open(path + ".swp", "w") as f:
        f.write(text)
    os.replace(path + ".swp", path)


def whole_ppm(data):
    """True when `data` is a complete binary PPM of W x H."""
    parts = data.split(b"\n", 3)
    if len(parts) < 4 or parts[0] != b"P6" or parts[1] != b"%d %d" % (W, H) or parts[2] != b"255":
        return False
    return len(parts[3]) == W * H * 3


def main():
    vkrt, shaders, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene, obj, out = (os.path.join(work, n) for n in ("scene.xml", "tri.obj", "out.ppm"))
    kernel_dir = os.path.join(work, "shaders")
    shutil.copytree(shaders, kernel_dir)
    comp = os.path.join(kernel_dir, "render.comp")
    comp_text = open(comp).read()
    if STORE not in comp_text:
        fail("render.comp has no line '%s' to edit: update this test with the kernel" % STORE)
    write(scene, SCENE.replace("COLOUR", "0.9 0.1 0.1"))
    write(obj, OBJ.replace("X", "0.7"))
    size = ["-w", str(W), "-h", str(H), "-r", str(RPP), "--device", "gpu"]

    def one_shot(name, shader_dir=shaders):
        expected = os.path.join(work, name + ".ppm")
        subprocess.run([vkrt, scene, *size, "-q", "--shader-dir", shader_dir, "-o", expected], check=True)
        return open(expected, "rb").read()

    # The reader: polls the output as fast as it can for the whole test.
    reads, partial, contents, stop = [0], [0], set(), threading.Event()

    def reader():
        while not stop.is_set():
            try:
                data = open(out, "rb").read()
            except FileNotFoundError:
                continue
            reads[0] += 1
            if whole_ppm(data):
                contents.add(data)
            else:
                partial[0] += 1

    log, lock = [], threading.Lock()
    proc = subprocess.Popen([vkrt, "--watch", scene, *size, "--shader-dir", kernel_dir, "--progressive", "2", "-o", out],
                            stderr=subprocess.PIPE, text=True)

    def drain():
        for line in proc.stderr:
            with lock:
                log.append(line)

    threading.Thread(target=drain, daemon=True).start()
    threading.Thread(target=reader, daemon=True).start()

    def wait_for(text, count, what):
        deadline = time.time() + 60
        while time.time() < deadline:
            with lock:
                if sum(text in line for line in log) >= count:
                    return
            if proc.poll() is not None:
                fail("vkrt --watch exited (%d) waiting for %s" % (proc.returncode, what), log)
            time.sleep(0.05)
        fail("no '%s' #%d within 60 s (%s)" % (text, count, what), log)

    def expect_image(round_, expected, what):
        wait_for("] render %d: %dx%d" % (round_, W, H), 1, what)
        if open(out, "rb").read() != expected:
            fail("%s: the watched render differs from a one-shot render of the same inputs" % what, log)
        print("%s: render %d is the one-shot render's bytes" % (what, round_))

    expect_image(1, one_shot("first"), "first render")
    first = open(out, "rb").read()

    write_by_rename(scene, SCENE.replace("COLOUR", "0.1 0.1 0.9"))
    expect_image(2, one_shot("blue"), "scene edit")

    write(obj, OBJ.replace("X", "1.1"))
    expect_image(3, one_shot("mesh"), "mesh edit")

    write(comp, comp_text.replace(STORE, "storePixelSum(key.pixel, vec4(0.0));"))
    black_dir = os.path.join(work, "black_shaders")
    shutil.copytree(kernel_dir, black_dir)
    black = one_shot("black", black_dir)
    if black[-W * H * 3:] != bytes(W * H * 3):
        fail("the edited kernel should render black")
    expect_image(4, black, "shader edit")

    write(comp, comp_text.replace(STORE, STORE + "\n    this is not GLSL;"))
    wait_for("] render 5: error: GLSL compile of", 1, "broken shader")
    wait_for("render.comp:", 1, "the compile error's line")
    print("broken shader: its error is printed, vkrt --watch goes on")

    write(comp, comp_text)
    expect_image(6, one_shot("blue_again"), "shader restored")

    write_by_rename(scene, SCENE.replace("COLOUR", "0.1 0.1 0.9").replace("</scene>", "<shape"))
    wait_for("] render 7: error: %s:" % scene, 1, "broken scene")
    print("broken scene: its error is printed, vkrt --watch goes on")

    write_by_rename(scene, SCENE.replace("COLOUR", "0.9 0.1 0.1"))
    write(obj, OBJ.replace("X", "0.7"))
    expect_image(8, first, "scene and mesh restored")

    with lock:
        passes = sum(" 2/4 rpp at " in line for line in log)
    if passes < 6:
        fail("--progressive 2: %d half-sampled passes written, expected one per render (6)" % passes, log)
    print("--progressive 2: a 2/4 rpp pass was written before each of the %d images" % passes)

    proc.send_signal(signal.SIGINT)
    code = proc.wait(timeout=30)
    stop.set()
    time.sleep(0.1)
    if code != 0:
        fail("Ctrl-C while watching: exit %d, expected 0" % code, log)
    if partial[0] or reads[0] < 100 or len(contents) < 5:
        fail("reader: %d reads, %d partial, %d distinct images" % (reads[0], partial[0], len(contents)), log)
    print("reader: %d reads of the output, %d distinct whole images, none partial" % (reads[0], len(contents)))
    restart_on_change(vkrt, work)
    print("watch mode ok")


LONG = """<scene bgColor="0.1 0.1 0.1"><camera><position>0 0 3</position><viewDir>0 0 -1</viewDir></camera>
<light type="point"><position>2 3 4</position><intensity>1 1 1</intensity></light>
<shader name="g" type="Lambertian"><diffuse>COLOUR</diffuse></shader>
<shape name="b" type="sphere"><shader ref="g"/><center>0 0 0</center><radius>0.5</radius></shape></scene>
"""


def restart_on_change(vkrt, work):
    scene, out = os.path.join(work, "long.xml"), os.path.join(work, "long.ppm")
    # One 16x16 tile: one CPU thread, ~1.5 s here; the edit comes 0.4 s in. --exposure: a watched
    # render writes the image scaled as a one-shot render does (issue 39).
    size = ["-w", "16", "-h", "12", "-r", "65536", "--device", "cpu", "--exposure", "-1"]
    write(scene, LONG.replace("COLOUR", "0.5 0.5 0.5"))
    log = []
    proc = subprocess.Popen([vkrt, "--watch", scene, *size, "-o", out], stderr=subprocess.PIPE, text=True)
    threading.Thread(target=lambda: [log.append(line) for line in proc.stderr], daemon=True).start()

    def wait_for(text):
        deadline = time.time() + 60
        while time.time() < deadline and not any(text in line for line in log):
            if proc.poll() is not None:
                fail("vkrt --watch exited (%d) waiting for '%s'" % (proc.returncode, text), log)
            time.sleep(0.02)
        if not any(text in line for line in log):
            fail("no '%s' within 60 s" % text, log)

    time.sleep(0.4)
    edited = time.time()
    write_by_rename(scene, LONG.replace("COLOUR", "0.9 0.2 0.1"))
    wait_for("] render 1: stopped after")
    stopped = time.time() - edited
    expected = os.path.join(work, "long_expected.ppm")
    subprocess.run([vkrt, scene, *size, "-q", "-o", expected], check=True)
    wait_for("] render 2: 16x12")
    if open(out, "rb").read() != open(expected, "rb").read():
        fail("the render after the restart differs from a one-shot render of the edited scene", log)
    print("an edit during a render stopped it %.2f s after the edit; the next render is the one-shot bytes" % stopped)
    write_by_rename(scene, LONG.replace("COLOUR", "0.2 0.9 0.1"))
    time.sleep(0.4)
    proc.send_signal(signal.SIGINT)
    code = proc.wait(timeout=30)
    if code != 130 or not any("vkrt: interrupted" in line for line in log):
        fail("Ctrl-C during a render: exit %d, expected 130 with 'vkrt: interrupted'" % code, log)
    print("Ctrl-C during a render: exit 130")


if __name__ == "__main__":
    main()
