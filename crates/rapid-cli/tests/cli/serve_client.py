"""abb-robot-client 0.4.0, unmodified, against `rapid serve` on the program of
tests/cli/fixtures/serve_project (tests/cli/serve.rs starts the server and runs this
script with the server's URL). Every synchronous method of abb_robot_client.rws.RWS
that applies to a virtual controller is called; the expected values are worked out
from Module1.mod and eio.cfg. Prints `N passed, 0 failed` at the end; any failed
check exits non-zero."""

import sys
import time

import xml.etree.ElementTree as ET

import numpy as np
from abb_robot_client import rws

URL = sys.argv[1]
CHECKS = []


def check(name, condition, detail=""):
    CHECKS.append(name)
    if not condition:
        print(f"FAILED: {name} {detail}", flush=True)
        sys.exit(1)


def wait_for(what, timeout=10.0):
    """Polls `what()` until it is true, at most `timeout` seconds."""
    end = time.time() + timeout
    while time.time() < end:
        if what():
            return True
        time.sleep(0.05)
    return False


c = rws.RWS(URL)

# Panel.
check("controller state", c.get_controller_state() == "motoron")
check("operation mode", c.get_operation_mode() == "AUTO")
check("speed ratio", c.get_speedratio() == 100.0)
c.set_speedratio(50)
check("speed ratio set", c.get_speedratio() == 50.0)
c.set_speedratio(100)

# Execution and tasks, before the start: stopped with the PP at main.
state = c.get_execution_state()
check("stopped at boot", state.ctrlexecstate == "stopped", state)
tasks = c.get_tasks()
check("tasks", list(tasks) == ["T_ROB1"], tasks)
check("task T_ROB1", tasks["T_ROB1"].type_ == "normal" and tasks["T_ROB1"].motiontask and tasks["T_ROB1"].active)
c.deactivate_task("T_ROB1")
check("deactivated", not c.get_tasks()["T_ROB1"].active)
c.activate_task("T_ROB1")
check("activated", c.get_tasks()["T_ROB1"].active)

# Data: PERS values as RAPID literals, in and out.
check("pers num", c.get_rapid_variable("test_var_num") == "123.456")
check("pers string", c.get_rapid_variable("test_var_str") == '"Hello"')
c.set_rapid_variable_num("test_var_num", 7.5)
check("pers num set", c.get_rapid_variable_num("test_var_num") == 7.5)
c.set_rapid_variable("test_var_str", '"Hello World!"', "T_ROB1/Module1")
check("pers string set through the module", c.get_rapid_variable("test_var_str") == '"Hello World!"')
try:
    c.set_rapid_variable("test_var_num", '"text"')
    check("a string is no num", False)
except rws.ABBException as e:
    check("a string is no num", e.code != 0)
names = sorted(v["name"] for v in c.get_rapid_variables())
check("persistents listed", names == ["seen", "test_jt", "test_jts", "test_nums", "test_var_num", "test_var_str"], names)

# Arrays and jointtargets through the client's converters (radians on its side).
check("num array", list(c.get_rapid_variable_num_array("test_nums")) == [1, 2, 3])
c.set_rapid_variable_num_array("test_nums", [4.5, 5, -6])
check("num array set", list(c.get_rapid_variable_num_array("test_nums")) == [4.5, 5, -6])
jt = c.get_rapid_variable_jointtarget("test_jt")
check("jointtarget", np.allclose(np.rad2deg(jt.robax), [1, 2, 3, 4, 5, 6]) and np.allclose(np.rad2deg(jt.extax), 9e9), jt)
c.set_rapid_variable_jointtarget("test_jt", rws.JointTarget(np.deg2rad([10, 20, 30, 40, 50, 60]), jt.extax))
check("jointtarget set", np.allclose(np.rad2deg(c.get_rapid_variable_jointtarget("test_jt").robax), [10, 20, 30, 40, 50, 60]))
jts = c.get_rapid_variable_jointtarget_array("test_jts")
check("jointtarget array", len(jts) == 2 and np.allclose(np.rad2deg(jts[1].robax), [6, 5, 4, 3, 2, 1]), jts)
c.set_rapid_variable_jointtarget_array("test_jts", [jts[1], jts[0]])
swapped = c.get_rapid_variable_jointtarget_array("test_jts")
check("jointtarget array set", np.allclose(np.rad2deg(swapped[0].robax), [6, 5, 4, 3, 2, 1]), swapped)

# Signals.
check("DO at its default", c.get_digital_io("test_do1") == 0)
check("DI at its default", c.get_digital_io("test_di1") == 0)
c.set_analog_io("test_ao1", 2.5)
check("AO set", abs(c.get_analog_io("test_ao1") - 2.5) < 0.001)

# A subscription: the DO the program sets, and the execution state.
events = []
sub = c.subscribe([
    rws.SubscriptionResourceRequest(rws.SubscriptionResourceType.Signal, rws.SubscriptionResourcePriority.High, "test_do1"),
    rws.SubscriptionResourceRequest(rws.SubscriptionResourceType.ExecutionState, rws.SubscriptionResourcePriority.Medium),
    rws.SubscriptionResourceRequest(rws.SubscriptionResourceType.PersVar, rws.SubscriptionResourcePriority.High, "seen"),
], events.append)
time.sleep(0.5)

# Start: the robot moves to `home` and waits for test_di1.
seq_before = c.read_event_log()[0].seqnum
c.resetpp()
c.start(cycle="forever", tasks=["T_ROB1"])
check("running", c.get_execution_state().ctrlexecstate == "running")
check("cycle", c.get_execution_state().cycle == "forever")
check("joints reach home", wait_for(lambda: all(
    abs(a - b) < 0.01 for a, b in zip(c.get_jointtarget().robax, [10, 20, 30, 40, 50, 60]))),
    c.get_jointtarget())
jt = c.get_jointtarget()
check("no external axes", all(e > 8.9e9 for e in jt.extax), jt)
rt = c.get_robtarget()
check("robtarget", len(rt.trans) == 3 and abs(sum(q * q for q in rt.rot) - 1) < 1e-6, rt)
check("still waiting for the input", c.get_rapid_variable("seen") == "0")

# The input the program waits on: it counts, sets its output and logs.
c.set_digital_io("test_di1", 1)
check("the program saw the input", wait_for(lambda: c.get_rapid_variable("seen") == "1"))
check("the program set its output", wait_for(lambda: c.get_digital_io("test_do1") == 1))
check("the subscription delivered the signal",
      wait_for(lambda: any(isinstance(e, rws.Signal) and e.name == "test_do1" and e.lvalue == "1" for e in events)),
      events)
# abb-robot-client 0.4.0 fills VariableValue's name with the path's first part (the
# task) and its task with the last (the name): either way round is accepted.
check("the subscription delivered the persistent",
      wait_for(lambda: any(isinstance(e, rws.VariableValue) and "seen" in (e.name, e.task) and e.value == "1"
                           for e in events)),
      events)
log = c.read_event_log()
newer = [e for e in log if e.seqnum > seq_before]
mine = [e for e in newer if e.code == 80003]
check("ErrWrite \\I in the event log", len(mine) == 1 and mine[0].title == "Serve test"
      and mine[0].msgtype == 1 and mine[0].args[:2] == ["Serve test", "the input was seen"], log[:3])
check("newest first", [e.seqnum for e in log] == sorted((e.seqnum for e in log), reverse=True))

# Stop: done when the call returns.
c.stop()
check("stopped", c.get_execution_state().ctrlexecstate == "stopped")
check("the subscription delivered the execution state", wait_for(
    lambda: [e.ctrlexecstate for e in events if isinstance(e, rws.RAPIDExecutionState)][-2:] == ["running", "stopped"]),
    events)
sub.close()

# Motors off: no start.
c.set_controller_state("motoroff")
check("motors off", c.get_controller_state() == "motoroff")
try:
    c.start(cycle="once")
    check("no start with the motors off", False)
except rws.ABBException:
    check("no start with the motors off", True)
c.set_controller_state("motoron")
check("motors on", c.get_controller_state() == "motoron")

# Files on the RAM disk.
ramdisk = c.get_ramdisk_path()
c.upload_file(f"{ramdisk}/serve_test.bin", b"\x00\x01rapid")
check("file listed", "serve_test.bin" in c.list_files(ramdisk))
check("file read", c.read_file(f"{ramdisk}/serve_test.bin") == b"\x00\x01rapid")
c.delete_file(f"{ramdisk}/serve_test.bin")
check("file deleted", "serve_test.bin" not in c.list_files(ramdisk))
try:
    c.read_file(f"{ramdisk}/../../etc/passwd")
    check("a path leaving the device is refused", False)
except Exception:
    check("a path leaving the device is refused", True)

# Remote mastership and DIPC queues between clients.
# request_rmmp/poll_rmmp of 0.4.0 GET `base_url + "/" + base_url + …` (poll_rmmp passes
# a whole URL to _do_get), which no controller serves: the two requests they are made
# of are sent through the client's own helpers instead.
c._do_post("users/rmmp", {"privilege": "modify"})
poll = c._do_get("users/rmmp/poll")["_embedded"]["_state"][0]
check("rmmp", poll["_type"] == "user-rmmp-poll" and poll["status"] == "GRANTED", poll)
check("queue created", c.try_create_ipc_queue("serve_q"))
check("queue exists", not c.try_create_ipc_queue("serve_q"))
check("queue read empty", c.get_ipc_queue("serve_q")["_embedded"]["_state"] == [])
c.send_ipc_message("serve_q", "hello", "serve_q", cmd=7, userdef=3)
got = c.read_ipc_message("serve_q")
check("queue message", len(got) == 1 and got[0].data == "hello" and got[0].userdef == "3", got)

# XHTML, the default format (abb_librws reads it): well-formed XML, items as
# <li class title> with one <span class> per field.
XHTML = "{http://www.w3.org/1999/xhtml}"
for path in ["rw/rapid/execution", "rw/rapid/tasks", "rw/iosystem/signals", "rw/elog/0", "rw/panel/ctrlstate",
             f"fileservice/{ramdisk}", "rw/motionsystem/mechunits/ROB_1/jointtarget", "rw/nothing"]:
    res = c._session.get(f"{URL}/{path}", auth=c.auth)
    root = ET.fromstring(res.content)
    check(f"XHTML of {path}", root.tag == XHTML + "html", res.text[:200])
spans = {s.get("class"): s.text for s in ET.fromstring(c._session.get(f"{URL}/rw/rapid/execution", auth=c.auth).content).iter(XHTML + "span")}
check("XHTML execution state", spans.get("ctrlexecstate") == "stopped", spans)

c.logout()
c.close()
print(f"{len(CHECKS)} passed, 0 failed", flush=True)
