//! Catalogue chapter: system and time (manual §1.14): clocks, date and time, file and module times.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // --- Stopwatch clocks -------------------------------------------------------------------
    routine(r#"PROC ClkReset(VAR clock Clock)"#, "Sets a stopwatch clock back to zero."),
    routine(r#"PROC ClkStart(VAR clock Clock)"#, "Starts (or continues) a stopwatch clock."),
    routine(r#"PROC ClkStop(VAR clock Clock)"#, "Stops a stopwatch clock, keeping its time."),
    routine(
        r#"FUNC num ClkRead(VAR clock Clock \switch HighRes)"#,
        "Returns the elapsed seconds of a clock, running or stopped.",
    ),
    // --- Current date and time --------------------------------------------------------------
    routine(r#"FUNC string CDate()"#, "Returns the current date as text in the form YYYY-MM-DD."),
    routine(r#"FUNC string CTime()"#, "Returns the current time as text in the form HH:MM:SS."),
    routine(
        r#"FUNC num GetTime(\switch WDay | switch Hour | switch Min | switch Sec)"#,
        "Returns one component of the current time: weekday, hour, minute or second.",
    ),
    // --- Time information of files and modules ----------------------------------------------
    routine(
        r#"FUNC dnum FileTimeDnum(string Path \switch ModifyTime | switch AccessTime | switch StatCTime \VAR stringdig StrDig)"#,
        "Returns a file's modification, access or status-change time in seconds.",
    ),
    routine(
        r#"FUNC dnum ModTimeDnum(string Object \VAR stringdig StrDig)"#,
        "Returns the file modification time of a loaded module.",
    ),
    routine(
        r#"FUNC bool ModExist(string ModuleName)"#,
        "Tells whether a module of the given name is loaded in the task.",
    ),
    // --- Program memory -----------------------------------------------------------------------
    routine(r#"FUNC num ProgMemFree()"#, "Returns the amount of free program memory."),
];
