//! The rest of the I/O system through `rapid run` on small backup folders: I/O devices
//! and networks (IODisable, IOEnable, IOUnitState, IOBusState, IOBusStart, ERR_NORUNUNIT,
//! ValidIO), GetSignalOrigin, GetGroupSignalInfo, and analog signal interrupts
//! (ISignalAI, ISignalAO). Every expectation is worked out by hand in the comments.

use std::path::Path;
use std::process::Output;

use crate::fixture::{rapid_in, scratch_in, text, write_files as write, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("iomore", name)
}

/// Runs backup folder `cell` in `dir` (with `--stimulus stimulus.txt` when given).
fn run_cell(dir: &Path, eio: &str, program: &str, stimulus: Option<&str>) -> Output {
    write(dir, &[("cell/SYSPAR/EIO.cfg", eio), ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program)]);
    let mut args = vec!["run"];
    if let Some(stimulus) = stimulus {
        write(dir, &[("stimulus.txt", stimulus)]);
        args.extend(["--stimulus", "stimulus.txt"]);
    }
    args.push("cell");
    rapid_in(dir, &args)
}

/// A DeviceNet network with d652 (enabled) and d651 (deactivated at start-up).
const UNITS_EIO: &str = "EIO:CFG_1.0:6:1::
#
INDUSTRIAL_NETWORK:

      -Name \"DeviceNet\" -Label \"DeviceNet Master/Slave Network\"
#
DEVICENET_DEVICE:

      -Name \"d652\" -Network \"DeviceNet\" -Address 10

      -Name \"d651\" -Network \"DeviceNet\" -Address 11 -StateWhenStartup \"Deactivated\"
#
EIO_SIGNAL:

      -Name \"doLamp\" -SignalType \"DO\" -Device \"d652\" -DeviceMap \"0\"

      -Name \"diPart\" -SignalType \"DI\" -Device \"d652\" -DeviceMap \"0\"

      -Name \"goCode\" -SignalType \"GO\" -Device \"d652\" -DeviceMap \"8-13\"\\
      -Label \"Recipe code\"

      -Name \"giWide\" -SignalType \"GI\" -DeviceMap \"0-31\"

      -Name \"doSpare\" -SignalType \"DO\" -Device \"d651\" -DeviceMap \"0\"

      -Name \"doVirtual\" -SignalType \"DO\"
";

const ERROR_HANDLER: &str = "  ERROR
    IF ERRNO = ERR_NORUNUNIT THEN
      TPWrite \"ERR_NORUNUNIT\";
      TRYNEXT;
    ENDIF
    IF ERRNO = ERR_NAME_INVALID THEN
      TPWrite \"ERR_NAME_INVALID\";
      TRYNEXT;
    ENDIF
    IF ERRNO = ERR_NO_ALIASIO_DEF THEN
      TPWrite \"ERR_NO_ALIASIO_DEF\";
      TRYNEXT;
    ENDIF
    IF ERRNO = ERR_ARGVALERR THEN
      TPWrite \"ERR_ARGVALERR\";
      TRYNEXT;
    ENDIF
";

fn program(declarations: &str, body: &str, traps: &str) -> String {
    format!("MODULE MainModule\n{declarations}  PROC main()\n{body}{ERROR_HANDLER}  ENDPROC\n{traps}ENDMODULE\n")
}

#[test]
fn devices_are_enabled_and_disabled_and_their_signals_follow() {
    // Worked by hand (manual §1.9, the iounit_state numbers RUNNING 1, DISABLE 3):
    // d652 runs, d651 starts deactivated. doSpare on d651 is not valid and Set raises
    // ERR_NORUNUNIT. Set doLamp works; after IODisable "d652" the lamp is not valid;
    // reading it, Reset, TestDI and WaitDI on the device raise ERR_NORUNUNIT; the state
    // is DISABLE, logically DISABLED. IOEnable brings it back with the value it had (1).
    // The virtual doVirtual is never affected. Unknown names: ERR_NAME_INVALID; a
    // negative MaxTime: ERR_ARGVALERR.
    let dir = scratch("units");
    let body = "    TPWrite \"d652 \" \\Num:=IOUnitState(\"d652\");
    TPWrite \"d651 \" \\Num:=IOUnitState(\"d651\");
    IF IOUnitState(\"d651\" \\Logic) = IOUNIT_LOG_STATE_DISABLED TPWrite \"d651 logically disabled\";
    IF IOUnitState(\"d651\" \\Phys) = IOUNIT_PHYS_STATE_DEACTIVATED TPWrite \"d651 deactivated\";
    IF IOUnitState(\"D652\" \\Phys) = IOUNIT_PHYS_STATE_RUNNING TPWrite \"d652 running\";
    TPWrite \"spare valid \" \\Bool:=ValidIO(doSpare);
    Set doSpare;
    Set doLamp;
    IODisable \"d652\", 5;
    TPWrite \"lamp valid \" \\Bool:=ValidIO(doLamp);
    TPWrite \"lamp \" \\Num:=doLamp;
    Reset doLamp;
    TPWrite \"part \" \\Bool:=TestDI(diPart);
    WaitDI diPart, 1 \\MaxTime:=1;
    IF IOUnitState(\"d652\") = IOUNIT_DISABLE TPWrite \"d652 disabled\";
    IF IOUnitState(\"d652\" \\Logic) = IOUNIT_LOG_STATE_DISABLED TPWrite \"d652 logically disabled\";
    Set doVirtual;
    TPWrite \"virtual \" \\Num:=doVirtual;
    IOEnable \"d652\", 5;
    IF IOUnitState(\"d652\" \\Logic) = IOUNIT_LOG_STATE_ENABLED TPWrite \"d652 logically enabled\";
    TPWrite \"lamp valid \" \\Bool:=ValidIO(doLamp);
    TPWrite \"lamp \" \\Num:=doLamp;
    IOEnable \"d651\", 0;
    Set doSpare;
    TPWrite \"spare \" \\Num:=doSpare;
    IODisable \"nosuch\", 1;
    IOEnable \"nosuch\", 1;
    TPWrite \"state \" \\Num:=IOUnitState(\"nosuch\");
    IODisable \"d652\", -1;
    TPWrite \"done\";
";
    let out = run_cell(&dir, UNITS_EIO, &program("", body, ""), None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "d652 1\nd651 3\nd651 logically disabled\nd651 deactivated\nd652 running\nspare valid FALSE\n\
         ERR_NORUNUNIT\nlamp valid FALSE\nERR_NORUNUNIT\nERR_NORUNUNIT\nERR_NORUNUNIT\nERR_NORUNUNIT\n\
         d652 disabled\n\
         d652 logically disabled\nvirtual 1\nd652 logically enabled\nlamp valid TRUE\nlamp 1\nspare 1\n\
         ERR_NAME_INVALID\nERR_NAME_INVALID\nERR_NAME_INVALID\nERR_ARGVALERR\ndone\n"
    );
}

#[test]
fn a_disconnected_device_is_waited_for_by_ioenable_up_to_its_max_time() {
    // The stimulus uncouples d652 at 1 s and couples it again at 4 s (a tool changer).
    // At 2 s its signals cannot be reached (ERR_NORUNUNIT) and it is in error, still
    // logically enabled. IODisable needs no answer; IOEnable with MaxTime 1 from 2 s
    // runs out at 3 s (ERR_IOENABLE); IOEnable with MaxTime 5 from 3 s waits until the
    // device answers at 4 s, then the lamp keeps the value it had (1).
    let dir = scratch("units_connect");
    let body = "    Set doLamp;
    WaitTime 2;
    TPWrite \"lamp valid \" \\Bool:=ValidIO(doLamp);
    TPWrite \"lamp \" \\Num:=doLamp;
    IF IOUnitState(\"d652\") = IOUNIT_RUNERROR TPWrite \"d652 in error\";
    IF IOUnitState(\"d652\" \\Phys) = IOUNIT_PHYS_STATE_ERROR TPWrite \"d652 physically in error\";
    IF IOUnitState(\"d652\" \\Logic) = IOUNIT_LOG_STATE_ENABLED TPWrite \"d652 logically enabled\";
    IODisable \"d652\", 1;
    TPWrite \"disabled at \" \\Num:=ClkRead(clock1);
    IOEnable \"d652\", 1;
    TPWrite \"timed out at \" \\Num:=ClkRead(clock1);
    IOEnable \"d652\", 5;
    TPWrite \"enabled at \" \\Num:=ClkRead(clock1);
    TPWrite \"lamp \" \\Num:=doLamp;
";
    let handler = "    IF ERRNO = ERR_IOENABLE THEN
      TPWrite \"ERR_IOENABLE\";
      TRYNEXT;
    ENDIF
";
    let program =
        program("", &format!("    ClkStart clock1;\n{body}"), "").replace("  ERROR\n", &format!("  ERROR\n{handler}"));
    let stimulus = "at 1 disconnect d652\nat 4 connect d652\n";
    let out = run_cell(&dir, UNITS_EIO, &program, Some(stimulus));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "lamp valid FALSE\nERR_NORUNUNIT\nd652 in error\nd652 physically in error\nd652 logically enabled\n\
         disabled at 2\nERR_IOENABLE\ntimed out at 3\nenabled at 4\nlamp 1\n"
    );
}

#[test]
fn an_unhandled_read_on_a_disabled_device_stops_with_err_norununit() {
    let dir = scratch("norununit");
    let program = "MODULE MainModule\n  PROC main()\n    IODisable \"d652\", 5;\n\
      IF diPart = 1 TPWrite \"part\";\n    TPWrite \"not reached\";\n  ENDPROC\nENDMODULE\n";
    let out = run_cell(&dir, UNITS_EIO, program, None);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stdout));
    assert_eq!(text(&out.stdout), "");
    assert!(text(&out.stderr).contains("ERR_NORUNUNIT"), "{}", text(&out.stderr));
}

#[test]
fn a_disabled_device_ignores_its_inputs_and_cancels_its_pulses() {
    // diPart is set by the stimulus at 1 s while d652 is disabled (0.5 s to 1.5 s): the
    // controller has no contact, so after IOEnable it still reads 0; at 2 s it becomes 1.
    // The pulse of doLamp (1 s from 0 s) is cancelled when the device is disabled at
    // 0.5 s, so the lamp stays 1.
    let dir = scratch("inputs");
    let body = "    PulseDO \\PLength:=1, doLamp;
    WaitTime 0.5;
    IODisable \"d652\", 5;
    WaitTime 1;
    IOEnable \"d652\", 5;
    TPWrite \"part \" \\Num:=diPart;
    TPWrite \"lamp \" \\Num:=doLamp;
    WaitTime 1;
    TPWrite \"part \" \\Num:=diPart;
";
    let stimulus = "at 1 s set diPart 1\nat 1.2 s set diPart 0\nat 2 s set diPart 1\n";
    let out = run_cell(&dir, UNITS_EIO, &program("", body, ""), Some(stimulus));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "part 0\nlamp 1\npart 1\n");
}

#[test]
fn networks_report_their_state() {
    // Every simulated network runs: BUSSTATE_RUN (1) without a switch. DeviceNet is
    // configured, Local exists on every controller; IOBusStart on a running network
    // changes nothing; IOEventMessage only checks the device name; unknown names:
    // ERR_NAME_INVALID.
    let dir = scratch("networks");
    let declarations = "  VAR busstate bs;\n";
    let body = "    IOBusState \"DeviceNet\", bs;
    TPWrite \"bus \" \\Num:=bs;
    IF bs = BUSSTATE_RUN TPWrite \"running\";
    IOBusState \"devicenet\", bs \\Logic;
    IF bs = IOBUS_LOG_STATE_STARTED TPWrite \"started\";
    IOBusState \"DeviceNet\", bs \\Phys;
    IF bs = IOBUS_PHYS_STATE_RUNNING TPWrite \"physically running\";
    IOBusStart \"DeviceNet\";
    IOEventMessage \\Off, \"d652\";
    IOEventMessage \\On, \"d652\";
    IOEventMessage \\Off, \"nosuch\";
    IOBusState \"Local\", bs;
    TPWrite \"local \" \\Num:=bs;
    IOBusState \"Profibus\", bs;
    IOBusStart \"Profibus\";
    TPWrite \"done\";
";
    let out = run_cell(&dir, UNITS_EIO, &program(declarations, body, ""), None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "bus 1\nrunning\nstarted\nphysically running\nERR_NAME_INVALID\nlocal 1\nERR_NAME_INVALID\nERR_NAME_INVALID\n\
         done\n"
    );
}

#[test]
fn signal_origin_and_group_information() {
    // GetSignalOrigin: doLamp is configured (SIGORIG_CFG), alias_do is connected by
    // AliasIO to doLamp (SIGORIG_ALIAS, name doLamp), unused_do is connected to nothing
    // (SIGORIG_NONE, name ""); after AliasIOReset alias_do is NONE again. A disabled
    // device does not change the origin. GetGroupSignalInfo: goCode maps bits 8-13, so
    // its largest value is 2^6 - 1 = 63, label "Recipe code", device d652; giWide has 32
    // bits (4294967295 = 65536 * 65536 - 1), no label and no device. A signal that is not
    // a group: ERR_ARGVALERR; unconnected data: ERR_NO_ALIASIO_DEF.
    let dir = scratch("origin");
    let declarations = "  VAR signaldo alias_do;
  VAR signaldo unused_do;
  VAR signalgo unused_go;
  VAR string name := \"x\";
  VAR signalorigin origin;
  VAR dnum maxv;
  VAR string lbl;
  VAR string dev := \"x\";
";
    let body = "    origin := GetSignalOrigin(doLamp, name);
    IF origin = SIGORIG_CFG TPWrite \"cfg \" + name;
    AliasIO \"doLamp\", alias_do;
    origin := GetSignalOrigin(alias_do, name);
    IF origin = SIGORIG_ALIAS TPWrite \"alias \" + name;
    IODisable \"d652\", 5;
    origin := GetSignalOrigin(alias_do, name);
    IF origin = SIGORIG_ALIAS TPWrite \"alias still \" + name;
    Set alias_do;
    IOEnable \"d652\", 5;
    Set alias_do;
    TPWrite \"lamp \" \\Num:=doLamp;
    origin := GetSignalOrigin(unused_do, name);
    IF origin = SIGORIG_NONE TPWrite \"none '\" + name + \"'\";
    AliasIOReset alias_do;
    origin := GetSignalOrigin(alias_do, name);
    IF origin = SIGORIG_NONE TPWrite \"reset '\" + name + \"'\";
    GetGroupSignalInfo goCode \\MaxDvalue:=maxv \\Label:=lbl \\DeviceName:=dev;
    TPWrite lbl + \" on \" + dev \\Dnum:=maxv;
    GetGroupSignalInfo giWide \\MaxDvalue:=maxv \\DeviceName:=dev;
    IF maxv = 65536 * 65536 - 1 TPWrite \"wide '\" + dev + \"'\";
    GetGroupSignalInfo doLamp \\MaxDvalue:=maxv;
    GetGroupSignalInfo unused_go \\MaxDvalue:=maxv;
    TPWrite \"done\";
";
    let out = run_cell(&dir, UNITS_EIO, &program(declarations, body, ""), None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "cfg doLamp\nalias doLamp\nalias still doLamp\nERR_NORUNUNIT\nlamp 1\nnone ''\nreset ''\n\
         Recipe code on d65263\nwide ''\nERR_ARGVALERR\nERR_NO_ALIASIO_DEF\ndone\n"
    );
}

/// An analog input (logical 0..10) and an analog output (0..100).
const ANALOG_EIO: &str = "EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:

      -Name \"aiLevel\" -SignalType \"AI\" -MinLog 0 -MaxLog 10

      -Name \"aoSpeed\" -SignalType \"AO\" -MinLog 0 -MaxLog 100
";

#[test]
fn analog_interrupts_follow_their_conditions_and_delta() {
    // The stimulus moves aiLevel 0 → 3 (1 s) → 3.5 (2 s) → 5.5 (3 s) → 7 (4 s) → 4 (5 s)
    // → 2 (6 s). Worked by hand from ISignalAI (reference = value when ordered, 0):
    // iHigh, AIO_ABOVE_HIGH 5, delta 0: 5.5 (new reference) and 7 fire; 4 and 2 are not
    // above 5. iBetween, AIO_BETWEEN 2.2..6.1, delta 1, \DPos: 3 fires (3 - 0 > 1); 3.5
    // is within 1 of 3; 5.5 fires (2.5 up); 7 is outside; 4 is 1.5 below the reference
    // 5.5, so it becomes the reference but \DPos gives no interrupt; 2 is outside.
    // iLow, AIO_BELOW_LOW 3.2 with \DNeg, delta 0: 3 is below 3.2 but up from 0 (no
    // interrupt, reference 3); 2 is below and down: fires. At 3 s iHigh (ordered first)
    // and iBetween fire on the same change, in the order of their numbers.
    // ISignalAO \Single on aoSpeed with AIO_ALWAYS fires once, at the first SetAO.
    let dir = scratch("analog");
    let declarations = "  VAR intnum iHigh;
  VAR intnum iBetween;
  VAR intnum iLow;
  VAR intnum iAo;
  VAR intnum iBad;
  VAR signalai unused_ai;
";
    let body = "    CONNECT iAo WITH tAo;
    ISignalAO \\Single, aoSpeed, AIO_ALWAYS, 0, 0, 0, iAo;
    SetAO aoSpeed, 20;
    SetAO aoSpeed, 30;
    CONNECT iHigh WITH tHigh;
    ISignalAI aiLevel, AIO_ABOVE_HIGH, 5, 0, 0, iHigh;
    CONNECT iBetween WITH tBetween;
    ISignalAI aiLevel, AIO_BETWEEN, 6.1, 2.2, 1 \\DPos, iBetween;
    CONNECT iLow WITH tLow;
    ISignalAI aiLevel, AIO_BELOW_LOW, 0, 3.2, 0 \\DNeg, iLow;
    CONNECT iBad WITH tLow;
    ISignalAI aiLevel, 8, 5, 0, 0, iBad;
    ISignalAI aiLevel, AIO_BETWEEN, 1, 2, 0, iBad;
    ISignalAI aiLevel, AIO_ALWAYS, 0, 0, -1, iBad;
    ISignalAI unused_ai, AIO_ALWAYS, 0, 0, 0, iBad;
    WaitTime 10;
    TPWrite \"speed \" \\Num:=aoSpeed;
";
    let traps = "  TRAP tAo\n    TPWrite \"ao \" \\Num:=aoSpeed;\n  ENDTRAP\n\
      TRAP tHigh\n    TPWrite \"high \" \\Num:=aiLevel;\n  ENDTRAP\n\
      TRAP tBetween\n    TPWrite \"between \" \\Num:=aiLevel;\n  ENDTRAP\n\
      TRAP tLow\n    TPWrite \"low \" \\Num:=aiLevel;\n  ENDTRAP\n";
    let stimulus = "at 1 set aiLevel 3\nat 2 set aiLevel 3.5\nat 3 set aiLevel 5.5\n\
      at 4 set aiLevel 7\nat 5 set aiLevel 4\nat 6 set aiLevel 2\n";
    let out = run_cell(&dir, ANALOG_EIO, &program(declarations, body, traps), Some(stimulus));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "ao 20\nERR_ARGVALERR\nERR_ARGVALERR\nERR_ARGVALERR\nERR_NO_ALIASIO_DEF\nbetween 3\nhigh 5.5\n\
         between 5.5\nhigh 7\nlow 2\nspeed 30\n"
    );
}

#[test]
fn a_stimulus_writes_an_output_every_client_may_write() {
    let dir = scratch("client_output");
    // aoPreempt has -Access "All": a remote client (an RWS application) may write it, and
    // so may the stimulus, at 0.5 s. The program waits for it (WaitAO) and reads it.
    let eio = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"aoPreempt\" -SignalType \"AO\" -Access \"All\" \
               -MaxLog 100 -MaxPhys 100 -MaxBitVal 65535\n";
    let body = "    VAR clock c;\n    ClkStart c;\n    WaitAO aoPreempt, \\GT, 2;\n    \
                TPWrite \"preempt \" \\Num:=AOutput(aoPreempt);\n    TPWrite \"at \" \\Num:=ClkRead(c);\n";
    let out = run_cell(&dir, eio, &program("", body, ""), Some("at 0.5 set aoPreempt 3\n"));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "preempt 3\nat 0.5\n");
}
