//! Catalogue chapter: I/O signal instructions and functions (manual §1.9 "输入输出信号").
//!
//! Signals are passed as IN arguments of the semi-value signal types; `anytype` stands for
//! "any signal type" where ABB accepts several. Output arguments that ABB requires to be a
//! variable are VAR.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // ---- Changing signal values ---------------------------------------------------------
    routine("PROC InvertDO(signaldo Signal)", "Flips a digital output: 0 becomes 1 and 1 becomes 0."),
    routine(
        r#"PROC PulseDO(\switch High, \num PLength, signaldo Signal)"#,
        "Gives a pulse on a digital output; default length 0.2 s, \\High forces a high pulse.",
    ),
    routine("PROC Reset(signaldo Signal)", "Sets a digital output to 0."),
    routine("PROC Set(signaldo Signal)", "Sets a digital output to 1."),
    routine("PROC SetAO(signalao Signal, num Value)", "Sets an analog output to a value."),
    routine(
        r#"PROC SetDO(\num SDelay | switch Sync, signaldo Signal, dionum Value)"#,
        "Sets a digital output, optionally after a delay or waiting for the physical change.",
    ),
    routine(
        r#"PROC SetGO(\num SDelay, signalgo Signal, num Value | dnum Dvalue)"#,
        "Sets a group of digital outputs to an integer, optionally after a delay.",
    ),
    // ---- Reading signal values ----------------------------------------------------------
    routine("FUNC num AInput(signalai Signal)", "Returns the current value of an analog input."),
    routine("FUNC num AOutput(signalao Signal)", "Returns the current value of an analog output."),
    routine("FUNC dionum DInput(signaldi Signal)", "Returns the current value of a digital input."),
    routine("FUNC dionum DOutput(signaldo Signal)", "Returns the current value of a digital output."),
    routine("FUNC num GInput(signalgi Signal)", "Returns the value of a digital input group (up to 23 bits)."),
    routine("FUNC num GOutput(signalgo Signal)", "Returns the value of a digital output group (up to 23 bits)."),
    routine(
        "FUNC dnum GInputDnum(signalgi Signal)",
        "Returns the value of a digital input group of up to 32 bits as a dnum.",
    ),
    routine(
        "FUNC dnum GOutputDnum(signalgo Signal)",
        "Returns the value of a digital output group of up to 32 bits as a dnum.",
    ),
    // ---- Waiting for and testing signals ------------------------------------------------
    routine(
        r#"PROC WaitDI(signaldi Signal, dionum Value, \num MaxTime, \VAR bool TimeFlag, \switch Visualize, \string Header, \string Message | string MsgArray{*}, \switch Wrap, \icondata Icon, \string Image, \num VisualizeTime, \signaldo UIActiveSignal)"#,
        "Waits until a digital input has a value; may time out and show a message box.",
    ),
    routine(
        r#"PROC WaitDO(signaldo Signal, dionum Value, \num MaxTime, \VAR bool TimeFlag, \switch Visualize, \string Header, \string Message | string MsgArray{*}, \switch Wrap, \icondata Icon, \string Image, \num VisualizeTime, \signaldo UIActiveSignal)"#,
        "Waits until a digital output has a value; may time out and show a message box.",
    ),
    routine(
        r#"PROC WaitGI(signalgi Signal, \switch NOTEQ | switch LT | switch GT, num Value | dnum Dvalue, \num MaxTime, \VAR num ValueAtTimeout | VAR dnum DvalueAtTimeout, \switch Visualize, \string Header, \string Message | string MsgArray{*}, \switch Wrap, \icondata Icon, \string Image, \num VisualizeTime, \signaldo UIActiveSignal)"#,
        "Waits until an input group equals, differs from, or is below/above a value.",
    ),
    routine(
        r#"PROC WaitGO(signalgo Signal, \switch NOTEQ | switch LT | switch GT, num Value | dnum Dvalue, \num MaxTime, \VAR num ValueAtTimeout | VAR dnum DvalueAtTimeout, \switch Visualize, \string Header, \string Message | string MsgArray{*}, \switch Wrap, \icondata Icon, \string Image, \num VisualizeTime, \signaldo UIActiveSignal)"#,
        "Waits until an output group equals, differs from, or is below/above a value.",
    ),
    routine(
        r#"PROC WaitAI(signalai Signal, \switch LT | switch GT, num Value, \num MaxTime, \VAR num ValueAtTimeout, \switch Visualize, \string Header, \string Message | string MsgArray{*}, \switch Wrap, \icondata Icon, \string Image, \num VisualizeTime, \signaldo UIActiveSignal)"#,
        "Waits until an analog input is below or above a value.",
    ),
    routine(
        r#"PROC WaitAO(signalao Signal, \switch LT | switch GT, num Value, \num MaxTime, \VAR num ValueAtTimeout, \switch Visualize, \string Header, \string Message | string MsgArray{*}, \switch Wrap, \icondata Icon, \string Image, \num VisualizeTime, \signaldo UIActiveSignal)"#,
        "Waits until an analog output is below or above a value.",
    ),
    routine("FUNC bool TestDI(signaldi Signal)", "TRUE when a digital input is 1."),
    routine("FUNC bool ValidIO(anytype Signal)", "TRUE when a signal of any type can be accessed without error now.")
        .takes_signals(),
    // uncertain: SignalName receives the configured name; VAR assumed.
    routine(
        "FUNC signalorigin GetSignalOrigin(anytype Signal, VAR string SignalName)",
        "Tells whether a signal is configured, aliased or unknown, and gives its configured name.",
    )
    .takes_signals(),
    // ---- I/O devices and networks -------------------------------------------------------
    routine(
        "PROC IODisable(string UnitName, num MaxTime)",
        "Deactivates an I/O device, waiting at most MaxTime seconds.",
    ),
    routine("PROC IOEnable(string UnitName, num MaxTime)", "Activates an I/O device, waiting at most MaxTime seconds."),
    routine(
        r#"FUNC iounit_state IOUnitState(string UnitName, \switch Phys | switch Logic)"#,
        "Returns the current (physical or logical) state of an I/O device.",
    ),
    routine(
        r#"PROC IOBusState(string BusName, VAR busstate State, \switch Phys | switch Logic)"#,
        "Reads the current (physical or logical) state of an I/O network.",
    ),
    routine("PROC IOBusStart(string BusName)", "Starts an I/O network."),
    routine(
        r#"PROC IOEventMessage(\switch On | switch Off, string DeviceName)"#,
        "Turns event-log messages from an I/O device on or off.",
    ),
    // ---- Defining signals ---------------------------------------------------------------
    // uncertain: FromSignal may also be a string holding a configured signal name.
    routine(
        "PROC AliasIO(anytype FromSignal, VAR anytype ToSignal)",
        "Connects a signal variable declared in RAPID to a configured signal.",
    )
    .takes_signals(),
    routine("PROC AliasIOReset(VAR anytype Signal)", "Disconnects a signal variable connected earlier by AliasIO.")
        .takes_signals(),
    // uncertain: access modes of the optional outputs assumed VAR.
    routine(
        r#"PROC GetGroupSignalInfo(anytype Signal, \VAR dnum MaxDvalue, \VAR string Label, \VAR string DeviceName)"#,
        "Reads the maximum value, label and device of a digital group signal.",
    )
    .takes_signals(),
];
