"""abb-robot-client 0.4.0 against `rapid serve` on examples/press_cell_project (three
tasks: T_ROB1 and T_PRESS NORMAL, T_MONITOR SEMISTATIC; see its rapid.toml).
tests/cli/serve.rs runs it; prints `N passed, 0 failed`."""

import sys
import time

from abb_robot_client import rws

c = rws.RWS(sys.argv[1])
CHECKS = []


def check(name, condition, detail=""):
    CHECKS.append(name)
    if not condition:
        print(f"FAILED: {name} {detail}", flush=True)
        sys.exit(1)


tasks = c.get_tasks()
check("three tasks in configuration order", list(tasks) == ["T_ROB1", "T_PRESS", "T_MONITOR"], tasks)
check("types", [t.type_ for t in tasks.values()] == ["normal", "normal", "semistatic"], tasks)
check("one motion task", [t.motiontask for t in tasks.values()] == [True, False, False], tasks)
check("NORMAL tasks stand stopped", tasks["T_ROB1"].excstate == "stopped" and tasks["T_PRESS"].excstate == "stopped")
check("a shared persistent", c.get_rapid_variable("partsDone", "T_PRESS") == "0")
c.start(cycle="forever", tasks=["T_ROB1"])
check("running", c.get_execution_state().ctrlexecstate == "running")
check("every NORMAL task started", all(t.excstate == "started" for t in c.get_tasks().values()), c.get_tasks())
c.stop()
check("stopped", c.get_execution_state().ctrlexecstate == "stopped")
print(f"{len(CHECKS)} passed, 0 failed", flush=True)
