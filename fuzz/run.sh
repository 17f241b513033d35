#!/usr/bin/env bash
# Runs the `check` fuzz target. Seeds the corpus from the checker's known-good modules
# (copied at run time; the corpus is not committed).
#
# Usage: fuzz/run.sh [SECONDS] [extra libFuzzer flags...]   (default 60 seconds)
# Needs the nightly toolchain and cargo-fuzz (`cargo install cargo-fuzz`).
# The crates have no `unsafe` code, so AddressSanitizer finds nothing that a panic would
# not, at several times the cost: the default is no sanitizer (debug assertions stay on).
# FUZZ_SANITIZER=address brings it back.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
seconds=${1:-60}
shift || true

if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "installing cargo-fuzz" >&2
    cargo install cargo-fuzz
fi

corpus="$here/corpus/check"
mkdir -p "$corpus"
for seed in "$here"/../tests/check/ok/*.mod "$here"/../examples/*.mod; do
    [[ -f "$seed" ]] && cp "$seed" "$corpus/"
done

cd "$here"
exec cargo +nightly fuzz run --sanitizer "${FUZZ_SANITIZER:-none}" check "$corpus" -- -max_total_time="$seconds" -max_len=65536 "$@"
