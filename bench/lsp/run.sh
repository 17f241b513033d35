#!/usr/bin/env bash
# The language server's latency on a large module: edit -> diagnostics, median and
# peak memory, with the cold `rapid check` of the same file as a peer. See README.md.
#
# Usage: bench/lsp/run.sh [LINES]      (default 10000)
# Environment: EDITS (default 21).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
lines=${1:-10000}
# One folder per size: the folder is the workspace, so it must hold this module only.
out_dir="$root/bench/out/lsp/$lines"
module="$out_dir/big.mod"

echo "building rapid (release)" >&2
cargo build --release -p rapid-cli --manifest-path "$root/Cargo.toml" >&2

mkdir -p "$out_dir"
python3 "$root/bench/lsp/gen_module.py" "$lines" "$module"
python3 "$root/bench/lsp/drive.py" "$root/target/release/rapid" "$module" "${EDITS:-21}"
