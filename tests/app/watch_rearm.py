#!/usr/bin/env python3
"""vkrt --watch where the watched folder goes away or the scene is a link (issue 38 item 6):

1. the scene's folder is deleted (the next render fails, saying so) and made again with the scene:
   vkrt renders it again, with no edit after the folder came back;
2. the scene is a symbolic link into another folder: an edit of the link's target renders again;
3. the folder of a scene that does not exist yet is created later with the scene: it renders.

    watch_rearm.py VKRT WORKDIR
"""
import os
import re
import shutil
import subprocess
import sys
import threading
import time

SCENE = '<scene bgColor="COLOUR"><camera><position>0 0 3</position><viewDir>0 0 -1</viewDir></camera>\n' \
        '<light type="point"><position>2 3 4</position><intensity>1 1 1</intensity></light>\n' \
        '<shader name="g" type="Lambertian"><diffuse>0.9 0.9 0.2</diffuse></shader>\n' \
        '<shape name="b" type="sphere"><shader ref="g"/><center>0 0 0</center><radius>0.6</radius></shape></scene>\n'


def write(path, colour):
    with open(path + ".tmp", "w") as f:
        f.write(SCENE.replace("COLOUR", colour))
    os.replace(path + ".tmp", path)


class Watch:
    def __init__(self, vkrt, scene, out):
        self.log = []
        self.proc = subprocess.Popen([vkrt, "--watch", scene, "-w", "16", "-h", "12", "-r", "1", "--device", "cpu",
                                      "-o", out], stderr=subprocess.PIPE, text=True)
        threading.Thread(target=lambda: [self.log.append(line) for line in self.proc.stderr], daemon=True).start()

    def wait_for(self, pattern, what):
        deadline = time.time() + 30
        while time.time() < deadline:
            if any(re.search(pattern, line) for line in list(self.log)):
                return
            if self.proc.poll() is not None:
                break
            time.sleep(0.05)
        self.stop()
        sys.exit("%s: no '%s' within 30 s\n--- log ---\n%s" % (what, pattern, "".join(self.log)))

    def stop(self):
        self.proc.terminate()
        self.proc.wait(timeout=30)


def main():
    vkrt, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "out.png")

    folder = os.path.join(work, "scenes")
    os.makedirs(folder)
    scene = os.path.join(folder, "ball.xml")
    write(scene, "0.1 0.2 0.3")
    w = Watch(vkrt, scene, out)
    w.wait_for(r"\] render 1: 16x12", "first render")
    shutil.rmtree(folder)
    w.wait_for(r"\] render 2: error", "the folder deleted")
    time.sleep(0.5)
    os.makedirs(folder)
    write(scene, "0.9 0.2 0.3")
    w.wait_for(r"\] render 3: 16x12", "the folder made again")
    w.stop()
    print("folder deleted and made again: rendered again")

    real = os.path.join(work, "real")
    links = os.path.join(work, "links")
    os.makedirs(real)
    os.makedirs(links)
    write(os.path.join(real, "ball.xml"), "0.1 0.2 0.3")
    os.symlink("../real/ball.xml", os.path.join(links, "ball.xml"))
    w = Watch(vkrt, os.path.join(links, "ball.xml"), out)
    w.wait_for(r"\] render 1: 16x12", "first render through the link")
    time.sleep(0.5)
    with open(os.path.join(real, "ball.xml"), "w") as f:  # edited in place, as some editors do
        f.write(SCENE.replace("COLOUR", "0.5 0.5 0.1"))
    w.wait_for(r"\] render 2: 16x12", "the link's target edited")
    w.stop()
    print("link's target edited: rendered again")

    later = os.path.join(work, "later", "deeper")
    w = Watch(vkrt, os.path.join(later, "ball.xml"), out)
    w.wait_for(r"\] render 1: error", "a scene that does not exist yet")
    time.sleep(0.5)
    os.makedirs(later)
    write(os.path.join(later, "ball.xml"), "0.3 0.3 0.3")
    w.wait_for(r"\] render 2: 16x12", "the folder and scene created later")
    w.stop()
    print("folder created later: rendered")
    print("watch re-arms")


if __name__ == "__main__":
    main()
