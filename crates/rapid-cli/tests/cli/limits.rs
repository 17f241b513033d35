//! The one table of limits (`rapid-limits`): what `rapid check` accepts, `rapid run`
//! accepts, and both refuse the same thing with the same message naming the limit.
//!
//! Expected values by hand: an array holds at most 2^20 = 1048576 elements, so
//! 1024 × 1024 fits exactly and 1024 × 1025 = 1049600 is one row too many.

use crate::fixture::{rapid_in, scratch_in, stderr, stdout, write_files};

const FITS: &str = "MODULE M\n  VAR num a{1024,1024};\n  PROC main()\n    a{1024,1024} := 7;\n    \
                    TPWrite \"\" \\Num:=a{1024,1024};\n  ENDPROC\nENDMODULE\n";
const TOO_BIG: &str = "MODULE M\n  VAR num a{1024,1025};\n  PROC main()\n  ENDPROC\nENDMODULE\n";
const TOO_BIG_LOCAL: &str = "MODULE M\n  PROC main()\n    VAR num b{100000000};\n  ENDPROC\nENDMODULE\n";

#[test]
fn an_array_at_the_limit_checks_and_runs() {
    let dir = scratch_in("limits", "fits");
    write_files(&dir, &[("m.mod", FITS)]);
    let check = rapid_in(&dir, &["check", "m.mod"]);
    assert!(check.status.success(), "{}", stderr(&check));
    let run = rapid_in(&dir, &["run", "m.mod"]);
    assert!(run.status.success(), "{}", stderr(&run));
    assert_eq!(stdout(&run), "7\n");
}

#[test]
fn check_and_run_refuse_an_array_over_the_limit_alike() {
    let dir = scratch_in("limits", "too_big");
    write_files(&dir, &[("m.mod", TOO_BIG), ("l.mod", TOO_BIG_LOCAL)]);
    for (file, message) in [
        ("m.mod", "error[E0313]: array `a` has 1049600 elements; at most 1048576 fit"),
        // 1e8 is a positive integer: it is the size that is refused, not the number.
        ("l.mod", "error[E0313]: array `b` has 100000000 elements; at most 1048576 fit"),
    ] {
        let check = rapid_in(&dir, &["check", file]);
        let run = rapid_in(&dir, &["run", file]);
        assert_eq!(check.status.code(), Some(1), "{file}");
        assert_eq!(run.status.code(), Some(1), "{file}");
        // check reports on stdout; run reports why it did not start on stderr.
        assert!(stdout(&check).contains(message), "{file}: {}", stdout(&check));
        assert!(stderr(&run).contains(message), "{file}: {}", stderr(&run));
    }
}

/// Opens 65 files in turn without closing them: the 65th Open is refused with
/// ERR_FILEOPEN (64 may be open at once), and the handler prints how many were open.
const OPENER: &str = "MODULE M\n  VAR iodev f{65};\n  VAR num n := 0;\n  PROC main()\n    \
                      FOR i FROM 1 TO 65 DO\n      Open \"HOME:\" \\File:=\"f\" + NumToStr(i, 0) + \".txt\", \
                      f{i} \\Write;\n      n := n + 1;\n    ENDFOR\n    TPWrite \"all open\";\n  \
                      ERROR\n    IF ERRNO = ERR_FILEOPEN TPWrite \"refused after \" \\Num:=n;\n  \
                      ENDPROC\nENDMODULE\n";

#[test]
fn open_files_are_bounded() {
    let dir = scratch_in("limits", "open_files");
    write_files(&dir, &[("m.mod", OPENER)]);
    let home = dir.join("home");
    std::fs::create_dir_all(&home).expect("home");
    let home = home.to_string_lossy().into_owned();
    let run = rapid_in(&dir, &["run", "--home", &home, "m.mod"]);
    assert_eq!(stdout(&run), "refused after 64\n", "{}", stderr(&run));
}

/// W0706, the program-memory note: a module of 65 comment lines of 1 MiB (over the
/// 64 MiB = 67108864 bytes of `rapid-limits`) is noted by check and by run alike, with
/// its size in bytes, and still runs: the figure is ours, so it is a warning.
#[test]
fn check_and_run_note_a_program_larger_than_program_memory_alike() {
    let dir = scratch_in("limits", "program_memory");
    let line = format!("! {}\n", "x".repeat((1 << 20) - 3));
    let text = format!("MODULE Points\n{}  PROC main()\n    TPWrite \"ran\";\n  ENDPROC\nENDMODULE\n", line.repeat(65));
    std::fs::write(dir.join("points.mod"), &text).expect("write points.mod");
    let message =
        format!("the task's program is {} bytes of source text; program memory holds at most 67108864 ", text.len());
    let check = rapid_in(&dir, &["check", "points.mod"]);
    assert_eq!(check.status.code(), Some(0), "{}", stdout(&check));
    assert!(stdout(&check).contains(&format!("warning[W0706]: {message}")), "{}", stdout(&check));
    let run = rapid_in(&dir, &["run", "points.mod"]);
    assert!(run.status.success(), "{}", stderr(&run));
    assert_eq!(stdout(&run), "ran\n");
    assert!(stderr(&run).contains(&format!("warning[W0706]: points.mod:1:1: {message}")), "{}", stderr(&run));
}
