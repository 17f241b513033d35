#!/usr/bin/env bash
# CI's smoke run: builds every fuzz target and runs each for SECONDS (default 5) from
# an empty corpus, so a target that no longer builds, or crashes at once, fails CI.
# Unoptimised by default (FUZZ_PROFILE=dev): building is most of its time.
# Usage: fuzz/smoke.sh [SECONDS]
set -euo pipefail
export FUZZ_PROFILE=${FUZZ_PROFILE:-dev} FUZZ_SEED=${FUZZ_SEED:-0}
here=$(cd "$(dirname "$0")" && pwd)
seconds=${1:-5}
"$here/build.sh"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for target in check run program controller cfg manifest stimulus rws lsp; do
    echo "== fuzz $target ($seconds s)"
    if ! "$here/fuzz.sh" "$target" "$seconds" >"$log" 2>&1; then
        tail -n 40 "$log" >&2
        echo "fuzz target $target failed (artifacts in fuzz/artifacts/$target)" >&2
        exit 1
    fi
    grep -E '^(#[0-9]+ +DONE|Done) ' "$log" || tail -n 3 "$log"
done
