//! Systems of several tasks (§1.20): backups whose SYS.cfg configures more than one
//! task run them pseudo-parallel. Expected outputs are worked out from the manual's
//! rules: round-robin among busy tasks, background tasks only while their foreground
//! task idles, global persistents shared by name, WaitSyncTask meeting points.

use std::fs;
use std::path::{Path, PathBuf};

use crate::fixture::{rapid_in, scratch_in, system, text, Scratch, TaskDef};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check/backups").join(name)
}

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("multitask", name)
}

/// When `signal` first became `new` in an `--io-log` CSV (time,signal,old,new,cause).
fn change_time(log: &str, signal: &str, new: &str) -> f64 {
    let line = log.lines().find(|l| l.split(',').nth(1) == Some(signal) && l.split(',').nth(3) == Some(new));
    line.and_then(|l| l.split(',').next()).and_then(|t| t.parse().ok()).unwrap_or_else(|| panic!("{signal}: {log}"))
}

fn copy_dir(from: &Path, to: &Path) {
    fs::create_dir_all(to).expect("folder");
    for entry in fs::read_dir(from).expect("read folder") {
        let entry = entry.expect("entry");
        let target = to.join(entry.file_name());
        if entry.path().is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            fs::copy(entry.path(), target).expect("copy");
        }
    }
}

#[test]
fn two_tasks_share_persistents_and_meet_at_sync_points() {
    let dir = scratch("sync_pair");
    copy_dir(&fixture("sync_pair"), &dir.join("sync_pair"));
    let out = rapid_in(&dir, &["run", "--io-log", "io.csv", "--save-pers", "sync_pair"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // The robot reads each part after the feeder wrote it (sync point), counts it in
    // the shared partsMade, and the feeder sees the count 0.1 s after the last meeting.
    assert_eq!(
        text(&out.stdout),
        "robot took part1\nrobot took part2\nrobot took part3\nrobot made 3\nfeeder sees 3\n"
    );
    // The feeder's output goes up at each part and down half a second later.
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let expected = "time,signal,old,new,cause\n0,doFeederBusy,0,1,Order\n0.5,doFeederBusy,1,0,Order\n\
                    0.5,doFeederBusy,0,1,Order\n1,doFeederBusy,1,0,Order\n1,doFeederBusy,0,1,Order\n\
                    1.5,doFeederBusy,1,0,Order\n";
    assert_eq!(log, expected);
    // One persistent object: both tasks' modules are saved with its final value.
    for module in ["RAPID/TASK1/PROGMOD/Cell.mod", "RAPID/TASK2/PROGMOD/Feeder.mod"] {
        let saved = fs::read_to_string(dir.join("sync_pair").join(module)).expect("module");
        assert!(saved.contains("PERS num partsMade := 3;"), "{module}: {saved}");
        assert!(saved.contains("PERS string lastPart := \"part3\";"), "{module}: {saved}");
    }
}

#[test]
fn persistents_of_one_name_must_agree_on_type_and_size() {
    let dir = scratch("pers_mismatch");
    let a = "MODULE A\n  PERS num shared{2} := [1, 2];\n  PROC main()\n    TPWrite \"a\";\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PERS num shared{3} := [1, 2, 3];\n  PROC main()\n    TPWrite \"b\";\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: a },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "", "nothing runs");
    let err = text(&out.stderr);
    assert!(err.contains("persistent `shared` is declared `num{3}` here and `num{2}` in task T_ROB1"), "{err}");
    assert!(err.contains(" --> sys/RAPID/TASK2/PROGMOD/Main.mod:2:12\n") && err.contains("it was not run"), "{err}");
}

#[test]
fn a_background_task_runs_only_while_its_foreground_task_waits() {
    let dir = scratch("background");
    // T_ROB1 writes, waits a second, writes. T_BG stands behind it and writes every
    // 0.4 s: at 0, 0.4 and 0.8 (all while T_ROB1 waits); the run ends with T_ROB1.
    let fg = "MODULE Fg\n  PROC main()\n    TPWrite \"fg start\";\n    WaitTime 1;\n    TPWrite \"fg end\";\n  \
              ENDPROC\nENDMODULE\n";
    let bg = "MODULE Bg\n  PROC main()\n    WHILE TRUE DO\n      TPWrite \"bg\";\n      WaitTime 0.4;\n    \
              ENDWHILE\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: fg },
        TaskDef { name: "T_BG", attrs: "-Type \"STATIC\" -TaskInForeground \"T_ROB1\"", module: bg },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "fg start\nbg\nbg\nbg\nfg end\n");
}

#[test]
fn wait_test_and_set_guards_a_critical_section() {
    let dir = scratch("semaphore");
    // T_ROB1 takes the lock at 0 and holds it for 0.2 s; T_B asks at 0.1 and gets it
    // only when T_ROB1 frees it at 0.2. TestAndSet on a taken lock answers FALSE.
    let a = "MODULE A\n  PERS bool lock := FALSE;\n  PROC main()\n    WaitTestAndSet lock;\n    \
             TPWrite \"a in\";\n    WaitTime 0.2;\n    TPWrite \"a out\";\n    lock := FALSE;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PERS bool lock := FALSE;\n  PROC main()\n    WaitTime 0.1;\n    \
             IF NOT TestAndSet(lock) TPWrite \"b finds it taken\";\n    WaitTestAndSet lock;\n    \
             TPWrite \"b in\";\n    lock := FALSE;\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: a },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "a in\nb finds it taken\na out\nb in\n");
}

#[test]
fn a_sync_point_times_out_with_err_waitsynctask() {
    let dir = scratch("sync_timeout");
    // T_B is busy for 2 s before it comes to the sync point; T_ROB1 waits at most
    // 0.5 s, handles ERR_WAITSYNCTASK and then waits without a limit: both meet at 2
    // (its handler returns: reaching ENDPROC in a handler would stop the task, §1.12).
    let a = "MODULE A\n  PERS tasks both{2} := [[\"T_ROB1\"], [\"T_B\"]];\n  VAR syncident meet;\n  \
             PROC main()\n    WaitSyncTask meet, both \\TimeOut:=0.5;\n    TPWrite \"a met b\";\n  \
             ERROR\n    IF ERRNO = ERR_WAITSYNCTASK THEN\n      TPWrite \"a gave up waiting\";\n      \
             WaitSyncTask meet, both;\n      TPWrite \"a met b late\";\n      RETURN;\n    ENDIF\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PERS tasks both{2} := [[\"T_ROB1\"], [\"T_B\"]];\n  VAR syncident meet;\n  \
             PROC main()\n    WaitTime 2;\n    TPWrite \"b arrives\";\n    WaitSyncTask meet, both;\n  \
             ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: a },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "a gave up waiting\nb arrives\na met b late\n");
}

#[test]
fn a_static_task_that_fails_stops_the_normal_tasks_by_its_trust_level() {
    let dir = scratch("trust");
    // T_MON divides by zero at 0.5 s. With the default trust level (SysFail) T_ROB1,
    // waiting until 2 s, is stopped: it never writes "done".
    let rob = "MODULE R\n  PROC main()\n    TPWrite \"start\";\n    WaitTime 2;\n    TPWrite \"done\";\n  \
               ENDPROC\nENDMODULE\n";
    let mon = "MODULE M\n  VAR num zero := 0;\n  PROC main()\n    WaitTime 0.5;\n    \
               TPWrite \"ratio \" \\Num:=1 / zero;\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: rob },
        TaskDef { name: "T_MON", attrs: "-Type \"STATIC\"", module: mon },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "start\n");
    let err = text(&out.stderr);
    assert!(err.contains("ERR_DIVZERO"), "{err}");
    assert!(err.contains("in task T_MON, routine main"), "{err}");
    assert!(err.contains("TrustLevel SysFail stopped every NORMAL task"), "{err}");

    // NoSafety: only the failing task stops; T_ROB1 finishes (the error is still
    // reported, so the run fails).
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: rob },
        TaskDef { name: "T_MON", attrs: "-Type \"STATIC\" -TrustLevel \"NoSafety\"", module: mon },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "start\ndone\n");
    assert!(!text(&out.stderr).contains("TrustLevel"), "{}", text(&out.stderr));
}

#[test]
fn an_output_set_in_one_task_interrupts_another() {
    let dir = scratch("interrupt");
    // The manual's example (§1.20, 使中断运用同步): task 1 sets do1, task 2's
    // ISignalDO trap runs. Task 2 also waits for the signal with WaitDO.
    let t1 = "MODULE M1\n  PROC main()\n    WaitTime 0.3;\n    SetDO do1, 1;\n  ENDPROC\nENDMODULE\n";
    let t2 = "MODULE M2\n  VAR intnum isiint1;\n  PROC main()\n    CONNECT isiint1 WITH isi_trap;\n    \
              ISignalDO do1, 1, isiint1;\n    WaitDO do1, 1;\n    TPWrite \"task 2 saw do1\";\n    \
              IDelete isiint1;\n  ENDPROC\n  TRAP isi_trap\n    TPWrite \"trap in task 2\";\n  ENDTRAP\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: t1 },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: t2 },
    ];
    system(&dir, &tasks, "\n      -Name \"do1\" -SignalType \"DO\"\n");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "trap in task 2\ntask 2 saw do1\n");
}

#[test]
fn tasks_know_their_names_numbers_and_each_other() {
    let dir = scratch("names");
    let t1 = "MODULE M1\n  PROC main()\n    VAR num no;\n    TPWrite GetTaskName(\\TaskNo:=no) \\Num:=no;\n    \
              IF TaskRunRob() TPWrite \"T_ROB1 moves the robot\";\n    IF TaskIsExecuting(T_PLCId) TPWrite \"T_PLC executes\";\n    WaitTime 1;\n  ENDPROC\nENDMODULE\n";
    let t2 = "MODULE M2\n  PROC main()\n    VAR num no;\n    WaitTime 0.5;\n    \
              TPWrite GetTaskName(\\TaskNo:=no) \\Num:=no;\n    IF NOT TaskRunRob() TPWrite \"T_PLC does not\";\n    \
              TPWrite \"motion task \" + GetTaskName(\\MecTaskNo:=no) \\Num:=no;\n    \
              IF TaskIsExecuting(\"T_ROB1\") AND TaskIsActive(T_ROB1Id) TPWrite \"T_ROB1 executes\";\n    WaitTime 1;\n    \
              IF NOT TaskIsExecuting(\"T_ROB1\") TPWrite \"T_ROB1 has ended\";\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: t1 },
        TaskDef { name: "T_PLC", attrs: "-Type \"NORMAL\"", module: t2 },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "T_ROB11\nT_ROB1 moves the robot\nT_PLC executes\nT_PLC2\nT_PLC does not\nmotion task T_ROB11\nT_ROB1 executes\nT_ROB1 has ended\n"
    );
}

#[test]
fn a_shared_record_keeps_its_type_when_the_tasks_number_types_differently() {
    let dir = scratch("records");
    // The two programs declare their record types in opposite orders, so each numbers
    // them differently; the shared persistent is still one `point` value.
    let t1 = "MODULE M1\n  RECORD other\n    num a;\n  ENDRECORD\n  RECORD point\n    num x;\n    num y;\n  \
              ENDRECORD\n  PERS point spot := [0, 0];\n  PROC main()\n    spot := [3, 4];\n  ENDPROC\nENDMODULE\n";
    let t2 = "MODULE M2\n  RECORD point\n    num x;\n    num y;\n  ENDRECORD\n  RECORD other\n    num a;\n  \
              ENDRECORD\n  PERS point spot := [0, 0];\n  PROC main()\n    VAR point want := [3, 4];\n    \
              WaitTime 0.1;\n    IF spot = want TPWrite \"same point\";\n    TPWrite ValToStr(spot);\n  \
              ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: t1 },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: t2 },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "same point\n[3,4]\n");
}

#[test]
fn check_reads_every_task_of_a_backup() {
    let dir = scratch("check_all");
    // T_B's module uses a name only T_ROB1 declares: each task is checked on its own,
    // so the finding is in T_B's file.
    let a = "MODULE A\n  VAR num onlyInA := 1;\n  PROC main()\n    onlyInA := 2;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC main()\n    onlyInA := 3;\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: a },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    let report = text(&out.stdout);
    assert!(report.contains("sys/RAPID/TASK2/PROGMOD/Main.mod:3:5"), "{report}");
    assert!(!report.contains("TASK1/PROGMOD/Main.mod:"), "{report}");
    assert!(report.contains("3 files"), "{report}");
}

#[test]
fn the_three_task_example_runs_as_worked_out() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = scratch("press_cell");
    copy_dir(&root.join("examples/press_cell"), &dir.join("press_cell"));
    fs::copy(root.join("examples/press_cell.stimulus"), dir.join("press_cell.stimulus")).expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "press_cell.stimulus", "--io-log", "io.csv", "press_cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // Part 1 arrives at 0.2; the robot needs 0.4 s to load, the press 1.1 s, the
    // unload 0.35 s; the next part is there 1.5 s after the last was taken; the
    // monitor reports at every whole second while the robot waits.
    let expected = [
        "robot: picking part 1",               // 0.2
        "press: pressing part 1",              // 0.6
        "monitor: 0 parts done, press closed", // 1.0
        "monitor: 0 parts done, press open",   // 2.0 (opened at 1.7)
        "robot: part 1 done",                  // 2.05
        "robot: picking part 2",               // 2.05 (part there since 1.7)
        "press: pressing part 2",              // 2.45
        "monitor: 1 parts done, press closed", // 3.0
        "robot: part 2 done",                  // 3.9 (press opened at 3.55)
        "robot: picking part 3",               // 3.9
        "monitor: 2 parts done, press open",   // 4.0
        "press: pressing part 3",              // 4.3
        "monitor: 2 parts done, press closed", // 5.0
        "robot: part 3 done",                  // 5.75 (press opened at 5.4)
        "press: 3 parts pressed",              // 5.75, after the last meeting
    ];
    assert_eq!(text(&out.stdout), expected.map(|l| format!("{l}\n")).concat());
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let press: Vec<&str> = log.lines().filter(|l| l.contains(",doPressClose,")).collect();
    assert_eq!(
        press,
        [
            "0.6,doPressClose,0,1,Order",
            "1.7,doPressClose,1,0,Order",
            "2.45,doPressClose,0,1,Order",
            "3.55,doPressClose,1,0,Order",
            "4.3,doPressClose,0,1,Order",
            "5.4,doPressClose,1,0,Order"
        ]
    );
}

#[test]
fn tasks_talk_through_rapid_message_queues() {
    let dir = scratch("rmq");
    // T_ROB1 (interrupt mode) takes string messages in a trap and answers with the
    // string's length; T_PLC (synchronous mode) asks at 0.5 s with RMQSendWait, then
    // sends a robjoint no trap is ordered for (discarded), then waits 0.3 s in vain.
    let robot = "MODULE M1\n  VAR intnum msgint;\n  VAR string command := \"\";\n  PROC main()\n    \
                 CONNECT msgint WITH on_message;\n    IRMQMessage command, msgint;\n    WaitTime 2;\n    \
                 TPWrite \"robot got \" + command;\n    IDelete msgint;\n  ENDPROC\n  TRAP on_message\n    \
                 VAR rmqmessage msg;\n    VAR rmqheader header;\n    VAR rmqslot sender;\n    VAR num userdef;\n    \
                 RMQGetMessage msg;\n    RMQGetMsgHeader msg \\Header:=header \\SenderId:=sender \\UserDef:=userdef;\n    \
                 RMQGetMsgData msg, command;\n    \
                 TPWrite \"trap: \" + header.datatype + \" \" + command + \" from \" + RMQGetSlotName(sender) \\Num:=userdef;\n    \
                 RMQSendMessage sender, StrLen(command);\n  ENDTRAP\nENDMODULE\n";
    let plc = "MODULE M2\n  VAR rmqslot robot;\n  VAR rmqmessage answer;\n  VAR num len;\n  \
               VAR robjoint rj := [1, 2, 3, 4, 5, 6];\n  PROC main()\n    RMQFindSlot robot, \"RMQ_T_ROB1\";\n    \
               WaitTime 0.5;\n    RMQSendWait robot, \"pick\" \\UserDef:=7, answer, len \\Timeout:=1;\n    \
               RMQGetMsgData answer, len;\n    TPWrite \"plc got answer \" \\Num:=len;\n    \
               RMQSendMessage robot, rj;\n    RMQReadWait answer \\TimeOut:=0.3;\n    TPWrite \"plc got more\";\n  \
               ERROR\n    IF ERRNO = ERR_RMQ_TIMEOUT THEN\n      TPWrite \"plc: no more messages\";\n      RETURN;\n    \
               ENDIF\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -RmqType \"Internal\"", module: robot },
        TaskDef {
            name: "T_PLC",
            attrs: "-Type \"NORMAL\" -RmqType \"Internal\" -RmqMode \"Synchronous\"",
            module: plc,
        },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "trap: string pick from RMQ_T_PLC7\nplc got answer 4\nplc: no more messages\nrobot got pick\n"
    );
}

#[test]
fn message_queue_errors_are_the_controllers() {
    let dir = scratch("rmq_errors");
    // T_SINK has a synchronous queue of at most 2 messages of at most 10 bytes that
    // nobody reads; T_ROB1 provokes each error once and handles it.
    let main = "MODULE M1\n  VAR rmqslot sink;\n  VAR rmqslot unset;\n  VAR rmqmessage empty;\n  VAR num stage := 0;\n  \
                PROC main()\n    stage := 1;\n    RMQFindSlot sink, \"RMQ_T_NOBODY\";\n    RMQFindSlot sink, \"rmq_t_sink\";\n    \
                TPWrite RMQGetSlotName(sink);\n    stage := 2;\n    RMQSendMessage unset, 1;\n    stage := 3;\n    \
                RMQSendMessage sink, \"more than ten bytes\";\n    stage := 4;\n    RMQSendMessage sink, 1;\n    \
                RMQSendMessage sink, 2;\n    RMQSendMessage sink, 3;\n    stage := 5;\n    RMQGetMsgHeader empty;\n    \
                stage := 6;\n    RMQGetMessage empty;\n    TPWrite \"done\";\n  ERROR\n    \
                TPWrite \"step \" + NumToStr(stage, 0) + \": \" \\Num:=ERRNO;\n    TRYNEXT;\n  \
                ENDPROC\nENDMODULE\n";
    // At 0.5 s T_SINK empties its queue (the two messages T_ROB1 put there), so its
    // RMQReadWait then waits in vain.
    let sink = "MODULE M2\n  VAR rmqmessage msg;\n  PROC main()\n    WaitTime 0.5;\n    RMQEmptyQueue;\n    \
                RMQReadWait msg \\TimeOut:=0.1;\n    TPWrite \"sink got one\";\n  ERROR\n    \
                IF ERRNO = ERR_RMQ_TIMEOUT THEN\n      TPWrite \"sink: the queue was emptied\";\n      RETURN;\n    \
                ENDIF\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: main },
        TaskDef {
            name: "T_SINK",
            attrs: "-Type \"NORMAL\" -RmqType \"Internal\" -RmqMode \"Synchronous\" -RmqMaxMsgSize 10 -RmqMaxNoOfMsg 2",
            module: sink,
        },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // ERR_RMQ_NAME 1118; the slot's name as configured; ERR_RMQ_INVALID 1115;
    // ERR_RMQ_MSGSIZE 1117 (19 characters > 10 bytes); ERR_RMQ_FULL 1114 on the third
    // message; ERR_RMQ_INVMSG 1116; T_ROB1 has no queue of its own: ERR_RMQ_NOMSG 1119.
    assert_eq!(
        text(&out.stdout),
        "step 1: 1118\nRMQ_T_SINK\nstep 2: 1115\nstep 3: 1117\nstep 4: 1114\nstep 5: 1116\nstep 6: 1119\ndone\n\
         sink: the queue was emptied\n"
    );
}

/// Adds CAB_EXEC_HOOKS lines to a test system's SYS.cfg.
fn add_hooks(root: &Path, hooks: &str) {
    let path = root.join("SYSPAR/SYS.cfg");
    let mut sys = fs::read_to_string(&path).expect("SYS.cfg");
    sys.push_str(&format!("#\nCAB_EXEC_HOOKS:\n{hooks}"));
    fs::write(path, sys).expect("SYS.cfg");
}

#[test]
fn event_routines_run_at_power_on_start_and_stop() {
    let dir = scratch("hooks");
    // POWER_ON in every task (-AllTask), then T_ROB1's START; T_ROB1 stops at once
    // (its STOP routine runs then), T_B ends a second later. EventType: EVENT_POWERON
    // 1, EVENT_START 2, EVENT_STOP 3, EVENT_NONE 0 outside event routines.
    let a = "MODULE A\n  PROC on_power()\n    TPWrite \"power on \" \\Num:=EventType();\n  ENDPROC\n  \
             PROC on_start()\n    TPWrite \"start \" \\Num:=EventType();\n  ENDPROC\n  PROC on_stop()\n    \
             TPWrite \"stop \" \\Num:=EventType();\n  ENDPROC\n  PROC main()\n    TPWrite \"main \" \\Num:=EventType();\n    \
             Stop;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC on_power()\n    TPWrite \"b power on\";\n  ENDPROC\n  PROC main()\n    WaitTime 1;\n    \
             TPWrite \"b done\";\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: a },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    let root = system(&dir, &tasks, "");
    add_hooks(
        &root,
        "\n      -Routine \"on_power\" -Shelf \"POWER_ON\" -AllTask\n\n      -Routine \"on_start\" -Shelf \"START\" -Task \"T_ROB1\"\n\n      -Routine \"on_stop\" -Shelf \"STOP\" -Task \"T_ROB1\"\n",
    );
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "power on 1\nb power on\nstart 2\nmain 0\nstop 3\nb done\n");

    // One task alone runs the same way (the single-task path).
    let root = system(&dir, &tasks[..1], "");
    add_hooks(
        &root,
        "\n      -Routine \"on_start\" -Shelf \"START\" -Task \"T_ROB1\"\n\n      -Routine \"on_stop\" -Shelf \"STOP\"\n",
    );
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "start 2\nmain 0\nstop 3\n");

    // A hook naming a procedure the task does not have: the system does not start.
    let root = system(&dir, &tasks, "");
    add_hooks(&root, "\n      -Routine \"missing\" -Shelf \"START\" -Task \"T_B\"\n");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    assert!(
        text(&out.stderr).contains("task T_B has no procedure `missing` for its START event routine"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn searchl_finds_the_edge_from_the_stimulus() {
    let dir = scratch("searchl");
    // The probe input rises 0.5 s after doStart; the search runs at 100 mm/s with a
    // 10 m/s^2 ramp (0.5 mm in its first 0.01 s), so the hit is 0.5 + 0.49 * 100 =
    // 49.5 mm along x; \Stop brakes over 0.08 s: 100 * 0.08 / 2 = 4 mm further, the
    // program goes on at 0.58 s with the robot at 353.5. A second search for a rising edge
    // starts with the input already high (ERR_SIGSUPSEARCH); a third, for a falling
    // edge that never comes, reaches its ToPoint without a hit (ERR_WHLSEARCH).
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR robtarget hit;\n  VAR pos at;\n  VAR clock c;\n  VAR num stage := 0;\n  PROC main()\n    \
                   MoveJ p0, v1000, fine, tool0;\n    ClkStart c;\n    SetDO doStart, 1;\n    stage := 1;\n    \
                   SearchL \\Stop, diProbe, hit, Offs(p0, 100, 0, 0), v100, tool0;\n    \
                   TPWrite \"hit x \" + NumToStr(hit.trans.x, 1) + \" after \" + NumToStr(ClkRead(c), 2);\n    \
                   at := CPos();\n    TPWrite \"robot at x \" + NumToStr(at.x, 1);\n    stage := 2;\n    \
                   SearchL diProbe, hit, Offs(p0, 100, 0, 0), v100, tool0;\n    stage := 3;\n    \
                   SearchL diProbe \\NegFlank, hit, Offs(p0, 100, 0, 0), v100, tool0;\n    TPWrite \"done\";\n  \
                   ERROR\n    IF ERRNO = ERR_SIGSUPSEARCH TPWrite \"stage \" + NumToStr(stage, 0) + \": ERR_SIGSUPSEARCH\";\n    \
                   at := CPos();\n    IF ERRNO = ERR_WHLSEARCH TPWrite \"stage \" + NumToStr(stage, 0) + \": ERR_WHLSEARCH, robot at x \" + NumToStr(at.x, 1);\n    \
                   TRYNEXT;\n  ENDPROC\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: program }];
    system(
        &dir,
        &tasks,
        "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"diProbe\" -SignalType \"DI\"\n",
    );
    fs::write(dir.join("probe.stim"), "when doStart = 1 after 0.5 s set diProbe 1\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--quiet", "--stimulus", "probe.stim", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "hit x 349.5 after 0.58\nrobot at x 353.5\nstage 2: ERR_SIGSUPSEARCH\nstage 3: ERR_WHLSEARCH, robot at x 400.0\ndone\n"
    );
}

#[test]
fn ierror_in_one_task_sees_the_errors_of_another() {
    let dir = scratch("ierror");
    // T_REPORT (static) orders an interrupt for every error of any domain
    // (COMMON_ERR, TYPE_ERR). T_ROB1 logs a user error at 0.5 s (ErrWrite: domain 8)
    // and divides by zero at 1 s with no handler (the system error handler's entry:
    // domain 4, program errors). The run ends with T_ROB1, after T_REPORT's trap for
    // the last error has run.
    let rob = "MODULE R\n  VAR num zero := 0;\n  PROC main()\n    WaitTime 0.5;\n    ErrWrite \"Gripper\", \"no part\";\n    \
               WaitTime 0.5;\n    TPWrite \"ratio \" \\Num:=1 / zero;\n  ENDPROC\nENDMODULE\n";
    let report = "MODULE E\n  VAR intnum errors;\n  VAR trapdata data;\n  PROC main()\n    CONNECT errors WITH on_error;\n    \
                  IError COMMON_ERR, TYPE_ERR, errors;\n    WHILE TRUE DO\n      WaitTime 10;\n    ENDWHILE\n  ENDPROC\n  \
                  TRAP on_error\n    VAR errdomain domain;\n    VAR num id;\n    VAR errtype kind;\n    VAR string title;\n    \
                  GetTrapData data;\n    ReadErrData data, domain, id, kind \\Title:=title;\n    \
                  TPWrite \"caught domain \" + NumToStr(domain, 0) + \" type \" + NumToStr(kind, 0);\n  ENDTRAP\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: rob },
        TaskDef { name: "T_REPORT", attrs: "-Type \"STATIC\" -TrustLevel \"NoSafety\"", module: report },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    // ErrWrite also shows its message on the pendant.
    assert_eq!(text(&out.stdout), "Gripper\nno part\ncaught domain 8 type 3\ncaught domain 4 type 3\n");
    assert!(text(&out.stderr).contains("ERR_DIVZERO"), "{}", text(&out.stderr));
}

#[test]
fn a_shared_module_has_one_variable_for_all_tasks_and_task_var_one_each() {
    let dir = scratch("shared_module");
    // HOME:/shared.sys is installed shared: `counter` is one variable every task
    // changes; `mine` (TASK VAR) has a value per task. T_ROB1 bumps at 0, T_B at 0.1.
    let shared = "MODULE shared(SYSMODULE)\n  VAR num counter := 0;\n  TASK VAR num mine := 0;\n  PROC bump()\n    \
                  counter := counter + 1;\n    mine := mine + 1;\n  ENDPROC\nENDMODULE\n";
    let rob =
        "MODULE R\n  PROC main()\n    bump;\n    WaitTime 0.2;\n    TPWrite \"rob counter \" \\Num:=counter;\n    \
               TPWrite \"rob mine \" \\Num:=mine;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC main()\n    WaitTime 0.1;\n    bump;\n    WaitTime 0.2;\n    \
             TPWrite \"b counter \" \\Num:=counter;\n    TPWrite \"b mine \" \\Num:=mine;\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: rob },
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
    assert_eq!(text(&out.stdout), "rob counter 2\nrob mine 1\nb counter 2\nb mine 1\n");

    // A shared module the backup's HOME does not hold: SYS.cfg's line is the finding.
    fs::remove_file(root.join("HOME/shared.sys")).expect("remove");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(err.contains("shared module `HOME:/shared.sys` is not in the backup's HOME folder"), "{err}");
    assert!(err.contains("SYS.cfg:"), "{err}");
}

#[test]
fn one_task_reads_and_writes_anothers_data_and_robot() {
    let dir = scratch("remote_data");
    // T_LOG reads T_ROB1's module data by name (\TaskName and \TaskRef), writes one
    // of its variables, and reads its robot's axes (CJointT \TaskRef), as a logger
    // task does; T_ROB1 moved axis 5 to 30 degrees first.
    let rob = "MODULE R\n  VAR num count := 7;\n  CONST num limit := 9;\n  PROC main()\n    \
               MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;\n    \
               WaitTime 1;\n    TPWrite \"rob count \" \\Num:=count;\n  ENDPROC\nENDMODULE\n";
    let log = "MODULE L\n  PROC main()\n    VAR num n;\n    VAR jointtarget jt;\n    WaitTime 0.5;\n    \
               GetDataVal \"count\" \\TaskName:=\"T_ROB1\", n;\n    TPWrite \"log read \" \\Num:=n;\n    \
               SetDataVal \"count\" \\TaskRef:=T_ROB1Id, n + 1;\n    jt := CJointT(\\TaskRef:=T_ROB1Id);\n    \
               TPWrite \"rob axis 5 \" \\Num:=jt.robax.rax_5;\n    SetDataVal \"limit\" \\TaskName:=\"T_ROB1\", 1;\n  \
               ERROR\n    IF ERRNO = ERR_SYM_ACCESS THEN\n      TPWrite \"limit is a constant\";\n      RETURN;\n    ENDIF\n  \
               ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: rob },
        TaskDef { name: "T_LOG", attrs: "-Type \"NORMAL\"", module: log },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "log read 7\nrob axis 5 30\nlimit is a constant\nrob count 8\n");
}

#[test]
fn move_do_sets_its_output_where_the_robot_passes_the_point() {
    let dir = scratch("movedo");
    // doStart marks when each move starts. A MoveLDO to a stop point 100 mm away at
    // 100 mm/s (10 m/s^2 ramps) sets doGlue when the robot stands there: 1.01 s later.
    // A MoveLDO to a fly-by point (z10, then a 90 degree turn) sets doFly in the middle
    // of the corner path: the zone is entered after 0.005 + 89.5/100 = 0.905 s, the
    // corner takes 20/100 = 0.2 s at full speed, so 1.005 s after the start.
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    SetDO doStart, 1;\n    \
                   MoveLDO Offs(p0, 100, 0, 0), v100, fine, tool0, doGlue, 1;\n    SetDO doStart, 0;\n    \
                   MoveLDO Offs(p0, 100, 100, 0), v100, z10, tool0, doFly, 1;\n    \
                   MoveL Offs(p0, 100, 200, 0), v100, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: program }];
    let signals = "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"doGlue\" -SignalType \"DO\"\n\n      -Name \"doFly\" -SignalType \"DO\"\n";
    system(&dir, &tasks, signals);
    let out = rapid_in(&dir, &["run", "--quiet", "--io-log", "io.csv", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let time_of = |signal: &str, new: &str| change_time(&log, signal, new);
    let glue = time_of("doGlue", "1") - time_of("doStart", "1");
    let fly = time_of("doFly", "1") - time_of("doStart", "0");
    assert!((glue - 1.01).abs() < 0.0015, "doGlue after {glue} s: {log}");
    assert!((fly - 1.005).abs() < 0.0015, "doFly after {fly} s: {log}");
}

#[test]
fn triggers_fire_at_their_places_on_the_path() {
    let dir = scratch("trigg");
    // TriggL 100 mm at 100 mm/s (10 m/s^2 ramps: 0.5 mm in the first 0.01 s) from
    // doStart: doGun on 10 mm after the start (0.01 + 9.5/100 = 0.105 s), off 20 mm
    // before the point (80 mm: 0.805 s), and an interrupt at 50 mm (0.505 s) whose
    // trap runs while the robot moves, before the move's end at 1.01 s.
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR triggdata gunOn;\n  VAR triggdata gunOff;\n  VAR triggdata half;\n  VAR intnum hit;\n  \
                   PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    TriggIO gunOn, 10 \\Start \\DOp:=doGun, 1;\n    \
                   TriggIO gunOff, 20 \\DOp:=doGun, 0;\n    CONNECT hit WITH at_half;\n    TriggInt half, 50 \\Start, hit;\n    \
                   SetDO doStart, 1;\n    TriggL Offs(p0, 100, 0, 0), v100, gunOn \\T2:=gunOff \\T3:=half, fine, tool0;\n    \
                   TPWrite \"arrived\";\n    IDelete hit;\n  ENDPROC\n  TRAP at_half\n    SetDO doHalf, 1;\n    \
                   TPWrite \"half way\";\n  ENDTRAP\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: program }];
    let signals = "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"doGun\" -SignalType \"DO\"\n\n      -Name \"doHalf\" -SignalType \"DO\"\n";
    system(&dir, &tasks, signals);
    let out = rapid_in(&dir, &["run", "--quiet", "--io-log", "io.csv", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "half way\narrived\n");
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let time_of = |signal: &str, new: &str| change_time(&log, signal, new);
    let start = time_of("doStart", "1");
    for (signal, value, expected) in [("doGun", "1", 0.105), ("doHalf", "1", 0.505), ("doGun", "0", 0.805)] {
        let after = time_of(signal, value) - start;
        assert!((after - expected).abs() < 0.0025, "{signal} = {value} after {after} s, expected {expected}: {log}");
    }
}

#[test]
fn stopmove_in_a_trap_holds_the_robot_until_startmove() {
    let dir = scratch("stopmove");
    // A 100 mm MoveL at 100 mm/s to a stop point takes 1.06 s (1.01 s and 0.05 s
    // settle). 0.3 s into it diStop rises: the trap stops the robot and waits for
    // diGo, which rises at 0.8 s, then restarts it; the robot stood 0.5 s, so the move
    // ends at 1.56 s.
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR intnum stopint;\n  VAR clock c;\n  PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    \
                   CONNECT stopint WITH on_stop;\n    ISignalDI diStop, 1, stopint;\n    ClkStart c;\n    SetDO doStart, 1;\n    \
                   MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;\n    \
                   TPWrite \"arrived after \" + NumToStr(ClkRead(c), 2);\n    IDelete stopint;\n  ENDPROC\n  \
                   TRAP on_stop\n    StopMove;\n    IF IsStopMoveAct(\\FromMoveTask) TPWrite \"stopped\";\n    \
                   WaitDI diGo, 1;\n    StartMove;\n    IF NOT IsStopMoveAct(\\FromMoveTask) TPWrite \"moving again\";\n  \
                   ENDTRAP\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: program }];
    let signals = "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"diStop\" -SignalType \"DI\"\n\n      -Name \"diGo\" -SignalType \"DI\"\n";
    system(&dir, &tasks, signals);
    fs::write(
        dir.join("stop.stim"),
        "when doStart = 1 after 0.3 s set diStop 1\nwhen doStart = 1 after 0.8 s set diGo 1\n",
    )
    .expect("stimulus");
    let out = rapid_in(&dir, &["run", "--quiet", "--stimulus", "stop.stim", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "stopped\nmoving again\narrived after 1.56\n");
}

#[test]
fn world_zones_set_outputs_and_stop_the_robot() {
    let dir = scratch("zones");
    // A slab zone from x = 340 to 360 mm: the TCP, moving from x = 300 at 100 mm/s
    // (0.5 mm in the first 0.01 s), enters it after 0.01 + 39.5/100 = 0.405 s and
    // leaves after 0.605 s; doInZone follows (to the 4 ms path resolution). Then a
    // sphere the robot may not enter (WZLimSup) lies on the next path: it stops.
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR shapedata slab;\n  VAR shapedata ball;\n  VAR wztemporary wzSlab;\n  VAR wztemporary wzBall;\n  \
                   PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    \
                   WZBoxDef \\Inside, slab, [340, -50, 350], [360, 50, 450];\n    \
                   WZDOSet \\Temp, wzSlab \\Inside, slab, doInZone, 1;\n    SetDO doStart, 1;\n    \
                   MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;\n    WZFree wzSlab;\n    TPWrite \"slab zone \" \\Num:=wzSlab.wz;\n    \
                   WZSphDef \\Inside, ball, [450, 0, 400], 20;\n    WZLimSup \\Temp, wzBall, ball;\n    \
                   MoveL Offs(p0, 200, 0, 0), v100, fine, tool0;\n    TPWrite \"not reached\";\n  ENDPROC\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: program }];
    let signals = "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"doInZone\" -SignalType \"DO\"\n";
    system(&dir, &tasks, signals);
    let out = rapid_in(&dir, &["run", "--quiet", "--io-log", "io.csv", "sys"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "slab zone 0\n");
    assert!(text(&out.stderr).contains("WZLimSup"), "{}", text(&out.stderr));
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    let time_of = |signal: &str, new: &str| change_time(&log, signal, new);
    let start = time_of("doStart", "1");
    for (value, expected) in [("1", 0.405), ("0", 0.605)] {
        let after = time_of("doInZone", value) - start;
        assert!((after - expected).abs() <= 0.0055, "doInZone = {value} after {after} s, expected {expected}: {log}");
    }
}

#[test]
fn a_stimulus_answers_a_pendant_dialog_at_its_time() {
    let dir = scratch("answer");
    // The dialog is shown at 0; the operator answers 7 at 4 s (the example line).
    let program = "MODULE S\n  VAR clock c;\n  PROC main()\n    VAR num n;\n    ClkStart c;\n    \
                   TPReadNum n, \"How many parts?\";\n    TPWrite \"got \" + NumToStr(n, 0) + \" at \" + NumToStr(ClkRead(c), 1);\n  \
                   ENDPROC\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: program }];
    system(&dir, &tasks, "\n      -Name \"diUnused\" -SignalType \"DI\"\n");
    fs::write(dir.join("op.stim"), "at 4 s answer TPReadNum 7\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "op.stim", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).ends_with("got 7 at 4.0\n"), "{}", text(&out.stdout));
}

#[test]
fn searchc_finds_the_edge_on_its_circle() {
    let dir = scratch("searchc");
    // A half circle from [300, 0] through [350, 50] to [400, 0] (centre [350, 0], r 50)
    // at 100 mm/s: the probe rises after 0.5 s, 49.5 mm along the arc, i.e. 0.99 rad
    // from the start: [350 - 50 cos 0.99, 50 sin 0.99] = [322.6, 41.8].
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR robtarget hit;\n  PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    SetDO doStart, 1;\n    \
                   SearchC \\Stop, diProbe, hit, Offs(p0, 50, 50, 0), Offs(p0, 100, 0, 0), v100, tool0;\n    \
                   TPWrite \"hit \" + NumToStr(hit.trans.x, 1) + \", \" + NumToStr(hit.trans.y, 1);\n  ENDPROC\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: program }];
    system(
        &dir,
        &tasks,
        "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"diProbe\" -SignalType \"DI\"\n",
    );
    fs::write(dir.join("probe.stim"), "when doStart = 1 after 0.5 s set diProbe 1\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--quiet", "--stimulus", "probe.stim", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "hit 322.6, 41.8\n");
}

#[test]
fn clearpath_drops_the_rest_of_the_path() {
    let dir = scratch("clearpath");
    // As in the StopMove test, the robot stops 0.3 s into a 100 mm move at 100 mm/s
    // (0.5 + 0.29 * 100 = 29.5 mm along); the trap clears the path, so when StartMove
    // comes at 0.8 s the move instruction ends there: the program goes on at 0.8 s
    // with the robot at x = 329.5.
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   VAR intnum stopint;\n  VAR clock c;\n  PROC main()\n    VAR pos at;\n    MoveJ p0, v1000, fine, tool0;\n    \
                   CONNECT stopint WITH on_stop;\n    ISignalDI diStop, 1, stopint;\n    ClkStart c;\n    SetDO doStart, 1;\n    \
                   MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;\n    at := CPos();\n    \
                   TPWrite \"went on after \" + NumToStr(ClkRead(c), 2) + \" at x \" + NumToStr(at.x, 1);\n    \
                   TPWrite \"path level \" \\Num:=PathLevel();\n    IDelete stopint;\n  ENDPROC\n  \
                   TRAP on_stop\n    StopMove;\n    ClearPath;\n    WaitDI diGo, 1;\n    StartMove;\n  ENDTRAP\nENDMODULE\n";
    let tasks = [TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: program }];
    let signals = "\n      -Name \"doStart\" -SignalType \"DO\"\n\n      -Name \"diStop\" -SignalType \"DI\"\n\n      -Name \"diGo\" -SignalType \"DI\"\n";
    system(&dir, &tasks, signals);
    fs::write(
        dir.join("stop.stim"),
        "when doStart = 1 after 0.3 s set diStop 1\nwhen doStart = 1 after 0.8 s set diGo 1\n",
    )
    .expect("stimulus");
    let out = rapid_in(&dir, &["run", "--quiet", "--stimulus", "stop.stim", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "went on after 0.80 at x 329.5\npath level 1\n");
}

#[test]
fn save_with_a_task_name_saves_the_other_tasks_module() {
    let dir = scratch("save_other");
    // T_ROB1 counts to 3 in its persistent; T_B then saves T_ROB1's module R to HOME:
    // (its persistent written with its value, the rest of the text as loaded), and
    // asks for a module T_ROB1 does not have (ERR_MODULE, handled in T_B).
    let rob =
        "MODULE R\n  PERS num count := 0;\n  PROC main()\n    count := 3;\n    WaitTime 1;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC main()\n    WaitTime 0.5;\n    Save \\TaskName:=\"T_ROB1\", \"R\" \\FilePath:=\"HOME:/R_saved.mod\";\n    \
             TPWrite \"saved\";\n    Save \\TaskName:=\"T_ROB1\", \"NoSuch\" \\FilePath:=\"HOME:/x.mod\";\n  \
             ERROR\n    IF ERRNO = ERR_MODULE TPWrite \"ERR_MODULE\";\n    TRYNEXT;\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: rob },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: b },
    ];
    let root = system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "saved\nERR_MODULE\n");
    let saved = fs::read_to_string(root.join("HOME/R_saved.mod")).expect("the saved module");
    assert_eq!(saved, rob.replace("count := 0", "count := 3"));
}
