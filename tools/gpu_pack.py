#!/usr/bin/env python3
"""Pack what a GPU machine needs to measure and test blackhole, into .gpu/.

A lent GPU machine (no Rust toolchain, no network) gets the repository's
working tree and the paths named to it; this puts beside the tree, in the
ignored folder .gpu/:

  bin/blackhole.xz     the release binary, stripped and xz'd
  tests/NAME.xz        the integration-test binaries, the same,
                       in the order of TESTS until BUDGET_MB is reached
  deb/*.deb            the Vulkan loader and the validation layer (Debian
                       packages, unpacked there by tools/gpu_run.sh)
  root                 the repository's path here: the test binaries have
                       it compiled in (CARGO_BIN_EXE_blackhole,
                       CARGO_TARGET_TMPDIR, CARGO_MANIFEST_DIR)

Then, on the machine, from the repository root: `bash tools/gpu_run.sh`
(docs/performance.md, "On a GPU", says what it measures and how it was run).

Usage (from the repository root):  python3 tools/gpu_pack.py [BUDGET_MB]
"""

import json
import lzma
import os
import shutil
import subprocess
import sys

# The test binaries that drive the device, most telling first (each is
# about 1 MB packed when it runs the CLI, 5 MB when it links the library).
# Not tests/window.rs: a lent GPU machine has no display and no Xvfb.
TESTS = [
    "render", "renderer", "kerr_gpu", "geodesic", "bake", "projections", "interior",
    "observer", "sky", "bloom", "look", "profile", "golden", "device", "graph",
    "hostile_cli", "film",
]
# The loader (as the device machine's README names it) and the layer.
DEBS = ["libvulkan1", "vulkan-validationlayers"]


def run(cmd, **kw):
    print("+", " ".join(cmd), flush=True)
    return subprocess.run(cmd, check=True, **kw)


def test_executables():
    """Name -> path of each integration test's binary, built now."""
    out = run(["cargo", "test", "--release", "--no-run", "--message-format=json"],
              stdout=subprocess.PIPE, text=True).stdout
    found = {}
    for line in out.splitlines():
        try:
            msg = json.loads(line)
        except json.JSONDecodeError:
            continue
        target = msg.get("target", {})
        if msg.get("reason") == "compiler-artifact" and msg.get("executable") \
                and "test" in target.get("kind", []):
            found[target["name"]] = msg["executable"]
    return found


def packed(src, dst):
    """src stripped and xz'd at dst + '.xz'; its size in MB."""
    shutil.copy(src, dst)
    run(["strip", dst])
    with open(dst, "rb") as f, lzma.open(dst + ".xz", "wb", preset=6) as z:
        z.write(f.read())
    os.remove(dst)
    return os.path.getsize(dst + ".xz") / 2**20


def main():
    budget = float(sys.argv[1]) if len(sys.argv) > 1 else 48.0
    root = os.getcwd()
    if not os.path.exists(os.path.join(root, "Cargo.toml")):
        sys.exit("gpu_pack: run from the repository root")
    pack = os.path.join(root, ".gpu")
    shutil.rmtree(pack, ignore_errors=True)
    for d in ("bin", "tests", "deb"):
        os.makedirs(os.path.join(pack, d))
    run(["cargo", "build", "--release"])
    used = packed("target/release/blackhole", os.path.join(pack, "bin", "blackhole"))
    exes = test_executables()
    for name in TESTS:
        if name not in exes:
            print(f"gpu_pack: no test binary named {name}, skipped")
            continue
        tmp = os.path.join(pack, "tests", name)
        size = packed(exes[name], tmp)
        if used + size > budget:
            os.remove(tmp + ".xz")
            print(f"gpu_pack: {name} ({size:.1f} MB) left out: over the {budget} MB budget")
            continue
        used += size
    run(["apt-get", "download", *DEBS], cwd=os.path.join(pack, "deb"))
    used += sum(os.path.getsize(os.path.join(pack, "deb", f))
                for f in os.listdir(os.path.join(pack, "deb"))) / 2**20
    with open(os.path.join(pack, "root"), "w") as f:
        f.write(root + "\n")
    print(f"gpu_pack: .gpu holds {used:.1f} MB; on the machine: bash tools/gpu_run.sh")


if __name__ == "__main__":
    main()
