"""Python against the command line (docs/performance.md, "Python"): a
still's GPU time, 100 geodesic AOVs in one process against 100 CLI runs,
and the resident memory over 1000 renders.

Usage (from the repository root, the package installed, the CLI built):
    python tools/python_bench.py
"""
import os
import subprocess
import time

import blackhole
CLI = os.environ.get("BLACKHOLE_BIN", "target/release/blackhole")
r = blackhole.Renderer()
s = blackhole.Scene.preset("gargantua")
# 1. A still, 640x360: the profile's frame (same code path) vs the CLI's profile.
py = r.profile(s, 640, 360, frames=10)["frame"]["median_ms"]
t = time.time(); r.render(s, 640, 360); still_wall = (time.time() - t) * 1e3
out = subprocess.run([CLI, "profile", "--scene", "gargantua", "--width", "640", "--height", "360", "--frames", "10"],
                     capture_output=True, text=True).stdout
cli = float([l.split()[1] for l in out.splitlines() if l.startswith("frame")][0])
print(f"still 640x360 gargantua: python profile frame {py:.1f} ms, CLI profile frame {cli:.1f} ms, python render() wall {still_wall:.1f} ms")
# 2. 100 AOVs of 64x36.
g = blackhole.Scene.preset("default")
r.aov(g, "geodesic", 64, 36)
t = time.time()
for _ in range(100):
    r.aov(g, "geodesic", 64, 36)
py100 = time.time() - t
t = time.time()
for i in range(100):
    subprocess.run([CLI, "render", "--aov", "geodesic", "--width", "64", "--height", "36", "--out", "/tmp/blackhole-bench-aov.exr"],
                   check=True, capture_output=True)
cli100 = time.time() - t
print(f"100 geodesic AOVs 64x36: python {py100:.2f} s, CLI runs {cli100:.2f} s, ratio {cli100/py100:.1f}x")
# 3. Memory over 1000 renders.
def rss():
    return int(open("/proc/self/statm").read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20
small = blackhole.Scene.preset("default")
for _ in range(20): r.render(small, 64, 36)
m0 = rss()
for i in range(1000):
    r.render(small, 64, 36)
    if i == 499: m1 = rss()
m2 = rss()
print(f"RSS after 20 renders {m0:.1f} MiB, after 520 {m1:.1f} MiB, after 1020 {m2:.1f} MiB")
