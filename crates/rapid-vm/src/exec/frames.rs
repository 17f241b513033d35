//! The call stack: `Frame`s in a `Vec` whose returned plain frames stay behind as
//! spares, so that the common call writes a few fields of a spare in place.
//!
//! Why: pushing a whole `Frame` built in a temporary read it back with wide loads
//! just after it was written field by field, a store-forwarding stall on every call
//! (perf on bench/interp fib: the frame push alone took about a tenth of the run).

use std::ops::{Deref, DerefMut};
use std::rc::Rc;

use super::ActiveError;
use crate::ir::Code;

#[derive(Debug)]
pub(crate) struct Frame {
    pub(super) code: Rc<Code>,
    pub(super) pc: u32,
    pub(super) base: u32,
    /// The error this frame's handler is taking (boxed: frames stay small, so a call
    /// pushes a few words, not a block copy).
    pub(super) active: Option<Box<ActiveError>>,
    pub(super) retries: u32,
    pub(super) last_retry_stmt: Option<u32>,
    /// Running this frame's UNDO handler while the program exits.
    pub(super) undoing: bool,
    /// Running this frame's BACKWARD handler, or a TRAP: where the caller's PP goes
    /// afterwards.
    pub(super) return_to: Option<u32>,
    /// A TRAP routine an interrupt started: it returns to the interrupted instruction,
    /// and an error it does not handle goes to the system error handler.
    pub(super) interrupted: bool,
    /// A built-in wait this frame's statement stands in, with the arguments it was
    /// first called with (`repeat.rs`).
    pub(super) repeated: Option<Box<super::repeat::Repeated>>,
}

impl Frame {
    /// A frame entering `code` at its start, its slots from `base`.
    pub(super) fn new(code: Rc<Code>, base: u32) -> Frame {
        Frame {
            code,
            pc: 0,
            base,
            active: None,
            retries: 0,
            last_retry_stmt: None,
            undoing: false,
            return_to: None,
            interrupted: false,
            repeated: None,
        }
    }

    /// The routine this frame runs and the instruction it is at: for a caller, its
    /// call (ArgName follows arguments out through the chain).
    pub(crate) fn position(&self) -> (&Code, u32) {
        (&self.code, self.pc)
    }

    /// Which handler of its routine this frame runs (ExecHandler): the handler_type
    /// values HANDLER_NONE 0, HANDLER_BWD 1, HANDLER_ERR 2, HANDLER_UNDO 3.
    pub(crate) fn handler_type(&self) -> u8 {
        if self.undoing {
            3
        } else if self.active.is_some() {
            2
        } else if self.return_to.is_some() && !self.interrupted {
            1
        } else {
            0
        }
    }

    pub(crate) fn is_trap(&self) -> bool {
        self.code.is_trap
    }
}

/// The frames of the running routines, innermost last; seen as a slice of the live
/// ones. Slots past them are spares: frames that returned plainly, whose memory
/// (and often whose code) the next call takes over.
#[derive(Debug, Default)]
pub(crate) struct Frames {
    slots: Vec<Frame>,
    live: usize,
}

impl Deref for Frames {
    type Target = [Frame];

    #[inline(always)]
    fn deref(&self) -> &[Frame] {
        &self.slots[..self.live]
    }
}

impl DerefMut for Frames {
    #[inline(always)]
    fn deref_mut(&mut self) -> &mut [Frame] {
        &mut self.slots[..self.live]
    }
}

impl Frames {
    pub(super) fn push(&mut self, frame: Frame) {
        self.slots.truncate(self.live);
        self.slots.push(frame);
        self.live += 1;
    }

    pub(super) fn pop(&mut self) -> Option<Frame> {
        self.slots.truncate(self.live);
        let frame = self.slots.pop()?;
        self.live -= 1;
        Some(frame)
    }

    pub(super) fn clear(&mut self) {
        self.slots.clear();
        self.live = 0;
    }

    /// Pushes a frame entering `code` at its start, its slots from `base`: a spare is
    /// rewritten field by field (its code kept when it is the same routine, as in
    /// recursion), else a new frame is added.
    #[inline(always)]
    pub(super) fn enter(&mut self, code: &Rc<Code>, base: u32) {
        match self.slots.get_mut(self.live) {
            Some(spare) => {
                if !Rc::ptr_eq(&spare.code, code) {
                    spare.code = code.clone();
                }
                spare.pc = 0;
                spare.base = base;
                // Tested first: assigning runs the drop code out of line.
                if spare.active.is_some() {
                    spare.active = None;
                }
                spare.retries = 0;
                spare.last_retry_stmt = None;
                spare.undoing = false;
                spare.return_to = None;
                spare.interrupted = false;
            }
            None => self.slots.push(Frame::new(code.clone(), base)),
        }
        self.live += 1;
    }

    /// Leaves the top frame, which stays behind as a spare (its values are dropped
    /// when a call rewrites it or the stack is cut).
    #[inline]
    pub(super) fn leave(&mut self) {
        self.live = self.live.saturating_sub(1);
    }
}
