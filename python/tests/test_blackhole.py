"""The package against the command line: binding names, pixels equal to
the CLI's PNG, the AOVs, every exception path, threads and Ctrl-C."""

import os
import re
import signal
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

import blackhole

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("BLACKHOLE_BIN", str(ROOT / "target" / "release" / "blackhole"))


def cli_png(tmp_path, scene_args, width, height):
    """The command line's PNG of the same scene, as an (H, W, 4) array."""
    from PIL import Image

    out = tmp_path / "cli.png"
    subprocess.run(
        [CLI, "render", *scene_args, "--width", str(width), "--height", str(height), "--out", str(out)],
        check=True,
        capture_output=True,
    )
    return np.asarray(Image.open(out).convert("RGBA"))


def test_the_binding_names_exist():
    for name in ["Scene", "Renderer", "Error", "DeviceError", "FileError", "OUTCOMES", "outcome",
                 "horizons", "isco", "photon_orbits", "sequence", "light_path", "shadow_outline"]:
        assert hasattr(blackhole, name), name
    assert issubclass(blackhole.DeviceError, blackhole.Error)
    assert "gargantua" in blackhole.Scene.presets()


def test_a_still_is_the_clis_png(renderer, tmp_path):
    pytest.importorskip("PIL")
    scene = blackhole.Scene.preset("gargantua")
    img = renderer.render(scene, 96, 54)
    assert img.shape == (54, 96, 4) and img.dtype == np.uint8 and img.flags["C_CONTIGUOUS"]
    assert np.array_equal(img, cli_png(tmp_path, ["--scene", "gargantua"], 96, 54))


def test_a_scene_from_toml_text_is_the_clis_file(renderer, tmp_path):
    pytest.importorskip("PIL")
    text = "[camera]\nposition = [2.0, 1.0, -12.0]\nvfov_deg = 40.0\n"
    path = tmp_path / "s.toml"
    path.write_text(text)
    img = renderer.render(blackhole.Scene.from_toml(text), 64, 36)
    assert np.array_equal(img, cli_png(tmp_path, ["--scene", str(path)], 64, 36))
    assert np.array_equal(renderer.render(blackhole.Scene.load(path), 64, 36), img)


def read_exr(path):
    OpenEXR = pytest.importorskip("OpenEXR")
    import Imath

    f = OpenEXR.InputFile(str(path))
    dw = f.header()["dataWindow"]
    w, h = dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1
    px = Imath.PixelType(Imath.PixelType.FLOAT)
    return np.stack([np.frombuffer(f.channel(c, px), dtype=np.float32).reshape(h, w) for c in "RGBA"], axis=-1)


@pytest.mark.parametrize("args, aov", [(["--scene", "gargantua"], None), (["--scene", "default", "--aov", "geodesic"], "geodesic")])
def test_hdr_and_the_aov_are_the_clis_exr(renderer, tmp_path, args, aov):
    out = tmp_path / "cli.exr"
    subprocess.run([CLI, "render", *args, "--width", "64", "--height", "36", "--out", str(out)],
                   check=True, capture_output=True)
    want = read_exr(out)
    scene = blackhole.Scene.preset(args[1])
    got = renderer.aov(scene, aov, 64, 36) if aov else renderer.render(scene, 64, 36, hdr=True)
    assert got.shape == want.shape
    assert np.array_equal(got, want)


def test_hdr_and_the_aovs_have_their_shapes(renderer):
    scene = blackhole.Scene.preset("default")
    hdr = renderer.render(scene, 64, 36, hdr=True)
    assert hdr.shape == (36, 64, 4) and hdr.dtype == np.float32
    assert np.isfinite(hdr).all() and hdr[..., :3].max() > 0
    aov = renderer.aov(scene, "geodesic", 64, 36)
    assert aov.shape == (36, 64, 4) and aov.dtype == np.float32
    names = blackhole.outcome(aov)
    assert {"escaped", "captured", "disk"} <= set(np.unique(names))
    # The disk's pixels carry radii inside the annulus.
    r = aov[..., 0][names == "disk"]
    assert r.min() >= scene["disk.inner_radius"] - 1e-4 and r.max() <= scene["disk.outer_radius"] + 1e-4
    stokes = renderer.aov(blackhole.Scene.preset("m87"), "stokes", 64, 36)
    assert np.isfinite(stokes).all() and stokes[..., 0].max() > 0 and not stokes[..., 3].any()


def test_keys_read_and_write_through_the_validation():
    scene = blackhole.Scene.preset("gargantua")
    assert scene["black_hole.0.spin"] == pytest.approx(0.998)
    scene["camera.vfov_deg"] = 30
    assert scene.get("camera.vfov_deg") == 30.0
    wider = scene.with_key("camera.position", np.array([0.0, 2.0, -20.0]))
    assert wider["camera.position"] == [0.0, 2.0, -20.0] and scene["camera.position"] != [0.0, 2.0, -20.0]
    assert blackhole.Scene.from_toml(scene.to_toml()) == scene
    assert isinstance(scene.to_dict()["camera"], dict)


@pytest.mark.parametrize(
    "key, value, words",
    [
        ("camera.vfov_deg", -5, ["camera.vfov_deg = -5"]),
        ("camera.vfv", 5, ["vfv"]),
        ("black_hole.0.spin", 2.0, ["spin"]),
        ("disk.kind", "cloud", ["kind", "cloud"]),
        ("camera.vfov_deg", None, ["camera.vfov_deg"]),
        ("camera..up", 1, ["not a scene key"]),
    ],
)
def test_a_bad_key_or_value_raises_value_error_and_keeps_the_scene(key, value, words):
    scene = blackhole.Scene.preset("default")
    before = scene.to_toml()
    with pytest.raises(ValueError) as e:
        scene[key] = value
    for w in words:
        assert w in str(e.value), str(e.value)
    assert "\n" not in str(e.value)
    assert scene.to_toml() == before


def test_bad_calls_raise_value_error(renderer):
    scene = blackhole.Scene.preset("default")
    with pytest.raises(ValueError, match="preset"):
        blackhole.Scene.preset("nope")
    with pytest.raises(ValueError, match=":1: "):
        blackhole.Scene.from_toml("[camera\n")
    with pytest.raises(ValueError, match="AOVs"):
        renderer.aov(scene, "depth", 8, 8)
    with pytest.raises(ValueError):
        renderer.render(scene, 0, 10)
    with pytest.raises(ValueError):
        renderer.render(scene, 100000, 100000)
    with pytest.raises(ValueError, match="not both"):
        renderer.render(scene, 8, 8, time=1.0, frame=2)
    with pytest.raises(ValueError, match="finite"):
        renderer.render(scene, 8, 8, time=float("nan"))
    with pytest.raises(ValueError, match="width = -1"):
        renderer.render(scene, -1, 8)
    with pytest.raises(TypeError):
        renderer.render("default", 8, 8)
    with pytest.raises(ValueError, match="spin"):
        blackhole.horizons(1.5)
    with pytest.raises(blackhole.FileError):
        blackhole.Scene.preset("default").save("/nonexistent-dir/x.toml")
    with pytest.raises(ValueError):
        blackhole.Scene.load("/nonexistent-dir/x.toml")
    # The renderer works after each of them.
    assert renderer.render(scene, 8, 8).shape == (8, 8, 4)


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda r, s: r.render(s, 8, -3), "height = -3"),
        (lambda r, s: r.render(s, 2**40, 8), "width = 1099511627776"),
        (lambda r, s: r.render(s, 8, 8, spp=0), "spp = 0"),
        (lambda r, s: r.render(s, 8, 8, spp=-1), "spp = -1"),
        (lambda r, s: r.render(s, 8, 8, spp=10**9), "spp = 1000000000"),
        (lambda r, s: r.render(s, 8, 8, frame=-1), "frame = -1"),
        (lambda r, s: r.aov(s, "geodesic", 50000, 50000), "50000x50000"),
        (lambda r, s: r.profile(s, 8, 8, frames=0), "frames"),
        (lambda r, s: r.profile(s, 8, 8, frames=10**9), "frames"),
        (lambda r, s: r.profile(s, 8, 8, warmup=-1), "warmup = -1"),
        (lambda r, s: list(r.sequence(s, 8, 8, [-1])), "frame = -1"),
        (lambda r, s: blackhole.light_path(s, -1, 0, 8, 8), "x = -1"),
        (lambda r, s: blackhole.light_path(s, 0, 0, 8, 8, samples=10**12), "samples"),
        (lambda r, s: blackhole.shadow_outline(0.5, 60.0, n=-4), "n = -4"),
    ],
)
def test_numbers_out_of_range_raise_value_error_before_any_work(renderer, call, words):
    # Sizes and counts past the limits are refused by name before anything
    # is allocated or rendered (the command line's limits: --spp 1 to 1024,
    # --frames 1 to 100000), never an OverflowError that names no argument.
    scene = blackhole.Scene.preset("default")
    with pytest.raises(ValueError, match=re.escape(words)):
        call(renderer, scene)
    assert renderer.render(scene, 8, 8).shape == (8, 8, 4)


def test_wrong_types_and_none_raise_type_error(renderer):
    scene = blackhole.Scene.preset("default")
    for call in [
        lambda: renderer.render(None, 8, 8),
        lambda: renderer.render(scene, "8", 8),
        lambda: renderer.render(scene, 8.5, 8),
        lambda: renderer.render(scene, None, 8),
        lambda: renderer.aov(scene, None, 8, 8),
        lambda: renderer.render(scene, 8, 8, time="0"),
        lambda: scene.get(None),
        lambda: blackhole.Scene.from_toml(None),
        lambda: blackhole.isco(None),
    ]:
        with pytest.raises(TypeError):
            call()
    with pytest.raises(ValueError, match="not a scene value"):
        scene.set("camera.vfov_deg", None)


def test_outcome_refuses_what_is_not_a_geodesic_aov(renderer):
    with pytest.raises(ValueError, match="geodesic AOV"):
        blackhole.outcome(np.zeros(3))
    with pytest.raises(ValueError, match="geodesic AOV"):
        blackhole.outcome(np.zeros((2, 2, 3), dtype=np.float32))
    odd = np.zeros((1, 3, 4), dtype=np.float32)
    odd[0, :, 3] = [np.nan, -1.0, 2.0]
    assert list(blackhole.outcome(odd)[0]) == ["unknown", "unknown", "disk"]


def test_a_scene_edited_into_an_invalid_state_is_refused_and_kept():
    scene = blackhole.Scene.preset("default")
    before = scene.to_toml()
    with pytest.raises(ValueError, match="fall_end_radius"):
        scene.set("animation.fall_end_radius", 1e3)
    with pytest.raises(ValueError, match="polarization.field"):
        scene.set("polarization.field", [0.0, 0.0, 0.0])
    assert scene.to_toml() == before


def _run_python(script, env=None, timeout=120):
    e = dict(os.environ)
    e.update(env or {})
    p = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, env=e, timeout=timeout
    )
    return p.returncode, p.stdout, p.stderr


def test_a_lost_device_raises_device_error_on_every_call_and_never_hangs():
    # BLACKHOLE_FAULT=device-lost: the first frame's wait returns
    # ERROR_DEVICE_LOST while the GPU still runs it, as a real lost device
    # does. Every later call raises DeviceError too (a lost device stays
    # lost), closing works, and the process exits normally.
    script = (
        "import blackhole\n"
        "r = blackhole.Renderer(); s = blackhole.Scene()\n"
        "for call in [lambda: r.render(s, 16, 9), lambda: r.render(s, 16, 9),\n"
        "             lambda: r.aov(s, 'geodesic', 8, 8), lambda: r.profile(s, 8, 8, frames=2)]:\n"
        "    try:\n"
        "        call(); print('rendered')\n"
        "    except blackhole.DeviceError as e:\n"
        "        print('lost' if 'lost' in str(e) else e)\n"
        "r.close(); print('closed')\n"
    )
    code, out, err = _run_python(script, {"BLACKHOLE_FAULT": "device-lost"})
    assert code == 0, err
    assert out.split() == ["lost", "lost", "lost", "lost", "closed"], out + err


def test_a_closed_renderer_raises_device_error():
    r = blackhole.Renderer()
    r.close()
    with pytest.raises(blackhole.DeviceError, match="closed"):
        r.render(blackhole.Scene(), 8, 8)


def test_frames_and_times_are_the_animations(renderer):
    scene = blackhole.Scene.preset("plunge")
    frames = list(renderer.sequence(scene, 32, 18, range(2)))
    assert len(frames) == 2 and not np.array_equal(frames[0], frames[1])
    at = renderer.render(scene, 32, 18, time=1.0 / scene.fps)
    assert np.array_equal(at, frames[1])


def test_one_renderer_serves_several_threads(renderer):
    scene = blackhole.Scene.preset("default")
    want = renderer.render(scene, 48, 27)
    got = [None] * 4

    def work(i):
        got[i] = renderer.render(scene, 48, 27)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(g, want) for g in got)


def test_threads_that_fail_leave_the_others_and_the_renderer_working(renderer):
    scene = blackhole.Scene.preset("default")
    want = renderer.render(scene, 32, 18)
    results = [None] * 8

    def work(i):
        try:
            if i % 2:
                renderer.render(scene, 32, 18, spp=0 if i % 4 == 1 else 5000)
            results[i] = renderer.render(scene, 32, 18)
        except ValueError as e:
            results[i] = e

    threads = [threading.Thread(target=work, args=(i,)) for i in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert all(not t.is_alive() for t in threads)
    for i, r in enumerate(results):
        if i % 2:
            assert isinstance(r, ValueError) and "spp" in str(r)
        else:
            assert np.array_equal(r, want)
    assert renderer.validation_counts() == (0, 0)


def test_the_physics_is_the_closed_form():
    assert blackhole.horizons(0.0) == (1.0, 0.0)
    outer, inner = blackhole.horizons(0.6, rs=2.0)
    assert outer == pytest.approx(1 + 0.8) and inner == pytest.approx(1 - 0.8)
    assert blackhole.isco(0.0) == pytest.approx(3.0)
    assert blackhole.photon_orbits(0.0) == pytest.approx((1.5, 1.5))
    assert blackhole.critical_lambdas(0.0) == pytest.approx((3 * 3**0.5, -3 * 3**0.5))


def test_the_shadow_outline_meets_the_rendered_shadow(renderer):
    circle = blackhole.shadow_outline(0.0, 60.0, n=64)
    assert circle.shape == (128, 2) and np.allclose(np.hypot(*circle.T), 1.5 * 3**0.5)
    # Edge-on, its ends on the equator are the equatorial critical rays.
    edge = blackhole.shadow_outline(0.9, 90.0)
    width = edge[:, 0].max() - edge[:, 0].min()
    assert width == pytest.approx(abs(np.subtract(*blackhole.critical_lambdas(0.9))) / 2, rel=1e-9)
    # From 60 degrees off the axis, 1000 rs away: the captured pixels'
    # extent across and along the image matches the outline's to a pixel.
    spin, inc, dist, vfov, n = 0.9, 60.0, 1000.0, 0.4, 256
    t = np.radians(inc)
    scene = blackhole.Scene.from_toml(
        f"[[black_hole]]\nspin = {spin}\n[camera]\nposition = [0.0, {dist * np.cos(t)}, {-dist * np.sin(t)}]\n"
        f"vfov_deg = {vfov}\nobserver = \"zamo\"\n[disk]\nkind = \"none\"\n[sky]\nkind = \"black\"\n"
    )
    captured = blackhole.outcome(renderer.aov(scene, "geodesic", n, n)) == "captured"
    pixel = 2 * dist * np.tan(np.radians(vfov) / 2) / n
    rows, cols = np.nonzero(captured)
    outline = blackhole.shadow_outline(spin, inc)
    assert (cols.max() - cols.min() + 1) * pixel == pytest.approx(np.ptp(outline[:, 0]), abs=2 * pixel)
    assert (rows.max() - rows.min() + 1) * pixel == pytest.approx(np.ptp(outline[:, 1]), abs=2 * pixel)
    with pytest.raises(ValueError, match="inclination"):
        blackhole.shadow_outline(0.5, 200.0)


@pytest.mark.parametrize("preset", ["default", "gargantua"])
def test_a_pixels_light_path_ends_where_its_geodesic_aov_says(renderer, preset):
    scene = blackhole.Scene.preset(preset)
    w, h = 24, 14
    aov = renderer.aov(scene, "geodesic", w, h)
    names = blackhole.outcome(aov)
    hole = np.array(scene["black_hole.0.position"], dtype=float)
    camera = np.array(scene["camera.position"], dtype=float)
    seen = set()
    for y in range(0, h, 3):
        for x in range(0, w, 3):
            path = blackhole.light_path(scene, x, y, w, h, samples=200)
            pts = path["points"]
            assert pts.dtype == np.float64 and pts.ndim == 2 and pts.shape[1] == 3
            assert pts.flags["C_CONTIGUOUS"] and np.isfinite(pts).all()
            assert np.allclose(pts[0], camera, atol=1e-9)
            assert path["outcome"] == names[y, x], (x, y)
            seen.add(path["outcome"])
            if path["outcome"] == "disk":
                # The AOV's radius (channel 0: Boyer-Lindquist r, rs) at the
                # path's last point, in the disk's plane at sqrt(r^2 + a^2).
                a = 0.5 * scene["black_hole.0.spin"]
                r = np.sqrt(np.sum((path["end"] - hole) ** 2) - a * a)
                assert np.allclose(pts[-1], path["end"], atol=1e-9)
                assert abs(r - aov[y, x, 0]) < 1e-4 * r, (x, y, r, aov[y, x])
    assert {"escaped", "disk"} <= seen, seen
    with pytest.raises(ValueError, match="outside the 24x14 image"):
        blackhole.light_path(scene, 24, 0, w, h)
    with pytest.raises(ValueError, match="samples"):
        blackhole.light_path(scene, 0, 0, w, h, samples=1)
    with pytest.raises(ValueError, match="reach"):
        blackhole.light_path(scene, 0, 0, w, h, reach=-1.0)


def test_a_light_path_from_inside_the_horizon_is_refused():
    scene = blackhole.Scene.from_toml('[camera]\nposition = [0.0, 0.2, -0.5]\nobserver = "falling"\n')
    with pytest.raises(ValueError, match="outside the horizon"):
        blackhole.light_path(scene, 3, 3, 8, 8)


@pytest.mark.parametrize("preset", ["default", "gargantua"])
def test_the_trace_fan_is_arrays_of_paths(preset):
    paths = blackhole.photon_paths(blackhole.Scene.preset(preset), extent=8.0)
    assert any(p["captured"] for p in paths) and any(not p["captured"] for p in paths)
    rh = blackhole.horizons(blackhole.Scene.preset(preset)["black_hole.0.spin"])[0]
    for p in paths:
        for piece in p["pieces"]:
            assert piece.ndim == 2 and piece.shape[1] == 2 and piece.dtype == np.float64
            assert np.abs(piece).max() <= 8.0 + 1e-9
            # No point inside the horizon (x, y in rs, the hole at the origin).
            assert np.hypot(piece[:, 0], piece[:, 1]).min() >= 0.99 * rh
    with pytest.raises(ValueError, match="extent"):
        blackhole.photon_paths(blackhole.Scene(), extent=-1.0)


def test_ctrl_c_raises_keyboard_interrupt_within_a_sample():
    script = (
        "import sys, blackhole\n"
        "r = blackhole.Renderer(); s = blackhole.Scene.preset('interstellar')\n"
        "r.render(s, 16, 16)\n"
        "print('started', flush=True)\n"
        "try:\n"
        "    r.render(s, 320, 180, spp=1024)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "    assert r.render(s, 16, 16).shape == (16, 16, 4)\n"
        "    print('rendered again', flush=True); sys.exit(3)\n"
    )
    p = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "started"
    import time

    time.sleep(1.0)
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    # The renderer works after the interrupt.
    assert p.returncode == 3 and "interrupted" in out and "rendered again" in out


@pytest.mark.parametrize("name", ["spin_sweep", "shadow_width", "stokes_map"])
def test_the_examples_run_headless(tmp_path, name):
    pytest.importorskip("matplotlib")
    out = tmp_path / f"{name}.png"
    script = ROOT / "python" / "examples" / f"{name}.py"
    env = dict(os.environ, MPLBACKEND="Agg")
    run = subprocess.run([sys.executable, str(script), str(out)], env=env, capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr
    assert out.stat().st_size > 10_000


@pytest.mark.parametrize("spin", [0.0, 0.9999, -0.9])
def test_the_stokes_aov_has_no_nan_for_any_field_or_observer(renderer, spin):
    # Fields along the line of sight, the disk's normal and the camera's
    # axis, cameras face-on, edge-on, on the axis and far: where the angle
    # is undefined (sin theta_B = 0, no polarized light) P = 0, never NaN.
    cases = [
        ("[0, 20, 0.0]", "[0, 1, 0]", "static"),
        ("[0, 1, 20]", "[0, 0, 1]", "zamo"),
        ("[3, 0.01, 0]", "[1, 0, 0]", "falling"),
        ("[1e4, 1, 1]", "[0.3, 0.4, 0.5]", "orbiting"),
        ("[0, -20, 0]", "[0, 1, 0]", "falling"),
    ]
    for position, field, observer in cases:
        scene = blackhole.Scene.from_toml(
            f"[[black_hole]]\nspin = {spin}\n[camera]\nposition = {position}\n"
            f'look_at = [0, 0, 0]\nup = [0, 0, 1]\nobserver = "{observer}"\n'
            f"[polarization]\nfield = {field}\n"
        )
        stokes = renderer.aov(scene, "stokes", 24, 14)
        assert np.isfinite(stokes).all(), (spin, position, field, observer)
    assert renderer.validation_counts() == (0, 0)


@pytest.mark.parametrize("spin", [0.0, 0.9, -0.6])
def test_a_falling_camera_inside_the_horizon_sees_the_polarized_disk(renderer, spin):
    # Between the horizons (or inside the non-rotating hole's), on the spin
    # axis, near the disk's plane and looking back in: finite everywhere, the
    # disk polarized where it is seen, nothing circular.
    seen = 0
    for position, look, field in [
        ("[0.0, 0.5, 0.0]", "[0.3, -1.0, -3.0]", "[0, 0, 1]"),
        ("[0.5, 0.05, -0.4]", "[2.0, 0.0, -1.6]", "[0.87, 0.5, 0]"),
        ("[0.2, 0.3, -0.3]", "[0, 0, 0]", "[1, 0, 0]"),
    ]:
        scene = blackhole.Scene.from_toml(
            f"[[black_hole]]\nspin = {spin}\n[camera]\nposition = {position}\n"
            f'look_at = {look}\nvfov_deg = 110\nobserver = "falling"\n'
            f"[polarization]\nfield = {field}\n"
        )
        stokes = renderer.aov(scene, "stokes", 32, 18)
        assert np.isfinite(stokes).all(), (spin, position)
        assert not stokes[..., 3].any()
        i, p = stokes[..., 0], np.hypot(stokes[..., 1], stokes[..., 2])
        assert (p <= 0.7 * i * (1 + 1e-5) + 1e-30).all(), (spin, position)
        seen += int((i > 0).sum())
    assert seen > 20, seen
    assert renderer.validation_counts() == (0, 0)


@pytest.mark.parametrize("spin", [0.0, 0.9])
def test_the_volumetric_disk_is_polarized_sample_by_sample(renderer, spin):
    # The gas's Stokes vectors summed along each ray: finite, nothing
    # circular, P at most the emitted fraction of I (samples at different
    # angles only lower it), and a thin slab draws the thin disk's angle.
    def stokes_of(disk):
        scene = blackhole.Scene.from_toml(
            f"[[black_hole]]\nspin = {spin}\n[camera]\nposition = [1.0, 3.0, -14.0]\n"
            f"vfov_deg = 50\n[disk]\ninner_radius = 3.0\nouter_radius = 10.0\n{disk}"
        )
        return renderer.aov(scene, "stokes", 48, 27)

    thick = stokes_of('kind = "volumetric"\nheight = 0.5\n')
    assert np.isfinite(thick).all() and not thick[..., 3].any()
    i, p = thick[..., 0], np.hypot(thick[..., 1], thick[..., 2])
    assert (i > 0).sum() > 200
    assert (p <= 0.7 * i * (1 + 1e-5) + 1e-30).all()
    slab = stokes_of('kind = "volumetric"\nheight = 0.002\n')
    thin = stokes_of('kind = "thin"\n')
    both = (slab[..., 0] > 0) & (thin[..., 0] > 0)
    both &= np.hypot(slab[..., 1], slab[..., 2]) > 0.99 * 0.7 * slab[..., 0]
    assert both.sum() > 200, both.sum()
    chi = lambda s: 0.5 * np.arctan2(s[..., 2], s[..., 1])
    d = chi(slab) - chi(thin)
    d = np.abs(0.5 * np.arctan2(np.sin(2 * d), np.cos(2 * d)))[both]
    assert np.percentile(d, 99) < 1e-3, np.percentile(d, 99)
    assert renderer.validation_counts() == (0, 0)
