#!/usr/bin/env python3
"""vkrt --watch --preview against hostile clients (issue 38 item 5):

1. a request whose Host (or Origin) is not the server's loopback name is refused with 403 (DNS
   rebinding), while Host 127.0.0.1:PORT and localhost:PORT are served;
2. a request body past 4 KiB is refused (413) without being read into memory;
3. 24 clients that connect and send nothing do not keep /status from answering within 3 s;
4. a scene whose path is not valid UTF-8 keeps the server up: /status is valid JSON with U+FFFD
   in the path, and vkrt is still running.

    preview_hardening.py VKRT WORKDIR
"""
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import threading
import time

SCENE = b'<scene><camera><position>0 0 3</position><viewDir>0 0 -1</viewDir></camera>\n' \
        b'<light type="point"><position>2 3 4</position><intensity>1 1 1</intensity></light>\n' \
        b'<shape name="b" type="sphere"><center>0 0 0</center><radius>0.6</radius></shape></scene>\n'


def fail(message, log):
    sys.exit(message + "\n--- log ---\n" + "".join(log))


def request(port, head, body=b"", timeout=10):
    """The raw response (status line and all) to `head` + `body` sent to 127.0.0.1:port."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        s.sendall(head + body)
        data = b""
        while True:
            chunk = s.recv(65536)
            if not chunk:
                return data
            data += chunk
            if b"\r\n\r\n" in data and b"Connection: close" in data.split(b"\r\n\r\n")[0]:
                pass


def status_code(response):
    m = re.match(rb"HTTP/1\.[01] (\d+)", response)
    return int(m.group(1)) if m else None


def get(port, path, host=None, extra=b""):
    host = host if host is not None else ("127.0.0.1:%d" % port)
    return request(port, b"GET " + path + b" HTTP/1.1\r\nHost: " + host.encode() + b"\r\nConnection: close\r\n" + extra + b"\r\n")


def main():
    vkrt, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    # A folder name in Latin-1: not valid UTF-8.
    folder = os.path.join(os.fsencode(work), b"sc\xe8nes")
    os.makedirs(folder)
    scene = os.path.join(folder, b"ball.xml")
    with open(scene, "wb") as f:
        f.write(SCENE)
    log = []
    proc = subprocess.Popen([os.fsencode(vkrt), b"--watch", scene, b"-w", b"16", b"-h", b"12", b"-r", b"1",
                             b"--device", b"cpu", b"--preview", b"0", b"-o", os.path.join(folder, b"out.png")],
                            stderr=subprocess.PIPE)
    threading.Thread(target=lambda: [log.append(line.decode("utf-8", "replace")) for line in proc.stderr],
                     daemon=True).start()
    try:
        deadline, port = time.time() + 60, None
        while port is None and time.time() < deadline:
            for line in list(log):
                m = re.search(r"preview on http://127\.0\.0\.1:(\d+)/", line)
                if m:
                    port = int(m.group(1))
            if proc.poll() is not None:
                fail("vkrt exited (%d) before serving" % proc.returncode, log)
            time.sleep(0.05)
        if port is None:
            fail("no preview port within 60 s", log)
        while not any("render 1" in line for line in log) and time.time() < deadline:
            time.sleep(0.05)

        # 1. Host and Origin.
        for host, expected in (("127.0.0.1:%d" % port, 200), ("localhost:%d" % port, 200),
                               ("evil.example:%d" % port, 403), ("127.0.0.1:1", 403), ("", 403)):
            code = status_code(get(port, b"/status", host))
            if code != expected:
                fail("Host '%s': status %s, expected %d" % (host, code, expected), log)
        code = status_code(get(port, b"/status", extra=b"Origin: http://evil.example\r\n"))
        if code != 403:
            fail("Origin http://evil.example: status %s, expected 403" % code, log)
        print("Host/Origin: loopback names served, others 403")

        # 2. A large body is refused by its Content-Length, before it is sent.
        head = b"POST / HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nContent-Length: 1000000000\r\nConnection: close\r\n\r\n" % port
        code = status_code(request(port, head, b"x" * 65536))
        if code != 413:
            fail("a 1 GB POST: status %s, expected 413" % code, log)
        print("1 GB POST: 413")

        # 3. Slow clients.
        idle = [socket.create_connection(("127.0.0.1", port)) for _ in range(24)]
        start = time.time()
        code = status_code(get(port, b"/status"))
        took = time.time() - start
        for s in idle:
            s.close()
        if code != 200 or took > 3.0:
            fail("with 24 idle clients /status took %.1f s (status %s)" % (took, code), log)
        print("24 idle clients: /status in %.2f s" % took)

        # 4. The non-UTF-8 path.
        response = get(port, b"/status")
        status = json.loads(response.split(b"\r\n\r\n", 1)[1].decode("utf-8"))
        if "\ufffd" not in status["scene"] or proc.poll() is not None:
            fail("status with a non-UTF-8 path: %s (vkrt %s)" % (status, "exited" if proc.poll() is not None else "running"), log)
        print("non-UTF-8 scene path: /status is JSON with U+FFFD, vkrt still running")
        print("preview hardened")
    finally:
        proc.terminate()
        proc.wait(timeout=30)


if __name__ == "__main__":
    main()
