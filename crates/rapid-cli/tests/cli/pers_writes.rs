//! What one task writes of the data it shares with another (global persistents, the
//! variables of a shared module) reaches the other task whichever way the statement
//! writes it: a whole persistent, an element of a persistent array, a component of a
//! persistent record, a num variable and an element of a num array (written by the
//! interpreter's fast kernels), a variable through a VAR parameter, SetDataVal, and
//! through a PERS parameter.

use std::fs;

use crate::fixture::{rapid_in, scratch_in, system, text, TaskDef};

#[test]
fn every_way_of_writing_shared_data_reaches_the_other_task() {
    let dir = scratch_in("pers_writes", "paths");
    let shared = "MODULE shared(SYSMODULE)\n  VAR num k := 0;\n  VAR num karr{3} := [0, 0, 0];\n  \
                  VAR num m := 0;\nENDMODULE\n";
    let a = "MODULE A\n  PERS num n := 0;\n  PERS num parr{3} := [0, 0, 0];\n  PERS pos p := [0, 0, 0];\n  \
             PERS num s := 0;\n  PERS num q := 0;\n  PERS bool done := FALSE;\n  PROC main()\n    \
             VAR num loc := 1;\n    n := 5;\n    parr{2} := 7;\n    p.x := 3;\n    k := k + 1;\n    \
             karr{2} := loc * 2;\n    bump m;\n    SetDataVal \"s\", 6;\n    setp q;\n    done := TRUE;\n  \
             ENDPROC\n  PROC bump(VAR num x)\n    x := x + 10;\n  ENDPROC\n  PROC setp(PERS num y)\n    \
             y := 4;\n  ENDPROC\nENDMODULE\n";
    // T_B declares the persistents without values: T_A's give them theirs (§1.2.2).
    let b = "MODULE B\n  PERS num n;\n  PERS num parr{3};\n  PERS pos p;\n  PERS num s;\n  PERS num q;\n  \
             PERS bool done;\n  PROC main()\n    WaitUntil done;\n    TPWrite \"n \" \\Num:=n;\n    \
             TPWrite \"parr \" \\Num:=parr{2};\n    TPWrite \"p.x \" \\Num:=p.x;\n    TPWrite \"k \" \\Num:=k;\n    \
             TPWrite \"karr \" \\Num:=karr{2};\n    TPWrite \"m \" \\Num:=m;\n    TPWrite \"s \" \\Num:=s;\n    \
             TPWrite \"q \" \\Num:=q;\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_A", attrs: "-Type \"NORMAL\"", module: a },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    let root = system(&dir, &tasks, "");
    fs::create_dir_all(root.join("HOME")).expect("HOME");
    fs::write(root.join("HOME/shared.sys"), shared).expect("shared module");
    let path = root.join("SYSPAR/SYS.cfg");
    let sys = fs::read_to_string(&path).expect("SYS.cfg");
    fs::write(&path, format!("{sys}#\nCAB_TASK_MODULES:\n\n      -File \"HOME:/shared.sys\" -Shared\n"))
        .expect("SYS.cfg");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "n 5\nparr 7\np.x 3\nk 1\nkarr 2\nm 10\ns 6\nq 4\n");
}
