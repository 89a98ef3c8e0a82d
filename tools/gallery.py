#!/usr/bin/env python3
"""Re-render the README's pictures: docs/default.jpg, docs/interstellar.jpg
and docs/gallery.jpg (every preset, three columns).

Usage (from the repository root, after `cargo build --release`):
    pip install pillow
    python3 tools/gallery.py
"""

import os
import subprocess
import sys
import tempfile

from PIL import Image

BIN = os.path.join("target", "release", "blackhole")
PRESETS = ["default", "interstellar", "doppler", "grid", "binary", "edge-on",
           "no-gravity", "top-down", "falling"]


def render(out, scene, width, height, spp):
    subprocess.run([BIN, "render", "--scene", scene, "--width", str(width),
                    "--height", str(height), "--spp", str(spp), "--out", out],
                   check=True, stdout=subprocess.DEVNULL)
    return Image.open(out).convert("RGB")


def main():
    if not os.path.exists(BIN):
        sys.exit(f"{BIN} is missing: run `cargo build --release` first")
    with tempfile.TemporaryDirectory() as tmp:
        big = render(os.path.join(tmp, "default.png"), "default", 1280, 720, 8)
        big.resize((640, 360), Image.LANCZOS).save("docs/default.jpg", quality=88)
        big = render(os.path.join(tmp, "inter.png"), "interstellar", 1280, 720, 4)
        big.resize((640, 360), Image.LANCZOS).save("docs/interstellar.jpg", quality=88)
        w, h, gap = 320, 180, 8
        sheet = Image.new("RGB", (3 * w + 2 * gap, 3 * h + 2 * gap), (255, 255, 255))
        for i, name in enumerate(PRESETS):
            im = render(os.path.join(tmp, name + ".png"), name, 640, 360, 4)
            sheet.paste(im.resize((w, h), Image.LANCZOS),
                        ((i % 3) * (w + gap), (i // 3) * (h + gap)))
        sheet.save("docs/gallery.jpg", quality=85)
    print("wrote docs/default.jpg, docs/interstellar.jpg, docs/gallery.jpg")


if __name__ == "__main__":
    main()
