#!/usr/bin/env bash
# The GPU figures of docs/performance.md ("On a GPU") in one run, on a
# machine with no Rust toolchain and no network: what tools/gpu_pack.py put
# in .gpu/ (the stripped binary, the test binaries, the loader and the
# validation layer). From the repository root:
#
#   bash tools/gpu_run.sh            # profiles at 3840x2160, then the tests
#
# Writes three files to $OUT (default ./gpu-out): device.txt (the device and
# driver), profile.txt (`blackhole profile` of each scene, per pass) and
# tests.txt (each test binary's output and a summary line). SIZE=WxH,
# FRAMES=N and TESTS="render bake ..." narrow a run (a try on lavapipe:
# SIZE=320x180 FRAMES=3 TESTS=bake).
set -u
cd "$(dirname "$0")/.." || exit 1
OUT=${OUT:-$PWD/gpu-out}
SIZE=${SIZE:-3840x2160}
FRAMES=${FRAMES:-50}
W=${SIZE%x*}
H=${SIZE#*x}
mkdir -p "$OUT"
[ -f .gpu/root ] || { echo "gpu_run: no .gpu/ (run python3 tools/gpu_pack.py first)"; exit 1; }

# The loader where the system has none (the machine's README: unpacked into
# /), the validation layer beside it in /tmp.
if ! ldconfig -p | grep -q 'libvulkan.so.1 '; then
    for f in .gpu/deb/libvulkan1_*.deb; do dpkg -x "$f" /; done
    ldconfig
fi
rm -rf /tmp/vvl && mkdir -p /tmp/vvl
for f in .gpu/deb/vulkan-validationlayers_*.deb; do dpkg -x "$f" /tmp/vvl; done
export VK_LAYER_PATH=/tmp/vvl/usr/share/vulkan/explicit_layer.d
export LD_LIBRARY_PATH=/tmp/vvl/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
nv=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -z "${VK_DRIVER_FILES:-}" ] && [ -f "$nv" ]; then export VK_DRIVER_FILES=$nv; fi
export XDG_CACHE_HOME=/tmp/gpu-xdg

# The test binaries look for the binary, their scratch space and the
# repository at the path they were built in.
root=$(cat .gpu/root)
if [ "$root" != "$PWD" ] && [ ! -e "$root" ]; then
    mkdir -p "$(dirname "$root")" && ln -s "$PWD" "$root"
fi
unxz() {  # FILE.xz DEST (the machine's python3: xz itself may be missing)
    python3 -c 'import lzma,sys; open(sys.argv[2],"wb").write(lzma.open(sys.argv[1]).read())' "$1" "$2" \
        && chmod +x "$2"
}
mkdir -p target/release target/tmp
unxz .gpu/bin/blackhole.xz target/release/blackhole || exit 1
B=$PWD/target/release/blackhole

{
    date -u
    command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv
    "$B" profile --width 64 --height 64 --frames 1 2>&1 | grep -i "device\|at 64x64"
} >"$OUT/device.txt" 2>&1

# The scenes: the presets, the default view spun up (with the 64-bit roots
# and without), a dome master and VR.
s=/tmp/gpu-scenes && mkdir -p $s
printf '[[black_hole]]\nspin = 0.9\n' >$s/spin09.toml
printf '[camera]\nprojection = "fisheye"\nvfov_deg = 180.0\n' >$s/dome.toml
printf '[camera]\nprojection = "equirect"\nstereo = "ods"\n' >$s/vr.toml
profile() {  # label, env, scene, width, height
    echo "== $1 (${2:-no env}) ${4}x${5}"
    env $2 "$B" profile --scene "$3" --width "$4" --height "$5" --frames "$FRAMES" --warmup 3 2>&1 \
        | grep -v '^\[' || echo "(exit ${PIPESTATUS[0]})"
}
{
    profile default "" default "$W" "$H"
    profile interstellar "" interstellar "$W" "$H"
    profile gargantua "" gargantua "$W" "$H"
    profile "spin 0.9" "" $s/spin09.toml "$W" "$H"
    profile "spin 0.9, 32-bit roots" "BLACKHOLE_NO_F64=1" $s/spin09.toml "$W" "$H"
    profile "default, one dispatch" "BLACKHOLE_NO_SPLIT=1" default "$W" "$H"
    # (4096 a side at the full size: a 4Kx4K dome master, two 4096x2048
    # panoramas for the eyes.)
    side=$([ "$SIZE" = 3840x2160 ] && echo 4096 || echo "$H")
    profile "dome master (fisheye 180)" "" $s/dome.toml "$side" "$side"
    profile "VR (equirect, ods stereo)" "" $s/vr.toml "$side" "$side"
} >"$OUT/profile.txt" 2>&1

# The test binaries, one at a time (each timed out at TEST_TIMEOUT seconds,
# 150 unless set).
rm -rf /tmp/gpu-tests && mkdir -p /tmp/gpu-tests
{
    for z in .gpu/tests/*.xz; do
        name=$(basename "$z" .xz)
        case " ${TESTS:-$name} " in *" $name "*) ;; *) continue ;; esac
        unxz "$z" /tmp/gpu-tests/$name
        echo "== $name"
        log=/tmp/gpu-tests/$name.log
        timeout "${TEST_TIMEOUT:-150}" /tmp/gpu-tests/$name --test-threads=4 >"$log" 2>&1
        rc=$?
        cat "$log"
        echo "== $name: exit $rc, $(grep '^test result' "$log" | tail -1)" | tee -a /tmp/gpu-tests/summary
    done
    echo "== summary"
    cat /tmp/gpu-tests/summary
} >"$OUT/tests.txt" 2>&1
tail -n 30 "$OUT/tests.txt"
