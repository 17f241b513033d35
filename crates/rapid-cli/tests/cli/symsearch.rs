//! The symbol search across modules (one conformance program holds one module only):
//! LOCAL data of the same name in two modules, `\InMod`, and a datapos that makes
//! GetDataVal/SetDataVal see the LOCAL data of the module it names.

use std::fs;
use std::process::Command;

use crate::fixture::{scratch_in, Scratch};

/// A fresh, empty scratch folder for one test.
fn temp_dir(name: &str) -> Scratch {
    scratch_in("symsearch", name)
}

const MAIN: &str = r#"MODULE mainmod
    LOCAL VAR num count := 1;
    VAR num total := 10;

    PROC main()
        VAR string name;
        VAR datapos block;
        VAR num value;
        SetDataSearch "num" \Object:="count";
        WHILE GetNextSym(name, block) DO
            GetDataVal name \Block:=block, value;
            TPWrite name + "=" \Num:=value;
        ENDWHILE
        SetDataSearch "num" \InMod:="OtherMod";
        WHILE GetNextSym(name, block) DO
            TPWrite "othermod: " + name;
        ENDWHILE
        SetDataSearch "num" \Object:="count" \InMod:="othermod";
        IF GetNextSym(name, block) THEN
            SetDataVal name \Block:=block, 22;
            GetDataVal "total" \Block:=block, value;
            TPWrite "total=" \Num:=value;
        ENDIF
        TPWrite "count=" \Num:=count;
        TPWrite "other=" \Num:=othercount();
    ENDPROC
ENDMODULE
"#;

const OTHER: &str = r#"MODULE othermod
    LOCAL VAR num count := 2;
    VAR num shared := 3;

    FUNC num othercount()
        RETURN count;
    ENDFUNC
ENDMODULE
"#;

#[test]
fn local_data_of_two_modules_through_datapos() {
    let dir = temp_dir("modules");
    fs::write(dir.join("mainmod.mod"), MAIN).unwrap();
    fs::write(dir.join("othermod.mod"), OTHER).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .arg("run")
        .arg("--home")
        .arg(dir.join("home"))
        .arg(dir.join("mainmod.mod"))
        .arg(dir.join("othermod.mod"))
        .output()
        .expect("run rapid");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    // Declaration order: mainmod's count, then othermod's; othermod's data only with
    // \InMod; from othermod's block, its LOCAL count is the one written and the global
    // total of mainmod is still visible.
    let expected = "count=1\ncount=2\nothermod: count\nothermod: shared\ntotal=10\ncount=1\nother=22\n";
    assert_eq!(String::from_utf8_lossy(&out.stdout), expected);
}

#[test]
fn a_search_sees_the_data_of_modules_loaded_and_no_longer_of_those_unloaded() {
    let dir = temp_dir("loaded");
    fs::create_dir_all(dir.join("home").join("HOME")).unwrap();
    fs::write(dir.join("home").join("HOME").join("extra.mod"), "MODULE extra\n    PERS num extra_n := 5;\nENDMODULE\n")
        .unwrap();
    let main = r#"MODULE mainmod
    VAR num main_n := 1;

    PROC list(string title)
        VAR string name;
        VAR datapos block;
        SetDataSearch "num" \Object:=".*_n";
        WHILE GetNextSym(name, block) DO
            TPWrite title + ": " + name;
        ENDWHILE
    ENDPROC

    PROC main()
        list "before";
        Load "HOME:/extra.mod";
        list "loaded";
        UnLoad "HOME:/extra.mod";
        list "unloaded";
    ENDPROC
ENDMODULE
"#;
    fs::write(dir.join("mainmod.mod"), main).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .arg("run")
        .arg("--home")
        .arg(dir.join("home"))
        .arg(dir.join("mainmod.mod"))
        .output()
        .expect("run rapid");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    // The loaded module's persistent is the task's data while it is loaded (§1.17).
    let expected = "before: main_n\nloaded: main_n\nloaded: extra_n\nunloaded: main_n\n";
    assert_eq!(String::from_utf8_lossy(&out.stdout), expected);
}
