//! Software options and encrypted modules in name resolution: names of an option
//! the system has (or may have) are known, names of one it lacks are E0217, and in a
//! task with an encrypted module undefined names are W0218 warnings.

use rapid_sema::{check, Diagnostic, Options, SourceInput};
use rapid_syntax::LineIndex;

/// An EGM and an arc-welding routine using each option's data, constants and calls
/// as the application manuals write them.
const CELL: &str = "MODULE Cell
VAR egmident egm_id;
CONST egm_minmax conv := [-0.1, 0.1];
PERS welddata weld1 := [10, 0, [1, 0, 25, 200, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0, 0, 0, 0]];
PERS seamdata seam1 := [0.5, 1, [1, 0, 20, 100, 0, 0, 0, 0, 0], 0, 0, 0, 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0];
PERS tooldata torch := [TRUE, [[0, 0, 200], [1, 0, 0, 0]], [2, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
CONST robtarget p10 := [[500, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
PROC guide()
  EGMGetId egm_id;
  EGMSetupUC ROB_1, egm_id, \"default\", \"UCdevice\" \\Joint \\CommTimeout:=10;
  EGMActJoint egm_id \\J1:=conv \\J2:=conv \\SampleRate:=4;
  EGMRunJoint egm_id, EGM_STOP_HOLD \\J1 \\J2 \\CondTime:=20 \\RampInTime:=0.05;
  IF EGMGetState(egm_id) = EGM_STATE_RUNNING EGMStop egm_id, EGM_STOP_RAMP_DOWN;
  EGMReset egm_id;
ENDPROC
PROC weld()
  ArcLStart p10, v100, seam1, weld1, fine, torch;
  ArcLEnd p10, v10, seam1, weld1, fine, torch;
  weld1.weld_speed := weld1.main_arc.voltage * 2;
ENDPROC
ENDMODULE
";

fn diagnostics(files: &[SourceInput], system_options: Option<&[&str]>) -> Vec<Diagnostic> {
    let system_options = system_options.map(|names| names.iter().map(|n| n.to_string()).collect());
    check(files, &Options { system_options, ..Options::default() })
}

/// (code, line, message) of each diagnostic of the first file.
fn found(files: &[SourceInput], system_options: Option<&[&str]>) -> Vec<(String, u32, String)> {
    diagnostics(files, system_options)
        .iter()
        .map(|d| {
            let text = &files[d.file].text;
            let line = LineIndex::new(text).line_col(text, d.span.start).line;
            (d.code.as_str().to_owned(), line, d.message.clone())
        })
        .collect()
}

#[test]
fn option_names_check_clean_where_the_system_has_the_options_or_nobody_says() {
    let files = [SourceInput::from_text("cell.mod", CELL)];
    // A loose module: the target's options are unknown, so they are assumed present.
    assert_eq!(found(&files, None), vec![]);
    // The descriptions a backup's system.xml gives, and a manifest's short names.
    let backup = ["RobotWare Base", "689-1 Externally Guided Motion (EGM)", "633-1 Arc", "623-1 Multitasking"];
    assert_eq!(found(&files, Some(&backup)), vec![]);
    assert_eq!(found(&files, Some(&["EGM", "arc"])), vec![]);
}

#[test]
fn names_of_an_option_the_system_lacks_belong_to_it() {
    let files = [SourceInput::from_text("cell.mod", CELL)];
    let egm = "belongs to option Externally Guided Motion (EGM), which this system does not have";
    let expected: Vec<(String, u32, String)> = [
        (2, format!("`egmident` {egm}")),
        (3, format!("`egm_minmax` {egm}")),
        (9, format!("`EGMGetId` {egm}")),
        (10, format!("`EGMSetupUC` {egm}")),
        (11, format!("`EGMActJoint` {egm}")),
        (12, format!("`EGMRunJoint` {egm}")),
        (12, format!("`EGM_STOP_HOLD` {egm}")),
        (13, format!("`EGMGetState` {egm}")),
        (13, format!("`EGM_STATE_RUNNING` {egm}")),
        (13, format!("`EGMStop` {egm}")),
        (13, format!("`EGM_STOP_RAMP_DOWN` {egm}")),
        (14, format!("`EGMReset` {egm}")),
    ]
    .into_iter()
    .map(|(line, message)| ("E0217".to_owned(), line, message))
    .collect();
    // Arc present, EGM absent: only the EGM names are reported, each once where it is
    // used; the arguments that are the program's own data (egm_id, conv) are fine.
    let got = found(&files, Some(&["633-1 Arc"]));
    assert_eq!(got, expected);
}

#[test]
fn an_arc_name_without_arc_is_no_undefined_name() {
    let files = [SourceInput::from_text("cell.mod", CELL)];
    let got = found(&files, Some(&["689-1 Externally Guided Motion (EGM)"]));
    let codes: Vec<&str> = got.iter().map(|d| d.0.as_str()).collect();
    // welddata (4), seamdata (5), ArcLStart (17), ArcLEnd (18): E0217 each.
    assert_eq!(codes, ["E0217"; 4], "{got:?}");
    assert_eq!(got[0].2, "`welddata` belongs to option Arc (RobotWare Arc), which this system does not have");
    assert_eq!(got.iter().map(|d| d.1).collect::<Vec<_>>(), [4, 5, 17, 18]);
}

#[test]
fn an_opaque_option_type_is_declared_and_passed_but_its_components_are_not_read() {
    let text = "MODULE Be
CONST be_device dev1 := [\"diBE_SEN1\", TRUE, [6, 45, 100, 100], 0.1];
VAR trackdata track1;
PROC check_tool()
  BECheckTcp tool0 \\XYZOnly;
  TPWrite \"\" \\Num:=dev1.beam;
ENDPROC
ENDMODULE
";
    let files = [SourceInput::from_text("be.mod", text)];
    let got = found(&files, None);
    assert_eq!(got.len(), 1, "{got:?}");
    assert_eq!(got[0].0, "E0305");
    assert_eq!(got[0].1, 6);
    assert!(got[0].2.contains("option BullsEye"), "{}", got[0].2);
}

#[test]
fn undefined_names_beside_an_encrypted_module_are_warnings_naming_it() {
    let user = "MODULE Main\nPROC main()\n  TuneInit;\n  reg1 := tune_gain;\nENDPROC\nENDMODULE\n";
    let files = [
        SourceInput::from_text("Main.mod", user),
        SourceInput::from_bytes("TuneLib.mod", vec![0xFC, 0x12, 0x34, 0x56]),
    ];
    let got = found(&files, None);
    let codes: Vec<(&str, u32)> = got.iter().map(|d| (d.0.as_str(), d.1)).collect();
    // Main.mod lines 3 and 4 (W0218 each), TuneLib.mod line 1 (W0131).
    assert_eq!(codes, [("W0218", 3), ("W0218", 4), ("W0131", 1)], "{got:?}");
    assert!(got[0].2.contains("encrypted module `TuneLib.mod`"), "{}", got[0].2);
    assert!(got[1].2.starts_with("undefined data `tune_gain`"), "{}", got[1].2);
    assert!(!diagnostics(&files, None).iter().any(|d| d.severity() == rapid_sema::Severity::Error));
}

/// Calls of option routines written the way public RobotWare programs write them:
/// ABB's BullsEye user template, SmarTac and arc welding programs, Force Control
/// programs, ABB's EGM state machine add-in and a Production Manager system (the
/// sources are named in the catalogue files, `rapid-lib/src/catalogue/options/`).
const PUBLIC_CALLS: &str = "MODULE Calls
TASK PERS menudata mdClean:=[\"Clean\",\"\",\"Clean\",1,\"\",255,TRUE,2,0,FALSE,12];
TASK PERS tooldata tGun:=[TRUE,[[0,0,380],[1,0,0,0]],[3,[0,0,100],[1,0,0,0],0,0,0]];
TASK PERS wobjdata woTable:=[FALSE,TRUE,\"\",[[800,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
TASK PERS loaddata ldTool:=[2,[0,0,60],[1,0,0,0],0,0,0];
TASK PERS pose peFound:=[[0,0,0],[1,0,0,0]];
TASK PERS num nWidth:=0;
TASK PERS num nTime:=0;
CONST robtarget pA:=[[600,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
CONST robtarget pB:=[[650,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
CONST jointtarget jA:=[[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
VAR be_device dev;
VAR be_scan scan;
VAR be_tooldesign design;
VAR egmident egmId;
PROC calls()
  BESetupToolJ jA,jA,15,design,scan,dev,v100,fine,tGun\\ElapsedTime:=nTime;
  BECheckTcp tGun\\XYZOnly\\SingleScan;
  Search_1D \\Wire,peFound\\SearchStop:=pStop,pA,pB,v100,tGun\\WObj:=woTable;
  Search_Groove peFound,nWidth,pA,pB,25,v100,tGun;
  ldTool:=FCLoadId(\\MaxMoveAx5:=30\\MaxMoveAx6:=60);
  FCCalib ldTool;
  FCPress1LStart pA,v50\\Fz:=40,20\\ForceChange:=80,z5,tGun\\WObj:=woTable;
  EGMActJoint egmId\\Tool:=tGun\\WObj:=woTable\\TLoad:=ldTool;
  ArcL pB,v100,seamx,weldx,z1,tGun\\PreProcessTracking;
  ExecEngine;
ENDPROC
VAR seamdata seamx;
VAR welddata weldx;
TASK PERS robtarget pStop:=[[600,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
ENDMODULE
";

#[test]
fn option_calls_as_public_programs_write_them_check_clean() {
    let files = [SourceInput::from_text("calls.mod", PUBLIC_CALLS)];
    assert_eq!(found(&files, None), vec![]);
    let all = ["633-4 Arc with MultiProcess", "652-1 BullsEye", "657-1 SmarTac IO version", "661-2 Force Control Base"];
    let all = [&all[..], &["689-1 Externally Guided Motion (EGM)", "812-1 Production Manager"]].concat();
    assert_eq!(found(&files, Some(&all)), vec![]);
}

#[test]
fn option_calls_without_their_options_belong_to_them() {
    let files = [SourceInput::from_text("calls.mod", PUBLIC_CALLS)];
    let got = found(&files, Some(&["RobotWare Base"]));
    let names: Vec<(u32, &str)> = got
        .iter()
        .map(|d| {
            assert_eq!(d.0, "E0217", "{d:?}");
            (d.1, d.2.split('`').nth(1).unwrap_or(""))
        })
        .collect();
    // One E0217 per use, at its line: the menu data's type (2), the BullsEye types
    // (12-14), egmident (15), each call (17-26), the arc data types (28, 29).
    let expected = [
        (2, "menudata"),
        (12, "be_device"),
        (13, "be_scan"),
        (14, "be_tooldesign"),
        (15, "egmident"),
        (17, "BESetupToolJ"),
        (18, "BECheckTcp"),
        (19, "Search_1D"),
        (20, "Search_Groove"),
        (21, "FCLoadId"),
        (22, "FCCalib"),
        (23, "FCPress1LStart"),
        (24, "EGMActJoint"),
        (25, "ArcL"),
        (26, "ExecEngine"),
        (28, "seamdata"),
        (29, "welddata"),
    ];
    assert_eq!(names, expected, "{got:?}");
}

#[test]
fn wrong_calls_of_option_routines_still_get_their_errors() {
    // Each line gets the error any RAPID routine would: open optional arguments do not
    // excuse a missing required argument, a positional argument too many, a wrong type
    // or a function called as a procedure, and the value of an optional argument the
    // declaration does not list is still checked.
    let text = "MODULE Wrong
TASK PERS tooldata tGun:=[TRUE,[[0,0,380],[1,0,0,0]],[3,[0,0,100],[1,0,0,0],0,0,0]];
TASK PERS pose peFound:=[[0,0,0],[1,0,0,0]];
CONST robtarget pA:=[[600,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
VAR egmident egmId;
PROC wrong()
  Search_1D peFound,pA,pA,v100;
  BECheckTcp tGun,5;
  FCCalib;
  FCLoadId;
  PDispAdd pA;
  EGMActJoint egmId\\TLoad:=tGun;
  BECheckTcp tGun\\Progress:=nowhere;
ENDPROC
ENDMODULE
";
    let files = [SourceInput::from_text("wrong.mod", text)];
    let got: Vec<(String, u32)> = found(&files, None).into_iter().map(|d| (d.0, d.1)).collect();
    let expected = [
        ("E0402", 7),  // Search_1D needs Tool
        ("E0401", 8),  // BECheckTcp takes one required argument
        ("E0402", 9),  // FCCalib needs Load
        ("E0209", 10), // FCLoadId is a function
        ("E0301", 11), // PDispAdd takes a pose, not a robtarget
        ("E0301", 12), // \TLoad is loaddata
        ("E0201", 13), // an undeclared optional argument's value is still resolved
    ];
    let expected: Vec<(String, u32)> = expected.iter().map(|&(c, l)| (c.to_owned(), l)).collect();
    assert_eq!(got, expected);
}
