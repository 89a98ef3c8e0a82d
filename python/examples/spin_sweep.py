"""A spin sweep as a matplotlib grid: the same view of a hole spinning at
a* = 0, 0.5, 0.9 and 0.998, seen nearly edge-on (the disk to each spin's
ISCO). Writes spin_sweep.png (or the path given)."""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import blackhole  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "spin_sweep.png"
r = blackhole.Renderer()
scene = blackhole.Scene.preset("gargantua")
spins = [0.0, 0.5, 0.9, 0.998]
fig, axes = plt.subplots(1, len(spins), figsize=(12, 2.4))
for ax, spin in zip(axes, spins):
    s = scene.with_key("black_hole.0.spin", spin)
    s["disk.inner_radius"] = blackhole.isco(spin)
    ax.imshow(r.render(s, 320, 180))
    ax.set_title(f"a* = {spin}, ISCO {blackhole.isco(spin):.2f} rs")
    ax.axis("off")
fig.tight_layout()
fig.savefig(out, dpi=100)
print("wrote", out)
