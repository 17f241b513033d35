#!/usr/bin/env bash
# Peak memory of `rapid run` on a generated CAM module, as a multiple of the file size,
# next to `rapid check`'s (issue 23 aims at 5x for `rapid run`). One run each: peak
# resident memory (GNU time's %M) is deterministic enough, and no timing is reported.
#
# Usage: bench/memory/run.sh [LINES]              default 100000 lines (14 MB)
#        RAPID=/path/to/rapid bench/memory/run.sh  measure that binary (no build)
#        FULL=1 bench/memory/run.sh 20000          also run the whole path to its end
#
# `rapid run` of the generated module stops at its first move, which the default robot
# (IRB 120) cannot reach: by then the module is loaded and compiled whole, and what is
# measured is what the compiled program holds. FULL=1 runs a copy that starts with
# ConfL\Off on an IRB 6700, which reaches every target, so every move is planned.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
lines=${1:-100000}
out_dir="$root/bench/out"
module="$out_dir/cam_$lines.mod"

if [[ ! -x /usr/bin/time ]]; then
    echo "installing GNU time for peak-memory figures" >&2
    apt-get update -qq && apt-get install -y -qq time >/dev/null
fi
if [[ -z "${RAPID:-}" ]]; then
    echo "building rapid (release)" >&2
    cargo build --release --quiet -p rapid-cli --manifest-path "$root/Cargo.toml" >&2
fi
rapid=${RAPID:-$root/target/release/rapid}

mkdir -p "$out_dir"
if [[ ! -f "$module" ]]; then
    echo "generating $module" >&2
    python3 "$root/bench/gen_cam_module.py" --lines "$lines" "$module"
fi
bytes=$(stat -c %s "$module")

# Peak resident memory in KB of one run of the command (its exit status is ignored:
# `rapid run` stops with an error at the first unreachable move).
peak_kb() {
    /usr/bin/time -f "%M" -o "$out_dir/memory_time.txt" "$@" >/dev/null 2>&1 || true
    tail -n 1 "$out_dir/memory_time.txt"
}

# "N.NNx file size (M MiB)" for a peak of $1 KB.
ratio() {
    awk -v kb="$1" -v b="$bytes" 'BEGIN { printf "%.2fx file size (%d MiB)", kb * 1024 / b, kb / 1024 }'
}

echo "input: $module ($(awk -v b="$bytes" 'BEGIN { printf "%.1f", b / 1e6 }') MB, $lines MoveL lines)"
echo "rapid check:        peak memory $(ratio "$(peak_kb "$rapid" check "$module")")"
echo "rapid run (load):   peak memory $(ratio "$(peak_kb "$rapid" run "$module")")"
echo "empty program:      peak memory $(peak_kb "$rapid" run "$root/bench/interp/startup.mod") KB (the floor)"
if [[ "${FULL:-0}" == 1 ]]; then
    full="$out_dir/cam_${lines}_full.mod"
    sed 's/^    PROC main()$/    PROC main()\n        ConfL\\Off;/' "$module" >"$full"
    echo "rapid run (whole):  peak memory $(ratio "$(peak_kb "$rapid" run --robot "IRB 6700" "$full")")"
fi
