//! The pendant dialogs driven through whole programs: answers from a RecordingHost,
//! results printed with TPWrite.

use rapid_sema::SourceInput;

use crate::{load, Exit, RecordingHost};

/// Runs `body` as main (with `decls` before it in the module) answering `answers`;
/// the pendant lines, or the name of the error no handler took.
fn run(decls: &str, body: &str, answers: &[&str]) -> Result<Vec<String>, String> {
    let src = format!("MODULE t\n{decls}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n");
    let mut loaded = match load(&[SourceInput::from_text("t.mod", &src)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}\n{src}"),
    };
    let mut host = RecordingHost::default();
    host.answers.extend(answers.iter().map(|a| a.to_string()));
    match loaded.vm.run(&mut host, 100_000) {
        Exit::Done => {
            assert!(host.answers.is_empty(), "answers left over: {:?}", host.answers);
            Ok(host.lines)
        }
        Exit::Unhandled(u) => Err(u.error.name.to_string()),
        other => panic!("unexpected exit {other:?}"),
    }
}

fn lines(decls: &str, body: &str, answers: &[&str]) -> Vec<String> {
    run(decls, body, answers).unwrap_or_else(|e| panic!("unhandled {e} for {answers:?}"))
}

fn fails(decls: &str, body: &str, answers: &[&str]) -> String {
    match run(decls, body, answers) {
        Ok(lines) => panic!("expected an error for {answers:?}, got {lines:?}"),
        Err(name) => name,
    }
}

const MSG_BOX: &str = "  VAR btnres r;\n  UIMsgBox \\Header:=\"H\", \"line 1\" \\MsgLine2:=\"line 2\" \\Buttons:=btnOKCancel \\Result:=r;\n  TPWrite \"r=\" \\Num:=r;\n  IF r = resOK TPWrite \"ok\";\n  IF r = resCancel TPWrite \"cancel\";";

#[test]
fn ui_msg_box_takes_a_button_name_or_btnres_value() {
    assert_eq!(lines("", MSG_BOX, &["OK"]), ["r=1", "ok"]);
    assert_eq!(lines("", MSG_BOX, &["  cancel "]), ["r=5", "cancel"]);
    assert_eq!(lines("", MSG_BOX, &["resCancel"]), ["r=5", "cancel"]);
    assert_eq!(lines("", MSG_BOX, &["5"]), ["r=5", "cancel"]);
    // Buttons not shown, values that are no button, and other text fit nothing.
    for bad in ["Yes", "6", "0", "maybe", ""] {
        assert_eq!(fails("", MSG_BOX, &[bad]), "ERR_ARGVALERR", "answer {bad:?}");
    }
}

#[test]
fn ui_msg_box_standard_button_sets() {
    let body = |buttons: &str| {
        format!("  VAR btnres r;\n  UIMsgBox \"?\" \\Buttons:={buttons} \\Result:=r;\n  TPWrite \"\" \\Num:=r;")
    };
    /// A buttondata constant, answers with the btnres value they give, answers refused.
    type Case = (&'static str, &'static [(&'static str, &'static str)], &'static [&'static str]);
    let cases: [Case; 6] = [
        ("btnOK", &[("ok", "1")], &["Cancel"]),
        ("btnAbrtRtryIgn", &[("Abort", "2"), ("retry", "3"), ("IGNORE", "4")], &["OK"]),
        ("btnOKCancel", &[("OK", "1"), ("Cancel", "5")], &["No"]),
        ("btnRetryCancel", &[("Retry", "3"), ("Cancel", "5")], &["OK"]),
        ("btnYesNo", &[("Yes", "6"), ("no", "7")], &["Cancel"]),
        ("btnYesNoCancel", &[("Yes", "6"), ("No", "7"), ("Cancel", "5")], &["OK"]),
    ];
    for (buttons, good, bad) in cases {
        for (answer, value) in good {
            assert_eq!(lines("", &body(buttons), &[answer]), [*value], "{buttons} answered {answer}");
        }
        for answer in bad {
            assert_eq!(fails("", &body(buttons), &[answer]), "ERR_ARGVALERR", "{buttons} answered {answer}");
        }
    }
}

#[test]
fn ui_msg_box_defaults_to_one_ok_button() {
    let body = "  VAR btnres r;\n  UIMsgBox \"Done\" \\Result:=r;\n  TPWrite \"\" \\Num:=r;\n  UIMsgBox \"Again\";";
    assert_eq!(lines("", body, &["OK", "ok"]), ["1"]);
    assert_eq!(fails("", body, &["Cancel"]), "ERR_ARGVALERR");
}

#[test]
fn ui_msg_box_without_answer() {
    assert_eq!(fails("", MSG_BOX, &[]), "ERR_TP_NO_CLIENT");
    let timed = "  UIMsgBox \"?\" \\MaxTime:=5;";
    assert_eq!(fails("", timed, &[]), "ERR_TP_MAXTIME");
    let flagged = "  VAR btnres r := 3;\n  VAR errnum e;\n  UIMsgBox \"?\" \\Result:=r \\MaxTime:=5 \\BreakFlag:=e;\n  IF e = ERR_TP_MAXTIME TPWrite \"timeout\";\n  TPWrite \"r=\" \\Num:=r;";
    assert_eq!(lines("", flagged, &[]), ["timeout", "r=0"]);
}

#[test]
fn ui_msg_box_btn_none_uses_no_answer() {
    let body = "  VAR errnum e;\n  UIMsgBox \"Wait\" \\Buttons:=btnNone \\MaxTime:=1 \\BreakFlag:=e;\n  IF e = ERR_TP_MAXTIME TPWrite \"timeout\";\n  TPReadNum e, \"n?\";\n  TPWrite \"\" \\Num:=e;";
    // The one answer goes to TPReadNum: the message box without buttons takes none.
    assert_eq!(lines("", body, &["42"]), ["timeout", "42"]);
    assert_eq!(fails("", "  UIMsgBox \"Wait\" \\Buttons:=btnNone;", &["OK"]), "ERR_TP_NO_CLIENT");
}

#[test]
fn ui_message_box_returns_the_btnres() {
    let body = "  VAR btnres r;\n  r := UIMessageBox(\\Header:=\"H\" \\Message:=\"Go on?\" \\Buttons:=btnYesNo);\n  IF r = resYes TPWrite \"yes\";\n  IF r = resNo TPWrite \"no\";";
    assert_eq!(lines("", body, &["Yes"]), ["yes"]);
    assert_eq!(lines("", body, &["NO"]), ["no"]);
    assert_eq!(lines("", body, &["7"]), ["no"]);
    assert_eq!(fails("", body, &["OK"]), "ERR_ARGVALERR");
    let default = "  TPWrite \"\" \\Num:=UIMessageBox(\\Message:=\"Done\");";
    assert_eq!(lines("", default, &["ok"]), ["1"]);
    assert_eq!(fails("", default, &["Cancel"]), "ERR_ARGVALERR");
}

#[test]
fn ui_message_box_btn_array_returns_the_index() {
    let decls = "VAR string btns{5} := [\"\", \"Left\", \"\", \"Right\", \"\"];";
    let body = "  VAR btnres r;\n  r := UIMessageBox(\\MsgArray:=[\"Which side?\", \"Pick one\"] \\BtnArray:=btns);\n  TPWrite \"r=\" \\Num:=r;";
    assert_eq!(lines(decls, body, &["left"]), ["r=2"]);
    assert_eq!(lines(decls, body, &[" RIGHT "]), ["r=4"]);
    assert_eq!(lines(decls, body, &["4"]), ["r=4"]);
    // Empty texts are no buttons.
    for bad in ["1", "3", "6", "Middle"] {
        assert_eq!(fails(decls, body, &[bad]), "ERR_ARGVALERR", "answer {bad:?}");
    }
}

#[test]
fn ui_message_box_break_flag_returns_default_btn() {
    let body = "  VAR errnum e;\n  VAR btnres r;\n  r := UIMessageBox(\\Message:=\"?\" \\Buttons:=btnOKCancel \\DefaultBtn:=resCancel \\MaxTime:=2 \\BreakFlag:=e);\n  IF e = ERR_TP_MAXTIME TPWrite \"timeout\";\n  TPWrite \"r=\" \\Num:=r;\n  r := UIMessageBox(\\Message:=\"?\" \\BreakFlag:=e);\n  IF e = ERR_TP_NO_CLIENT TPWrite \"no client\";\n  TPWrite \"r=\" \\Num:=r;";
    assert_eq!(lines("", body, &[]), ["timeout", "r=5", "no client", "r=0"]);
}

const LIST: &str = "CONST listitem items{3} := [[\"\", \"Small\"], [\"\", \"Medium\"], [\"\", \"Large\"]];";

#[test]
fn ui_list_view_as_a_menu() {
    let body = "  VAR num n;\n  VAR btnres r := 9;\n  n := UIListView(\\Result:=r \\Header:=\"Size\", items);\n  TPWrite \"n=\" \\Num:=n;\n  TPWrite \"r=\" \\Num:=r;";
    assert_eq!(lines(LIST, body, &["2"]), ["n=2", "r=1"]);
    assert_eq!(lines(LIST, body, &["large"]), ["n=3", "r=1"]);
    for bad in ["0", "4", "Huge", "2;OK"] {
        assert_eq!(fails(LIST, body, &[bad]), "ERR_ARGVALERR", "answer {bad:?}");
    }
    let plain = "  TPWrite \"\" \\Num:=UIListView(items);";
    assert_eq!(lines(LIST, plain, &["Small"]), ["1"]);
}

#[test]
fn ui_list_view_with_buttons() {
    let body = "  VAR num n;\n  VAR btnres r;\n  n := UIListView(\\Result:=r, items \\Buttons:=btnOKCancel \\DefaultIndex:=2);\n  TPWrite \"n=\" \\Num:=n;\n  IF r = resOK TPWrite \"ok\";\n  IF r = resCancel TPWrite \"cancel\";";
    assert_eq!(lines(LIST, body, &["Medium"]), ["n=2", "ok"]);
    assert_eq!(lines(LIST, body, &["3;Cancel"]), ["n=3", "cancel"]);
    assert_eq!(lines(LIST, body, &["small ; ok"]), ["n=1", "ok"]);
    assert_eq!(lines(LIST, body, &[";Cancel"]), ["n=2", "cancel"]);
    assert_eq!(fails(LIST, body, &["2;Yes"]), "ERR_ARGVALERR");
    let yes_no = "  VAR btnres r;\n  TPWrite \"\" \\Num:=UIListView(\\Result:=r, items \\Buttons:=btnYesNo);\n  TPWrite \"\" \\Num:=r;";
    assert_eq!(lines(LIST, yes_no, &["1"]), ["1", "6"]);
}

#[test]
fn ui_list_view_with_btn_array() {
    let body = "  VAR num n;\n  VAR btnres r;\n  n := UIListView(\\Result:=r, items \\BtnArray:=[\"Run\", \"Exit\"]);\n  TPWrite \"n=\" \\Num:=n;\n  TPWrite \"r=\" \\Num:=r;";
    assert_eq!(lines(LIST, body, &["Large"]), ["n=3", "r=1"]);
    assert_eq!(lines(LIST, body, &["1;exit"]), ["n=1", "r=2"]);
    assert_eq!(lines(LIST, body, &["1;2"]), ["n=1", "r=2"]);
}

#[test]
fn ui_list_view_without_answer() {
    let body = "  VAR num n := 7;\n  VAR btnres r := 7;\n  VAR errnum e;\n  n := UIListView(\\Result:=r, items \\BreakFlag:=e);\n  IF e = ERR_TP_NO_CLIENT TPWrite \"no client\";\n  TPWrite \"n=\" \\Num:=n;\n  TPWrite \"r=\" \\Num:=r;";
    assert_eq!(lines(LIST, body, &[]), ["no client", "n=0", "r=0"]);
    assert_eq!(fails(LIST, "  TPWrite \"\" \\Num:=UIListView(items \\MaxTime:=3);", &[]), "ERR_TP_MAXTIME");
}

#[test]
fn ui_num_tune_takes_the_final_value() {
    let body = "  VAR num v;\n  v := UINumTune(\\Header:=\"Speed\" \\Message:=\"Tune\", 100, 10 \\MinValue:=50 \\MaxValue:=150);\n  TPWrite \"v=\" \\Num:=v;";
    assert_eq!(lines("", body, &["120"]), ["v=120"]);
    assert_eq!(lines("", body, &[" 50 "]), ["v=50"]);
    assert_eq!(lines("", body, &["+150"]), ["v=150"]);
    for bad in ["160", "40", "fast", "-100"] {
        assert_eq!(fails("", body, &[bad]), "ERR_ARGVALERR", "answer {bad:?}");
    }
    assert_eq!(fails("", body, &[]), "ERR_TP_NO_CLIENT");
    let negative = "  TPWrite \"\" \\Num:=UINumTune(\\Message:=\"T\", 0, 0.5);";
    assert_eq!(lines("", negative, &["-2.5"]), ["-2.5"]);
}

#[test]
fn ui_num_tune_break_flag_returns_init_value() {
    let body = "  VAR errnum e;\n  TPWrite \"\" \\Num:=UINumTune(\\Message:=\"T\", 7, 1 \\MaxTime:=1 \\BreakFlag:=e);\n  IF e = ERR_TP_MAXTIME TPWrite \"timeout\";";
    assert_eq!(lines("", body, &[]), ["7", "timeout"]);
}

#[test]
fn ui_num_tune_checks_its_limits_before_asking() {
    // ABB raises ERR_UI_INITVALUE / ERR_UI_MAXMIN; until the interpreter knows their
    // numbers they are ERR_ARGVALERR.
    let init_outside = "  TPWrite \"\" \\Num:=UINumTune(\\Message:=\"T\", 200, 1 \\MaxValue:=150);";
    assert!(["ERR_UI_INITVALUE", "ERR_ARGVALERR"].contains(&fails("", init_outside, &["100"]).as_str()));
    let max_min = "  TPWrite \"\" \\Num:=UINumTune(\\Message:=\"T\", 5, 1 \\MinValue:=10 \\MaxValue:=1);";
    assert!(["ERR_UI_MAXMIN", "ERR_ARGVALERR"].contains(&fails("", max_min, &["5"]).as_str()));
}

#[test]
fn ui_dnum_tune_keeps_dnum_precision() {
    let body = "  VAR dnum d;\n  d := UIDnumTune(\\Message:=\"T\", 4000000000, 1 \\MinValue:=0 \\MaxValue:=5000000000);\n  IF d = 4000000001 TPWrite \"exact\";\n  d := UIDnumTune(\\Message:=\"T\", 1, 1 \\MaxValue:=3);";
    assert_eq!(lines("", body, &["4000000001", "3"]), ["exact"]);
    assert_eq!(fails("", body, &["4000000001", "4"]), "ERR_ARGVALERR");
}

#[test]
fn ui_num_entry_as_integer_and_dnum_precision() {
    let body = "  TPWrite \"\" \\Num:=UINumEntry(\\Message:=\"n\" \\MinValue:=1 \\MaxValue:=10 \\AsInteger);";
    assert_eq!(lines("", body, &["4"]), ["4"]);
    assert_eq!(fails("", body, &["4.5"]), "ERR_ARGVALERR");
    assert_eq!(fails("", body, &["11"]), "ERR_ARGVALERR");
    let dnum = "  VAR dnum d;\n  d := UIDnumEntry(\\Message:=\"d\");\n  IF d = 4000000001 TPWrite \"exact\";";
    assert_eq!(lines("", dnum, &["4000000001"]), ["exact"]);
}

#[test]
fn ui_entries_honour_break_flag() {
    let body = "  VAR errnum e;\n  TPWrite \"\" \\Num:=UINumEntry(\\MsgArray:=[\"a\", \"b\"] \\InitValue:=3 \\BreakFlag:=e);\n  IF e = ERR_TP_NO_CLIENT TPWrite \"no client\";\n  TPWrite UIAlphaEntry(\\Message:=\"name\" \\InitString:=\"abc\" \\MaxTime:=2 \\BreakFlag:=e);\n  IF e = ERR_TP_MAXTIME TPWrite \"timeout\";";
    assert_eq!(lines("", body, &[]), ["3", "no client", "abc", "timeout"]);
}

#[test]
fn tp_read_fk_still_takes_numbers_and_key_texts() {
    let body =
        "  VAR num k;\n  TPReadFK k, \"Which?\", \"Go\", \"\", \"Stop\", stEmpty, stEmpty;\n  TPWrite \"k=\" \\Num:=k;";
    assert_eq!(lines("", body, &["stop"]), ["k=3"]);
    assert_eq!(lines("", body, &["1"]), ["k=1"]);
    assert_eq!(fails("", body, &["2"]), "ERR_ARGVALERR");
}

#[test]
fn answers_go_into_persistents() {
    // ABB's syntax: TPAnswer and \Result are "var or pers (INOUT)"; a PERS takes the answer.
    let decls = format!("{LIST}\nPERS num nAnswer := 0;\nPERS dnum dAnswer := 0;\nPERS btnres rAnswer := 0;");
    let body = "  TPReadNum nAnswer, \"n?\";\n  TPWrite \"num \" \\Num:=nAnswer;\n  TPReadDnum dAnswer, \"d?\";\n  TPWrite \"dnum \" \\Dnum:=dAnswer;\n  TPReadFK nAnswer, \"k?\", \"Go\", \"Stop\", stEmpty, stEmpty, stEmpty;\n  TPWrite \"key \" \\Num:=nAnswer;\n  UIMsgBox \"?\" \\Buttons:=btnOKCancel \\Result:=rAnswer;\n  TPWrite \"box \" \\Num:=rAnswer;\n  TPWrite \"item \" \\Num:=UIListView(\\Result:=rAnswer, items \\Buttons:=btnYesNo);\n  TPWrite \"list \" \\Num:=rAnswer;";
    let answers = ["12", "4000000001", "stop", "cancel", "3;No"];
    let expected = ["num 12", "dnum 4000000001", "key 2", "box 5", "item 3", "list 7"];
    assert_eq!(lines(&decls, body, &answers), expected);
}
