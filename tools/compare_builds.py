#!/usr/bin/env python3
"""Compare two builds of blackhole image by image: every preset at 320x180
and 640x360 (PNG), and the geodesic AOV (EXR) of each scene with a thin or no
disk, plus a few spinning-hole and projection cameras, and the Stokes AOV of
some of them. For a reshaping step
that must not change what is drawn.

A PNG passes when at most 0.1 % of its pixels differ by more than one 8-bit
level; an AOV when every outcome is equal and every value is within 1e-5
relative. Prints one line per comparison and the count of failures (exit 1
if any).

Usage (from the repository root):
    pip install numpy pillow OpenEXR
    python3 tools/compare_builds.py OLD_BINARY NEW_BINARY [OUT_DIR]

Keep the old binary before starting: `cp target/release/blackhole /tmp/old`.
"""

import os
import subprocess
import sys

import Imath
import numpy as np
import OpenEXR
from PIL import Image

PRESETS = ["default", "interstellar", "doppler", "grid", "binary", "edge-on",
           "no-gravity", "top-down", "falling", "gargantua", "kerr-doppler", "m87", "fields"]
# The scenes whose Stokes AOV (--aov stokes) is compared too.
STOKES = ["default", "m87", "fields", "spin09", "ergo", "retro", "fall05"]
EXTRA = {
    "spin09": '[[black_hole]]\nspin = 0.9\n',
    "ergo": '[[black_hole]]\nspin = 0.998\n[camera]\nposition = [0.8, 0.1, 0.2]\n'
            'look_at = [3.0, 0.5, 5.0]\nobserver = "zamo"\n',
    "retro": '[[black_hole]]\nspin = -0.7\n[camera]\nposition = [1.0, -2.0, -12.0]\n'
             'observer = "orbiting"\n',
    "fall05": '[[black_hole]]\nspin = 0.5\n[camera]\nposition = [3.0, 5.0, -6.0]\n'
              'observer = "falling"\n',
    "inside09": '[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.05, 0.5, -0.05]\n'
                'look_at = [0.0, -5.0, 1.0]\nobserver = "falling"\n',
    "inside0": '[camera]\nposition = [0.0, 0.1, -0.5]\nlook_at = [0.0, 0.0, 5.0]\n'
               'observer = "falling"\n',
    "fisheye": '[camera]\nprojection = "fisheye"\nvfov_deg = 180.0\n',
    "ods": '[camera]\nprojection = "equirect"\nstereo = "ods"\nipd = 0.2\n',
}
SIZES = [(320, 180), (640, 360)]


def render(binary, args, env):
    r = subprocess.run([binary, "render"] + args, env=env, capture_output=True, text=True)
    if r.returncode != 0:
        print("FAIL", binary, " ".join(args), r.stderr.strip().splitlines()[-1:])
    return r.returncode == 0


def read_exr(path):
    f = OpenEXR.InputFile(path)
    dw = f.header()["dataWindow"]
    w, h = dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1
    px = Imath.PixelType(Imath.PixelType.FLOAT)
    return np.stack([np.frombuffer(f.channel(c, px), dtype=np.float32).reshape(h, w)
                     for c in "RGBA"], -1)


def compare_png(a, b):
    # (RGBA both: a fisheye's PNG has alpha, a pinhole's not.)
    rgba = lambda f: np.asarray(Image.open(f).convert("RGBA")).astype(int)
    d = np.abs(rgba(a) - rgba(b)).max(-1)
    frac = (d > 1).mean()
    return frac <= 0.001, f"max diff {d.max():3d}, >1 level {100 * frac:.4f} %, identical {100 * (d == 0).mean():.3f} %"


def compare_aov(a, b):
    A, B = read_exr(a), read_exr(b)
    same = A[..., 3] == B[..., 3]
    diff = np.abs(A[..., :3] - B[..., :3])
    rel = np.where(np.abs(A[..., :3]) < 1e-30, diff, diff / np.maximum(np.abs(A[..., :3]), 1e-30))
    worst = rel[same].max() if same.any() else 0.0
    ok = same.all() and worst <= 1e-5
    return ok, f"outcomes equal {100 * same.mean():.3f} %, worst relative {worst:.2e}, bit-identical {100 * (A == B).all(-1).mean():.2f} %"


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    old, new = sys.argv[1], sys.argv[2]
    out = sys.argv[3] if len(sys.argv) > 3 else "target/compare-builds"
    os.makedirs(out, exist_ok=True)
    env = dict(os.environ, LP_NUM_THREADS=os.environ.get("LP_NUM_THREADS", "4"),
               XDG_CACHE_HOME=os.path.abspath(os.path.join(out, "cache")))
    for name, toml in EXTRA.items():
        with open(os.path.join(out, name + ".toml"), "w") as f:
            f.write(toml)
    scenes = PRESETS + [os.path.join(out, n + ".toml") for n in EXTRA]
    bad = 0

    def pair(args, what, ext, compare, label):
        """Renders args with both builds to OUT/what_{old,new}.ext and compares."""
        a, b = (os.path.join(out, f"{what}_{t}.{ext}") for t in ("old", "new"))
        if not (render(old, args + ["--out", a], env) and render(new, args + ["--out", b], env)):
            return 1
        ok, line = compare(a, b)
        print(f"{'ok ' if ok else 'BAD'} {label}: {line}")
        return int(not ok)

    for scene in scenes:
        name = os.path.basename(scene).removesuffix(".toml")
        for w, h in SIZES:
            size = ["--scene", scene, "--width", str(w), "--height", str(h)]
            bad += pair(size, f"{name}_{w}", "png", compare_png, f"png {name:14s} {w}x{h}")
        if name == "interstellar":
            continue  # the AOV describes thin-disk hits; a volumetric disk is refused
        args = ["--scene", scene, "--width", "320", "--height", "180", "--aov"]
        bad += pair(args + ["geodesic"], f"{name}_aov", "exr", compare_aov, f"aov {name:14s}")
        if name in STOKES:
            bad += pair(args + ["stokes"], f"{name}_stokes", "exr", compare_aov, f"stokes {name:11s}")
    print(f"{bad} comparisons failed")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
