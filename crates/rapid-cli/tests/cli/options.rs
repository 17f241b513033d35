//! Software options and encrypted modules on whole systems (`tests/check/options/`):
//! the options come from a backup's system.xml or backinfo.txt, or a manifest's
//! `options`; `rapid run` refuses option instructions and tasks that need encrypted
//! code before anything runs.

use std::path::{Path, PathBuf};

use crate::fixture::{rapid_in, scratch_in, stderr, stdout, write_files};

fn options_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check/options")
}

#[test]
fn egm_names_check_clean_on_a_system_with_egm() {
    // system.xml lists "689-1 Externally Guided Motion (EGM)".
    let out = rapid_in(&options_dir(), &["check", "egm_cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", stdout(&out));
    assert_eq!(stdout(&out), "checked 1 file: no problems found\n");
}

#[test]
fn egm_names_belong_to_an_option_a_system_without_egm_lacks() {
    // backinfo.txt's products have no EGM. Guide.mod uses eleven EGM names: egmident
    // (line 4), egm_minmax (5), EGMReset (10, 18), EGMGetId (11), EGMSetupUC (12),
    // EGMActJoint (13), EGMRunJoint and EGM_STOP_HOLD (14), EGMGetState and
    // EGM_STATE_CONNECTED (15).
    let out = rapid_in(&options_dir(), &["check", "no_egm"]);
    let report = stdout(&out);
    assert_eq!(out.status.code(), Some(1), "{report}");
    assert_eq!(report.matches("error[E0217]").count(), 11, "{report}");
    assert!(report.contains(
        "error[E0217]: `EGMSetupUC` belongs to option Externally Guided Motion (EGM), which this system does not have"
    ));
    assert!(!report.contains("undefined"), "{report}");
    assert!(report.ends_with("found 11 errors and 0 warnings in 1 file\n"), "{report}");
}

#[test]
fn run_refuses_an_option_instruction_naming_the_option_before_anything_runs() {
    let out = rapid_in(&options_dir(), &["run", "egm_cell"]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let err = stderr(&out);
    // One refusal for the option, at its first call (line 10), naming each EGM routine
    // the program calls once, in the order they are first called.
    assert!(
        err.starts_with(
            "error: `EGMReset`, `EGMGetId`, `EGMSetupUC`, `EGMActJoint`, `EGMRunJoint`, `EGMGetState` belong to \
             option Externally Guided Motion (EGM), which `rapid run` does not simulate \
             (egm_cell/RAPID/TASK1/PROGMOD/Guide.mod:10:9)\n"
        ),
        "{err}"
    );
    assert_eq!(err.lines().count(), 2, "{err}");
    assert!(err.ends_with("the program was not run\n"), "{err}");
    // Refused at load: not even the moves before the first EGM call ran.
    assert_eq!(stdout(&out), "");
}

#[test]
fn a_manifest_names_its_options() {
    // `options = ["633-1 Arc", "652-1 BullsEye"]`: the Arc data and instructions check.
    let out = rapid_in(&options_dir(), &["check", "arc_project"]);
    assert_eq!(stdout(&out), "checked 2 files: no problems found\n");
    // `rapid run` refuses the arc welding instructions; the TPWrite before them never runs.
    let out = rapid_in(&options_dir(), &["run", "arc_project"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains(
        "error: `ArcLStart`, `ArcLEnd` belong to option Arc (RobotWare Arc), which `rapid run` does not simulate"
    ));
    assert!(!stdout(&out).contains("weld speed"), "{}", stdout(&out));
}

#[test]
fn a_manifest_without_the_option_reports_its_names() {
    let dir = scratch_in("options", "manifest_without_arc");
    let weld = std::fs::read_to_string(options_dir().join("arc_project/Weld.mod")).expect("Weld.mod");
    let manifest = "[system]\noptions = [\"EGM\"]\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"Weld.mod\"]\n";
    write_files(dir.path(), &[("cell/rapid.toml", manifest), ("cell/Weld.mod", &weld)]);
    let out = rapid_in(dir.path(), &["check", "cell"]);
    let report = stdout(&out);
    // seamdata (line 3), welddata (4), weavedata (5), ArcLStart (12), ArcLEnd (13).
    assert_eq!(report.matches("error[E0217]").count(), 5, "{report}");
    assert!(report.contains("`weavedata` belongs to option Arc (RobotWare Arc), which this system does not have"));
}

#[test]
fn an_encrypted_module_makes_undefined_names_warnings_and_the_task_unrunnable() {
    let out = rapid_in(&options_dir(), &["check", "encrypted"]);
    let report = stdout(&out);
    assert_eq!(out.status.code(), Some(0), "{report}");
    assert_eq!(report.matches("warning[W0218]").count(), 2, "{report}");
    assert_eq!(report.matches("warning[W0131]").count(), 1, "{report}");
    assert!(report.contains("it may be defined in the encrypted module `encrypted/RAPID/TASK1/PROGMOD/TuneLib.mod`"));
    assert!(report.ends_with("found 0 errors and 3 warnings in 2 files\n"), "{report}");

    let out = rapid_in(&options_dir(), &["run", "encrypted"]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(
        err.contains(
            "error: the task cannot run: it needs code from the encrypted module \
             `encrypted/RAPID/TASK1/PROGMOD/TuneLib.mod`, which cannot be read (`TuneInit`, `tune_gain` defined in no \
             readable module)"
        ),
        "{err}"
    );
}

#[test]
fn module_data_of_an_opaque_option_type_checks_but_does_not_run() {
    // be_device's components are not public: declaring and passing it checks (no
    // system information: every option assumed present), running it is refused.
    let dir = scratch_in("options", "opaque_data");
    let module = "MODULE Be\n  PERS be_device dev1 := [\"diBE\", TRUE, [6, 45, 100, 100], 0.1];\n  \
                  PROC show(be_device d)\n    TPWrite \"passed\";\n  ENDPROC\n  \
                  PROC main()\n    show dev1;\n  ENDPROC\nENDMODULE\n";
    write_files(dir.path(), &[("Be.mod", module)]);
    let out = rapid_in(dir.path(), &["check", "Be.mod"]);
    assert_eq!(stdout(&out), "checked 1 file: no problems found\n");
    let out = rapid_in(dir.path(), &["run", "Be.mod"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains(
            "error: `dev1` is data of `be_device`, a type of option BullsEye whose components are not public"
        ),
        "{}",
        stderr(&out)
    );
    assert_eq!(stdout(&out), "");
}

#[test]
fn option_calls_as_public_programs_write_them_check_clean_on_a_system_with_the_options() {
    // weld_cell's system.xml lists EGM, Force Control, Production Manager and Arc with
    // BullsEye and SmarTac; its modules call each option the way public programs do.
    let out = rapid_in(&options_dir(), &["check", "weld_cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", stdout(&out));
    assert_eq!(stdout(&out), "checked 2 files: no problems found\n");
}

#[test]
fn option_calls_on_a_system_without_the_options_belong_to_them() {
    // The same modules with only RobotWare Base: every option name is E0217, once per
    // use. Counted by hand from the modules: Production Manager 3 (menudata, partdata,
    // ExecEngine), Arc 9 (seamdata, welddata, weavedata, trackdata, ArcLStart, ArcL,
    // ArcCEnd, ArcRefresh, ArcMoveExtJ), SmarTac 4 (Search_1D twice, PDispAdd,
    // Search_Groove), Force Control 7 (fcforcevector, FCLoadId, FCCalib, FCAct,
    // FCPress1LStart, FCPressL, FCGetForce), EGM 8 (egmident, egm_minmax, EGMGetId,
    // EGMSetupUC, EGMActJoint, EGMRunJoint, EGM_STOP_HOLD, EGMReset), BullsEye 9
    // (be_device, be_scan, be_tooldesign, BEDebugState, BESetupToolJ, BECheckTcp,
    // BEUpdateTcp, BERefPointer, BETcpExtend): 40.
    let dir = scratch_in("options", "weld_cell_without_options");
    let source = options_dir().join("weld_cell/RAPID/TASK1");
    let cell = std::fs::read_to_string(source.join("PROGMOD/Cell.mod")).expect("Cell.mod");
    let torch = std::fs::read_to_string(source.join("SYSMOD/TorchCheck.sys")).expect("TorchCheck.sys");
    let system = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<SystemProperties>\n  <ControlModule>\n    \
                  <Option descr=\"RobotWare Base\">\n    </Option>\n  </ControlModule>\n</SystemProperties>\n";
    write_files(
        dir.path(),
        &[
            ("cell/system.xml", system),
            ("cell/RAPID/TASK1/PROGMOD/Cell.mod", &cell),
            ("cell/RAPID/TASK1/SYSMOD/TorchCheck.sys", &torch),
        ],
    );
    let out = rapid_in(dir.path(), &["check", "cell"]);
    let report = stdout(&out);
    assert_eq!(out.status.code(), Some(1), "{report}");
    for (option, count) in [
        ("Production Manager", 3),
        ("Arc (RobotWare Arc)", 9),
        ("SmarTac", 4),
        ("Force Control", 7),
        ("Externally Guided Motion (EGM)", 8),
        ("BullsEye", 9),
    ] {
        let needle = format!("belongs to option {option}, which this system does not have");
        assert_eq!(report.matches(&needle).count(), count, "{option}: {report}");
    }
    assert!(report.contains("error[E0217]: `FCLoadId` belongs to option Force Control"), "{report}");
    assert!(report.ends_with("found 40 errors and 0 warnings in 2 files\n"), "{report}");
}

#[test]
fn run_refuses_the_production_manager_loop_naming_its_option() {
    // menudata and partdata are opaque: module data of them cannot be given a value.
    let out = rapid_in(&options_dir(), &["run", "weld_cell"]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("`mdCleanTorch` is data of `menudata`, a type of option Production Manager"), "{err}");
    assert_eq!(stdout(&out), "");
}
