//! `--virtual-io` beyond the AliasIO names the text shows: AliasIO names computed at
//! run time, and signals a program names directly (SetDO, DInput, SetGO…) that no
//! configuration defines, each a virtual signal of the kind its place needs, listed
//! once on stderr; `rapid check --virtual-io` does not call them undefined.

use std::fs;
use std::process::Command;

use crate::fixture::scratch_in;

const PROGRAM: &str = r#"MODULE vio
  VAR signaldo doLamp;
  VAR bool late;
  PROC main()
    VAR num n := 3;
    AliasIO "DO_" + NumToStr(n, 0), doLamp;
    SetDO doGrip, 1;
    SetDO doLamp, 1;
    TPWrite "grip " \Num:=DOutput(doGrip);
    TPWrite "lamp " \Num:=DOutput(doLamp);
    TPWrite "part " \Num:=DInput(diPart);
    SetGO goCode, 5;
    TPWrite "code " \Num:=GOutput(goCode);
    WaitDI diPart, 1 \MaxTime:=0.2 \TimeFlag:=late;
    TPWrite "late " \Bool:=late;
    more;
  ENDPROC
  PROC more()
    ! the same signal in another routine is the same virtual signal
    SetDO doGrip, 0;
    TPWrite "grip " \Num:=DOutput(doGrip);
  ENDPROC
ENDMODULE
"#;

fn rapid(args: &[&str]) -> (Option<i32>, String, String) {
    let dir = scratch_in("virtual_signals", args[0]);
    let path = dir.join("vio.mod");
    fs::write(&path, PROGRAM).expect("write module");
    let out = Command::new(env!("CARGO_BIN_EXE_rapid")).args(args).arg(&path).output().expect("run rapid");
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

#[test]
fn signals_named_directly_or_computed_become_virtual_and_are_listed_once() {
    let (code, stdout, stderr) = rapid(&["run", "--virtual-io"]);
    assert_eq!(code, Some(0), "stdout:\n{stdout}\nstderr:\n{stderr}");
    // SetDO sets the outputs, DInput reads an input nothing drives (0), SetGO sets the
    // group, the wait for diPart runs out (\TimeFlag), SetDO 0 resets doGrip.
    assert_eq!(stdout, "grip 1\nlamp 1\npart 0\ncode 5\nlate TRUE\ngrip 0\n");
    let listed: Vec<&str> = stderr.lines().filter(|l| l.starts_with("note: virtual signal")).collect();
    for (name, kind) in [("doGrip", "DO"), ("diPart", "DI"), ("goCode", "GO"), ("DO_3", "DO")] {
        let lines: Vec<&&str> = listed.iter().filter(|l| l.contains(&format!(" {name} ({kind})"))).collect();
        assert_eq!(lines.len(), 1, "{name}: {stderr}");
    }
    assert_eq!(listed.len(), 4, "{stderr}");
}

#[test]
fn check_with_virtual_io_does_not_call_them_undefined() {
    let (code, stdout, _) = rapid(&["check", "--virtual-io"]);
    assert_eq!(code, Some(0), "{stdout}");
    // Without the flag they are undefined data, as on a controller lacking them.
    let (code, stdout, _) = rapid(&["check"]);
    assert_ne!(code, Some(0));
    for name in ["doGrip", "diPart", "goCode"] {
        assert!(stdout.contains(&format!("undefined data `{name}`")), "{name}: {stdout}");
    }
}
