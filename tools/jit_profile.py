#!/usr/bin/env python3
"""Where lavapipe spends a frame, instruction by instruction: `perf` on the
shader code llvmpipe compiled (which no symbol names), read back from the
running process.

Runs `blackhole profile` on many frames, samples it with `perf record`,
copies llvmpipe's anonymous executable mappings out of the process with
`gdb`, disassembles them with `objdump` and attributes the samples: each
mapping's share of the time (one shader pipeline or a few), the share by
kind of instruction (vector arithmetic; stack loads and stores, which are
mostly spills; lane-by-lane element moves, the mark of a gather or of a
value read one lane at a time) and the hottest 128-byte blocks. A block of
scalar arithmetic (`vmulss`, `vsqrtps` of a broadcast) or of lane-by-lane
moves in a per-pixel shader is work the shader repeats for every pixel that
could be done once: that is how the nearest-hole search of the static frame
was found (docs/performance.md, "Step 14").

Needs perf, gdb and objdump (binutils); run as a user that may attach to
its own processes. Usage (from the repository root, after `cargo build
--release`):

    python3 tools/jit_profile.py [--seconds S] [--asm ADDRESS] -- BINARY [profile args]

e.g. `python3 tools/jit_profile.py -- target/release/blackhole --scene
interstellar`. `--asm 7f45f07e6180` prints that block's instructions with
their samples (addresses as the table prints them; they change every run,
so use it together with the same run's table: it keeps its files in
/tmp/jit_profile until the next run).
"""

import argparse
import collections
import os
import re
import shutil
import signal
import subprocess
import sys
import time

WORK = "/tmp/jit_profile"
LANE = {"vpextrd", "vpinsrd", "vpextrq", "vpinsrq", "vpextrw", "vpinsrw", "vpextrb", "vpinsrb",
        "movslq", "vmovd", "vmovq", "vinserti128", "vextracti128", "vinsertf128", "vextractf128",
        "vmovsd", "vmovss", "vinsertps", "vextractps", "vmovlhps", "vpunpckldq", "movzwl",
        "movzbl"}


def classify(op, text):
    if "(%rsp)" in text:
        return "stack"
    if op in LANE:
        return "lane by lane"
    if op.endswith("ss") and op.startswith("v") and op not in ("vbroadcastss",):
        return "scalar float"
    if op in ("vsqrtps", "vdivps", "vrsqrt14ps", "vrcp14ps"):
        return "sqrt and div"
    if op.startswith("vpgather") or op.startswith("vgather"):
        return "hardware gather"
    if op.startswith("v"):
        return "vector"
    if op.startswith("j") or op in ("cmp", "cmpl", "test"):
        return "branch"
    return "integer and other"


def record(binary, args, seconds):
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    env = dict(os.environ, LP_NUM_THREADS=os.environ.get("LP_NUM_THREADS", "4"))
    proc = subprocess.Popen([binary, "profile", "--frames", "100000", *args], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(3)  # pipelines built, frames running
        if proc.poll() is not None:
            sys.exit(f"jit_profile: `{binary} profile` exited early ({proc.returncode})")
        data = os.path.join(WORK, "perf.data")
        subprocess.run(["perf", "record", "-F", "4000", "-p", str(proc.pid), "-o", data, "--",
                        "sleep", str(seconds)], check=True, capture_output=True)
        # llvmpipe's code: executable mappings backed by no file.
        dumps = []
        with open(f"/proc/{proc.pid}/maps") as maps:
            for line in maps:
                f = line.split()
                if f[1] == "r-xp" and f[4] == "0" and len(f) == 5:
                    lo, hi = f[0].split("-")
                    dumps += ["-ex", f"dump binary memory {WORK}/{lo}.bin 0x{lo} 0x{hi}"]
        subprocess.run(["gdb", "-p", str(proc.pid), "-batch", *dumps], check=True,
                       capture_output=True)
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    script = subprocess.run(["perf", "script", "-i", data, "-F", "ip"], check=True,
                            capture_output=True, text=True).stdout
    with open(os.path.join(WORK, "samples.txt"), "w") as f:
        f.write(script)
    for name in os.listdir(WORK):
        if name.endswith(".bin"):
            asm = subprocess.run(["objdump", "-D", "-b", "binary", "-mi386:x86-64",
                                  f"--adjust-vma=0x{name[:-4]}", os.path.join(WORK, name)],
                                 check=True, capture_output=True, text=True).stdout
            with open(os.path.join(WORK, name[:-4] + ".asm"), "w") as f:
                f.write(asm)


def load():
    samples = collections.Counter()
    with open(os.path.join(WORK, "samples.txt")) as f:
        for line in f:
            if line.strip():
                samples[int(line.split()[0], 16)] += 1
    regions, rows = [], []
    for name in sorted(os.listdir(WORK)):
        if name.endswith(".asm"):
            lo = int(name[:-4], 16)
            hi = lo + os.path.getsize(os.path.join(WORK, name[:-4] + ".bin"))
            regions.append((lo, hi))
            with open(os.path.join(WORK, name)) as f:
                for line in f:
                    m = re.match(r"\s*([0-9a-f]+):\s+(?:[0-9a-f]{2} )+\s*([a-z].*)", line)
                    if m:
                        rows.append((int(m.group(1), 16), m.group(2)))
    rows.sort()
    return samples, regions, rows


def report(samples, regions, rows):
    total = sum(samples.values())
    print(f"{total} samples")
    for lo, hi in regions:
        n = sum(v for a, v in samples.items() if lo <= a < hi)
        if n > 0.005 * total:
            print(f"shader code {lo:x}-{hi:x} ({hi - lo} bytes): {100 * n / total:5.1f} %")
    kinds = collections.Counter()
    blocks = collections.defaultdict(lambda: [0, collections.Counter()])
    for a, text in rows:
        op = text.split()[0]
        kinds[classify(op, text)] += samples.get(a, 0)
        b = blocks[a >> 7]
        b[0] += samples.get(a, 0)
        b[1][op] += 1
    jit = sum(kinds.values())
    print("in the shaders, by kind of instruction:")
    for k, v in kinds.most_common():
        print(f"  {k:18s} {100 * v / max(jit, 1):5.1f} %")
    print("hottest 128-byte blocks (share of all samples, commonest instructions):")
    for k, (v, ops) in sorted(blocks.items(), key=lambda kv: -kv[1][0])[:20]:
        print(f"  {k << 7:x} {100 * v / total:5.2f} %  " + " ".join(o for o, _ in ops.most_common(7)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=4.0)
    ap.add_argument("--asm", help="print the block at this address from the last run")
    ap.add_argument("command", nargs="*", help="BINARY [profile args]")
    a = ap.parse_args()
    if a.asm:
        samples, _, rows = load()
        lo = int(a.asm, 16) & ~127
        for addr, text in rows:
            if lo <= addr < lo + 128:
                print(f"{addr:x} {samples.get(addr, 0):5d}  {text}")
        return
    if not a.command:
        ap.error("give the binary (and profile arguments) after --")
    for tool in ("perf", "gdb", "objdump"):
        if not shutil.which(tool):
            sys.exit(f"jit_profile: `{tool}` is not installed")
    record(a.command[0], a.command[1:], a.seconds)
    report(*load())


if __name__ == "__main__":
    main()
