#!/usr/bin/env bash
# Runs one fuzz target for SECONDS (default 60) with its corpus kept in
# fuzz/corpus/TARGET between runs (not committed), seeded from the repository's own
# inputs. Flags after SECONDS go to libFuzzer as they are (`-jobs=2`, `-max_len=…`).
# A crash is written to fuzz/artifacts/TARGET/ and the script fails.
#
# Targets: check (bytes -> checker), run (bytes -> interpreter), program (generated
# RAPID programs -> checker and interpreter), controller (generated programs as one to
# three tasks of the controller), cfg (bytes -> .cfg parser and views), manifest
# (bytes -> rapid.toml reader), stimulus (bytes -> --stimulus parser), rws (generated
# requests -> `rapid serve`'s router), lsp (generated message sessions -> the language
# server's loop).
#
# Usage: fuzz/fuzz.sh TARGET [SECONDS] [libFuzzer flags...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root="$here/.."
target=${1:?usage: fuzz/fuzz.sh TARGET [SECONDS] [libFuzzer flags...]}
seconds=${2:-60}
shift $(( $# < 2 ? $# : 2 ))

corpus="$here/corpus/$target"
# FUZZ_SEED=0: a fresh, unseeded corpus (CI's smoke run: the seeds are the test
# suite's own inputs, and running them unoptimised would be most of its time).
if [[ "${FUZZ_SEED:-1}" == 0 ]]; then
    corpus="$here/corpus/smoke/$target"
    rm -rf "$corpus"
fi
mkdir -p "$corpus" "$here/artifacts/$target"
seed() {
    [[ "${FUZZ_SEED:-1}" == 0 ]] && return 0
    for file in "$@"; do [[ -f "$file" ]] && cp "$file" "$corpus/"; done; true
}
# Seeds that share a file name (every manifest is `rapid.toml`), each kept under its
# folder's name.
seed_by_folder() {
    [[ "${FUZZ_SEED:-1}" == 0 ]] && return 0
    for file in "$@"; do [[ -f "$file" ]] && cp "$file" "$corpus/$(basename "$(dirname "$file")").$(basename "$file")"; done; true
}
case "$target" in
    check) seed "$root"/tests/check/ok/*.mod "$root"/examples/*.mod; max_len=65536
           set -- -dict="$here/dict/rapid.dict" "$@" ;;
    run) seed "$root"/tests/conformance/*.mod; max_len=16384
         set -- -dict="$here/dict/rapid.dict" "$@" ;;
    # The generator reads choices, not text: it starts from nothing.
    program | controller) max_len=8192 ;;
    cfg) while IFS= read -r -d '' file; do seed "$file"; done < <(find "$root/crates" "$root/examples" -name '*.cfg' -print0)
         max_len=65536 ;;
    manifest) while IFS= read -r -d '' file; do seed_by_folder "$file"; done < <(find "$root/examples" "$root/tests" -name '*.toml' -print0)
         max_len=16384 ;;
    stimulus) seed "$root"/examples/*.stimulus "$root"/examples/*/*.stim; max_len=4096
              set -- -dict="$here/dict/stimulus.dict" "$@" ;;
    # Both build their inputs from choices: they start from nothing.
    rws | lsp) max_len=4096 ;;
    *) echo "unknown target \`$target\` (check, run, program, controller, cfg, manifest, stimulus, rws, lsp)" >&2; exit 2 ;;
esac

# FUZZ_BUILD=0: run the binary built last (a campaign while the sources change).
[[ "${FUZZ_BUILD:-1}" == 0 ]] || "$here/build.sh" "$target"
triple=$(rustc -vV | sed -n 's/^host: //p')
# cargo puts the dev profile's output in `debug`.
dir=${FUZZ_PROFILE:-release}
[[ "$dir" == dev ]] && dir=debug
exec "$here/target/$triple/$dir/$target" "$corpus" -max_total_time="$seconds" -max_len="$max_len" \
    -artifact_prefix="$here/artifacts/$target/" "$@"
