#!/usr/bin/env bash
# Load on `rapid serve` over loopback, next to the Python RWS stub measured in the same
# run (../shared/reference/rws_contract/stub.py). See bench/serve/README.md.
#
# Usage: bench/serve/run.sh [SECONDS]      (default 10; the issue's figure is 60)
# Environment: CLIENTS (default 200), SUBSCRIBERS (default 20), RAPID (a rapid binary;
# default target/release/rapid, built when missing), STUB (the stub's folder;
# BENCH_SKIP_STUB=1 skips it).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
seconds=${1:-10}
clients=${CLIENTS:-200}
subscribers=${SUBSCRIBERS:-20}
rapid=${RAPID:-$root/target/release/rapid}
stub=${STUB:-$root/../shared/reference/rws_contract}
[[ -d "$stub" ]] || stub=/work/shared/reference/rws_contract

if [[ ! -x "$rapid" ]]; then
    echo "building rapid (release)" >&2
    cargo build --release -p rapid-cli --manifest-path "$root/Cargo.toml" >&2
fi
echo "building the load client (release, its own small workspace)" >&2
cargo build --release --quiet --manifest-path "$root/bench/serve/load/Cargo.toml" >&2
load="$root/bench/serve/load/target/release/rws-load"

free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }

# Waits (at most 30 s) until something accepts connections on port $1.
wait_port() {
    for _ in $(seq 300); do
        if python3 -c "import socket, sys; socket.create_connection(('127.0.0.1', $1), 0.2)" 2>/dev/null; then return 0; fi
        sleep 0.1
    done
    echo "error: nothing listens on port $1" >&2
    return 1
}

status=0
work=$(mktemp -d)
server_pid=""
cleanup() {
    if [[ -n "$server_pid" ]]; then kill -INT "$server_pid" 2>/dev/null || true; wait "$server_pid" 2>/dev/null || true; fi
    rm -rf "$work"
}
trap cleanup EXIT

# rapid serve on a copy of the system (Ctrl-C writes persistents back into it).
cp -r "$root/bench/serve/system" "$work/system"
port=$(free_port)
"$rapid" serve --bind "127.0.0.1:$port" "$work/system" >/dev/null 2>"$work/serve.err" &
server_pid=$!
wait_port "$port"
# The program runs while the clients poll (continuous run mode).
python3 - "$port" <<'PY'
import hashlib, re, sys, urllib.request
port = sys.argv[1]
url = f"http://127.0.0.1:{port}/rw/rapid/execution?action=start"
mgr = urllib.request.HTTPPasswordMgrWithDefaultRealm()
mgr.add_password(None, f"http://127.0.0.1:{port}/", "Default User", "robotics")
opener = urllib.request.build_opener(urllib.request.HTTPDigestAuthHandler(mgr))
body = b"regain=continue&execmode=continue&cycle=forever&condition=none&stopatbp=disabled&alltaskbytsp=false"
opener.open(urllib.request.Request(url, data=body, method="POST"), timeout=10)
PY
echo "rapid serve ($clients clients, $subscribers subscribers, ${seconds} s, program running):"
"$load" "http://127.0.0.1:$port" "$seconds" "$clients" "$subscribers" test_digital_io1 go_seq || status=1
kill -INT "$server_pid"
wait "$server_pid" || { echo "error: rapid serve did not exit 0"; cat "$work/serve.err"; status=1; }
server_pid=""

if [[ "${BENCH_SKIP_STUB:-}" != 1 ]]; then
    port=$(free_port)
    python3 -c "import sys, time; sys.path.insert(0, '$stub'); import stub; stub.serve($port); time.sleep(1e9)" &
    server_pid=$!
    wait_port "$port"
    echo "python stub ($clients clients, $subscribers subscribers, ${seconds} s, no program):"
    "$load" "http://127.0.0.1:$port" "$seconds" "$clients" "$subscribers" test_digital_io1 || true
    kill "$server_pid"; wait "$server_pid" 2>/dev/null || true
    server_pid=""
fi
exit $status
