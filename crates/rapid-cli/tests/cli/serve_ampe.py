"""abb-motion-program-exec, unmodified, against `rapid serve` of its own RAPID system.

Usage: python serve_ampe.py URL [multimove]

Runs two motion programs through `MotionProgramExecClient.execute_motion_program`
(upload to $RAMDISK, resetpp, start, poll, event log, read the joint log back):
a MoveAbsJ to a start pose, then MoveJ / MoveL / MoveC / WaitTime / MoveAbsJ around
the pose the controller reports there. With `multimove` (the system's
config_params_multimove layout: T_ROB1 and T_ROB2) two pairs of programs through
`execute_multimove_motion_program`: MoveAbsJ, then SyncMoveOn / MoveAbsJ / MoveL /
WaitTime / MoveAbsJ synchronized (\ID).
Prints one line per check, the log's last rows, and "N passed, M failed" last;
exits 1 on any failure.
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

# Joint positions inside every ABB six-axis robot's limits, wrist away from its
# singularity (axis 5 far from 0).
START = [0.0, 10.0, 20.0, 0.0, 45.0, 0.0]
FINAL = [10.0, 5.0, 15.0, -20.0, 50.0, 30.0]
EXT = [0.0] * 6


def check(name, ok, detail=""):
    RESULTS.append(bool(ok))
    print(f"{'ok  ' if ok else 'FAIL'} {name} {detail}".rstrip(), flush=True)


# The second robot's poses (MultiMove).
START_2 = [-5.0, 12.0, 18.0, 0.0, 40.0, 0.0]
FINAL_2 = [-10.0, 8.0, 12.0, 20.0, 55.0, -30.0]


def joint_columns(log, suffix=""):
    """The six robot-axis columns of a joint log (J1..J6, or J1_2..J6_2), by header name."""
    names = [h.strip() for h in log.column_headers]
    return [names.index(f"J{i}{suffix}") for i in range(1, 7)]


def last_joints(log):
    cols = joint_columns(log)
    return np.array([log.data[-1, c] for c in cols], dtype=np.float64)


def run(client, name, program, target):
    """Executes `program`; checks the log and that its last row is `target` (±0.01°)."""
    try:
        log = client.execute_motion_program(program)
    except Exception:
        check(name + ": execute_motion_program", False, traceback.format_exc())
        return None
    check(name + ": execute_motion_program returned a log", log is not None)
    print(f"     headers {log.column_headers} rows {log.data.shape[0]}", flush=True)
    check(name + ": the log has rows", log.data.shape[0] > 1, str(log.data.shape))
    if log.data.shape[0] == 0:
        return log
    last = last_joints(log)
    error = np.max(np.abs(last - np.array(target)))
    print(f"     last row {np.round(last, 4).tolist()} target {target} max error {error:.6f} deg", flush=True)
    check(name + ": last row matches the final target within 0.01 deg", error <= 0.01, f"error {error:.6f}")
    times = log.data[:, log.column_headers.index("timestamp")] if "timestamp" in log.column_headers else None
    if times is not None:
        check(name + ": timestamps never go back", bool(np.all(np.diff(times) >= 0)))
    return log


def main():
    client = MotionProgramExecClient(base_url=URL)
    rws = client.abb_client
    check("ramdisk path", rws.get_ramdisk_path().startswith("$") or "RAMDISK" in rws.get_ramdisk_path().upper(),
          rws.get_ramdisk_path())

    first = MotionProgram()
    first.MoveAbsJ(jointtarget(START, EXT), v1000, fine)
    run(client, "MoveAbsJ", first, START)

    # The pose at START, as the controller computes it; the Cartesian moves stay
    # within 60 mm of it (reachable by any model) and keep its configuration.
    here = rws.get_robtarget()
    trans = np.array(here.trans, dtype=np.float64)
    rot = np.array(here.rot, dtype=np.float64)
    conf = confdata(*[float(c) for c in here.robconf])

    def near(dx, dy, dz):
        return robtarget(trans + np.array([dx, dy, dz]), rot, conf, EXT)

    second = MotionProgram()
    second.MoveAbsJ(jointtarget(START, EXT), v1000, fine)
    second.MoveJ(near(0, 40, -30), v1000, z10)
    second.MoveL(near(40, 40, -30), v500, z10)
    second.MoveC(near(60, 0, -30), near(40, -40, -30), v200, fine)
    second.WaitTime(0.2)
    second.MoveAbsJ(jointtarget(FINAL, EXT), v1000, fine)
    log = run(client, "MoveAbsJ/MoveJ/MoveL/MoveC/WaitTime", second, FINAL)
    if log is not None and log.data.shape[0] > 0:
        cmds = log.data[:, log.column_headers.index("cmdnum")]
        seen = sorted(set(int(c) for c in cmds))
        # The system's RAPID sets the command number from TriggJ/TriggL/TriggC's
        # trigger and at WaitTime; a MoveAbsJ leaves it as it was: -1 before the
        # first trigger, then 2 (MoveJ), 3 (MoveL), 4 (MoveC), 5 (WaitTime) to the end.
        check("the log's command numbers are the program's", seen == [-1, 2, 3, 4, 5], str(seen))
        check("the log's command numbers never go back", bool(np.all(np.diff(cmds) >= 0)))
        cols = joint_columns(log)
        first_row = np.array([log.data[0, c] for c in cols], dtype=np.float64)
        error = np.max(np.abs(first_row - np.array(START)))
        check("the log's first row is the start pose", error <= 0.01, f"error {error:.6f}")
        times = log.data[:, log.column_headers.index("timestamp")]
        # WaitTime 0.2 alone, plus four moves: the program took longer than 0.2 s.
        check("the log spans the program's time", times[-1] - times[0] > 0.2, f"{times[-1] - times[0]:.3f} s")

    state = rws.get_execution_state()
    check("stopped after the program", state.ctrlexecstate == "stopped", state.ctrlexecstate)


def row_error(log, row, target, suffix=""):
    got = np.array([log.data[row, c] for c in joint_columns(log, suffix)], dtype=np.float64)
    return float(np.max(np.abs(got - np.array(target))))


def run_multimove(client, name, programs, targets):
    """Executes `programs` on T_ROB1 and T_ROB2; checks each robot's last row (±0.01°)."""
    try:
        log = client.execute_multimove_motion_program(programs)
    except Exception:
        check(name + ": execute_multimove_motion_program", False, traceback.format_exc())
        return None
    print(f"     headers {log.column_headers} rows {log.data.shape[0]}", flush=True)
    check(name + ": the log has rows", log.data.shape[0] > 1, str(log.data.shape))
    if log.data.shape[0] == 0:
        return None
    for suffix, target in zip(["", "_2"], targets):
        error = row_error(log, -1, target, suffix)
        print(f"     last row{suffix} target {target} max error {error:.6f} deg", flush=True)
        check(f"{name}: robot{suffix or '_1'}'s last row matches its final target within 0.01 deg", error <= 0.01,
              f"error {error:.6f}")
    return log


def main_multimove():
    client = MotionProgramExecClient(base_url=URL)
    rws = client.abb_client
    one, two = MotionProgram(), MotionProgram()
    one.MoveAbsJ(jointtarget(START, EXT), v1000, fine)
    two.MoveAbsJ(jointtarget(START_2, EXT), v1000, fine)
    run_multimove(client, "MoveAbsJ x2", [one, two], [START, START_2])

    def near(unit, dx, dy, dz):
        here = rws.get_robtarget(mechunit=unit)
        conf = confdata(*[float(c) for c in here.robconf])
        return robtarget(np.array(here.trans, dtype=np.float64) + np.array([dx, dy, dz]),
                         np.array(here.rot, dtype=np.float64), conf, EXT)

    programs = []
    for unit, start, final, side in [("ROB_1", START, FINAL, 1), ("ROB_2", START_2, FINAL_2, -1)]:
        mp = MotionProgram()
        mp.SyncMoveOn()
        mp.MoveAbsJ(jointtarget(start, EXT), v1000, fine)
        mp.MoveL(near(unit, 0, 30 * side, -30), v200, fine)
        mp.WaitTime(0.1)
        mp.MoveAbsJ(jointtarget(final, EXT), v500, fine)
        programs.append(mp)
    log = run_multimove(client, "synchronized MoveAbsJ/MoveL/WaitTime", programs, [FINAL, FINAL_2])
    if log is not None:
        cmds = log.data[:, log.column_headers.index("cmdnum")]
        # Command 1 is SyncMoveOn, 2 the MoveAbsJ (neither sets the number: -1 from
        # the start), 3 the TriggL (its trap, 0.001 s into the move, which runs in an
        # IF ... ELSE of a FUNC), 4 the WaitTime; the last MoveAbsJ keeps 4.
        seen = sorted(set(int(c) for c in cmds))
        check("the log's command numbers are the program's", seen == [-1, 3, 4], str(seen))
        check("the log's command numbers never go back", bool(np.all(np.diff(cmds) >= 0)))
        check("the log's command number ends at the WaitTime's", int(cmds[-1]) == 4, str(seen))
        error = max(row_error(log, 0, START), row_error(log, 0, START_2, "_2"))
        check("the log's first row is both start poses", error <= 0.01, f"error {error:.6f}")
    state = rws.get_execution_state()
    check("stopped after the programs", state.ctrlexecstate == "stopped", state.ctrlexecstate)


try:
    if sys.argv[2:] == ["multimove"]:
        main_multimove()
    else:
        main()
except Exception:
    check("no exception", False, traceback.format_exc())
passed = sum(RESULTS)
failed = len(RESULTS) - passed
print(f"{passed} passed, {failed} failed", flush=True)
sys.exit(1 if failed else 0)
