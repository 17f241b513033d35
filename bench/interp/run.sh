#!/usr/bin/env bash
# Interpreter benchmarks: the same small programs in RAPID (`rapid run`), Lua 5.4 and
# CPython, timed in one run on one machine, with every output checked against the others.
# See bench/interp/README.md.
#
# Usage: bench/interp/run.sh [BENCHMARK...]   (default: all, in the order below)
# Environment: RUNS (runs per language and benchmark, default 5; the median is reported)
#              TIMEOUT (seconds allowed for one run, default 300)
#              BENCH_SKIP_BUILD=1 (use target/release/rapid as it is, no cargo build)
set -uo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
runs=${RUNS:-5}
limit=${TIMEOUT:-300}
rapid="$root/target/release/rapid"
all_benchmarks=(startup fib arith strings bubble pos varcall strops fileio)
if (($# > 0)); then benchmarks=("$@"); else benchmarks=("${all_benchmarks[@]}"); fi

if ! [[ "$runs" =~ ^[1-9][0-9]*$ ]]; then
    echo "RUNS must be a positive integer, got '$runs'" >&2
    exit 2
fi
for name in "${benchmarks[@]}"; do
    for ext in mod lua py expected; do
        if [[ ! -f "$here/$name.$ext" ]]; then
            echo "unknown benchmark '$name' (no $name.$ext); known: ${all_benchmarks[*]}" >&2
            exit 2
        fi
    done
done

# --- tools ------------------------------------------------------------------------------
if ! command -v lua5.4 >/dev/null 2>&1; then
    echo "installing lua5.4 with apt-get" >&2
    apt-get update -qq >&2 && apt-get install -y -qq lua5.4 >&2
fi
if ! command -v lua5.4 >/dev/null 2>&1; then
    echo "lua5.4 is missing and could not be installed" >&2
    exit 1
fi
if ! command -v python3 >/dev/null 2>&1; then
    echo "python3 is missing" >&2
    exit 1
fi
# Time the interpreter itself, not a wrapper in front of it (pyenv's shims are shell
# scripts that add about 0.1 s to every start).
python=$(python3 -c 'import sys; print(sys.executable)')

have_rapid=1
if [[ "${BENCH_SKIP_BUILD:-0}" == 1 ]]; then
    echo "BENCH_SKIP_BUILD=1: using $rapid as it is" >&2
else
    echo "building rapid (release)" >&2
    if ! cargo build --release -p rapid-cli --manifest-path "$root/Cargo.toml" >&2; then
        echo "!!! cargo build failed: RAPID column left empty" >&2
        have_rapid=0
    fi
fi
if ((have_rapid)) && [[ ! -x "$rapid" ]]; then
    echo "!!! $rapid does not exist: RAPID column left empty" >&2
    have_rapid=0
elif ((have_rapid)) && ! "$rapid" run --help >/dev/null 2>&1; then
    echo "!!! 'rapid run' does not exist yet: timing Lua and Python only" >&2
    have_rapid=0
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# --- measuring --------------------------------------------------------------------------
# measure LABEL CMD...: runs CMD $runs times with stdout to $work/LABEL.out. Prints the
# median wall time in nanoseconds, or "fail" when a run exits non-zero, times out, or
# prints something different from the first run (stderr of the failing run is shown).
measure() {
    local label=$1
    shift
    local times=() start end status
    for ((run = 0; run < runs; run++)); do
        start=$(date +%s%N)
        timeout "$limit" "$@" >"$work/$label.run" 2>"$work/$label.err"
        status=$?
        end=$(date +%s%N)
        if ((status != 0)); then
            if ((status == 124)); then
                echo "!!! $label: timed out after ${limit}s" >&2
            else
                echo "!!! $label: exited with status $status" >&2
            fi
            sed 's/^/    /' "$work/$label.err" | head -20 >&2
            echo fail
            return
        fi
        if ((run == 0)); then
            mv "$work/$label.run" "$work/$label.out"
        elif ! cmp -s "$work/$label.run" "$work/$label.out"; then
            echo "!!! $label: output differs between runs" >&2
            echo fail
            return
        fi
        times+=($((end - start)))
    done
    printf '%s\n' "${times[@]}" | sort -n | awk '
        { t[NR] = $1 }
        END { if (NR % 2) print t[(NR + 1) / 2]; else print int((t[NR / 2] + t[NR / 2 + 1]) / 2) }'
}

seconds() { # ns -> seconds with 3 decimals, or the word as it is
    if [[ "$1" =~ ^[0-9]+$ ]]; then awk -v n="$1" 'BEGIN { printf "%.3f", n / 1e9 }'; else echo "$1"; fi
}
ratio() { # a_ns b_ns -> a/b, or "-"
    if [[ "$1" =~ ^[0-9]+$ && "$2" =~ ^[0-9]+$ && "$2" != 0 ]]; then
        awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1fx", a / b }'
    else
        echo "-"
    fi
}

# --- running ----------------------------------------------------------------------------
echo "runs per language: $runs (median reported); $(lua5.4 -v 2>&1 | cut -d' ' -f1-2); $("$python" -V 2>&1) ($python)" >&2
failures=0
rows=()
for name in "${benchmarks[@]}"; do
    echo "running $name" >&2
    # A folder of its own for the files a benchmark writes: the controller root
    # (`--home`) for RAPID, the first argument for Lua and Python.
    home="$work/$name.home"
    mkdir -p "$home"
    lua_ns=$(measure "$name.lua" lua5.4 "$here/$name.lua" "$home")
    py_ns=$(measure "$name.py" "$python" "$here/$name.py" "$home")
    rapid_ns="n/a"
    if ((have_rapid)); then
        rapid_ns=$(measure "$name.rapid" "$rapid" run --home "$home" "$here/$name.mod")
    fi

    # Every output that was produced must equal the expected text and each other.
    status=ok
    for label in "$name.lua" "$name.py" "$name.rapid"; do
        [[ -f "$work/$label.out" ]] || continue
        if ! cmp -s "$work/$label.out" "$here/$name.expected"; then
            status=MISMATCH
            {
                echo
                echo "!!!!!!!! OUTPUT MISMATCH in $name: $label differs from $name.expected !!!!!!!!"
                diff "$here/$name.expected" "$work/$label.out" | sed 's/^/    /'
                echo
            } >&2
        fi
    done
    for value in "$lua_ns" "$py_ns" "$rapid_ns"; do
        [[ "$value" == fail ]] && status=FAILED
    done
    [[ "$status" == ok ]] || failures=$((failures + 1))

    rows+=("$(printf '| %-9s | %8s | %8s | %8s | %9s | %13s | %-8s |' "$name" \
        "$(seconds "$rapid_ns")" "$(seconds "$lua_ns")" "$(seconds "$py_ns")" \
        "$(ratio "$rapid_ns" "$lua_ns")" "$(ratio "$rapid_ns" "$py_ns")" "$status")")
done

echo
printf '| %-9s | %8s | %8s | %8s | %9s | %13s | %-8s |\n' \
    benchmark "RAPID s" "Lua s" "Python s" "RAPID/Lua" "RAPID/CPython" output
echo "|-----------|----------|----------|----------|-----------|---------------|----------|"
printf '%s\n' "${rows[@]}"
if ((!have_rapid)); then
    echo
    echo "RAPID not measured: 'rapid run' is not available in this build."
fi
if ((failures > 0)); then
    echo
    echo "!!!!!!!! $failures benchmark(s) with a mismatched output or a failed run (see above) !!!!!!!!"
    exit 1
fi
