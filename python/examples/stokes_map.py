"""A Stokes map with ticks from the Stokes AOV of the m87 preset: Stokes I
in afmhot, the electric vector's direction as ticks (length: polarized
intensity), north up and east left, with the image's numbers in the
title. Writes stokes_map.png."""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import blackhole  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "stokes_map.png"
r = blackhole.Renderer()
scene = blackhole.Scene.preset("m87")
n = 160
s = r.aov(scene, "stokes", n, n)
i, q, u = s[..., 0], s[..., 1], s[..., 2]
p = np.hypot(q, u)
# |m|_net and <|m|>, as the EHT reports them.
m_net = np.hypot(q.sum(), u.sum()) / i.sum()
m_avg = p.sum() / i.sum()
fig, ax = plt.subplots(figsize=(5, 5))
ax.imshow(i, cmap="afmhot", origin="upper")
# Ticks on a coarse grid: the angle chi east of north from Q and U (the
# image's up is north, its left east), length with P.
step = 10
ys, xs = np.mgrid[step // 2:n:step, step // 2:n:step]
chi = 0.5 * np.arctan2(u[ys, xs], q[ys, xs])
length = 0.9 * step * p[ys, xs] / p.max()
keep = i[ys, xs] > 0.1 * i.max()
dx, dy = -length * np.sin(chi), -length * np.cos(chi)  # east is left, north up
ax.quiver(xs[keep], ys[keep], dx[keep], dy[keep], color="cyan", headwidth=0, headlength=0,
          headaxislength=0, pivot="middle", angles="xy", scale_units="xy", scale=1)
ax.set_title(f"m87 Stokes AOV: |m|_net {m_net:.3f}, <|m|> {m_avg:.2f}")
ax.axis("off")
fig.tight_layout()
fig.savefig(out, dpi=100)
print("wrote", out)
