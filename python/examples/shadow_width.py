"""The shadow's width against spin, measured from the geodesic AOV (the
captured pixels of the image's central row, seen from the disk's plane)
beside the closed form (the critical rays' lambda+ - lambda-): 3 sqrt(3)
rs wide at a* = 0, narrowing as the spin grows. Writes shadow_width.png."""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import blackhole  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "shadow_width.png"
r = blackhole.Renderer()
distance, vfov = 1000.0, 0.4  # rs, degrees: far enough that angles are lengths
scene = blackhole.Scene.from_toml(
    f"[camera]\nposition = [0.0, 0.0, {-distance}]\nvfov_deg = {vfov}\nobserver = \"zamo\"\n"
    "[disk]\nkind = \"none\"\n[sky]\nkind = \"black\"\n"
)
w, h = 256, 256
rs_per_pixel = 2 * distance * np.tan(np.radians(vfov) / 2) / h
spins = [0.0, 0.3, 0.6, 0.9, 0.99]
widths = []
for spin in spins:
    s = scene.with_key("black_hole", [{"spin": spin}])
    aov = r.aov(s, "geodesic", w, h)
    row = blackhole.outcome(aov)[h // 2]
    widths.append(float((row == "captured").sum() * rs_per_pixel))
fig, ax = plt.subplots(figsize=(5, 3.2))
fine = np.linspace(0.0, 0.99, 100)
closed = [abs(np.subtract(*blackhole.critical_lambdas(a))) / 2 for a in fine]
ax.plot(fine, closed, color="gray", ls="--", label="closed form |lambda+ - lambda-| M")
ax.plot(spins, widths, "o", label="geodesic AOV (captured pixels)")
ax.set_xlabel("spin a*")
ax.set_ylabel("shadow width in the disk's plane (rs)")
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=100)
print("wrote", out, "widths", [round(x, 3) for x in widths])
