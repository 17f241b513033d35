#!/usr/bin/env bash
# Runs the `run` fuzz target (the interpreter), seeded from the conformance corpus.
# Usage: fuzz/run_vm.sh [SECONDS] [extra libFuzzer flags...]   (default 60 seconds)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
seconds=${1:-60}
shift || true
cargo fuzz --version >/dev/null 2>&1 || cargo install cargo-fuzz
corpus="$here/corpus/run"
mkdir -p "$corpus"
cp "$here"/../tests/conformance/*.mod "$corpus/"
cd "$here"
exec cargo +nightly fuzz run --sanitizer "${FUZZ_SANITIZER:-none}" run "$corpus" -- -max_total_time="$seconds" -max_len=16384 "$@"
