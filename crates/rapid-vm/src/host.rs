//! The teach pendant, behind a trait so tests and the server provide their own. The
//! rest of the outside world (files, sockets, clocks) is the task's [`crate::world`].

/// What the program's pendant instructions reach.
pub trait Host {
    /// One line on the pendant's display (TPWrite, ErrWrite).
    fn tp_write(&mut self, line: &str);
    /// TPErase.
    fn tp_erase(&mut self) {}
    /// TPShow: bring pendant window `window` (a tpnum value) to the front. A pendant
    /// with one window (stdout) has nothing to switch.
    fn tp_show(&mut self, _window: i32) {}
    /// The operator's next answer to a pendant dialog (TPReadNum, TPReadFK, UI...),
    /// or `None` when no operator answers.
    fn tp_answer(&mut self, _prompt: &str) -> Option<String> {
        None
    }
    /// A dialog of task `prompt.task` waits for the operator: the answer now, or
    /// [`PromptReply::Pending`] when a front end will answer later (the task waits and
    /// asks again; the caller's thread is never blocked). By default the answer of
    /// [`Host::tp_answer`], and no client when there is none.
    fn tp_prompt(&mut self, prompt: &Prompt<'_>) -> PromptReply {
        match self.tp_answer(prompt.text) {
            Some(text) => PromptReply::Answer(text),
            None => PromptReply::NoClient,
        }
    }
    /// A dialog left [`PromptReply::Pending`] gave up waiting (`\MaxTime` ran out).
    fn tp_prompt_closed(&mut self, _prompt: &Prompt<'_>) {}
    /// A line about the run for its user, not the pendant's (how the virtual controller
    /// stands in for the real one); `rapid run` writes it on stderr.
    fn note(&mut self, _text: &str) {}
    /// A wait with `\Visualize` (WaitUntil, WaitDI…) shows a message box while it
    /// waits; the box takes no answer, the wait ends as it would without it.
    fn visualize_open(&mut self, _prompt: &Prompt<'_>) {}
    /// The box of [`Host::visualize_open`] closes: the wait ended, or `\VisualizeTime`
    /// ran out while it goes on.
    fn visualize_close(&mut self, _prompt: &Prompt<'_>) {}
}

/// A pendant dialog waiting for the operator (TPReadNum, TPReadFK, UI...).
#[derive(Debug, Clone, Copy)]
pub struct Prompt<'a> {
    /// The task that shows it.
    pub task: &'a str,
    /// What the dialog shows.
    pub text: &'a str,
}

/// What the pendant says to a dialog.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PromptReply {
    /// The operator's answer.
    Answer(String),
    /// Shown; no answer yet: the dialog waits (with `\MaxTime` at most that long).
    Pending,
    /// No pendant is connected (ERR_TP_NO_CLIENT, or ERR_TP_MAXTIME with `\MaxTime`).
    NoClient,
}

/// A host that records pendant lines (for tests).
#[derive(Debug, Default)]
pub struct RecordingHost {
    pub lines: Vec<String>,
    /// Answers handed out in order.
    pub answers: std::collections::VecDeque<String>,
    /// The windows TPShow brought to the front, in order.
    pub shown: Vec<i32>,
    /// The message boxes of waits with `\Visualize`: (text, opened) as they opened
    /// (`true`) and closed (`false`), in order.
    pub boxes: Vec<(String, bool)>,
    /// The notes about the run, in order.
    pub notes: Vec<String>,
}

impl Host for RecordingHost {
    fn tp_write(&mut self, line: &str) {
        self.lines.push(line.to_string());
    }

    fn tp_answer(&mut self, _prompt: &str) -> Option<String> {
        self.answers.pop_front()
    }

    fn tp_show(&mut self, window: i32) {
        self.shown.push(window);
    }

    fn note(&mut self, text: &str) {
        self.notes.push(text.to_string());
    }

    fn visualize_open(&mut self, prompt: &Prompt<'_>) {
        self.boxes.push((prompt.text.to_string(), true));
    }

    fn visualize_close(&mut self, prompt: &Prompt<'_>) {
        self.boxes.push((prompt.text.to_string(), false));
    }
}
