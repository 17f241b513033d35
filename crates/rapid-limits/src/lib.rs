//! The one table of limits. Every bound a RAPID program, a configuration or a system
//! can run into is declared here once, with where its value comes from; the lexer,
//! the checker, the interpreter, the configuration reader and the CLI all read it, so
//! anything `rapid check` accepts, `rapid run` accepts too.
//!
//! A crate of its own, with no dependencies, because its readers sit at every layer:
//! rapid-syntax (identifier length, nesting) and rapid-config (tasks) depend on
//! neither rapid-lib nor each other.
//!
//! Sources: "overview" is ABB's *Technical reference manual – RAPID overview*
//! (3HAC050947, RobotWare 6; `/work/shared/spec`), by section. Values marked **ours**
//! are not in the public record: they are chosen to keep the host safe and are as
//! generous as a real program needs.
#![forbid(unsafe_code)]

/// One entry of [`TABLE`]: what is limited, the bound and where it comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limit {
    /// What is counted, as a message names it ("array elements").
    pub what: &'static str,
    /// The largest allowed count.
    pub value: u64,
    /// The manual section the value comes from, or "ours" with the reason.
    pub source: &'static str,
}

/// Characters in an identifier (overview §1.1.2 "Identifiers": at most 32).
pub const IDENT_CHARS: usize = 32;

/// Characters in a string value (overview §1.1.2 "String values": at most 80).
pub const STRING_CHARS: usize = 80;

/// Dimensions of an array (overview §1.2.2 "Data declarations": 1, 2 or 3).
pub const ARRAY_DIMENSIONS: usize = 3;

/// Elements of one array, in total over its dimensions, so also in any one dimension.
/// **Ours**: the controller's program memory is a few megabytes (a million nums is
/// 4 MB there); a bigger array would only exhaust the host's memory and make every
/// copy of it slow. Checked by the checker and again by the compiler.
pub const ARRAY_ELEMENTS: u64 = 1 << 20;

/// Tasks of one system (overview §1.20 "Multitasking": up to 20 tasks run
/// pseudo-parallel).
pub const TASKS: usize = 20;

/// Expressions nested inside each other (parentheses, operands, arguments).
/// **Ours**: deeper input is refused (E0122) rather than recursed into.
pub const EXPR_DEPTH: u32 = 256;

/// Statements nested inside each other (IF, WHILE, FOR, TEST).
/// **Ours**: as [`EXPR_DEPTH`].
pub const STMT_DEPTH: u32 = 256;

/// Routine calls active at once in one task. **Ours**: the controller stops on its
/// stack size, which is not published; deeper calls stop the program (runaway
/// recursion) instead of exhausting the host.
pub const CALL_DEPTH: usize = 10_000;

/// Entries the event log keeps (the newest). **Ours**: the controller's event log is
/// bounded per domain; its size is not in the public record.
pub const EVENT_LOG_ENTRIES: usize = 1000;

/// Sockets a task may hold open at once. As the manual's SocketCreate limitations are
/// remembered by the project (uncertain: not found in the stored public text).
pub const SOCKETS: usize = 32;

/// Files (`iodev`) a task may hold open at once; Open past it raises ERR_FILEOPEN. **Ours**: the
/// controller's figure is not public; this keeps a program that opens in a loop
/// from exhausting the host's file handles.
pub const OPEN_FILES: usize = 64;

/// Error numbers a program may raise itself (overview §1.12 "Error recovery": RAISE
/// takes 1 to 90).
pub const RAISE_ERRNO_MAX: i32 = 90;

/// Global (world) zones defined at once (overview §2.9 "World zones": at most 20).
pub const WORLD_ZONES: usize = 20;

/// Signals pulsed at once (overview §2.10 "I/O principles": at most 10).
pub const PULSES: usize = 10;

/// Signal orders delayed at once (overview §2.10: at most 20).
pub const DELAYED_ORDERS: usize = 20;

/// Bytes of source text one task's program may have before program memory is said to
/// be full: every module of the task (program and system modules) counted as the bytes
/// of its text as read (UTF-8; a Latin-1 letter past ASCII counts two), summed.
///
/// **Ours**, and only a warning (W0706), the same in check and run. A real controller
/// refuses a module that does not fit its program memory (Load raises ERR_PRGMEMFULL,
/// "program memory full"; ProgMemFree reports what is left), and the manual presents
/// Load/UnLoad as the way to run a program larger than that memory (overview §1.6,
/// "Loading program modules").
/// But ABB publishes neither the size of an IRC5's program memory nor how a program is
/// counted against it (the controller holds the program compiled, in a form that is not
/// public), and no public event-log message gives a figure. Source bytes are what a
/// user can see and split; our own compiled size is not used because it would make the
/// finding change with the interpreter's version. 64 MiB lets the largest programs we
/// know pass (a 357,000-line, 50 MB CAM module) and notes a synthetic 1,000,000-line
/// (140 MB) one, which no controller is known to hold; with the figure not public that
/// is a warning, not a refusal.
pub const PROGRAM_MEMORY_BYTES: u64 = 64 << 20;

/// Every limit with its value and source, for documentation and tests.
pub const TABLE: &[Limit] = &[
    Limit { what: "identifier characters", value: IDENT_CHARS as u64, source: "overview §1.1.2" },
    Limit { what: "string characters", value: STRING_CHARS as u64, source: "overview §1.1.2" },
    Limit { what: "array dimensions", value: ARRAY_DIMENSIONS as u64, source: "overview §1.2.2" },
    Limit { what: "array elements", value: ARRAY_ELEMENTS, source: "ours: host memory" },
    Limit { what: "tasks", value: TASKS as u64, source: "overview §1.20" },
    Limit { what: "expression nesting", value: EXPR_DEPTH as u64, source: "ours: parser stack" },
    Limit { what: "statement nesting", value: STMT_DEPTH as u64, source: "ours: parser stack" },
    Limit { what: "call depth", value: CALL_DEPTH as u64, source: "ours: runaway recursion" },
    Limit { what: "event log entries", value: EVENT_LOG_ENTRIES as u64, source: "ours: not public" },
    Limit { what: "open sockets", value: SOCKETS as u64, source: "SocketCreate (uncertain)" },
    Limit { what: "open files", value: OPEN_FILES as u64, source: "ours: host file handles" },
    Limit { what: "raised error numbers", value: RAISE_ERRNO_MAX as u64, source: "overview §1.12" },
    Limit { what: "world zones", value: WORLD_ZONES as u64, source: "overview §2.9" },
    Limit { what: "pulsed signals", value: PULSES as u64, source: "overview §2.10" },
    Limit { what: "delayed signal orders", value: DELAYED_ORDERS as u64, source: "overview §2.10" },
    Limit { what: "program source bytes", value: PROGRAM_MEMORY_BYTES, source: "ours: not public (warning)" },
];

/// The element count of an array with dimensions `dims` (each at least 1) as a number
/// that never saturates: `f64` holds the product of three dimensions exactly up to
/// 2^53 and approximately far beyond, so a message can say how large it really is.
pub fn array_elements(dims: &[f64]) -> f64 {
    dims.iter().product()
}

/// A count for a message: an integer when it is one up to 2^53, else `1e21` style.
pub fn count_text(n: f64) -> String {
    if n.fract() == 0.0 && n.abs() < 9_007_199_254_740_992.0 {
        format!("{n:.0}")
    } else {
        format!("{n:e}")
    }
}

/// The message for an array over [`ARRAY_ELEMENTS`], the same in check and run:
/// "array `a` has 1e21 elements; at most 1048576 fit".
pub fn array_too_large(name: &str, elements: f64) -> String {
    format!("array `{name}` has {} elements; at most {ARRAY_ELEMENTS} fit", count_text(elements))
}

/// The note for a task's program over [`PROGRAM_MEMORY_BYTES`], the same in check and
/// run: "the task's program is 146000000 bytes of source text; program memory holds at
/// most 67108864 …".
pub fn program_too_large(bytes: u64) -> String {
    format!(
        "the task's program is {bytes} bytes of source text; program memory holds at most \
         {PROGRAM_MEMORY_BYTES} (our figure: ABB does not publish an IRC5's), so a controller may \
         refuse to load it (program memory full, ERR_PRGMEMFULL): split it into modules loaded \
         when needed (Load, UnLoad)"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_never_saturate() {
        assert_eq!(count_text(array_elements(&[1e7, 1e7, 1e7])), "1e21");
        assert_eq!(count_text(array_elements(&[1024.0, 1025.0])), "1049600");
        assert_eq!(count_text(4_294_967_296.0 * 4_294_967_296.0 * 4_294_967_296.0), "7.922816251426434e28");
    }

    #[test]
    fn message_names_the_limit() {
        assert_eq!(array_too_large("a", 1e8), "array `a` has 100000000 elements; at most 1048576 fit");
    }

    #[test]
    fn program_memory_message_names_the_limit_and_the_size() {
        let text = program_too_large(146_000_000);
        assert!(text.starts_with("the task's program is 146000000 bytes of source text;"), "{text}");
        assert!(text.contains("at most 67108864 "), "{text}");
        assert!(text.contains("ERR_PRGMEMFULL"), "{text}");
    }

    #[test]
    fn table_lists_each_constant_once() {
        let mut names: Vec<_> = TABLE.iter().map(|l| l.what).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), TABLE.len());
        assert!(TABLE.iter().all(|l| l.value > 0 && !l.source.is_empty()));
    }
}
