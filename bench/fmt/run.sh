#!/usr/bin/env bash
# Throughput of `rapid fmt` on the large CAM-style module of bench/run.sh, with peers
# measured in the same run on the same file. See bench/fmt/README.md.
#
# Usage: bench/fmt/run.sh [LINES]      (default 1000000 MoveL lines, about 140 MB)
# Environment: RUNS (default 5).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
lines=${1:-1000000}
runs=${RUNS:-5}
out_dir="$root/bench/out"
module="$out_dir/cam_$lines.mod"
rapid="$root/target/release/rapid"

echo "building rapid (release)" >&2
cargo build --release -p rapid-cli --manifest-path "$root/Cargo.toml" >&2

mkdir -p "$out_dir"
if [[ ! -f "$module" ]]; then
    echo "generating $module" >&2
    python3 "$root/bench/gen_cam_module.py" --lines "$lines" "$module"
fi
bytes=$(stat -c %s "$module")
mb=$(awk -v b="$bytes" 'BEGIN { printf "%.1f", b / 1e6 }')

# Runs a command $runs times with the module on stdin and stdout to a file; prints the
# median wall time in seconds (from the clock in nanoseconds).
measure() {
    local times=() start end status
    for ((run = 0; run < runs; run++)); do
        status=0
        start=$(date +%s%N)
        "$@" <"$module" >"$out_dir/fmt_stdout.txt" 2>"$out_dir/fmt_stderr.txt" || status=$?
        end=$(date +%s%N)
        if ((status > 1)); then
            echo "error: '$*' exited with status $status" >&2
            cat "$out_dir/fmt_stderr.txt" >&2
            exit 1
        fi
        times+=("$(awk -v ns=$((end - start)) 'BEGIN { printf "%.4f", ns / 1e9 }')")
    done
    printf '%s\n' "${times[@]}" | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'
}

rate() {
    awk -v b="$bytes" -v s="$1" 'BEGIN { printf "%.1f", b / 1e6 / s }'
}

echo "input: $module ($mb MB, $lines MoveL lines); median of $runs runs" >&2

fmt_s=$(measure "$rapid" fmt -)
out_bytes=$(stat -c %s "$out_dir/fmt_stdout.txt")
# The peer: the parse rapid fmt must pass before it may touch a file.
check_s=$(measure "$rapid" check --syntax-only "$module")
cat_s=$(measure cat)

echo
echo "rapid fmt -:                 $(rate "$fmt_s") MB/s (${fmt_s} s; output $((out_bytes / 1000000)) MB)"
echo "rapid check --syntax-only:   $(rate "$check_s") MB/s (${check_s} s)"
echo "baseline cat:                $(rate "$cat_s") MB/s (${cat_s} s)"
awk -v a="$fmt_s" -v b="$check_s" 'BEGIN { printf "ratio fmt/check time:        %.2f\n", a / b }'
