#!/usr/bin/env python3
"""Drives `rapid lsp` as an editor would and times it (see bench/lsp/README.md).

Opens MODULE in a workspace folder, then makes EDITS edits in the middle of it, one at
a time: odd edits add an undeclared name (one E0201), even edits take it out again.
For each edit it measures the time from sending `didChange` to receiving the
diagnostics of that document version, and checks their number. It also times a hover
sent right after an edit (the editor is never kept waiting by a check), and as a peer
in the same run the cold `rapid check MODULE` process. Peak memory (max RSS) of each
process comes from wait4.

Usage: drive.py RAPID MODULE [EDITS]
"""
import json
import os
import statistics
import subprocess
import sys
import time


def frame(message):
    body = json.dumps(message).encode()
    return b"Content-Length: %d\r\n\r\n%s" % (len(body), body)


class Server:
    def __init__(self, rapid, root):
        self.proc = subprocess.Popen([rapid, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL)
        self.next_id = 0
        # Messages read while waiting for another one, kept for a later wait.
        self.backlog = []
        self.request("initialize", {"capabilities": {}, "rootUri": "file://" + root})
        self.notify("initialized", {})

    def send(self, message):
        self.proc.stdin.write(frame(message))
        self.proc.stdin.flush()

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def request(self, method, params, wait=True):
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": self.next_id, "method": method, "params": params})
        return self.wait(lambda m: m.get("id") == self.next_id) if wait else self.next_id

    def read(self):
        length = 0
        while True:
            line = self.proc.stdout.readline()
            if not line:
                raise SystemExit("rapid lsp ended unexpectedly")
            line = line.strip()
            if not line:
                break
            if line.lower().startswith(b"content-length:"):
                length = int(line.split(b":")[1])
        return json.loads(self.proc.stdout.read(length))

    def wait(self, wanted):
        for at, message in enumerate(self.backlog):
            if wanted(message):
                return self.backlog.pop(at)
        while True:
            message = self.read()
            if wanted(message):
                return message
            self.backlog.append(message)

    def stop(self):
        self.request("shutdown", None)
        self.notify("exit", None)
        self.proc.stdin.close()
        _, status, usage = os.wait4(self.proc.pid, 0)
        return usage.ru_maxrss


def published(uri, version):
    return lambda m: (m.get("method") == "textDocument/publishDiagnostics"
                      and m["params"]["uri"] == uri and m["params"].get("version") == version)


def cold_check(rapid, module, runs):
    times, peaks = [], []
    for _ in range(runs):
        start = time.perf_counter()
        proc = subprocess.Popen([rapid, "check", module], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(proc.pid, 0)
        times.append(time.perf_counter() - start)
        peaks.append(usage.ru_maxrss)
    return statistics.median(times), statistics.median(peaks)


def main():
    rapid, module = sys.argv[1], os.path.abspath(sys.argv[2])
    edits = int(sys.argv[3]) if len(sys.argv) > 3 else 21
    text = open(module, encoding="utf-8").read()
    lines = text.count("\n")
    uri = "file://" + module
    server = Server(rapid, os.path.dirname(module))
    server.notify("textDocument/didOpen",
                  {"textDocument": {"uri": uri, "languageId": "rapid", "version": 1, "text": text}})
    server.wait(published(uri, 1))

    # The middle of the module, inside a routine's body: before a `counter := ...` line.
    middle = next(i for i, l in enumerate(text.split("\n")) if i >= lines // 2 and l.startswith("    counter"))
    add = {"range": {"start": {"line": middle, "character": 0}, "end": {"line": middle, "character": 0}},
           "text": "    nowhere := 1;\n"}
    remove = {"range": {"start": {"line": middle, "character": 0}, "end": {"line": middle + 1, "character": 0}},
              "text": ""}
    latencies, hovers = [], []
    for version in range(2, edits + 2):
        change = add if version % 2 == 0 else remove
        start = time.perf_counter()
        server.notify("textDocument/didChange",
                      {"textDocument": {"uri": uri, "version": version}, "contentChanges": [change]})
        found = server.wait(published(uri, version))["params"]["diagnostics"]
        latencies.append(time.perf_counter() - start)
        expected = 1 if version % 2 == 0 else 0
        if len(found) != expected:
            raise SystemExit(f"version {version}: {len(found)} diagnostics, expected {expected}: {found[:3]}")
    # A hover right after an edit: answered while the check of that edit runs.
    for version in range(edits + 2, edits + 12):
        change = add if version % 2 == 0 else remove
        server.notify("textDocument/didChange",
                      {"textDocument": {"uri": uri, "version": version}, "contentChanges": [change]})
        # On `counter`, one line lower while the added line is there.
        line = middle + (1 if change is add else 0)
        start = time.perf_counter()
        answer = server.request("textDocument/hover",
                                {"textDocument": {"uri": uri}, "position": {"line": line, "character": 6}})
        hovers.append(time.perf_counter() - start)
        if "VAR num counter" not in json.dumps(answer.get("result")):
            raise SystemExit(f"hover on counter answered {answer}")
        server.wait(published(uri, version))
    lsp_peak = server.stop()
    check_time, check_peak = cold_check(rapid, module, 5)

    print(f"module: {module} ({lines} lines); {edits} edits")
    print(f"rapid lsp, edit -> diagnostics: median {statistics.median(latencies) * 1000:.1f} ms "
          f"(min {min(latencies) * 1000:.1f}, max {max(latencies) * 1000:.1f}); "
          f"peak memory {lsp_peak / 1024:.1f} MB")
    print(f"rapid lsp, hover right after an edit: median {statistics.median(hovers) * 1000:.1f} ms")
    print(f"peer: rapid check MODULE, cold process: median {check_time * 1000:.1f} ms; "
          f"peak memory {check_peak / 1024:.1f} MB")


if __name__ == "__main__":
    main()
