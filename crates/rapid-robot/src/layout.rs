//! Where a move instruction's arguments are, read from its declared signature once
//! (`builtins/signature.rs`): the `Layout` every move, search-free trigger move and
//! MoveExtJ is run with, and one layout per move instruction.

use std::sync::LazyLock;

/// Where a move instruction's arguments are (`signature::ABSENT` where the instruction
/// has no such parameter: the `Move*DO/AO/GO` family has no `\Conc`, `\V`, `\Z`, `\Inpos`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Layout {
    pub(super) conc: usize,
    pub(super) cir: Option<usize>,
    pub(super) to: usize,
    pub(super) id: usize,
    pub(super) speed: usize,
    pub(super) v: usize,
    pub(super) t: usize,
    pub(super) zone: usize,
    pub(super) z: usize,
    pub(super) inpos: usize,
    pub(super) tool: usize,
    pub(super) wobj: usize,
    pub(super) corr: Option<usize>,
    /// Whether the external axis offsets (EOffs) apply to the target.
    pub(super) eoffs: EOffsRule,
    /// The output a Move*DO/AO/GO sets and its value (a group's `\Dvalue` too).
    pub(super) signal: usize,
    pub(super) value: usize,
    pub(super) dvalue: Option<usize>,
    /// The procedure a Move*Sync runs.
    pub(super) proc_name: usize,
    /// The first of a Trigg move's triggers (`Trigg_1`, then TriggArray, T2 … T8; or
    /// TriggLIOs' `\TriggData1` … `\TriggData3`).
    pub(super) trigg: usize,
}

/// When EOffsOn/EOffsSet offsets move a target's external axes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum EOffsRule {
    /// Always (moves to robtargets).
    Always,
    /// Unless the switch at this place is given (MoveAbsJ `\NoEOffs`).
    Unless(usize),
    /// Only when the switch at this place is given (MoveExtJ `\UseEOffs`).
    Only(usize),
}

impl Layout {
    /// Where the arguments of move instruction `name` are, by the parameter names of
    /// its declaration (`ToPoint` or `ToJointPos`, `\NoEOffs`/`\UseEOffs` for the
    /// external axes' offsets); built once per instruction, see `signature.rs`.
    pub(super) fn of(name: &str) -> Layout {
        let sig = rapid_vm::ext::signature(name);
        let eoffs = match (sig.opt("NoEOffs"), sig.opt("UseEOffs")) {
            (Some(at), _) => EOffsRule::Unless(at),
            (None, Some(at)) => EOffsRule::Only(at),
            (None, None) => EOffsRule::Always,
        };
        Layout {
            conc: sig.at("Conc"),
            cir: sig.opt("CirPoint"),
            to: sig.first_of(&["ToPoint", "ToJointPos"]),
            id: sig.at("ID"),
            speed: sig.at("Speed"),
            v: sig.at("V"),
            t: sig.at("T"),
            zone: sig.at("Zone"),
            z: sig.at("Z"),
            inpos: sig.at("Inpos"),
            tool: sig.at("Tool"),
            wobj: sig.at("WObj"),
            corr: sig.opt("Corr"),
            eoffs,
            signal: sig.at("Signal"),
            value: sig.at("Value"),
            dvalue: sig.opt("Dvalue"),
            proc_name: sig.at("ProcName"),
            trigg: sig.first_of(&["Trigg_1", "TriggData1"]),
        }
    }
}

/// One layout per instruction, each built the first time it is used.
macro_rules! layouts {
    ($($static:ident = $name:literal),* $(,)?) => {
        $(pub(super) static $static: LazyLock<Layout> = LazyLock::new(|| Layout::of($name));)*
    };
}

layouts! {
    MOVE_J = "MoveJ", MOVE_L = "MoveL", MOVE_C = "MoveC", MOVE_ABS_J = "MoveAbsJ",
    MOVE_J_DO = "MoveJDO", MOVE_J_AO = "MoveJAO", MOVE_J_GO = "MoveJGO",
    MOVE_L_DO = "MoveLDO", MOVE_L_AO = "MoveLAO", MOVE_L_GO = "MoveLGO",
    MOVE_C_DO = "MoveCDO", MOVE_C_AO = "MoveCAO", MOVE_C_GO = "MoveCGO",
    MOVE_J_SYNC = "MoveJSync", MOVE_L_SYNC = "MoveLSync", MOVE_C_SYNC = "MoveCSync",
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_vm::ext::ABSENT;

    // Positions counted by hand from the manual's syntax of each instruction (every
    // parameter and every alternative counts one):
    // MoveJ [\Conc] ToPoint [\ID] Speed [\V]|[\T] Zone [\Z] [\Inpos] Tool [\WObj] [\TLoad].
    #[test]
    fn move_j_and_move_l() {
        let j = *MOVE_J;
        assert_eq!((j.conc, j.cir, j.to, j.id, j.speed, j.v, j.t), (0, None, 1, 2, 3, 4, 5));
        assert_eq!((j.zone, j.z, j.inpos, j.tool, j.wobj, j.corr), (6, 7, 8, 9, 10, None));
        assert_eq!(j.eoffs, EOffsRule::Always);
        // MoveL: the same, with \Corr after \WObj.
        assert_eq!(*MOVE_L, Layout { corr: Some(11), ..j });
    }

    // MoveC [\Conc] CirPoint ToPoint [\ID] Speed [\V]|[\T] Zone [\Z] [\Inpos] Tool [\WObj] [\Corr].
    #[test]
    fn move_c() {
        let c = *MOVE_C;
        assert_eq!((c.conc, c.cir, c.to, c.id, c.speed, c.v, c.t), (0, Some(1), 2, 3, 4, 5, 6));
        assert_eq!((c.zone, c.z, c.inpos, c.tool, c.wobj, c.corr), (7, 8, 9, 10, 11, Some(12)));
    }

    // MoveAbsJ [\Conc] ToJointPos [\ID] [\NoEOffs] Speed …; MoveExtJ has [\UseEOffs] there.
    #[test]
    fn external_offsets_follow_the_switch() {
        let abs = *MOVE_ABS_J;
        assert_eq!((abs.to, abs.speed, abs.zone, abs.tool), (1, 4, 7, 10));
        assert_eq!(abs.eoffs, EOffsRule::Unless(3));
        let ext = Layout::of("MoveExtJ");
        assert_eq!((ext.to, ext.speed, ext.t, ext.zone, ext.inpos), (1, 4, 5, 6, 7));
        assert_eq!((ext.tool, ext.wobj, ext.v), (ABSENT, ABSENT, ABSENT));
        assert_eq!(ext.eoffs, EOffsRule::Only(3));
    }

    // MoveJDO ToPoint [\ID] Speed [\T] Zone Tool [\WObj] Signal Value [\TLoad];
    // MoveJGO: … Signal Value | Dvalue [\TLoad]; MoveCDO has CirPoint first.
    #[test]
    fn moves_setting_outputs() {
        let jdo = *MOVE_J_DO;
        assert_eq!((jdo.conc, jdo.v, jdo.z, jdo.inpos), (ABSENT, ABSENT, ABSENT, ABSENT));
        assert_eq!((jdo.to, jdo.id, jdo.speed, jdo.t, jdo.zone, jdo.tool, jdo.wobj), (0, 1, 2, 3, 4, 5, 6));
        assert_eq!((jdo.signal, jdo.value, jdo.dvalue), (7, 8, None));
        assert_eq!((MOVE_J_GO.value, MOVE_J_GO.dvalue), (8, Some(9)));
        for same in [&MOVE_J_AO, &MOVE_L_DO, &MOVE_L_AO] {
            assert_eq!(**same, jdo);
        }
        assert_eq!(*MOVE_L_GO, *MOVE_J_GO);
        let cdo = *MOVE_C_DO;
        assert_eq!((cdo.cir, cdo.to, cdo.id, cdo.speed, cdo.t, cdo.zone), (Some(0), 1, 2, 3, 4, 5));
        assert_eq!((cdo.tool, cdo.wobj, cdo.signal, cdo.value), (6, 7, 8, 9));
        assert_eq!((*MOVE_C_AO, MOVE_C_GO.dvalue), (cdo, Some(10)));
        assert_eq!((MOVE_J_SYNC.proc_name, MOVE_C_SYNC.proc_name), (7, 8));
    }

    // TriggL [\Conc] ToPoint [\ID] Speed [\T] Trigg_1 | TriggArray [\T2] … [\T8] Zone [\Inpos] Tool [\WObj] [\Corr].
    #[test]
    fn trigger_moves() {
        let l = Layout::of("TriggL");
        assert_eq!((l.to, l.speed, l.v, l.t, l.trigg), (1, 3, ABSENT, 4, 5));
        assert_eq!((l.zone, l.inpos, l.tool, l.wobj, l.corr), (14, 15, 16, 17, Some(18)));
        assert_eq!(Layout::of("TriggJ"), Layout { corr: None, ..l });
        let c = Layout::of("TriggC");
        assert_eq!((c.cir, c.to, c.id, c.speed, c.t, c.trigg), (Some(1), 2, 3, 4, 5, 6));
        assert_eq!((c.zone, c.inpos, c.tool, c.wobj, c.corr), (15, 16, 17, 18, Some(19)));
        let abs = Layout::of("TriggAbsJ");
        assert_eq!((abs.to, abs.speed, abs.t, abs.trigg, abs.zone, abs.wobj, abs.corr), (1, 4, 5, 6, 15, 18, None));
        assert_eq!(abs.eoffs, EOffsRule::Unless(3));
        // TriggLIOs … [\T] [\TriggData1] [\TriggData2] [\TriggData3] Zone [\Inpos] Tool [\WObj] [\Corr].
        let ios = Layout::of("TriggLIOs");
        assert_eq!((ios.trigg, ios.zone, ios.inpos, ios.tool, ios.wobj, ios.corr), (5, 8, 9, 10, 11, Some(12)));
        assert_eq!(Layout::of("TriggJIOs"), Layout { corr: None, ..ios });
    }
}
