//! The motion settings at PP to Main (manual 1.7: SYS_RESET sets the defaults when
//! the program is started from the beginning): VelSet, AccSet, ConfJ/ConfL, SingArea,
//! PathResol, CirPathMode, SpeedRefresh, the program displacement and the external
//! axis offsets all go back to their defaults, in the controller's state and in
//! C_MOTSET / C_PROGDISP alike. A conformance program runs only one cycle, so this
//! needs the API.

use rapid_robot::RobotResources;
use rapid_sema::SourceInput;
use rapid_vm::{Exit, RecordingHost};

/// Loads with the language's built-ins and the robot's (GripLoad, the motion
/// settings).
fn load(files: &[SourceInput], entry: &str) -> Result<rapid_vm::Loaded, rapid_vm::LoadError> {
    let set = std::sync::Arc::new(rapid_vm::builtins::Builtins::new(&[&rapid_robot::EXTENSION]));
    rapid_vm::load_in(files, entry, &rapid_sema::Options::default(), set)
}

const PROGRAM: &str = r#"MODULE t
PERS num runs := 0;
PERS loaddata piece := [2, [0, 0, 10], [1, 0, 0, 0], 0, 0, 0];
PROC main()
  runs := runs + 1;
  TPWrite "run " \Num:=runs;
  TPWrite ValToStr(C_MOTSET.vel) + ValToStr(C_MOTSET.acc) + ValToStr(C_MOTSET.conf.jsup) + ValToStr(C_MOTSET.sing.wrist);
  TPWrite ValToStr(C_MOTSET.pathresol) + " " + ValToStr(C_MOTSET.cirpathreori) + " " + ValToStr(CSpeedOverride(\CTask));
  TPWrite ValToStr(C_PROGDISP);
  IF runs = 1 THEN
    VelSet 20, 300;
    AccSet 50, 50;
    ConfJ \Off;
    SingArea \Wrist;
    PathResol 200;
    CirPathMode \ObjectFrame;
    SpeedRefresh 30;
    GripLoad piece;
    CornerPathWarning FALSE;
    PDispSet [[1, 2, 3], [1, 0, 0, 0]];
    EOffsSet [4, 5, 6, 7, 8, 9];
    TPWrite ValToStr(C_MOTSET.vel) + ValToStr(C_MOTSET.acc) + ValToStr(C_MOTSET.conf.jsup) + ValToStr(C_MOTSET.sing.wrist);
    TPWrite ValToStr(C_MOTSET.pathresol) + " " + ValToStr(C_MOTSET.cirpathreori) + " " + ValToStr(CSpeedOverride(\CTask));
    TPWrite ValToStr(C_PROGDISP);
  ENDIF
ENDPROC
ENDMODULE
"#;

#[test]
fn pp_to_main_resets_every_motion_setting() {
    let loaded = match load(&[SourceInput::from_text("t.mod", PROGRAM)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let (mut machine, entry) = (loaded.vm, loaded.entry);
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    assert_ne!(machine.resources().motion().settings, Default::default());
    machine.pp_to_main(&mut host, entry).expect("pp to main");
    assert_eq!(machine.resources().motion().settings, Default::default());
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    let defaults = ["[100,5000][100,100,100]TRUEFALSE", "100 0 100", "[[[0,0,0],[1,0,0,0]],[0,0,0,0,0,0]]"];
    let changed = ["[20,300][50,50,50]FALSETRUE", "200 1 30", "[[[1,2,3],[1,0,0,0]],[4,5,6,7,8,9]]"];
    let mut expected = vec!["run 1".to_string()];
    expected.extend(defaults.iter().chain(&changed).map(|s| s.to_string()));
    expected.push("run 2".to_string());
    expected.extend(defaults.iter().map(|s| s.to_string()));
    assert_eq!(host.lines, expected);
}
