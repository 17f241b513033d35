//! Option: Production Manager (812-1): a production loop (`ExecEngine`) that runs
//! parts and service menus the operator or a PLC orders.
//!
//! Source: ABB, "Application manual - Production Manager" (RobotWare 6); the manual is
//! not public to us. What the public record shows: ABB's own Production Manager modules
//! declare data of these types without declaring the types (`GoSafeMnu.sys` and
//! `PartR1S1.mod`, "(c) ABB", in zwj12/ZhongXunRapid `ApplSys/`), and partadv comes from
//! the encrypted `GAP_PARTADV.sys` shipped beside them; the main module of a Production
//! Manager system is `main` calling `ExecEngine;` with no argument (zwj12/ZhongXunRapid
//! `ApplSys/gapMain.mod`). ravenorb/abb-robot-welder's system.xml lists
//! `812-1 Production Manager` and its `mTSC.mod` declares menudata without the type.
//! Public data of these types always has the same shapes (menudata 11 components:
//! three strings, a number, a string, a number, a boolean, two numbers, a boolean and a
//! number; partdata 7), but no public text names the components: the types are opaque.

use super::super::entry::*;

pub(super) const ENTRIES: &[Entry] = &[
    opaque(
        "menudata",
        "Production Manager: a service or setup menu entry and the routine it runs; components not public.",
    ),
    opaque("partdata", "Production Manager: a part, the routine that makes it and its station; components not public."),
    opaque("partadv", "Production Manager: a part's positioner angles and options; components not public."),
    // uncertain: ExecEngine's optional arguments, if any (public systems call it bare).
    routine("PROC ExecEngine()", "Production Manager: runs the production loop (parts and menus as ordered).")
        .open_optionals(),
];
