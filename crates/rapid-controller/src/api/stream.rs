//! The change stream: what front ends subscribe to (signal and persistent changes,
//! execution state, event-log entries, pendant output and prompts), in the order the
//! API saw them, in one bounded buffer. Each subscriber reads from its own cursor;
//! when the buffer is full the oldest change goes, and a subscriber that had not read
//! it is told how many it missed. Memory is bounded by the buffer, never by a slow
//! subscriber.

use std::collections::VecDeque;

/// Changes the stream keeps at most.
pub const DEFAULT_CAPACITY: usize = 10_000;

/// One change a front end is told of.
#[derive(Debug, Clone, PartialEq)]
pub enum Change {
    /// A signal took a new value at controller time `time`.
    Signal { name: String, value: f64, time: f64 },
    /// A global persistent shared by the tasks took a new value (RAPID literal text).
    Persistent { name: String, value: String },
    /// The program's state changed: `Running`, `Stopping`, `Stopped`, `Stepping`.
    Execution { state: String },
    /// A task's state changed: `active`, or how it ended (`ended`, `ended: cycle`,
    /// `ended: stopped`, `ended: halted`, `ended: ` and its error).
    Task { task: String, state: String },
    /// The program stopped at a breakpoint.
    Breakpoint { task: String, file: String, line: u32 },
    /// An entry of a task's event log (code: domain × 10000 + number).
    Event { task: String, code: u32, kind: String, title: String, time: f64 },
    /// A line on the pendant.
    TpWrite { text: String },
    /// The pendant was erased.
    TpErase,
    /// A dialog waits for the operator's answer.
    PromptOpened { id: u64, task: String, text: String },
    /// A front end answered it.
    PromptAnswered { id: u64, answer: String },
    /// It was given up (its \MaxTime ran out, or the program pointer moved).
    PromptClosed { id: u64 },
}

/// A subscriber's handle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Subscription(usize);

/// What a poll returns: the changes since the last poll, and how many were dropped
/// (the buffer was full) before the subscriber read them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Batch {
    pub changes: Vec<Change>,
    pub dropped: u64,
}

/// The bounded buffer and its subscribers' cursors.
#[derive(Debug)]
pub(crate) struct Stream {
    buffer: VecDeque<Change>,
    capacity: usize,
    /// The sequence number of the buffer's first change.
    first: u64,
    /// Each subscriber's next sequence number to read (None: unsubscribed).
    cursors: Vec<Option<u64>>,
}

impl Default for Stream {
    fn default() -> Self {
        Stream::new(DEFAULT_CAPACITY)
    }
}

impl Stream {
    pub(crate) fn new(capacity: usize) -> Stream {
        Stream { buffer: VecDeque::new(), capacity: capacity.max(1), first: 0, cursors: Vec::new() }
    }

    /// Whether anyone listens (the API gathers changes only then).
    pub(crate) fn has_subscribers(&self) -> bool {
        self.cursors.iter().any(Option::is_some)
    }

    /// A new subscriber, who sees the changes from now on.
    pub(crate) fn subscribe(&mut self) -> Subscription {
        let next = self.first + self.buffer.len() as u64;
        if let Some(free) = self.cursors.iter().position(Option::is_none) {
            self.cursors[free] = Some(next);
            return Subscription(free);
        }
        self.cursors.push(Some(next));
        Subscription(self.cursors.len() - 1)
    }

    pub(crate) fn unsubscribe(&mut self, sub: Subscription) {
        if let Some(cursor) = self.cursors.get_mut(sub.0) {
            *cursor = None;
        }
        self.trim();
    }

    /// Adds a change; the oldest goes when the buffer is full.
    pub(crate) fn push(&mut self, change: Change) {
        if !self.has_subscribers() {
            return;
        }
        if self.buffer.len() == self.capacity {
            self.buffer.pop_front();
            self.first += 1;
        }
        self.buffer.push_back(change);
    }

    /// The changes subscriber `sub` has not read yet; None for no such subscriber.
    pub(crate) fn poll(&mut self, sub: Subscription) -> Option<Batch> {
        let cursor = (*self.cursors.get(sub.0)?)?;
        let dropped = self.first.saturating_sub(cursor);
        let from = cursor.max(self.first);
        let changes: Vec<Change> = self.buffer.iter().skip((from - self.first) as usize).cloned().collect();
        self.cursors[sub.0] = Some(self.first + self.buffer.len() as u64);
        self.trim();
        Some(Batch { changes, dropped })
    }

    /// Drops the changes every subscriber has read.
    fn trim(&mut self) {
        let Some(oldest) = self.cursors.iter().flatten().min().copied() else {
            self.first += self.buffer.len() as u64;
            self.buffer.clear();
            return;
        };
        while self.first < oldest && self.buffer.pop_front().is_some() {
            self.first += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Change, Stream};

    fn line(n: u32) -> Change {
        Change::TpWrite { text: n.to_string() }
    }

    #[test]
    fn each_subscriber_reads_in_order_from_when_it_subscribed() {
        let mut stream = Stream::new(10);
        stream.push(line(0)); // nobody listens: not kept
        let a = stream.subscribe();
        stream.push(line(1));
        let b = stream.subscribe();
        stream.push(line(2));
        let batch = stream.poll(a).unwrap_or_default();
        assert_eq!(batch.changes, vec![line(1), line(2)]);
        assert_eq!(batch.dropped, 0);
        assert_eq!(stream.poll(b).unwrap_or_default().changes, vec![line(2)]);
        assert!(stream.poll(a).unwrap_or_default().changes.is_empty());
    }

    #[test]
    fn a_full_buffer_drops_the_oldest_and_counts_them() {
        let mut stream = Stream::new(3);
        let sub = stream.subscribe();
        for n in 1..=5 {
            stream.push(line(n));
        }
        // 5 pushed into room for 3: 1 and 2 dropped.
        let batch = stream.poll(sub).unwrap_or_default();
        assert_eq!(batch.changes, vec![line(3), line(4), line(5)]);
        assert_eq!(batch.dropped, 2);
    }

    #[test]
    fn read_changes_are_freed_and_an_unsubscribed_handle_reads_nothing() {
        let mut stream = Stream::new(3);
        let sub = stream.subscribe();
        stream.push(line(1));
        let _ = stream.poll(sub);
        assert_eq!(stream.buffer.len(), 0);
        stream.unsubscribe(sub);
        assert!(stream.poll(sub).is_none());
    }
}
