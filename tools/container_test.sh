#!/usr/bin/env bash
# Builds the container image of tools/container/Containerfile from a Debian
# root file system made here (mmdebstrap, imported with podman: no registry
# needed) and renders in it: a still and a sequence of frames written to
# the output volume, each identical to the same render outside the
# container (the same binary on the same lavapipe).
#
# Usage (root, or sudo; from the repository root, after `cargo build
# --release`):  bash tools/container_test.sh [BINARY]
# It installs podman, mmdebstrap and runc from Debian if they are missing.
#
# On these machines (a gVisor sandbox, cgroups v1 with a v2 hierarchy
# beside) podman runs with runc and cgroupfs, and with the open-file and
# process limits set below the sandbox's (crun cannot run here at all:
# "cgroups in hybrid mode not supported"; without the limits either runtime
# fails to raise them). A normal host needs none of these flags.
set -euo pipefail
cd "$(dirname "$0")/.."

bin=$(realpath "${1:-target/release/blackhole}")
[ -x "$bin" ] || { echo "container_test: no binary at $bin (cargo build --release)" >&2; exit 2; }
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
need=()
command -v podman >/dev/null || need+=(podman)
command -v mmdebstrap >/dev/null || need+=(mmdebstrap)
command -v runc >/dev/null || need+=(runc)
if [ ${#need[@]} -gt 0 ]; then
    export DEBIAN_FRONTEND=noninteractive
    $sudo_cmd apt-get update -qq
    $sudo_cmd apt-get install -y -qq --no-install-recommends "${need[@]}" uidmap >/dev/null
fi

log() { echo "container_test: $*"; }
work=$(mktemp -d /tmp/blackhole-container.XXXXXX)
podman=(podman --runtime runc --cgroup-manager=cgroupfs)
cleanup() {
    "${podman[@]}" rmi -f localhost/blackhole:latest localhost/blackhole-base:bookworm >/dev/null 2>&1 || true
    rm -rf "$work"
}
trap cleanup EXIT
limits=(--ulimit nofile=4096:4096 --ulimit nproc=4096:4096)

log "the base: mmdebstrap --variant=minbase bookworm"
mmdebstrap --quiet --variant=minbase bookworm "$work/base.tar"
"${podman[@]}" import --quiet "$work/base.tar" localhost/blackhole-base:bookworm >/dev/null
rm "$work/base.tar"

log "podman build -f tools/container/Containerfile"
mkdir "$work/ctx"
cp "$bin" "$work/ctx/blackhole"
"${podman[@]}" build --quiet --network host "${limits[@]}" \
    -f tools/container/Containerfile -t localhost/blackhole:latest "$work/ctx" >/dev/null

# The output volume: a host folder the container's user (uid 1000) may
# write.
mkdir -m 0777 "$work/out"
run=("${podman[@]}" run --rm "${limits[@]}" -e BLACKHOLE_VALIDATION=1 -v "$work/out:/out" localhost/blackhole:latest)
log "podman run: a still (the image's default command) and 6 frames of plunge"
"${run[@]}" >"$work/run.log" 2>&1 || { cat "$work/run.log" >&2; exit 1; }
grep -q "validation: 0 errors, 0 warnings" "$work/run.log" || { cat "$work/run.log" >&2; exit 1; }
"${run[@]}" render --scene plunge --frames 0..6 --width 160 --height 90 --out /out/f.png \
    >"$work/run.log" 2>&1 || { cat "$work/run.log" >&2; exit 1; }

log "the same outside the container"
export XDG_CACHE_HOME="$work/cache" LP_NUM_THREADS=4
mkdir "$work/host"
"$bin" render --out "$work/host/blackhole.png" >/dev/null 2>&1
"$bin" render --scene plunge --frames 0..6 --width 160 --height 90 --out "$work/host/f.png" >/dev/null 2>&1
owner=$(stat -c %u "$work/out/blackhole.png")
[ "$owner" = 1000 ] || { log "FAIL: the container wrote as uid $owner, not its user render (1000)"; exit 1; }
for f in blackhole.png f_0000.png f_0001.png f_0002.png f_0003.png f_0004.png f_0005.png; do
    if ! cmp -s "$work/out/$f" "$work/host/$f"; then
        log "FAIL: $f differs from the render outside the container (or is missing)"
        exit 1
    fi
done
log "ok: the image builds, renders as a non-root user into its volume, and matches the host's pixels"
