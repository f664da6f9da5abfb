#!/usr/bin/env python3
"""Where lavapipe's JIT-compiled kernel spends its time: samples a running vkrt command with
`perf`, reads the sampled machine code from the process, and prints each loop of the kernel with
its share of the samples; the annotated disassembly goes to a file.

    tools/profile_jit.py [--wait 8] [--seconds 5] [--out jit_profile.txt] -- \\
        build/vkrt-bench gpu rays sphere:64 512 512 4 --rounds 60 --no-peer --shader-dir shaders

Why a tool: llvmpipe compiles kernels into anonymous memory, so `perf report` shows bare
addresses and `perf annotate` has no code to show. The code is still in the process while it
runs, so this script samples first, then copies the sampled address ranges out of
/proc/PID/mem and disassembles them with objdump. A backward jump marks a loop; the loop that
holds most samples is the traversal's main loop, and the loops inside it are the walk and the
leaf tests (shaders/traverse.glsl). Give the command enough work to outlast --wait + --seconds
(it is stopped afterwards), and give the renderer itself, not a wrapper such as `env` or a shell
(perf samples the process it starts; set variables before this script instead). Needs perf
(Debian: linux-perf) and objdump (binutils), as root or with kernel.perf_event_paranoid <= 1.
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

REGION_GAP = 4096  # sampled addresses closer than this belong to one block of JIT code


def sampled_jit_addresses(perf_data):
    """Sample addresses in JIT code (perf's [JIT] or [unknown] objects) -> share in percent."""
    report = subprocess.run(["perf", "report", "-i", perf_data, "--no-children", "--sort", "dso,sym", "--stdio"],
                            capture_output=True, text=True)
    if report.returncode != 0:
        sys.exit(f"profile_jit: perf report failed: {report.stderr.strip()}")
    shares = {}
    for line in report.stdout.splitlines():
        m = re.match(r"\s*([0-9.]+)%\s+(.*?)\s+\[\.\]\s+0x([0-9a-f]+)\s*$", line)
        # A stripped library's unresolved samples also print as bare offsets: keep JIT code only.
        if m and ("[JIT]" in m.group(2) or "[unknown]" in m.group(2)):
            shares[int(m.group(3), 16)] = float(m.group(1))
    return shares


def regions(addresses):
    spans = []
    for a in sorted(addresses):
        if spans and a - spans[-1][1] < REGION_GAP:
            spans[-1][1] = a
        else:
            spans.append([a, a])
    return spans


def disassemble(pid, lo, hi):
    """(address, text) of each instruction in [lo, hi], read from the live process."""
    start, size = lo, hi - lo + 64  # sampled addresses start instructions: decode from the first
    code = bytearray()
    try:
        mem = open(f"/proc/{pid}/mem", "rb", buffering=0)
    except OSError as error:
        sys.exit(f"profile_jit: cannot read the process's memory ({error}); run as root or allow ptrace")
    with mem:
        # Page by page: a span of samples can cross pages that are not mapped (or were unmapped
        # since); those read as zero bytes rather than failing the whole read.
        address = start
        while address < start + size:
            chunk = min(start + size, (address // 4096 + 1) * 4096) - address
            try:
                mem.seek(address)
                code += mem.read(chunk)
            except OSError:
                code += bytes(chunk)
            address += chunk
    with tempfile.NamedTemporaryFile(suffix=".bin") as blob:
        blob.write(code)
        blob.flush()
        text = subprocess.run(["objdump", "-D", "-b", "binary", "-mi386:x86-64", f"--adjust-vma={start}", blob.name],
                              capture_output=True, text=True).stdout
    out = []
    for line in text.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\t(?:[0-9a-f]{2} )+\s*\t(.*)$", line)
        if m:
            out.append((int(m.group(1), 16), m.group(2)))
    return out


def loops(instructions):
    """(target, source) of every backward jump: the loops of the code."""
    found = []
    for address, text in instructions:
        m = re.match(r"j[a-z]+\s+0x([0-9a-f]+)", text)
        if m and int(m.group(1), 16) < address:
            found.append((int(m.group(1), 16), address))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--wait", type=float, default=8.0, help="seconds before sampling (set-up, JIT, warm-up)")
    parser.add_argument("--seconds", type=float, default=5.0, help="seconds of sampling")
    parser.add_argument("--out", default="jit_profile.txt", help="annotated disassembly")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="-- the command to profile")
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("no command to profile (give it after --)")
    for tool in ("perf", "objdump"):
        if shutil.which(tool) is None:
            sys.exit(f"profile_jit: '{tool}' not found (Debian: apt-get install -y linux-perf binutils)")

    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(args.wait)
        if process.poll() is not None:
            sys.exit(f"profile_jit: the command ended (status {process.returncode}) before sampling began; "
                     "give it more work or a shorter --wait")
        with tempfile.TemporaryDirectory() as tmp:
            perf_data = os.path.join(tmp, "perf.data")
            record = subprocess.run(["perf", "record", "-q", "-p", str(process.pid), "-o", perf_data, "sleep", str(args.seconds)],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if record.returncode != 0:
                sys.exit(f"profile_jit: perf record failed: {record.stderr.strip()} "
                         "(root, or kernel.perf_event_paranoid <= 1)")
            shares = sampled_jit_addresses(perf_data)
            if process.poll() is not None:
                sys.exit("profile_jit: the command ended while sampling; its JIT code is gone (give it more work)")
            with open(args.out, "w") as out:
                for lo, hi in regions(shares):
                    total = sum(p for a, p in shares.items() if lo <= a <= hi)
                    if total < 1.0:
                        continue  # stray samples, not a kernel
                    code = disassemble(process.pid, lo, hi)
                    print(f"JIT code {lo:#x}-{hi:#x}: {total:.1f}% of all samples")
                    for target, source in loops(code):
                        share = sum(p for a, p in shares.items() if target <= a <= source)
                        if share >= 0.5:
                            print(f"  loop {target:#x}-{source:#x} ({source - target} bytes): {share:.1f}%")
                    out.write(f"==== {lo:#x}-{hi:#x} {total:.2f}%\n")
                    for address, text in code:
                        share = shares.get(address)
                        out.write((f"{share:6.2f} " if share else "       ") + f"{address:x}  {text}\n")
            print(f"annotated disassembly: {args.out} (column 1: % of all samples at that instruction)")
    finally:
        if process.poll() is None:
            process.send_signal(signal.SIGTERM)
            process.wait()


if __name__ == "__main__":
    main()
