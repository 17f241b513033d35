#!/usr/bin/env bash
# Simulation speed of `rapid run` on an offline-programming module of N MoveL lines
# (default 100,000) with a 4 ms trace: simulated (cycle) time / wall time, the
# median of RUNS runs (default 3). The goal (issue 6) is at least 1000x.
# Usage: bench/motion/sim.sh [N]     RUNS=5 bench/motion/sim.sh 20000
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
n=${1:-100000}
runs=${RUNS:-3}
out="$root/bench/out"
mkdir -p "$out"
module="$out/olp_${n}.mod"
[ -f "$module" ] || python3 "$root/bench/motion/gen_moves.py" "$n" "$module"
if [ -z "${BENCH_SKIP_BUILD:-}" ]; then
    cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p rapid-cli
fi
rapid="$root/target/release/rapid"
ratios=()
for _ in $(seq "$runs"); do
    start=$(date +%s.%N)
    line=$("$rapid" run --trace "$out/olp_${n}.csv" --home "$out/rc" "$module" 2>&1 >/dev/null | grep '^cycle time')
    end=$(date +%s.%N)
    cycle=$(echo "$line" | sed -E 's/.*: ([0-9.]+) s.*/\1/')
    wall=$(echo "$end - $start" | bc -l)
    ratios+=("$(echo "$cycle / $wall" | bc -l)")
    printf 'run: simulated %.1f s in %.2f s wall\n' "$cycle" "$wall"
done
median=$(printf '%s\n' "${ratios[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
rows=$(($(wc -l < "$out/olp_${n}.csv") - 1))
printf '%d MoveL, %d trace rows: simulated/wall median %.0fx (goal >= 1000x)\n' "$n" "$rows" "$median"
