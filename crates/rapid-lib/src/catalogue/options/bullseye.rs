//! Option: BullsEye (652-1, a sub-option of Arc): automatic TCP measurement of
//! welding torches.
//!
//! Source: ABB, "Application manual - BullsEye" (RobotWare 6), chapter "RAPID
//! reference", which names the data types be_device, be_scan and be_tooldesign and
//! the instructions below; the manual is not public to us. The signatures are checked
//! against ABB's own `BE_User.sys` template (a SYSMODULE BullsEye installs; public copies
//! in taeyangshim-stack/s25016 `RAPID/SpGantry_1200_526406_BACKUP_2025-12-18/RAPID/
//! TASK1/SYSMOD/BE_User.sys`, zwj12/AddInPackages `Ebara/Ebara RobotWare Add-in/RAPID/
//! T_ROB1/BE_User.sys` and `1200-503845-20180502/.../BullsEye/BE_User.sys`, and
//! ravenorb/abb-robot-welder `RAPID/PROGMOD/BE_User1.mod`). That template declares its
//! own scan data and tool design (`scanMig`, `tdMig`): BullsEye predefines no data the
//! public record shows.
//!
//! The manual may document optional arguments no public program passes: the routines
//! take optional arguments they do not declare (`open_optionals`); every argument
//! declared is checked.

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    // The template writes be_device with 8 components, be_scan with 6 and be_tooldesign
    // with 11, but no public text names the components: accepted opaquely.
    opaque("be_device", "BullsEye: the measuring device (its input signal and beam geometry); components not public."),
    opaque("be_scan", "BullsEye: how the beam is scanned; components not public."),
    opaque("be_tooldesign", "BullsEye: the torch's geometry; components not public."),
    // Verified (BE_User.sys): approach and start positions, the TCP extension (mm), tool
    // design, scan, device, speed, zone and tool; the Ebara copy adds \ElapsedTime,
    // \MeanDev and \MaxDev, which receive results (it passes PERS num).
    routine(
        r#"PROC BESetupToolJ(jointtarget ApprPos, jointtarget StartPos, num TcpExtension, be_tooldesign ToolDesign, be_scan Scan, be_device Device, speeddata Speed, zonedata Zone, PERS tooldata Tool, \INOUT num ElapsedTime, \INOUT num MeanDev, \INOUT num MaxDev)"#,
        "BullsEye: sets a tool up for measurement from an approach and a start position.",
    )
    .open_optionals(),
    // Verified (BE_User.sys): the tool, \XYZOnly, \SingleScan.
    routine(
        r#"PROC BECheckTcp(PERS tooldata Tool, \switch XYZOnly, \switch SingleScan)"#,
        "BullsEye: measures the tool and reports how far its TCP moved.",
    )
    .open_optionals(),
    // Verified (BE_User.sys): the tool, \XYZOnly.
    routine(r#"PROC BEUpdateTcp(PERS tooldata Tool, \switch XYZOnly)"#, "BullsEye: measures the tool and corrects its TCP.")
        .open_optionals(),
    // Verified (BE_User.sys): the tool.
    routine("PROC BERefPointer(PERS tooldata Tool)", "BullsEye: references the device with a reference pointer.")
        .open_optionals(),
    // Verified (zwj12/AddInPackages BE_User.sys): the tool and \Absolute (mm).
    routine(r#"PROC BETcpExtend(PERS tooldata Tool, \num Absolute)"#, "BullsEye: moves the tool's TCP along its z axis.")
        .open_optionals(),
    // Verified (zwj12/AddInPackages BE_User.sys): `BEDebugState \On`.
    // uncertain: an \Off switch (not seen in public code) is accepted as an undeclared
    // optional argument.
    routine(r#"PROC BEDebugState(\switch On)"#, "BullsEye: turns BullsEye's debug logging on.").open_optionals(),
];
