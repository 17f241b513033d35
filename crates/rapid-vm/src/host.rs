//! The world outside the interpreter: the teach pendant (and, later, files, sockets
//! and I/O), behind a trait so tests and the server provide their own.

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
}

/// A host that records pendant lines (for tests).
#[derive(Debug, Default)]
pub struct RecordingHost {
    pub lines: Vec<String>,
    /// Answers handed out in order.
    pub answers: std::collections::VecDeque<String>,
    /// The windows TPShow brought to the front, in order.
    pub shown: Vec<i32>,
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
}
