"""blackhole: exact black-hole images in a notebook.

The renderer's scenes, stills (uint8 sRGB or float32 linear HDR), AOVs and
per-pass timings as numpy arrays, and the f64 physics of a hole (horizons,
photon orbits, ISCO) without a GPU. docs/python.md is the guide::

    import blackhole
    scene = blackhole.Scene.preset("gargantua")
    r = blackhole.Renderer()
    img = r.render(scene, 640, 360)            # (360, 640, 4) uint8
    aov = r.aov(scene, "geodesic", 64, 36)     # (36, 64, 4) float32
"""

from typing import Iterable, Iterator, Optional

import numpy as np

from ._blackhole import (
    DeviceError,
    Error,
    FileError,
    Renderer,
    Scene,
    critical_lambdas,
    horizons,
    isco,
    light_path,
    photon_orbits,
    photon_paths,
    shadow_outline,
)

__all__ = [
    "DeviceError",
    "Error",
    "FileError",
    "OUTCOMES",
    "Renderer",
    "Scene",
    "critical_lambdas",
    "horizons",
    "isco",
    "light_path",
    "outcome",
    "photon_orbits",
    "photon_paths",
    "sequence",
    "shadow_outline",
]

#: The geodesic AOV's outcome codes (channel 3): where each pixel's light
#: path went (docs/physics.md, "The geodesic AOV").
OUTCOMES = {
    0: "escaped",
    1: "captured",
    2: "disk",
    3: "no steps",
    4: "no ray",
    5: "other universe",
}


def outcome(aov: np.ndarray) -> np.ndarray:
    """The outcome of each pixel of a geodesic AOV as a (H, W) array of
    names (``OUTCOMES``): ``outcome(aov) == "disk"`` masks the disk."""
    aov = np.asarray(aov)
    if aov.ndim != 3 or aov.shape[2] != 4 or not np.issubdtype(aov.dtype, np.number):
        raise ValueError(
            f"outcome: expects a geodesic AOV, a numeric (H, W, 4) array; this one is {aov.dtype} {aov.shape}"
        )
    names = np.array([OUTCOMES.get(i, "unknown") for i in range(max(OUTCOMES) + 1)] + ["unknown"])
    code = aov[..., 3].astype(np.float64)
    known = np.isfinite(code) & (code >= 0) & (code < len(names) - 1) & (code == np.floor(code))
    return names[np.where(known, np.nan_to_num(code), len(names) - 1).astype(np.int64)]


def sequence(
    renderer: Renderer,
    scene: Scene,
    width: int,
    height: int,
    frames: Iterable[int],
    *,
    hdr: bool = False,
    spp: int = 1,
) -> Iterator[np.ndarray]:
    """The frames of the scene's animation (indices as `render --frames`),
    one array each, rendered as they are asked for."""
    for i in frames:
        yield renderer.render(scene, width, height, hdr=hdr, spp=spp, frame=int(i))


def _sequence_method(self, scene, width, height, frames, *, hdr=False, spp=1):
    return sequence(self, scene, width, height, frames, hdr=hdr, spp=spp)


_sequence_method.__doc__ = sequence.__doc__
Renderer.sequence = _sequence_method  # type: ignore[attr-defined]
