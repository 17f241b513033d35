//! Catalogue routines `rapid run` does not run yet, each with the reason. A program
//! that calls one is refused when it is loaded ("… is not supported by `rapid run`
//! yet"); `docs/builtins.md` shows the reasons. Implementing one means registering it
//! in its family and taking it off this list (`CONTRIBUTING.md`, "How to add a
//! built-in"); a test in `registry.rs` keeps the list, the families and the catalogue
//! in step.

/// (name as the catalogue spells it, why it is not run yet).
pub(super) static NOT_YET: &[(&str, &str)] = &[
    // system.rs
    ("GetMaxNumberOfCyclicBool", "cyclic bools (conditions the controller evaluates cyclically) are not modelled"),
    ("GetNextCyclicBool", "cyclic bools (conditions the controller evaluates cyclically) are not modelled"),
    ("GetNumberOfCyclicBool", "cyclic bools (conditions the controller evaluates cyclically) are not modelled"),
    ("IsCyclicBool", "cyclic bools (conditions the controller evaluates cyclically) are not modelled"),
    ("RemoveAllCyclicBool", "cyclic bools (conditions the controller evaluates cyclically) are not modelled"),
    ("RemoveCyclicBool", "cyclic bools (conditions the controller evaluates cyclically) are not modelled"),
    ("SetupCyclicBool", "cyclic bools (conditions the controller evaluates cyclically) are not modelled"),
    ("GetUASUserName", "the user authorization system (UAS) and its users are not modelled"),
    ("ProcerrRecovery", "process error recovery (moving away from and back to the path) is not modelled"),
    ("RaiseToUser", "raising an error to the user level of NOSTEPIN routines is not modelled"),
    ("SystemStopAction", "stopping the whole system (all tasks, motors off) from RAPID is not modelled"),
    ("UIMsgWrite", "FlexPendant message windows that stay open are not modelled"),
    ("UIMsgWriteAbort", "FlexPendant message windows that stay open are not modelled"),
    ("UIShow", "FlexPendant applications are not modelled"),
    // motion.rs
    ("DropSensor", "sensor synchronization (a robot following a machine's sensor) is not modelled"),
    ("SyncToSensor", "sensor synchronization (a robot following a machine's sensor) is not modelled"),
    ("WaitSensor", "sensor synchronization (a robot following a machine's sensor) is not modelled"),
    ("GetTorqueMargin", "torque margins need the robot's full dynamic model"),
    ("ResetTorqueMargin", "torque margins need the robot's full dynamic model"),
    ("HollowWristReset", "hollow-wrist robots' wrist axes are not modelled"),
    ("IndCnvAddObject", "indexing conveyors are not modelled"),
    ("IndCnvDisable", "indexing conveyors are not modelled"),
    ("IndCnvEnable", "indexing conveyors are not modelled"),
    ("IndCnvInit", "indexing conveyors are not modelled"),
    ("IndCnvReset", "indexing conveyors are not modelled"),
    ("LoadId", "load identification needs measured motor torques"),
    ("ManLoadIdProc", "load identification needs measured motor torques"),
    ("ParIdPosValid", "load identification needs measured motor torques"),
    ("MaxExtLinearSpeed", "the speed limits of external linear axes are not modelled"),
    ("MaxExtReorientSpeed", "the speed limits of external rotational axes are not modelled"),
];

/// Why the built-in named `name` (any letter case) is not run yet, if it is listed.
pub(crate) fn reason(name: &str) -> Option<&'static str> {
    NOT_YET.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|&(_, why)| why)
}
