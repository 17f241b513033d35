//! Option: BullsEye (652-1, a sub-option of Arc): automatic TCP measurement of
//! welding torches.
//!
//! Source: ABB, "Application manual - BullsEye" (RobotWare 6), chapter "RAPID
//! reference", which names the data types be_device, be_scan and be_tooldesign and
//! the instructions below. Their component lists and full parameter lists are not in
//! any public text we could read: the types are accepted opaquely and the calls'
//! arguments are not checked (only their names are resolved).

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    opaque("be_device", "BullsEye: the measuring device (its input signal and beam geometry); components not public."),
    opaque("be_scan", "BullsEye: how the beam is scanned; components not public."),
    opaque("be_tooldesign", "BullsEye: the torch's geometry; components not public."),
    routine(
        "PROC BESetupToolJ()",
        "BullsEye: sets a tool up for measurement from a start position (arguments not checked).",
    )
    .unchecked_args(),
    routine(
        "PROC BECheckTcp()",
        "BullsEye: measures the tool and reports how far its TCP moved (arguments not checked).",
    )
    .unchecked_args(),
    routine("PROC BEUpdateTcp()", "BullsEye: measures the tool and corrects its TCP (arguments not checked).")
        .unchecked_args(),
    routine("PROC BERefPointer()", "BullsEye: references the device with a reference pointer (arguments not checked).")
        .unchecked_args(),
    routine("PROC BETcpExtend()", "BullsEye: moves the tool's TCP along its z axis (arguments not checked).")
        .unchecked_args(),
];
