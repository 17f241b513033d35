//! Catalogue chapter: interrupt instructions (manual §1.11 "中断").
//!
//! CONNECT is a statement, not a routine, and TriggInt lives in the motion chapter. The
//! interrupt identity is a `VAR intnum` everywhere, as ABB's formal syntax writes it.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // ---- Ordering interrupts ------------------------------------------------------------
    routine(
        r#"PROC ISignalDI(\switch Single | switch SingleSafe, signaldi Signal, dionum TriggValue, VAR intnum Interrupt)"#,
        "Orders an interrupt when a digital input goes to 1, to 0, or either (edge).",
    ),
    routine(
        r#"PROC ISignalDO(\switch Single | switch SingleSafe, signaldo Signal, dionum TriggValue, VAR intnum Interrupt)"#,
        "Orders an interrupt when a digital output goes to 1, to 0, or either (edge).",
    ),
    routine(
        r#"PROC ISignalGI(\switch Single | switch SingleSafe, signalgi Signal, VAR intnum Interrupt)"#,
        "Orders an interrupt whenever the value of a digital input group changes.",
    ),
    routine(
        r#"PROC ISignalGO(\switch Single | switch SingleSafe, signalgo Signal, VAR intnum Interrupt)"#,
        "Orders an interrupt whenever the value of a digital output group changes.",
    ),
    routine(
        r#"PROC ISignalAI(\switch Single | switch SingleSafe, signalai Signal, aiotrigg Condition, num HighValue, num LowValue, num DeltaValue, \switch DPos | switch DNeg, VAR intnum Interrupt)"#,
        "Orders an interrupt when an analog input meets a condition on low/high limits.",
    ),
    routine(
        r#"PROC ISignalAO(\switch Single | switch SingleSafe, signalao Signal, aiotrigg Condition, num HighValue, num LowValue, num DeltaValue, \switch DPos | switch DNeg, VAR intnum Interrupt)"#,
        "Orders an interrupt when an analog output meets a condition on low/high limits.",
    ),
    routine(
        r#"PROC ITimer(\switch Single | switch SingleSafe, num Time, VAR intnum Interrupt)"#,
        "Orders an interrupt after Time seconds, repeating unless \\Single is given.",
    ),
    routine(
        r#"PROC IPers(\switch Single | switch SingleSafe, PERS anytype Name, VAR intnum Interrupt)"#,
        "Orders an interrupt whenever a persistent changes value.",
    ),
    routine(
        r#"PROC IError(errdomain ErrorDomain, \num ErrorId, errtype ErrorType, VAR intnum Interrupt)"#,
        "Orders an interrupt when an event-log entry of a domain, number and type occurs.",
    ),
    routine(
        r#"PROC IRMQMessage(anytype InterruptDataType, VAR intnum Interrupt)"#,
        "Orders an interrupt when an RMQ message of the given data type arrives.",
    ),
    // ---- Cancelling, enabling and disabling ---------------------------------------------
    routine("PROC IDelete(VAR intnum Interrupt)", "Cancels an interrupt order and frees its identity."),
    routine("PROC ISleep(VAR intnum Interrupt)", "Deactivates one interrupt; events meanwhile are dropped."),
    routine("PROC IWatch(VAR intnum Interrupt)", "Reactivates an interrupt deactivated by ISleep."),
    routine("PROC IDisable()", "Holds all interrupts of the task; they queue until IEnable."),
    routine("PROC IEnable()", "Releases interrupts held by IDisable; queued ones run in order."),
    // ---- Interrupt data -----------------------------------------------------------------
    routine(
        "PROC GetTrapData(VAR trapdata TrapEvent)",
        "In a trap routine, gets data about the interrupt that started it.",
    ),
    routine(
        r#"PROC ReadErrData(VAR trapdata TrapEvent, VAR errdomain ErrorDomain, VAR num ErrorId, VAR errtype ErrorType, \VAR string Title, \VAR string Str1, \VAR string Str2, \VAR string Str3, \VAR string Str4, \VAR string Str5)"#,
        "Gets domain, number, type and message texts of the event that raised an IError trap.",
    ),
];
