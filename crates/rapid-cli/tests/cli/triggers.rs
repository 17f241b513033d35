//! The trigger family on the simulated robot: TriggRampAO, TriggSpeed, TriggCheckIO,
//! `\Inhib`, TriggLIOs and TriggAbsJ, each seen in the I/O log (`--io-log`) or the
//! program's output at the time and place worked out by hand.
//!
//! The timing model the expectations use (as in `multitask.rs`): a 100 mm MoveL at
//! v100 with the model's 10 m/s² ramps accelerates for 0.01 s over 0.5 mm, so the TCP
//! is d mm (0.5 ≤ d ≤ 99.5) along at 0.01 + (d - 0.5) / 100 s; it stands at the point
//! at 1.01 s, and a fine point lets the program go on 0.05 s later (1.06 s).

use std::fs;
use std::path::Path;
use std::process::Output;

use crate::fixture::{rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("triggers", name)
}

/// Writes backup `sys` in `dir`: one motion task running `module`, and the signals.
fn system(dir: &Path, module: &str, eio_signals: &str) {
    let root = dir.join("sys");
    let folder = root.join("RAPID/TASK1/PROGMOD");
    fs::create_dir_all(&folder).expect("task folder");
    fs::write(folder.join("Main.mod"), module).expect("module");
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n";
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    let eio = format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{eio_signals}");
    fs::write(root.join("SYSPAR/EIO.cfg"), eio).expect("EIO.cfg");
}

/// EIO_SIGNAL lines for `(name, type and options)`.
fn signals(list: &[(&str, &str)]) -> String {
    list.iter().map(|(name, rest)| format!("\n      -Name \"{name}\" -SignalType {rest}\n")).collect()
}

/// The changes of `signal` in an `--io-log` CSV (time,signal,old,new,cause): (time, new).
fn changes(log: &str, signal: &str) -> Vec<(f64, f64)> {
    log.lines()
        .filter(|l| l.split(',').nth(1) == Some(signal))
        .filter_map(|l| {
            let mut f = l.split(',');
            let t = f.next()?.parse().ok()?;
            Some((t, f.nth(2)?.parse().ok()?))
        })
        .collect()
}

/// When `signal` first became `new`.
fn change_time(log: &str, signal: &str, new: f64) -> f64 {
    changes(log, signal)
        .into_iter()
        .find(|&(_, v)| v == new)
        .map(|(t, _)| t)
        .unwrap_or_else(|| panic!("{signal} never became {new}: {log}"))
}

/// The value of `signal` at time `t` (0 before its first change).
fn value_at(log: &str, signal: &str, t: f64) -> f64 {
    changes(log, signal).into_iter().take_while(|&(ct, _)| ct <= t).last().map_or(0.0, |(_, v)| v)
}

const P0: &str = "CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];";

/// Runs `body` (the statements of main after a MoveJ to p0) with `decls` and `traps`.
fn run(name: &str, decls: &str, body: &str, traps: &str, sigs: &[(&str, &str)], stim: &str) -> (Output, String) {
    run_hooked(name, decls, body, traps, sigs, stim, "")
}

/// [`run`] with event routines (CAB_EXEC_HOOKS lines) in SYS.cfg.
fn run_hooked(
    name: &str,
    decls: &str,
    body: &str,
    traps: &str,
    sigs: &[(&str, &str)],
    stim: &str,
    hooks: &str,
) -> (Output, String) {
    let dir = scratch(name);
    let module = format!(
        "MODULE S\n  {P0}\n{decls}\n  PROC main()\n    MoveJ p0, v1000, fine, tool0;\n{body}\n  ENDPROC\n{traps}\nENDMODULE\n"
    );
    system(&dir, &module, &signals(sigs));
    if !hooks.is_empty() {
        let path = dir.join("sys/SYSPAR/SYS.cfg");
        let sys = fs::read_to_string(&path).expect("SYS.cfg") + "#\nCAB_EXEC_HOOKS:\n" + hooks;
        fs::write(path, sys).expect("SYS.cfg");
    }
    let mut args = vec!["run", "--quiet", "--io-log", "io.csv"];
    if !stim.is_empty() {
        fs::write(dir.join("s.stim"), stim).expect("stimulus");
        args.extend(["--stimulus", "s.stim"]);
    }
    args.push("sys");
    let out = rapid_in(&dir, &args);
    let log = fs::read_to_string(dir.join("io.csv")).unwrap_or_default();
    (out, log)
}

#[test]
fn trigg_ramp_ao_ramps_over_its_length_of_path_and_time() {
    // The ramp starts 10 mm after the start (0.105 s) and reaches 10 at 60 mm (0.01 +
    // 59.5 / 100 = 0.605 s); half way, at 35 mm (0.355 s), it is at 5. On the way back
    // a \Time ramp from 10 to 0 over 0.2 s from the start: 5 at 0.1 s, 0 at 0.2 s.
    let body = "    TriggRampAO up, 10 \\Start, 0, aoFlow, 10, 50;\n    TriggRampAO down, 0 \\Start, 0, aoFlow, 0, 0.2 \\Time;\n    \
                SetDO doStart, 1;\n    TriggL Offs(p0, 100, 0, 0), v100, up, fine, tool0;\n    \
                SetDO doStart, 0;\n    TriggL p0, v100, down, fine, tool0;";
    let sigs = [("doStart", "\"DO\""), ("aoFlow", "\"AO\" -MinLog 0 -MaxLog 10")];
    let (out, log) = run("ramp", "  VAR triggdata up;\n  VAR triggdata down;", body, "", &sigs, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let start = change_time(&log, "doStart", 1.0);
    assert_eq!(value_at(&log, "aoFlow", start + 0.1), 0.0, "{log}");
    let mid = value_at(&log, "aoFlow", start + 0.355);
    assert!((mid - 5.0).abs() < 0.1, "aoFlow {mid} half way: {log}");
    let full = change_time(&log, "aoFlow", 10.0) - start;
    assert!((full - 0.605).abs() < 0.0025, "aoFlow 10 after {full} s: {log}");
    // One order every 4 ms along the ramp (0.5 s): about 125 of them.
    let steps = changes(&log, "aoFlow").iter().filter(|&&(t, _)| t - start <= 0.61).count();
    assert!((115..=135).contains(&steps), "{steps} steps: {log}");
    let back = change_time(&log, "doStart", 0.0);
    let half = value_at(&log, "aoFlow", back + 0.1);
    assert!((half - 5.0).abs() < 0.25, "aoFlow {half} 0.1 s into the \\Time ramp: {log}");
    let zero = change_time(&log, "aoFlow", 0.0) - back;
    assert!((zero - 0.2).abs() < 0.0025, "aoFlow 0 after {zero} s: {log}");
}

#[test]
fn trigg_speed_follows_the_tcp_speed() {
    // aoSpeed = 0.01 × TCP speed: 1 at the cruise speed of 100 mm/s, reached when the
    // 0.01 s ramp ends; 0 where the robot stands (1.01 s). With ScaleLag 0.1 on the
    // way back the output falls 0.1 s before the robot brakes at 1.0 s: at 0.9 s.
    // A scale of 0.2 would ask 20 of a 0..10 output at v100: ERR_AO_LIM at the move.
    let body =
        "    TriggSpeed spd, 0 \\Start, 0, aoSpeed, 0.01;\n    TriggSpeed early, 0 \\Start, 0.1, aoSpeed, 0.01;\n    \
                TriggSpeed over, 0 \\Start, 0, aoSpeed, 0.2;\n    \
                SetDO doStart, 1;\n    TriggL Offs(p0, 100, 0, 0), v100, spd, fine, tool0;\n    \
                SetDO doStart, 0;\n    TriggL p0, v100, early, fine, tool0;\n    \
                TriggL Offs(p0, 100, 0, 0), v100, over, fine, tool0;\n    TPWrite \"not refused\";\n  \
                ERROR\n    IF ERRNO = ERR_AO_LIM TPWrite \"ERR_AO_LIM\";\n    RETURN;";
    let sigs = [("doStart", "\"DO\""), ("aoSpeed", "\"AO\" -MinLog 0 -MaxLog 10")];
    let decls = "  VAR triggdata spd;\n  VAR triggdata early;\n  VAR triggdata over;";
    let (out, log) = run("speed", decls, body, "", &sigs, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "ERR_AO_LIM\n");
    let start = change_time(&log, "doStart", 1.0);
    let cruise = change_time(&log, "aoSpeed", 1.0) - start;
    assert!((cruise - 0.01).abs() < 0.0045, "aoSpeed 1 after {cruise} s: {log}");
    assert_eq!(value_at(&log, "aoSpeed", start + 0.5), 1.0, "{log}");
    assert_eq!(value_at(&log, "aoSpeed", start + 1.03), 0.0, "{log}");
    let back = change_time(&log, "doStart", 0.0);
    let falls = changes(&log, "aoSpeed").into_iter().find(|&(t, v)| t > back + 0.5 && v < 1.0).map(|(t, _)| t - back);
    let falls = falls.unwrap_or_else(|| panic!("aoSpeed never fell: {log}"));
    assert!((falls - 0.9).abs() < 0.0045, "aoSpeed fell after {falls} s: {log}");
}

#[test]
fn trigg_check_io_interrupts_and_stops_the_robot_when_the_check_fails() {
    // The check at 50 mm (0.505 s) finds diGate low: the trap runs with the robot
    // stopped there (x = 350), waits 0.5 s and restarts it; the move ends 0.5 s late,
    // at 1.56 s. On the way back diGate is high (set as doOpen rises): no interrupt.
    let decls = "  VAR triggdata gate;\n  VAR intnum closed;\n  VAR clock c;";
    let body = "    CONNECT closed WITH on_closed;\n    TriggCheckIO gate, 50 \\Start, diGate, EQ, 1 \\StopMove, closed;\n    \
                ClkStart c;\n    TriggL Offs(p0, 100, 0, 0), v100, gate, fine, tool0;\n    \
                TPWrite \"arrived after \" + NumToStr(ClkRead(c), 2);\n    SetDO doOpen, 1;\n    \
                TriggL p0, v100, gate, fine, tool0;\n    TPWrite \"back\";\n    IDelete closed;";
    let traps = "  TRAP on_closed\n    VAR pos at;\n    at := CPos();\n    \
                 TPWrite \"gate closed at x \" + NumToStr(at.x, 1);\n    WaitTime 0.5;\n    StartMove;\n  ENDTRAP";
    let sigs = [("doOpen", "\"DO\""), ("diGate", "\"DI\"")];
    let (out, _) = run("check", decls, body, traps, &sigs, "when doOpen = 1 after 0 s set diGate 1\n");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "gate closed at x 350.0\narrived after 1.56\nback\n");
}

#[test]
fn inhib_flags_are_read_when_the_robot_gets_there() {
    // First move: noGlue FALSE, so doGlue goes to 1 and aoFlow to 8 at 10 mm (0.105 s)
    // and the interrupt at 20 mm fires. Second move: noGlue TRUE, so doGlue is set to 0
    // (it stays 0), aoFlow to InhibSetValue 2.5, and no interrupt. A check at 30 mm that
    // doGlue is 1 holds on the first move and is inhibited on the second (where it
    // would fail): its trap never runs.
    let decls =
        "  PERS bool noGlue := FALSE;\n  PERS num lowFlow := 2.5;\n  VAR triggdata glue;\n  VAR triggdata flow;\n  \
                 VAR triggdata mark;\n  VAR intnum marked;\n  VAR triggdata chk;\n  VAR intnum failed;";
    let body = "    CONNECT marked WITH on_mark;\n    TriggIO glue, 10 \\Start \\DOp:=doGlue, 1 \\Inhib:=noGlue;\n    \
                TriggIO flow, 10 \\Start \\AOp:=aoFlow, 8 \\Inhib:=noGlue \\InhibSetValue:=lowFlow;\n    \
                TriggInt mark, 20 \\Start, marked \\Inhib:=noGlue;\n    CONNECT failed WITH on_fail;\n    \
                TriggCheckIO chk, 30 \\Start, doGlue, EQ, 1, failed \\Inhib:=noGlue;\n    \
                SetDO doStart, 1;\n    TriggL Offs(p0, 100, 0, 0), v100, glue \\T2:=flow \\T3:=mark \\T4:=chk, fine, tool0;\n    \
                noGlue := TRUE;\n    SetDO doGlue, 0;\n    SetDO doStart, 0;\n    \
                TriggL p0, v100, glue \\T2:=flow \\T3:=mark \\T4:=chk, fine, tool0;\n    noGlue := FALSE;\n    TPWrite \"done\";\n    \
                IDelete marked;\n    IDelete failed;";
    let traps =
        "  TRAP on_mark\n    TPWrite \"mark\";\n  ENDTRAP\n  TRAP on_fail\n    TPWrite \"check failed\";\n  ENDTRAP";
    let sigs = [("doStart", "\"DO\""), ("doGlue", "\"DO\""), ("aoFlow", "\"AO\" -MinLog 0 -MaxLog 10")];
    let (out, log) = run("inhib", decls, body, traps, &sigs, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "mark\ndone\n");
    let start = change_time(&log, "doStart", 1.0);
    let glue = change_time(&log, "doGlue", 1.0) - start;
    assert!((glue - 0.105).abs() < 0.0025, "doGlue after {glue} s: {log}");
    assert_eq!(changes(&log, "doGlue").iter().filter(|&&(_, v)| v == 1.0).count(), 1, "{log}");
    let back = change_time(&log, "doStart", 0.0);
    let low = change_time(&log, "aoFlow", 2.5) - back;
    assert!((low - 0.105).abs() < 0.0025, "aoFlow 2.5 after {low} s: {log}");
}

#[test]
fn trigg_l_ios_sets_the_outputs_of_its_arrays() {
    // doGun on 10 mm after the start (0.105 s), off 20 mm before the point (80 mm:
    // 0.805 s) with 0.05 s equipment lag (0.755 s); goCode 300 at 50 mm (0.505 s).
    // Then a TriggJIOs back sets goCode to the digit string "4095" at its stop point,
    // where the robot stands 0.05 s before the program goes on (doStart 0). An array
    // naming an unknown signal is ERR_SIG_NAME.
    let decls = "  VAR triggios gun{2} := [[TRUE, 10, TRUE, 0, \"doGun\", 1, 0], [TRUE, 20, FALSE, 0.05, \"doGun\", 0, 0]];\n  \
                 VAR triggiosdnum code{2} := [[TRUE, 50, TRUE, 0, \"goCode\", 300, 0], [FALSE, 0, TRUE, 0, \"nothing\", 1, 0]];\n  \
                 VAR triggstrgo top{1} := [[TRUE, 0, FALSE, 0, \"goCode\", \"4095\", 0]];\n  \
                 VAR triggios bad{1} := [[TRUE, 0, TRUE, 0, \"doNone\", 1, 0]];";
    let body = "    SetDO doStart, 1;\n    TriggLIOs Offs(p0, 100, 0, 0), v100 \\TriggData1:=gun \\TriggData3:=code, fine, tool0;\n    \
                TriggJIOs p0, v1000 \\TriggData2:=top, fine, tool0;\n    SetDO doStart, 0;\n    \
                TriggLIOs p0, v100 \\TriggData1:=bad, fine, tool0;\n    TPWrite \"not refused\";\n  \
                ERROR\n    IF ERRNO = ERR_SIG_NAME TPWrite \"ERR_SIG_NAME\";\n    RETURN;";
    let sigs = [("doStart", "\"DO\""), ("doGun", "\"DO\""), ("goCode", "\"GO\" -DeviceMap \"0-15\"")];
    let (out, log) = run("ios", decls, body, "", &sigs, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "ERR_SIG_NAME\n");
    let start = change_time(&log, "doStart", 1.0);
    for (signal, value, expected) in [("doGun", 1.0, 0.105), ("goCode", 300.0, 0.505), ("doGun", 0.0, 0.755)] {
        let after = change_time(&log, signal, value) - start;
        assert!((after - expected).abs() < 0.0025, "{signal} = {value} after {after} s, expected {expected}: {log}");
    }
    let settle = change_time(&log, "doStart", 0.0) - change_time(&log, "goCode", 4095.0);
    assert!((settle - 0.05).abs() < 0.0015, "goCode 4095 {settle} s before the program went on: {log}");
}

#[test]
fn trigg_abs_j_fires_at_its_stop_point() {
    // A trigger at distance 0 fires where the robot stands at the fine point; the
    // program goes on 0.05 s later (the settle time of a fine point).
    let decls =
        "  CONST jointtarget j1 := [[20, 10, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  VAR triggdata done;";
    let body =
        "    TriggIO done, 0 \\DOp:=doDone, 1;\n    TriggAbsJ j1, v1000, done, fine, tool0;\n    SetDO doAfter, 1;";
    let sigs = [("doDone", "\"DO\""), ("doAfter", "\"DO\"")];
    let (out, log) = run("absj", decls, body, "", &sigs, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let settle = change_time(&log, "doAfter", 1.0) - change_time(&log, "doDone", 1.0);
    assert!((settle - 0.05).abs() < 0.0015, "the program went on {settle} s after doDone: {log}");
}

#[test]
fn trigg_stop_proc_zeroes_the_process_outputs_at_a_program_stop() {
    // The process starts 10 mm into a \\Conc move (0.105 s): doProc 1, goProc 5 and the
    // shadow doShadow 1. The program stops 0.5 s after the move started, with the robot
    // moving: doProc and goProc go to 0 then, doShadow stays, the robot stops on its
    // path (so doProc's off trigger 20 mm before the point never comes), and the STOP
    // event routine finds the restart data: stopped during motion, on the path, the
    // values before the stop (equal at standstill: the robot stands at once).
    let decls = "  PERS restartdata rd := [FALSE, FALSE, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0];\n  \
                 VAR triggdata on;\n  VAR triggdata off;\n  VAR triggdata code;\n  VAR triggdata shadow;";
    let body = "    TriggStopProc rd \\DO1:=doProc \\GO1:=goProc, doShadow;\n    \
                TriggIO on, 10 \\Start \\DOp:=doProc, 1;\n    TriggIO off, 20 \\DOp:=doProc, 0;\n    \
                TriggIO code, 10 \\Start \\GOp:=goProc, 5;\n    TriggIO shadow, 10 \\Start \\DOp:=doShadow, 1;\n    \
                SetDO doStart, 1;\n    \
                TriggL \\Conc, Offs(p0, 100, 0, 0), v100, on \\T2:=off \\T3:=code \\T4:=shadow, fine, tool0;\n    \
                WaitTime 0.5;\n    Stop;\n    TPWrite \"not reached\";";
    let traps = "  PROC on_stop()\n    TPWrite \"restartstop \" \\Bool:=rd.restartstop;\n    \
                 TPWrite \"stoponpath \" \\Bool:=rd.stoponpath;\n    TPWrite \"predo1val \" \\Num:=rd.predo1val;\n    \
                 TPWrite \"prego1val \" \\Num:=rd.prego1val;\n    TPWrite \"postgo1val \" \\Num:=rd.postgo1val;\n    \
                 TPWrite \"preshadowval \" \\Num:=rd.preshadowval;\n    TPWrite \"shadowflanks \" \\Num:=rd.shadowflanks;\n  ENDPROC";
    let sigs =
        [("doStart", "\"DO\""), ("doProc", "\"DO\""), ("doShadow", "\"DO\""), ("goProc", "\"GO\" -DeviceMap \"0-7\"")];
    let hooks = "\n      -Routine \"on_stop\" -Shelf \"STOP\" -Task \"T_ROB1\"\n";
    let (out, log) = run_hooked("stopproc", decls, body, traps, &sigs, "", hooks);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "restartstop TRUE\nstoponpath TRUE\npredo1val 1\nprego1val 5\npostgo1val 5\npreshadowval 1\nshadowflanks 0\n"
    );
    let start = change_time(&log, "doStart", 1.0);
    let on = change_time(&log, "doProc", 1.0) - start;
    assert!((on - 0.105).abs() < 0.0025, "doProc on after {on} s: {log}");
    for signal in ["doProc", "goProc"] {
        let zero = change_time(&log, signal, 0.0) - start;
        assert!((zero - 0.5).abs() < 0.0015, "{signal} 0 after {zero} s: {log}");
        assert_eq!(changes(&log, signal).len(), 2, "{signal}: {log}");
    }
    let shadow: Vec<f64> = changes(&log, "doShadow").into_iter().map(|(_, v)| v).collect();
    assert_eq!(shadow, [1.0], "doShadow: {log}");
}

#[test]
fn values_outside_a_signals_range_are_refused_when_the_trigger_is_defined() {
    // aoFlow's logical range is 0..10 and goSmall has 3 bits (0..7): a ramp to 20 and
    // a TriggIO of 20 are ERR_AO_LIM, a group value of 8 ERR_GO_LIM; opnum 7 names no
    // relation (ERR_ARGVALERR). Each is handled and skipped.
    let decls = "  VAR triggdata t;\n  VAR intnum never;\n  VAR num stage := 0;";
    let body = "    CONNECT never WITH on_never;\n    stage := 1;\n    TriggRampAO t, 0 \\Start, 0, aoFlow, 20, 10;\n    \
                stage := 2;\n    TriggIO t, 0 \\AOp:=aoFlow, 20;\n    stage := 3;\n    TriggIO t, 0 \\GOp:=goSmall, 8;\n    \
                stage := 4;\n    TriggCheckIO t, 0, aoFlow, 7, 1, never;\n    TPWrite \"done\";\n    IDelete never;\n  \
                ERROR\n    IF ERRNO = ERR_AO_LIM TPWrite \"stage \" + NumToStr(stage, 0) + \": ERR_AO_LIM\";\n    \
                IF ERRNO = ERR_GO_LIM TPWrite \"stage \" + NumToStr(stage, 0) + \": ERR_GO_LIM\";\n    \
                IF ERRNO = ERR_ARGVALERR TPWrite \"stage \" + NumToStr(stage, 0) + \": ERR_ARGVALERR\";\n    TRYNEXT;";
    let traps = "  TRAP on_never\n    TPWrite \"never\";\n  ENDTRAP";
    let sigs = [("aoFlow", "\"AO\" -MinLog 0 -MaxLog 10"), ("goSmall", "\"GO\" -DeviceMap \"0-2\"")];
    let (out, _) = run("limits", decls, body, traps, &sigs, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "stage 1: ERR_AO_LIM\nstage 2: ERR_AO_LIM\nstage 3: ERR_GO_LIM\nstage 4: ERR_ARGVALERR\ndone\n"
    );
}

#[test]
fn a_trigg_speed_output_is_0_while_the_robot_is_stopped_on_its_path() {
    // aoSpeed = 0.01 × TCP speed, 1 at 100 mm/s. A failing check at 50 mm (0.505 s)
    // stops the robot there: aoSpeed falls to 0 with it; the trap restarts it 0.5 s
    // later (1.005 s), aoSpeed is 1 again, and 0 where the robot stands at the point,
    // 0.5 s late (1.51 s).
    let decls = "  VAR triggdata spd;\n  VAR triggdata gate;\n  VAR intnum closed;";
    let body = "    CONNECT closed WITH on_closed;\n    TriggSpeed spd, 0 \\Start, 0, aoSpeed, 0.01;\n    \
                TriggCheckIO gate, 50 \\Start, diGate, EQ, 1 \\StopMove, closed;\n    SetDO doStart, 1;\n    \
                TriggL Offs(p0, 100, 0, 0), v100, spd \\T2:=gate, fine, tool0;\n    IDelete closed;";
    let traps = "  TRAP on_closed\n    WaitTime 0.5;\n    StartMove;\n  ENDTRAP";
    let sigs = [("doStart", "\"DO\""), ("diGate", "\"DI\""), ("aoSpeed", "\"AO\" -MinLog 0 -MaxLog 10")];
    let (out, log) = run("speedstop", decls, body, traps, &sigs, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let start = change_time(&log, "doStart", 1.0);
    let seen: Vec<(f64, f64)> = changes(&log, "aoSpeed").into_iter().map(|(t, v)| (t - start, v)).collect();
    let at = |t: f64| value_at(&log, "aoSpeed", start + t);
    assert_eq!((at(0.4), at(0.6), at(0.9), at(1.1), at(1.6)), (1.0, 0.0, 0.0, 1.0, 0.0), "{seen:?}");
    let stop = seen.iter().find(|&&(t, v)| t > 0.1 && v == 0.0).map_or(0.0, |&(t, _)| t);
    assert!((stop - 0.505).abs() < 0.0025, "aoSpeed 0 after {stop} s: {seen:?}");
    let again = seen.iter().find(|&&(t, v)| t > 0.6 && v == 1.0).map_or(0.0, |&(t, _)| t);
    assert!((again - 1.005).abs() < 0.0025, "aoSpeed 1 again after {again} s: {seen:?}");
}

#[test]
fn a_trigg_int_trap_runs_during_a_move_that_ends_a_block() {
    // §1.11: a trap runs "at any time" while a move instruction executes. Each TriggL
    // below is the last statement of a block, so the program's next instruction is the
    // block's own glue (the jump past ELSE, a loop's way back, FOR's step, the jump out
    // of a CASE), not a statement; the trap must still run 0.001 s after the move
    // starts, not when the program goes on after the fine point (1.06 s, the timing
    // model above). The last is the same IF in a FUNC called from an assignment.
    let decls = "  VAR triggdata td;\n  VAR intnum ti;\n  VAR clock c;\n  VAR num at;\n  VAR num n := 1;\n  \
                 VAR num k;\n  VAR bool ok;";
    let to = "Offs(p0, 100, 0, 0)";
    let go = |i: u32| {
        let target = if i % 2 == 1 { to } else { "p0" };
        format!("TriggL {target}, v100, td, fine, tool0;")
    };
    let report =
        |label: &str| format!("    TPWrite \"{label} \" + NumToStr(at, 3) + \" \" + NumToStr(ClkRead(c), 2);\n");
    let reset = "    at := -1;\n    ClkReset c;\n    ClkStart c;\n";
    let body = format!(
        "    CONNECT ti WITH on_trigg;\n    TriggInt td, 0.001 \\Start, ti;\n\
         {reset}    IF n = 1 THEN\n      {m1}\n    ELSE\n      {m2}\n    ENDIF\n{if_}\
         {reset}    k := 0;\n    WHILE k < 1 DO\n      k := k + 1;\n      {m2}\n    ENDWHILE\n{while_}\
         {reset}    FOR i FROM 1 TO 1 DO\n      {m1}\n    ENDFOR\n{for_}\
         {reset}    TEST n\n    CASE 1:\n      {m2}\n    DEFAULT:\n      {m1}\n    ENDTEST\n{test_}\
         {reset}    ok := leg();\n{func_}",
        m1 = go(1),
        m2 = go(2),
        if_ = report("IF"),
        while_ = report("WHILE"),
        for_ = report("FOR"),
        test_ = report("TEST"),
        func_ = report("FUNC"),
    );
    let traps = format!(
        "  FUNC bool leg()\n    IF n = 1 THEN\n      {m1}\n    ELSE\n      {m2}\n    ENDIF\n    RETURN TRUE;\n  ENDFUNC\n  \
         TRAP on_trigg\n    at := ClkRead(c);\n  ENDTRAP",
        m1 = go(1),
        m2 = go(2),
    );
    let (out, _) = run("int_block_end", decls, &body, &traps, &[], "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "IF 0.001 1.06\nWHILE 0.001 1.06\nFOR 0.001 1.06\nTEST 0.001 1.06\nFUNC 0.001 1.06\n"
    );
}
