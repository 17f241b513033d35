"""abb-motion-program-exec, unmodified, against `rapid serve` of OUR RAPID system
that speaks its protocol (tests/systems/ampe_protocol: written from the client's
Python, not the project's own RAPID).

Usage: python serve_ampe_protocol.py URL

Runs two motion programs through `MotionProgramExecClient.execute_motion_program`
(upload to $RAMDISK, resetpp, start, poll, event log, read the joint log back): a
MoveAbsJ to a start pose, then MoveAbsJ / MoveJ / MoveL / MoveC / WaitTime / MoveAbsJ
around the pose the controller reports there.
Prints one line per check and "N passed, M failed" last; exits 1 on any failure.
"""

import sys
import traceback

import numpy as np
from abb_motion_program_exec import (
    MotionProgram,
    MotionProgramExecClient,
    confdata,
    jointtarget,
    robtarget,
    fine,
    v200,
    v500,
    v1000,
    z10,
)

URL = sys.argv[1]
RESULTS = []

# Joint positions inside the IRB 120's limits, wrist away from its singularity.
START = [0.0, 10.0, 20.0, 0.0, 45.0, 0.0]
FINAL = [10.0, 5.0, 15.0, -20.0, 50.0, 30.0]
EXT = [0.0] * 6
WAIT = 0.2


def check(name, ok, detail=""):
    RESULTS.append(bool(ok))
    print(f"{'ok  ' if ok else 'FAIL'} {name} {detail}".rstrip(), flush=True)


def column(log, name):
    return log.data[:, [h.strip() for h in log.column_headers].index(name)]


def joints(log, row):
    return np.array([column(log, f"J{i}")[row] for i in range(1, 7)], dtype=np.float64)


def run(client, name, program, target):
    """Executes `program`; checks that the log's last row is `target` (within 0.01 deg)."""
    log = client.execute_motion_program(program)
    print(f"     headers {log.column_headers} rows {log.data.shape[0]}", flush=True)
    check(name + ": the log has rows", log.data.shape[0] > 1, str(log.data.shape))
    error = np.max(np.abs(joints(log, -1) - np.array(target)))
    print(f"     last row {np.round(joints(log, -1), 4).tolist()} target {target}", flush=True)
    check(name + ": last row matches the final target within 0.01 deg", error <= 0.01, f"error {error:.6f}")
    check(name + ": timestamps never go back", bool(np.all(np.diff(column(log, "timestamp")) >= 0)))
    return log


def main():
    client = MotionProgramExecClient(base_url=URL)
    rws = client.abb_client

    first = MotionProgram()
    first.MoveAbsJ(jointtarget(START, EXT), v1000, fine)
    run(client, "MoveAbsJ", first, START)

    # The pose at START as the controller computes it; the Cartesian moves stay within
    # 60 mm of it and keep its configuration.
    here = rws.get_robtarget()
    trans = np.array(here.trans, dtype=np.float64)
    rot = np.array(here.rot, dtype=np.float64)
    conf = confdata(*[float(c) for c in here.robconf])

    def near(dx, dy, dz):
        return robtarget(trans + np.array([dx, dy, dz]), rot, conf, EXT)

    second = MotionProgram()
    second.MoveAbsJ(jointtarget(START, EXT), v1000, fine)  # command 1
    second.MoveJ(near(0, 40, -30), v1000, z10)  # 2
    second.MoveL(near(40, 40, -30), v500, z10)  # 3
    second.MoveC(near(60, 0, -30), near(40, -40, -30), v200, fine)  # 4
    second.WaitTime(WAIT)  # 5
    second.MoveAbsJ(jointtarget(FINAL, EXT), v1000, fine)  # 6
    log = run(client, "MoveAbsJ/MoveJ/MoveL/MoveC/WaitTime", second, FINAL)
    cmds = column(log, "cmdnum")
    seen = sorted(set(int(c) for c in cmds))
    check("the log has every command's number", seen == [1, 2, 3, 4, 5, 6], str(seen))
    check("the log's command numbers never go back", bool(np.all(np.diff(cmds) >= 0)))
    error = np.max(np.abs(joints(log, 0) - np.array(START)))
    check("the log's first row is the start pose", error <= 0.01, f"error {error:.6f}")
    times = column(log, "timestamp")
    check("the log spans at least the WaitTime", times[-1] - times[0] >= WAIT, f"{times[-1] - times[0]:.3f} s")
    state = rws.get_execution_state()
    check("stopped after the program", state.ctrlexecstate == "stopped", state.ctrlexecstate)


try:
    main()
except Exception:
    check("no exception", False, traceback.format_exc())
passed = sum(RESULTS)
failed = len(RESULTS) - passed
print(f"{passed} passed, {failed} failed", flush=True)
sys.exit(1 if failed else 0)
