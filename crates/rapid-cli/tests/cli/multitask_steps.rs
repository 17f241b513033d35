//! How tasks take turns (§1.20 优先级): the tasks at one level run "a basic step" each
//! in turn. A basic step is taken to be a statement, so no statement of one task is cut
//! between its reads and writes by another's.

use crate::fixture::{rapid_in, scratch_in, system, text, TaskDef};

#[test]
fn two_tasks_counting_in_one_shared_persistent_lose_no_count() {
    let dir = scratch_in("multitask_steps", "shared_counter");
    // Each task adds 1 to the shared counter 1000 times, computing only (no waits), so
    // their statements interleave one by one. A statement read-modify-write is whole:
    // 1000 + 1000.
    let a = "MODULE A\n  PERS num counter := 0;\n  PERS bool bDone := FALSE;\n  PROC main()\n    \
             FOR i FROM 1 TO 1000 DO\n      counter := counter + 1;\n    ENDFOR\n    WaitUntil bDone;\n    \
             TPWrite \"counter \" \\Num:=counter;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PERS num counter := 0;\n  PERS bool bDone := FALSE;\n  PROC main()\n    \
             FOR i FROM 1 TO 1000 DO\n      counter := counter + 1;\n    ENDFOR\n    bDone := TRUE;\n  \
             ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: a },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "counter 2000\n");
}
