#!/usr/bin/env bash
# Runs the `check` fuzz target: fuzz/fuzz.sh check [SECONDS] [libFuzzer flags...].
exec "$(dirname "$0")/fuzz.sh" check "$@"
