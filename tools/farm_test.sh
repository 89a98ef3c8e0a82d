#!/usr/bin/env bash
# The render farm's recipes, run: a one-node Slurm cluster on this machine
# (slurmctld and slurmd on localhost, munge for their authentication)
# renders a short film as the job array of docs/render-farm.md, one task is
# cancelled part-way and submitted again with --resume; then the same with
# GNU parallel, killed part-way and run again. Every frame must be there and
# identical to the same frames rendered in one process.
#
# Usage (root, or sudo; from the repository root, after `cargo build
# --release`):  bash tools/farm_test.sh [BINARY]
# It installs slurm-wlm, munge and parallel from Debian if they are missing,
# and stops every daemon it started (by its process id) on the way out.
set -euo pipefail
cd "$(dirname "$0")/.."

bin=$(realpath "${1:-target/release/blackhole}")
[ -x "$bin" ] || { echo "farm_test: no binary at $bin (cargo build --release)" >&2; exit 2; }
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"

need=()
command -v slurmctld >/dev/null || need+=(slurm-wlm)
command -v munged >/dev/null || need+=(munge)
command -v parallel >/dev/null || need+=(parallel)
if [ ${#need[@]} -gt 0 ]; then
    export DEBIAN_FRONTEND=noninteractive
    $sudo_cmd apt-get update -qq
    $sudo_cmd apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

# The film: 24 frames of the `plunge` preset in 4 tasks of 6.
scene=plunge
frames=24
per_task=6
size=(--width 160 --height 90 --spp 2)
work=$(mktemp -d /tmp/blackhole-farm.XXXXXX)
export XDG_CACHE_HOME="$work/cache" LP_NUM_THREADS="${LP_NUM_THREADS:-4}"
pids=()
cleanup() {
    for p in "${pids[@]}"; do
        kill "$p" 2>/dev/null || true
    done
    # (each is waited for, so that no daemon outlives the test)
    for p in "${pids[@]}"; do
        while kill -0 "$p" 2>/dev/null; do sleep 0.2; done
    done
    rm -rf "$work"
}
trap cleanup EXIT

log() { echo "farm_test: $*"; }

# The reference: every frame in one process.
mkdir -p "$work/ref"
log "reference: frames 0..$frames of $scene in one process"
"$bin" render --scene "$scene" --frames "0..$frames" "${size[@]}" --out "$work/ref/f.png" \
    >/dev/null 2>"$work/ref.log" || { cat "$work/ref.log" >&2; exit 1; }

# Every frame there and identical to the reference's.
check() {
    local dir=$1 what=$2 missing=0 differ=0
    for i in $(seq 0 $((frames - 1))); do
        f=$(printf "f_%04d.png" "$i")
        if [ ! -f "$dir/$f" ]; then
            missing=$((missing + 1))
        elif ! cmp -s "$dir/$f" "$work/ref/$f"; then
            differ=$((differ + 1))
        fi
    done
    local stray
    stray=$(find "$dir" -name '*.tmp*' -o -name '.*' -type f | wc -l)
    if [ "$missing" -ne 0 ] || [ "$differ" -ne 0 ] || [ "$stray" -ne 0 ]; then
        log "FAIL $what: $missing missing, $differ different, $stray temporaries"
        exit 1
    fi
    log "ok $what: all $frames frames there, identical to one process's"
}

# ------------------------------------------------------------------ Slurm
host=$(hostname -s)
spool="$work/slurm"
mkdir -p "$spool/state" "$spool/d" "$work/munge"
# munge: a key of its own, its socket in the work folder.
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 0400 "$work/munge/munge.key"
munge_socket="$work/munge/munge.socket"
munged --force --key-file="$work/munge/munge.key" --socket="$munge_socket" \
    --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" \
    --seed-file="$work/munge/seed"
for _ in $(seq 50); do [ -s "$work/munge/munged.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$work/munge/munged.pid")")

conf="$spool/slurm.conf"
cat >"$conf" <<EOF
ClusterName=blackhole-test
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$munge_socket
CredType=cred/munge
StateSaveLocation=$spool/state
SlurmdSpoolDir=$spool/d
SlurmctldPidFile=$spool/slurmctld.pid
SlurmdPidFile=$spool/slurmd.pid
SlurmctldLogFile=$spool/slurmctld.log
SlurmdLogFile=$spool/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=render Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$conf"
log "Slurm: slurmctld and slurmd on $host"
slurmctld -f "$conf"
slurmd -f "$conf"
for _ in $(seq 100); do [ -s "$spool/slurmctld.pid" ] && [ -s "$spool/slurmd.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$spool/slurmd.pid")" "$(cat "$spool/slurmctld.pid")")
for _ in $(seq 100); do
    sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)' && break
    sleep 0.2
done
sinfo -h -o %t | grep -qE '^(idle|mix|alloc)' || { log "FAIL: the node never came up"; cat "$spool/slurmd.log" >&2; exit 1; }

# The job script of docs/render-farm.md, as it is there but for the
# binary's path and the frame size.
job="$work/film.sbatch"
cat >"$job" <<EOF
#!/bin/bash
#SBATCH --job-name=film
#SBATCH --array=0-3
#SBATCH --cpus-per-task=1
#SBATCH --output=$work/slurm-%A_%a.out
set -e
first=\$((SLURM_ARRAY_TASK_ID * $per_task))
"$bin" render --scene $scene --frames \$first..\$((first + $per_task)) --resume \\
    ${size[*]} --out "$work/slurm-frames/f.png"
EOF
mkdir -p "$work/slurm-frames"

wait_jobs() {
    for _ in $(seq 1200); do
        [ -z "$(squeue -h -j "$1" 2>/dev/null)" ] && return 0
        sleep 0.25
    done
    log "FAIL: job $1 did not finish"; exit 1
}

array=$(sbatch --parsable "$job")
log "submitted array job $array (4 tasks of $per_task frames)"
# Cancel task 2 part-way: once its first frame is written.
first2=$(printf "$work/slurm-frames/f_%04d.png" $((2 * per_task)))
for _ in $(seq 1200); do [ -f "$first2" ] && break; sleep 0.05; done
scancel "${array}_2"
wait_jobs "$array"
done_before=$(ls "$work/slurm-frames" | grep -c '\.png$' || true)
log "task 2 cancelled part-way: $done_before of $frames frames there"
[ "$done_before" -lt "$frames" ] || { log "FAIL: the cancelled task had finished"; exit 1; }
again=$(sbatch --parsable --array=2 "$job")
log "resubmitted task 2 as job $again (--resume renders only what is missing)"
wait_jobs "$again"
check "$work/slurm-frames" "Slurm job array"

# ------------------------------------------------------------ GNU parallel
mkdir -p "$work/parallel-frames"
recipe="'$bin' render --scene $scene --frames {}..\$(({} + $per_task)) --resume ${size[*]} --out '$work/parallel-frames/f.png'"
log "GNU parallel: 4 jobs of $per_task frames, killed part-way"
setsid parallel -j 2 "$recipe" ::: $(seq 0 $per_task $((frames - 1))) >/dev/null 2>&1 &
ppid=$!
for _ in $(seq 1200); do
    [ "$(ls "$work/parallel-frames" | grep -c '\.png$')" -ge 3 ] && break
    sleep 0.05
done
kill -TERM -- -"$ppid" 2>/dev/null || true
wait "$ppid" 2>/dev/null || true
done_before=$(ls "$work/parallel-frames" | grep -c '\.png$' || true)
log "killed: $done_before of $frames frames there"
[ "$done_before" -lt "$frames" ] || { log "FAIL: parallel had finished"; exit 1; }
parallel -j 2 "$recipe" ::: $(seq 0 $per_task $((frames - 1))) >/dev/null 2>&1
check "$work/parallel-frames" "GNU parallel"
log "all recipes passed"
