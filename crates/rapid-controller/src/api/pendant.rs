//! The pendant a front end sees: what the program writes (TPWrite, ErrWrite, TPErase)
//! goes into the change stream, and a dialog waiting for the operator (TPReadNum,
//! TPReadFK, UINumEntry, UIMessageBox…) becomes a pending prompt the front end
//! answers through the API. The task waits meanwhile (as a WaitDI waits: other tasks
//! run, the clock moves); nothing blocks the caller's thread.

use rapid_vm::{Host, Prompt, PromptReply};

use super::stream::Change;

/// A pendant dialog waiting for the operator's answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PendingPrompt {
    /// The prompt's number, to answer it by.
    pub id: u64,
    /// The task whose dialog it is.
    pub task: String,
    /// What the dialog shows.
    pub text: String,
    /// The answer given, not yet taken by the dialog.
    answer: Option<String>,
}

/// Lines the pendant's screen keeps (a front end that connects late sees them).
const SCREEN_LINES: usize = 100;

/// The front end's pendant: the [`Host`] the controller's tasks run with.
#[derive(Debug, Default)]
pub(crate) struct Pendant {
    /// The newest lines written, oldest first, since the last TPErase.
    pub(crate) screen: std::collections::VecDeque<String>,
    prompts: Vec<PendingPrompt>,
    next_id: u64,
    /// What happened on the pendant since the API last took it, in order.
    pub(crate) changes: Vec<Change>,
    /// The message boxes of waits with `\Visualize` on the screen: (id, task, text).
    /// They are shown as prompts that take no answer.
    boxes: Vec<(u64, String, String)>,
}

impl Pendant {
    /// The dialogs waiting for an answer, oldest first.
    pub(crate) fn pending(&self) -> impl Iterator<Item = &PendingPrompt> {
        self.prompts.iter().filter(|p| p.answer.is_none())
    }

    /// Answers prompt `id`; false when no such prompt waits.
    pub(crate) fn answer(&mut self, id: u64, text: &str) -> bool {
        let Some(prompt) = self.prompts.iter_mut().find(|p| p.id == id && p.answer.is_none()) else { return false };
        prompt.answer = Some(text.to_owned());
        self.changes.push(Change::PromptAnswered { id, answer: text.to_owned() });
        true
    }

    /// Forgets the prompts of a task whose program pointer moved (its dialog is gone).
    pub(crate) fn drop_task(&mut self, task: &str) {
        let (gone, kept): (Vec<_>, Vec<_>) =
            std::mem::take(&mut self.prompts).into_iter().partition(|p| p.task == task);
        self.prompts = kept;
        self.changes.extend(gone.into_iter().map(|p| Change::PromptClosed { id: p.id }));
    }
}

impl Host for Pendant {
    fn tp_write(&mut self, line: &str) {
        if self.screen.len() == SCREEN_LINES {
            self.screen.pop_front();
        }
        self.screen.push_back(line.to_owned());
        self.changes.push(Change::TpWrite { text: line.to_owned() });
    }

    fn tp_erase(&mut self) {
        self.screen.clear();
        self.changes.push(Change::TpErase);
    }

    /// A dialog asks: the answer given for it, else it is shown (once) and waits.
    fn tp_prompt(&mut self, prompt: &Prompt<'_>) -> PromptReply {
        let same = |p: &PendingPrompt| p.task == prompt.task && p.text == prompt.text;
        if let Some(at) = self.prompts.iter().position(same) {
            if self.prompts[at].answer.is_none() {
                return PromptReply::Pending;
            }
            return PromptReply::Answer(self.prompts.remove(at).answer.unwrap_or_default());
        }
        self.next_id += 1;
        let id = self.next_id;
        let (task, text) = (prompt.task.to_owned(), prompt.text.to_owned());
        self.changes.push(Change::PromptOpened { id, task: task.clone(), text: text.clone() });
        self.prompts.push(PendingPrompt { id, task, text, answer: None });
        PromptReply::Pending
    }

    fn visualize_open(&mut self, prompt: &Prompt<'_>) {
        self.next_id += 1;
        let id = self.next_id;
        let (task, text) = (prompt.task.to_owned(), prompt.text.to_owned());
        self.changes.push(Change::PromptOpened { id, task: task.clone(), text: text.clone() });
        self.boxes.push((id, task, text));
    }

    fn visualize_close(&mut self, prompt: &Prompt<'_>) {
        if let Some(at) = self.boxes.iter().position(|(_, task, text)| task == prompt.task && text == prompt.text) {
            let (id, _, _) = self.boxes.remove(at);
            self.changes.push(Change::PromptClosed { id });
        }
    }

    fn tp_prompt_closed(&mut self, prompt: &Prompt<'_>) {
        if let Some(at) = self.prompts.iter().position(|p| p.task == prompt.task && p.text == prompt.text) {
            let id = self.prompts.remove(at).id;
            self.changes.push(Change::PromptClosed { id });
        }
    }
}
