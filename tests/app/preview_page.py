#!/usr/bin/env python3
"""vkrt --watch --preview 0 (issue 23), in headless Chromium:

1. the page's image (/image.png) is the bytes of the PNG vkrt wrote, and a Chromium screenshot of the
   page shows it: the screenshot's pixels over the image are the render's pixels;
2. after a scene edit the page (reloaded by its own script, never by the test) shows the new render;
3. after a broken edit the page shows the error with the file and line, and the last good image.

    preview_page.py VKRT CHROMIUM WORKDIR
"""
import json
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import threading
import time
import urllib.request
import zlib

W, H = 64, 48
SCENE = '<scene bgColor="COLOUR"><camera><position>0 0 3</position><viewDir>0 0 -1</viewDir></camera>\n' \
        '<light type="point"><position>2 3 4</position><intensity>1 1 1</intensity></light>\n' \
        '<shader name="g" type="Lambertian"><diffuse>0.9 0.9 0.2</diffuse></shader>\n' \
        '<shape name="b" type="sphere"><shader ref="g"/><center>0 0 0</center><radius>0.6</radius></shape>\n' \
        '</scene>\n'


def fail(message, log=None):
    sys.exit(message + ("\n--- log ---\n" + "".join(log) if log is not None else ""))


def decode_png(data):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    at, idat = 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise ValueError("PNG kind %d/%d/%d not handled" % (depth, colour, interlace))
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def main():
    vkrt, chromium, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene, out = os.path.join(work, "scene.xml"), os.path.join(work, "out.png")
    with open(scene, "w") as f:
        f.write(SCENE.replace("COLOUR", "0.2 0.6 0.9"))
    log = []
    proc = subprocess.Popen([vkrt, "--watch", scene, "-w", str(W), "-h", str(H), "-r", "4", "--device", "cpu",
                             "--preview", "0", "-o", out], stderr=subprocess.PIPE, text=True)
    threading.Thread(target=lambda: [log.append(line) for line in proc.stderr], daemon=True).start()

    def wait_for(pattern):
        deadline = time.time() + 60
        while time.time() < deadline:
            for line in list(log):
                m = re.search(pattern, line)
                if m:
                    return m
            if proc.poll() is not None:
                fail("vkrt exited (%d) waiting for '%s'" % (proc.returncode, pattern), log)
            time.sleep(0.05)
        fail("no '%s' within 60 s" % pattern, log)

    url = "http://127.0.0.1:%s/" % wait_for(r"preview on http://127\.0\.0\.1:(\d+)/").group(1)

    def get(path):
        with urllib.request.urlopen(url + path, timeout=10) as r:
            return r.read()

    def browse(name, *flags):
        # --virtual-time-budget lets the page's script fetch /status and the image before the
        # capture; --force-color-profile=srgb keeps Chromium from converting the PNG's colours.
        shot = os.path.join(work, name)
        p = subprocess.run([chromium, "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--force-color-profile=srgb",
                            "--force-device-scale-factor=1", "--window-size=320,240", "--virtual-time-budget=3000",
                            *flags, url], capture_output=True, text=True, timeout=120)
        if p.returncode != 0:
            fail("%s: exit %d\n%s" % (chromium, p.returncode, p.stderr[-2000:]))
        return p.stdout

    def screenshot_shows(name, what):
        browse(name, "--screenshot=" + os.path.join(work, name))
        _, _, shot = decode_png(open(os.path.join(work, name), "rb").read())
        _, _, render = decode_png(open(out, "rb").read())
        # The image sits at the page's top left at its own size: every pixel of it must be the
        # render's (PNG colours are shown as they are under the sRGB profile; 1 step allowed for
        # the compositor's rounding).
        worst = max(abs(a - b) for y in range(H) for x in range(W) for a, b in zip(shot[y][x], render[y][x]))
        if worst > 1:
            fail("%s: the screenshot's image differs from the render by %d/255" % (what, worst), log)
        print("%s: the screenshot shows the render (%dx%d pixels, worst %d/255)" % (what, W, H, worst))
        return render

    wait_for(r"\] render 1: %dx%d" % (W, H))
    status = json.loads(get("status"))
    if status["image"] != 1 or status["error"] != "" or "render 1" not in status["status"]:
        fail("status after the first render: %s" % status, log)
    if get("image.png") != open(out, "rb").read():
        fail("/image.png is not the PNG vkrt wrote", log)
    print("/image.png is the written PNG's bytes; /status: %s" % status["status"][:40])
    first = screenshot_shows("first.png", "first render")

    with open(scene + ".swp", "w") as f:
        f.write(SCENE.replace("COLOUR", "0.8 0.1 0.1"))
    os.replace(scene + ".swp", scene)
    wait_for(r"\] render 2: %dx%d" % (W, H))
    second = screenshot_shows("second.png", "after a scene edit")
    if second[0][0] == first[0][0]:
        fail("the edit did not change the background", log)

    with open(scene, "w") as f:
        f.write(SCENE.replace("COLOUR", "0.8 0.1 0.1").replace("</scene>", "<shape"))
    wait_for(r"\] render 3: error")
    dom = browse("dom", "--dump-dom")
    m = re.search(r'<div id="error">([^<]*)</div>', dom)
    if not m or "scene.xml:5: xml: malformed XML" not in m.group(1):
        fail("the page does not show the error with its line: %s" % (m.group(1) if m else dom[-1500:]), log)
    print("after a broken edit the page shows: %s" % m.group(1).strip()[:90])
    screenshot_shows("third.png", "after a broken edit, the last good image")

    proc.send_signal(signal.SIGINT)
    if proc.wait(timeout=30) != 0:
        fail("Ctrl-C: exit %d" % proc.returncode, log)
    print("preview ok")


if __name__ == "__main__":
    main()
