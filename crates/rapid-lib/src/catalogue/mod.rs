//! The catalogue of predefined RAPID: one file per chapter of the manual.
//!
//! Each chapter file exposes `ENTRIES: &[Entry]`. `ALL_CHAPTERS` lists them; nothing
//! else in the workspace may declare a built-in. The software options (Arc, EGM, …)
//! are in `options/`, one file per option, listed in `options::ALL_OPTIONS`.

pub mod entry;
pub mod options;

mod data;
mod files;
mod interrupts;
mod io;
mod math;
mod motion;
mod sockets;
mod strings;
mod system;
mod time;
mod types;

pub use entry::{Entry, EntryKind, RoutineFlags};

/// Every chapter: (chapter name, its entries).
pub const ALL_CHAPTERS: &[(&str, &[Entry])] = &[
    ("types", types::ENTRIES),
    ("data", data::ENTRIES),
    ("math", math::ENTRIES),
    ("strings", strings::ENTRIES),
    ("time", time::ENTRIES),
    ("files", files::ENTRIES),
    ("sockets", sockets::ENTRIES),
    ("system", system::ENTRIES),
    ("io", io::ENTRIES),
    ("interrupts", interrupts::ENTRIES),
    ("motion", motion::ENTRIES),
];
