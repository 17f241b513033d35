#!/usr/bin/env bash
# Builds the fuzz targets (all, or those named) with libFuzzer's coverage
# instrumentation, on the stable toolchain, without cargo-fuzz: the flags are the ones
# `cargo fuzz build --sanitizer none` (cargo-fuzz 0.13) passes, and the binaries go
# where it puts them (`cargo fuzz run --sanitizer none TARGET` works on stable too, if
# installed; its build is not shared with this one). The crates have no
# `unsafe` code, so a sanitizer would find nothing a panic does not; with nightly (or
# RUSTC_BOOTSTRAP=1), `cargo fuzz build --sanitizer address` brings AddressSanitizer.
#
# FUZZ_PROFILE=dev builds unoptimised (much quicker to build, slower to run: CI's
# smoke run); the default is release.
#
# Usage: fuzz/build.sh [TARGET...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
triple=$(rustc -vV | sed -n 's/^host: //p')
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cllvm-args=-simplifycfg-branch-fold-threshold=0 \
-Cllvm-args=-sanitizer-coverage-stack-depth -Cdebug-assertions -Ccodegen-units=1"
bins=()
for target in "$@"; do bins+=(--bin "$target"); done
[[ ${#bins[@]} -gt 0 ]] || bins=(--bins)
cargo build --manifest-path "$here/Cargo.toml" --profile "${FUZZ_PROFILE:-release}" --target "$triple" "${bins[@]}"
