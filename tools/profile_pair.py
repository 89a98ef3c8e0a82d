#!/usr/bin/env python3
"""Time two builds of blackhole against each other in one sitting:
`blackhole profile` of the same scenes at the same size, the two builds
alternated round by round (A B, then B A, ...), so a machine whose speed
drifts affects both alike. Prints, per scene, each round's frame median and
the ratio NEW / OLD, and the median GPU time of each pass.

Usage (from the repository root):
    python3 tools/profile_pair.py OLD_BINARY NEW_BINARY [ROUNDS] [WIDTHxHEIGHT]

Timings on a CPU driver wander 10-30 % between runs: quote the ratios of one
sitting, not absolute milliseconds from different ones.
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile

# (label, --scene, frames)
SCENES = [("default", "default", 20), ("spin 0.9", None, 20), ("interstellar", "interstellar", 8)]
if os.environ.get("PAIR_SCENES"):
    SCENES = [(s, s, 10) for s in os.environ["PAIR_SCENES"].split(",")]


def profile(binary, scene, size, frames, env):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([binary, "profile", "--scene", scene, "--width", str(size[0]),
                        "--height", str(size[1]), "--frames", str(frames), "--json", out.name],
                       env=env, capture_output=True, check=True)
        d = json.load(open(out.name))
    return d["frame"]["median_ms"], {p["name"]: p["median_ms"] for p in d["passes"]}


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    old, new = sys.argv[1], sys.argv[2]
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    size = tuple(int(x) for x in (sys.argv[4] if len(sys.argv) > 4 else "1280x720").split("x"))
    env = dict(os.environ, LP_NUM_THREADS=os.environ.get("LP_NUM_THREADS", "4"))
    spin = tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False)
    spin.write("[[black_hole]]\nspin = 0.9\n")
    spin.close()
    results = {}
    for r in range(rounds):
        for label, scene, frames in SCENES:
            pair = [("old", old), ("new", new)]
            for tag, binary in pair if r % 2 == 0 else pair[::-1]:
                results.setdefault((label, tag), []).append(
                    profile(binary, scene or spin.name, size, frames, env))
    for label, _, _ in SCENES:
        o, n = results[(label, "old")], results[(label, "new")]
        ratios = [b[0] / a[0] for a, b in zip(o, n)]
        print(f"{label}: frame ms old {[round(x[0], 1) for x in o]}, new {[round(x[0], 1) for x in n]}, "
              f"new/old {[round(x, 3) for x in ratios]}, median {statistics.median(ratios):.3f}")
        for p in n[0][1]:
            before = [x[1].get(p) for x in o]
            if None in before:
                continue
            after = [x[1][p] for x in n]
            print(f"    {p:22s} old {statistics.median(before):8.2f}  new {statistics.median(after):8.2f}  "
                  f"ratio {statistics.median(after) / statistics.median(before):.3f}")
    os.unlink(spin.name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
