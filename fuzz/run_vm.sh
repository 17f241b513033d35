#!/usr/bin/env bash
# Runs the `run` fuzz target (the interpreter): fuzz/fuzz.sh run [SECONDS] [libFuzzer flags...].
exec "$(dirname "$0")/fuzz.sh" run "$@"
