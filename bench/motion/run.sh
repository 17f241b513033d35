#!/usr/bin/env bash
# Kinematics throughput (FK and IK per second) of rapid-motion, release build.
# Usage: bench/motion/run.sh [MODEL] [RUNS]    (default "IRB 120", 5 runs; median printed)
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
model=${1:-IRB 120}
runs=${2:-5}
cargo bench --manifest-path "$root/Cargo.toml" -p rapid-motion --bench ik -- "$model" "$runs"
