//! Pendant dialogs that wait for the operator: TPReadNum, TPReadDnum, TPReadFK,
//! UINumEntry, UIDnumEntry, UIAlphaEntry, UINumTune, UIDnumTune, UIMsgBox,
//! UIMessageBox, UIListView, UIClientExist. Answers come from the host
//! (`rapid run --tp-input FILE`, one line per dialog); with none left, the dialog fails
//! as it does when no pendant is connected (ERR_TP_NO_CLIENT), or with \MaxTime as a
//! timeout (ERR_TP_MAXTIME). With \BreakFlag the error number is stored there instead
//! and the dialog returns what it shows by default (see each function).
//!
//! Answers are read leniently: surrounding blanks are ignored and texts (button names,
//! list items, function keys) match in any letter case. An answer that fits nothing
//! the dialog offers raises ERR_ARGVALERR: on a real pendant the operator cannot give
//! it, so it is a mistake in the answers file.

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// The built-ins this family runs (see `registry.rs`).
pub(super) static FAMILY: super::Family = super::Family {
    file: file!(),
    builtins: &[
        super::native("TPReadNum", tp_read_num),
        super::native("TPReadDnum", tp_read_num),
        super::native("TPReadFK", tp_read_fk),
        super::native("UINumEntry", ui_num_entry),
        super::native("UIDnumEntry", ui_dnum_entry),
        super::native("UIAlphaEntry", ui_alpha_entry),
        super::native("UIClientExist", ui_client_exist),
        super::native("UIMsgBox", ui_msg_box),
        super::native("UIMessageBox", ui_message_box),
        super::native("UIListView", ui_list_view),
        super::native("UINumTune", ui_num_tune),
        super::native("UIDnumTune", ui_dnum_tune),
    ],
};

#[cfg(test)]
#[path = "dialogs_tests.rs"]
mod dialogs_tests;

type Res = Result<Option<Value>, RapidError>;

// Parameter positions in the catalogue's signatures (rapid-lib catalogue/system.rs).
// Every parameter has its own position, each alternative of a `|` group included.

// TPReadNum / TPReadDnum (INOUT TPAnswer, TPText \MaxTime \DIBreak \DIPassive \DOBreak
// \DOPassive \PersBoolBreak \PersBoolPassive \BreakFlag).
const READ_NUM_MAX_TIME: usize = 2;
const READ_NUM_BREAK_FLAG: usize = 9;
// TPReadFK (INOUT TPAnswer, TPText, TPFK1..TPFK5 \MaxTime ... \BreakFlag).
const READ_FK_KEYS: std::ops::Range<usize> = 2..7;
const READ_FK_MAX_TIME: usize = 7;
const READ_FK_BREAK_FLAG: usize = 14;

// The UI functions start alike: \Header (0), \Message (1) | MsgArray (2), \Wrap (3),
// \Icon (4); UIMsgBox and UIListView differ (below).
const UI_HEADER: usize = 0;
const UI_MESSAGE: usize = 1;
const UI_MSG_ARRAY: usize = 2;

// UINumEntry / UIDnumEntry (... \Icon (4) \InitValue \MinValue \MaxValue \AsInteger
// \MaxTime \DIBreak \DIPassive \DOBreak \DOPassive \PersBoolBreak \PersBoolPassive
// \BreakFlag \UIActiveSignal).
const NUM_ENTRY_INIT: usize = 5;
const NUM_ENTRY_MIN: usize = 6;
const NUM_ENTRY_MAX: usize = 7;
const NUM_ENTRY_AS_INTEGER: usize = 8;
const NUM_ENTRY_MAX_TIME: usize = 9;
const NUM_ENTRY_BREAK_FLAG: usize = 16;

// UIAlphaEntry (... \Icon (4) \InitString \MaxTime \DIBreak \DIPassive \DOBreak
// \DOPassive \PersBoolBreak \PersBoolPassive \BreakFlag \UIActiveSignal).
const ALPHA_ENTRY_INIT: usize = 5;
const ALPHA_ENTRY_MAX_TIME: usize = 6;
const ALPHA_ENTRY_BREAK_FLAG: usize = 13;

// UINumTune / UIDnumTune (... \Icon (4), InitValue, Increment \MinValue \MaxValue
// \MaxTime \DIBreak \DIPassive \DOBreak \DOPassive \PersBoolBreak \PersBoolPassive
// \BreakFlag \UIActiveSignal).
const TUNE_INIT: usize = 5;
const TUNE_MIN: usize = 7;
const TUNE_MAX: usize = 8;
const TUNE_MAX_TIME: usize = 9;
const TUNE_BREAK_FLAG: usize = 16;

// UIMsgBox (\Header, MsgLine1 \MsgLine2 \MsgLine3 \MsgLine4 \MsgLine5 \Wrap \Buttons
// \Icon \Image \INOUT Result \MaxTime \DIBreak \DIPassive \DOBreak \DOPassive
// \PersBoolBreak \PersBoolPassive \BreakFlag \UIActiveSignal).
const MSG_BOX_HEADER: usize = 0;
const MSG_BOX_LINES: std::ops::Range<usize> = 1..6;
const MSG_BOX_BUTTONS: usize = 7;
const MSG_BOX_RESULT: usize = 10;
const MSG_BOX_MAX_TIME: usize = 11;
const MSG_BOX_BREAK_FLAG: usize = 18;

// UIMessageBox (\Header \Message | MsgArray \Wrap \Buttons | BtnArray \DefaultBtn
// \Icon \Image \MaxTime \DIBreak \DIPassive \DOBreak \DOPassive \PersBoolBreak
// \PersBoolPassive \BreakFlag \UIActiveSignal).
const MESSAGE_BOX_BUTTONS: usize = 4;
const MESSAGE_BOX_BTN_ARRAY: usize = 5;
const MESSAGE_BOX_DEFAULT_BTN: usize = 6;
const MESSAGE_BOX_MAX_TIME: usize = 9;
const MESSAGE_BOX_BREAK_FLAG: usize = 16;

// UIListView (\INOUT Result \Header, ListItems \Buttons | BtnArray \Icon \DefaultIndex
// \MaxTime \DIBreak \DIPassive \DOBreak \DOPassive \PersBoolBreak \PersBoolPassive
// \BreakFlag \UIActiveSignal).
const LIST_RESULT: usize = 0;
const LIST_HEADER: usize = 1;
const LIST_ITEMS: usize = 2;
const LIST_BUTTONS: usize = 3;
const LIST_BTN_ARRAY: usize = 4;
const LIST_DEFAULT_INDEX: usize = 6;
const LIST_MAX_TIME: usize = 7;
const LIST_BREAK_FLAG: usize = 14;

/// The field of `listitem` (`RECORD listitem string image; string text; ENDRECORD`)
/// that holds the text shown.
const LISTITEM_TEXT: usize = 1;

// btnres values, as catalogue/data.rs declares them (resUnkwn .. resNo).
const RES_UNKWN: i32 = 0;
const RES_OK: i32 = 1;
const RES_ABORT: i32 = 2;
const RES_RETRY: i32 = 3;
const RES_IGNORE: i32 = 4;
const RES_CANCEL: i32 = 5;
const RES_YES: i32 = 6;
const RES_NO: i32 = 7;

/// The text on each standard button, by its btnres value.
const BUTTON_NAMES: [(i32, &str); 7] = [
    (RES_OK, "OK"),
    (RES_ABORT, "Abort"),
    (RES_RETRY, "Retry"),
    (RES_IGNORE, "Ignore"),
    (RES_CANCEL, "Cancel"),
    (RES_YES, "Yes"),
    (RES_NO, "No"),
];

/// The buttons of a buttondata value (btnNone -1, btnOK 0, btnAbrtRtryIgn 1,
/// btnOKCancel 2, btnRetryCancel 3, btnYesNo 4, btnYesNoCancel 5, as catalogue/data.rs
/// declares them), or `None` for a value that is none of these.
fn standard_buttons(buttondata: f64) -> Option<&'static [i32]> {
    if buttondata.fract() != 0.0 {
        return None;
    }
    Some(match buttondata as i64 {
        -1 => &[],
        0 => &[RES_OK],
        1 => &[RES_ABORT, RES_RETRY, RES_IGNORE],
        2 => &[RES_OK, RES_CANCEL],
        3 => &[RES_RETRY, RES_CANCEL],
        4 => &[RES_YES, RES_NO],
        5 => &[RES_YES, RES_NO, RES_CANCEL],
        _ => return None,
    })
}

/// The push buttons of a dialog: a standard set (results are btnres values) or the
/// texts of \BtnArray (results are array indexes; empty texts are not shown).
enum Buttons {
    Standard(&'static [i32]),
    Own(Vec<String>),
}

impl Buttons {
    /// Whether the operator has a button to press at all.
    fn any(&self) -> bool {
        match self {
            Buttons::Standard(set) => !set.is_empty(),
            Buttons::Own(texts) => texts.iter().any(|t| !t.is_empty()),
        }
    }

    /// The button an answer names: for standard buttons its text ("OK", "Cancel",
    /// also "resCancel") or btnres value; for own buttons its index (1..n) or text.
    fn parse(&self, text: &str) -> Option<i32> {
        let text = text.trim();
        match self {
            Buttons::Standard(set) => {
                if let Ok(n) = text.parse::<i32>() {
                    return set.contains(&n).then_some(n);
                }
                let name = match text.get(..3) {
                    Some(prefix) if prefix.eq_ignore_ascii_case("res") => &text[3..],
                    _ => text,
                };
                BUTTON_NAMES
                    .iter()
                    .find(|(res, shown)| set.contains(res) && shown.eq_ignore_ascii_case(name))
                    .map(|(res, _)| *res)
            }
            Buttons::Own(texts) => pick(texts, text),
        }
    }

    /// The button taken when an answer only picks a list item: OK when there is one,
    /// else the first button shown.
    fn first(&self) -> i32 {
        match self {
            Buttons::Standard(set) if set.contains(&RES_OK) => RES_OK,
            Buttons::Standard(set) => set.first().copied().unwrap_or(RES_UNKWN),
            Buttons::Own(texts) => texts.iter().position(|t| !t.is_empty()).map_or(RES_UNKWN, |i| i as i32 + 1),
        }
    }

    fn describe(&self) -> String {
        match self {
            Buttons::Standard(set) => {
                let names: Vec<&str> =
                    set.iter().filter_map(|r| BUTTON_NAMES.iter().find(|(res, _)| res == r)).map(|(_, n)| *n).collect();
                names.join(", ")
            }
            Buttons::Own(texts) => {
                let shown: Vec<&str> = texts.iter().filter(|t| !t.is_empty()).map(String::as_str).collect();
                shown.join(", ")
            }
        }
    }
}

/// The choice an answer makes among `texts` (shown when not empty): its number
/// 1..n, or its text in any letter case.
fn pick(texts: &[String], text: &str) -> Option<i32> {
    let text = text.trim();
    if let Ok(n) = text.parse::<usize>() {
        return (1..=texts.len()).contains(&n).then_some(n).filter(|&n| !texts[n - 1].is_empty()).map(|n| n as i32);
    }
    texts.iter().position(|t| !t.is_empty() && t.trim().eq_ignore_ascii_case(text)).map(|i| i as i32 + 1)
}

/// What a dialog does when no answer comes: the error (ERR_TP_MAXTIME with \MaxTime,
/// else ERR_TP_NO_CLIENT), or `Ok(())` when \BreakFlag took its number.
fn no_answer(ctx: &mut Ctx<'_>, max_time: Option<&Value>, break_flag: Option<&Value>) -> Result<(), RapidError> {
    let err = if present(max_time) { Err::TpMaxTime } else { Err::TpNoClient };
    let error = ctx.error(err, "no operator answered the pendant dialog (see --tp-input)");
    match break_flag.filter(|f| present(Some(f))) {
        Some(flag) => ctx.store(flag, Value::Num(error.errno as f32)),
        None => Err(error),
    }
}

/// The next answer, or the error (stored in \BreakFlag when given) of a dialog that
/// gets none.
fn answer(
    ctx: &mut Ctx<'_>,
    prompt: &str,
    max_time: Option<&Value>,
    break_flag: Option<&Value>,
) -> Result<Option<String>, RapidError> {
    // The operator's timed answers (a stimulus) come first: a dialog shown before the
    // answer's time waits for it (re-run when the time comes).
    if let Some(&(at, _)) = ctx.resources.answers.front() {
        if at > ctx.time {
            ctx.wait = Some(at - ctx.time);
            ctx.stop = super::StopKind::Repeat;
            return Ok(None);
        }
        let text = ctx.resources.answers.pop_front().map(|(_, text)| text).unwrap_or_default();
        return Ok(Some(text.trim().to_string()));
    }
    let task = ctx.resources.tasks.me.clone();
    match ctx.host.tp_prompt(&crate::host::Prompt { task: &task, text: prompt }) {
        crate::host::PromptReply::Answer(text) => {
            ctx.resources.waiting = None;
            return Ok(Some(text.trim().to_string()));
        }
        crate::host::PromptReply::Pending => {
            // A front end answers later: the dialog waits (as a WaitDI does, re-run
            // when the shared state changes) until the answer or \MaxTime.
            let started = super::wait::wait_started(ctx);
            let deadline = ctx.opt_num(max_time)?.map(|max| started + max);
            if !deadline.is_some_and(|d| ctx.time >= d) {
                super::wait::wait_again(ctx, started, deadline, None);
                return Ok(None);
            }
            ctx.resources.waiting = None;
            ctx.host.tp_prompt_closed(&crate::host::Prompt { task: &task, text: prompt });
        }
        crate::host::PromptReply::NoClient => {}
    }
    no_answer(ctx, max_time, break_flag)?;
    Ok(None)
}

fn parse_num(ctx: &Ctx<'_>, text: &str) -> Result<f64, RapidError> {
    let (negative, body) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text.strip_prefix('+').unwrap_or(text)),
    };
    match rapid_syntax::literal::num_value(body.trim_start()) {
        Some(v) => Ok(if negative { -v } else { v }),
        None => Err(ctx.error(Err::ArgValue, format!("the operator's answer `{text}` is not a number"))),
    }
}

/// The error a UI dialog raises for bad arguments: the predefined `name`
/// (ERR_UI_MAXMIN, ERR_UI_INITVALUE, ERR_UI_NOTINT) when the interpreter knows its
/// number, else ERR_ARGVALERR.
fn ui_error(ctx: &Ctx<'_>, name: &'static str, message: String) -> RapidError {
    match ctx.errnos.get(name) {
        Some(&errno) => RapidError { errno, name, message, fatal: false, event: None },
        None => ctx.error(Err::ArgValue, message),
    }
}

/// An optional string argument, empty when absent.
fn opt_string(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<String, RapidError> {
    match arg {
        Some(v) if present(Some(v)) => ctx.string(v),
        _ => Ok(String::new()),
    }
}

/// The strings of an array argument (MsgArray, BtnArray).
fn strings(ctx: &Ctx<'_>, arg: &Value) -> Result<Vec<String>, RapidError> {
    match ctx.value(arg)? {
        Value::Array(array) => array.elems.iter().map(|e| ctx.string(e)).collect(),
        _ => Err(ctx.error(Err::ArgValue, "an array of strings was expected")),
    }
}

/// What a UI dialog shows, as one prompt for the host: \Header, then \Message or the
/// lines of MsgArray.
fn ui_prompt(ctx: &Ctx<'_>, args: &[Value]) -> Result<String, RapidError> {
    let mut lines = Vec::new();
    let header = opt_string(ctx, args.get(UI_HEADER))?;
    if !header.is_empty() {
        lines.push(header);
    }
    match (args.get(UI_MESSAGE), args.get(UI_MSG_ARRAY)) {
        (Some(message), _) if present(Some(message)) => lines.push(ctx.string(message)?),
        (_, Some(array)) if present(Some(array)) => lines.extend(strings(ctx, array)?),
        _ => {}
    }
    Ok(lines.join("\n"))
}

/// The buttons of a dialog with \Buttons and maybe \BtnArray; without either ABB
/// shows a single OK button.
fn dialog_buttons(ctx: &Ctx<'_>, buttons: Option<&Value>, btn_array: Option<&Value>) -> Result<Buttons, RapidError> {
    if let Some(array) = btn_array.filter(|a| present(Some(a))) {
        return Ok(Buttons::Own(strings(ctx, array)?));
    }
    match ctx.opt_num(buttons)? {
        None => Ok(Buttons::Standard(&[RES_OK])),
        Some(data) => match standard_buttons(data) {
            Some(set) => Ok(Buttons::Standard(set)),
            None => Err(ctx.error(Err::ArgValue, format!("{data} is not a buttondata value"))),
        },
    }
}

/// Stores `value` in an optional VAR argument when it was passed.
fn store_opt(ctx: &mut Ctx<'_>, arg: Option<&Value>, value: Value) -> Result<(), RapidError> {
    match arg {
        Some(place) if present(Some(place)) => ctx.store(place, value),
        _ => Ok(()),
    }
}

/// `TPReadNum TPAnswer, TPText [\MaxTime] ... [\BreakFlag]` (and TPReadDnum).
pub(super) fn tp_read_num(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = ctx.string(&args[1])?;
    if let Some(text) = answer(ctx, &prompt, args.get(READ_NUM_MAX_TIME), args.get(READ_NUM_BREAK_FLAG))? {
        let value = parse_num(ctx, &text)?;
        ctx.store(&args[0], Value::Dnum(value))?;
    }
    Ok(None)
}

/// `TPReadFK TPAnswer, TPText, FK1, ..., FK5 ...`: the answer is the key number 1..5
/// or the text of a key.
pub(super) fn tp_read_fk(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = ctx.string(&args[1])?;
    let Some(text) = answer(ctx, &prompt, args.get(READ_FK_MAX_TIME), args.get(READ_FK_BREAK_FLAG))? else {
        return Ok(None);
    };
    let mut keys = Vec::new();
    for idx in READ_FK_KEYS {
        keys.push(ctx.string(&args[idx])?);
    }
    let Some(key) = pick(&keys, &text) else {
        return Err(ctx.error(Err::ArgValue, format!("`{text}` is none of the function keys")));
    };
    ctx.store(&args[0], Value::Num(key as f32))?;
    Ok(None)
}

/// Checks \MinValue, \MaxValue and the initial value of a number dialog (ABB:
/// ERR_UI_MAXMIN, ERR_UI_INITVALUE) and returns the limits.
fn checked_limits(
    ctx: &Ctx<'_>,
    init: Option<f64>,
    min: Option<&Value>,
    max: Option<&Value>,
) -> Result<(Option<f64>, Option<f64>), RapidError> {
    let (min, max) = (ctx.opt_num(min)?, ctx.opt_num(max)?);
    if let (Some(lo), Some(hi)) = (min, max) {
        if lo > hi {
            return Err(ui_error(ctx, "ERR_UI_MAXMIN", format!("\\MinValue {lo} is larger than \\MaxValue {hi}")));
        }
    }
    if let Some(init) = init {
        if min.is_some_and(|m| init < m) || max.is_some_and(|m| init > m) {
            return Err(ui_error(ctx, "ERR_UI_INITVALUE", format!("the initial value {init} is outside the range")));
        }
    }
    Ok((min, max))
}

/// The operator's number, checked against the limits.
fn ranged_answer(ctx: &Ctx<'_>, text: &str, min: Option<f64>, max: Option<f64>) -> Result<f64, RapidError> {
    let value = parse_num(ctx, text)?;
    if min.is_some_and(|m| value < m) || max.is_some_and(|m| value > m) {
        return Err(ctx.error(Err::ArgValue, format!("the operator's answer {value} is outside the allowed range")));
    }
    Ok(value)
}

/// UINumEntry and UIDnumEntry: the number entered. With \BreakFlag and no answer,
/// \InitValue (or 0).
fn num_entry(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<f64, RapidError> {
    let prompt = ui_prompt(ctx, args)?;
    let init = ctx.opt_num(args.get(NUM_ENTRY_INIT))?;
    let as_integer = present(args.get(NUM_ENTRY_AS_INTEGER));
    let (min, max) = checked_limits(ctx, init, args.get(NUM_ENTRY_MIN), args.get(NUM_ENTRY_MAX))?;
    if as_integer && init.is_some_and(|v| v.fract() != 0.0) {
        return Err(ui_error(ctx, "ERR_UI_NOTINT", "\\InitValue is not an integer but \\AsInteger is used".into()));
    }
    let Some(text) = answer(ctx, &prompt, args.get(NUM_ENTRY_MAX_TIME), args.get(NUM_ENTRY_BREAK_FLAG))? else {
        return Ok(init.unwrap_or(0.0));
    };
    let value = ranged_answer(ctx, &text, min, max)?;
    if as_integer && value.fract() != 0.0 {
        return Err(ctx.error(Err::ArgValue, format!("the operator's answer {value} is not an integer (\\AsInteger)")));
    }
    Ok(value)
}

/// `UINumEntry(...)`: the operator's number, checked against \MinValue and \MaxValue.
pub(super) fn ui_num_entry(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(Some(Value::Num(num_entry(ctx, args)? as f32)))
}

/// `UIDnumEntry(...)`: [`ui_num_entry`] giving a dnum.
pub(super) fn ui_dnum_entry(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(Some(Value::Dnum(num_entry(ctx, args)?)))
}

/// UINumTune and UIDnumTune: the operator steps InitValue by Increment and accepts;
/// the answer is the final number (not checked to lie on the Increment grid), within
/// \MinValue and \MaxValue. With \BreakFlag and no answer, InitValue.
fn num_tune(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<f64, RapidError> {
    let prompt = ui_prompt(ctx, args)?;
    let init = ctx.num(&args[TUNE_INIT])?;
    let (min, max) = checked_limits(ctx, Some(init), args.get(TUNE_MIN), args.get(TUNE_MAX))?;
    match answer(ctx, &prompt, args.get(TUNE_MAX_TIME), args.get(TUNE_BREAK_FLAG))? {
        Some(text) => ranged_answer(ctx, &text, min, max),
        None => Ok(init),
    }
}

/// `UINumTune(... InitValue, Increment ...)`: the tuned num.
pub(super) fn ui_num_tune(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(Some(Value::Num(num_tune(ctx, args)? as f32)))
}

/// `UIDnumTune(... InitValue, Increment ...)`: the tuned dnum.
pub(super) fn ui_dnum_tune(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    Ok(Some(Value::Dnum(num_tune(ctx, args)?)))
}

/// `UIAlphaEntry(...)`: the operator's text. With \BreakFlag and no answer,
/// \InitString (or "").
pub(super) fn ui_alpha_entry(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = ui_prompt(ctx, args)?;
    let Some(text) = answer(ctx, &prompt, args.get(ALPHA_ENTRY_MAX_TIME), args.get(ALPHA_ENTRY_BREAK_FLAG))? else {
        let init = opt_string(ctx, args.get(ALPHA_ENTRY_INIT))?;
        return Ok(Some(Value::Str(init.into())));
    };
    if text.chars().count() > crate::value::MAX_STRING_CHARS {
        return Err(ctx.error(Err::StringTooLong, "the operator's answer is longer than 80 characters"));
    }
    Ok(Some(Value::Str(text.into())))
}

/// The button the operator pressed in a message box, or `None` when \BreakFlag took
/// the error of a dialog without answer. Without buttons (btnNone) nobody can answer:
/// no answer is used and the dialog ends as without answer.
fn press_button(
    ctx: &mut Ctx<'_>,
    prompt: &str,
    buttons: &Buttons,
    max_time: Option<&Value>,
    break_flag: Option<&Value>,
) -> Result<Option<i32>, RapidError> {
    if !buttons.any() {
        no_answer(ctx, max_time, break_flag)?;
        return Ok(None);
    }
    let Some(text) = answer(ctx, prompt, max_time, break_flag)? else { return Ok(None) };
    match buttons.parse(&text) {
        Some(button) => Ok(Some(button)),
        None => Err(ctx.error(
            Err::ArgValue,
            format!("the operator's answer `{text}` is none of the buttons ({})", buttons.describe()),
        )),
    }
}

/// `UIMsgBox [\Header], MsgLine1 [\MsgLine2] ... [\Buttons] ... [\Result] ...`: the
/// answer is a button of \Buttons (default: OK alone), stored in \Result. With
/// \BreakFlag and no answer, \Result gets resUnkwn.
pub(super) fn ui_msg_box(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let mut lines = Vec::new();
    for idx in std::iter::once(MSG_BOX_HEADER).chain(MSG_BOX_LINES) {
        let line = opt_string(ctx, args.get(idx))?;
        if !line.is_empty() || idx == MSG_BOX_LINES.start {
            lines.push(line);
        }
    }
    let buttons = dialog_buttons(ctx, args.get(MSG_BOX_BUTTONS), None)?;
    let pressed =
        press_button(ctx, &lines.join("\n"), &buttons, args.get(MSG_BOX_MAX_TIME), args.get(MSG_BOX_BREAK_FLAG))?;
    store_opt(ctx, args.get(MSG_BOX_RESULT), Value::Num(pressed.unwrap_or(RES_UNKWN) as f32))?;
    Ok(None)
}

/// `UIMessageBox(...)`: the button pressed: its btnres value, or with \BtnArray its
/// index in the array (ABB: "the array index is returned"). The default is one OK
/// button. With \BreakFlag and no answer, \DefaultBtn (or resUnkwn).
pub(super) fn ui_message_box(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let prompt = ui_prompt(ctx, args)?;
    let buttons = dialog_buttons(ctx, args.get(MESSAGE_BOX_BUTTONS), args.get(MESSAGE_BOX_BTN_ARRAY))?;
    let default = ctx.opt_num(args.get(MESSAGE_BOX_DEFAULT_BTN))?.unwrap_or(f64::from(RES_UNKWN));
    let pressed =
        press_button(ctx, &prompt, &buttons, args.get(MESSAGE_BOX_MAX_TIME), args.get(MESSAGE_BOX_BREAK_FLAG))?;
    Ok(Some(Value::Num(pressed.map_or(default as f32, |b| b as f32))))
}

/// `UIListView([\Result] [\Header,] ListItems [\Buttons | \BtnArray] ...)`: the index
/// of the item chosen. The answer is the item's number (1..n) or text; with buttons it
/// may name the button after a `;` (`2;Cancel`, `;Cancel` keeping \DefaultIndex), else
/// the button is OK (or the first one shown). \Result gets the button (its btnres
/// value, or its \BtnArray index); without buttons the list is a menu and \Result gets
/// resOK. With \BreakFlag and no answer the result is 0 and \Result resUnkwn.
pub(super) fn ui_list_view(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let header = opt_string(ctx, args.get(LIST_HEADER))?;
    let items: Vec<String> = match ctx.value(&args[LIST_ITEMS])? {
        Value::Array(array) => array
            .elems
            .iter()
            .map(|item| match item {
                Value::Record(record) => record.fields.get(LISTITEM_TEXT).map_or(Ok(String::new()), |t| ctx.string(t)),
                _ => Err(ctx.error(Err::ArgValue, "ListItems must be listitem data")),
            })
            .collect::<Result<_, _>>()?,
        _ => return Err(ctx.error(Err::ArgValue, "ListItems must be an array of listitem")),
    };
    let buttons = match (args.get(LIST_BUTTONS), args.get(LIST_BTN_ARRAY)) {
        (b, a) if !present(b) && !present(a) => None,
        (b, a) => Some(dialog_buttons(ctx, b, a)?).filter(Buttons::any),
    };
    let default_index = ctx.opt_num(args.get(LIST_DEFAULT_INDEX))?;
    let prompt = std::iter::once(header).chain(items.iter().cloned()).collect::<Vec<_>>().join("\n");
    let Some(text) = answer(ctx, &prompt, args.get(LIST_MAX_TIME), args.get(LIST_BREAK_FLAG))? else {
        store_opt(ctx, args.get(LIST_RESULT), Value::Num(RES_UNKWN as f32))?;
        return Ok(Some(Value::Num(0.0)));
    };
    let bad = |ctx: &Ctx<'_>| {
        ctx.error(Err::ArgValue, format!("the operator's answer `{text}` is none of the list items (or buttons)"))
    };
    let (item, button) = match (pick(&items, &text), &buttons) {
        (Some(item), Some(buttons)) => (item, buttons.first()),
        (Some(item), None) => (item, RES_OK),
        (None, Some(buttons)) => {
            let Some((item_text, button_text)) = text.rsplit_once(';') else { return Err(bad(ctx)) };
            let item = match item_text.trim() {
                "" => default_index.map_or(0, |d| d as i32),
                named => pick(&items, named).ok_or_else(|| bad(ctx))?,
            };
            (item, buttons.parse(button_text).ok_or_else(|| bad(ctx))?)
        }
        (None, None) => return Err(bad(ctx)),
    };
    store_opt(ctx, args.get(LIST_RESULT), Value::Num(button as f32))?;
    Ok(Some(Value::Num(item as f32)))
}

/// `UIClientExist()`: a pendant is connected when the host can answer dialogs.
pub(super) fn ui_client_exist(_ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    // The virtual controller always has its (scripted) pendant.
    Ok(Some(Value::Bool(true)))
}
