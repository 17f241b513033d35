//! SearchL, SearchC and SearchExtJ (§1.8): a linear (circular) move to ToPoint, or a
//! move of the external axes alone to ToJointPos, that records where a digital input (or a
//! persistent bool) changes — by default on its rising edge, `\Flanks` on both,
//! `\NegFlank` falling, `\HighLevel`/`\LowLevel` on a level. With `\Stop`, `\PStop` or
//! `\SStop` the robot brakes on its path from the first hit; otherwise it goes on to ToPoint (`\Sup`:
//! a second hit is an error). No hit: ERR_WHLSEARCH; the edge's level already there at
//! the start: ERR_SIGSUPSEARCH.
//!
//! The move is planned as a stop point when the instruction starts; the instruction
//! then waits (re-checking) until the move ends, looking at the signal's change log
//! (or the persistent's value) at every wake, so a hit has its exact time for a
//! signal, and the time of the wake for a persistent another task changed.

use crate::RobotResources;
use std::sync::LazyLock;

use rapid_motion::plan::{MoveRequest, Target};

use super::data;
use super::moves::EOffsRule;
use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, Err, RapidError, StopKind, Value};

type Res = Result<Option<Value>, RapidError>;

/// Where the arguments up to SearchPoint are: the same in SearchL, SearchC and
/// SearchExtJ (a test checks), read from SearchL's declaration once.
#[derive(Debug, PartialEq, Eq)]
struct Head {
    stop: usize,
    pstop: usize,
    sstop: usize,
    sup: usize,
    signal: usize,
    pers_bool: usize,
    flanks: usize,
    neg_flank: usize,
    high_level: usize,
    low_level: usize,
    /// SearchPoint (SearchExtJ: SearchJointPos).
    search_point: usize,
}

impl Head {
    fn of(name: &str) -> Head {
        let sig = rapid_vm::ext::signature(name);
        Head {
            stop: sig.at("Stop"),
            pstop: sig.at("PStop"),
            sstop: sig.at("SStop"),
            sup: sig.at("Sup"),
            signal: sig.at("Signal"),
            pers_bool: sig.at("PersBool"),
            flanks: sig.at("Flanks"),
            neg_flank: sig.at("NegFlank"),
            high_level: sig.at("HighLevel"),
            low_level: sig.at("LowLevel"),
            search_point: sig.first_of(&["SearchPoint", "SearchJointPos"]),
        }
    }
}

static HEAD: LazyLock<Head> = LazyLock::new(|| Head::of("SearchL"));

/// Where the arguments after SearchPoint are (SearchC has CirPoint first;
/// `signature::ABSENT` where the instruction has no such parameter).
#[derive(Debug, PartialEq, Eq)]
struct Places {
    cir: Option<usize>,
    to: usize,
    id: usize,
    speed: usize,
    v: usize,
    t: usize,
    tool: usize,
    wobj: usize,
    corr: usize,
    /// SearchExtJ: only the external axes move (no tool, no TCP); `\UseEOffs` here.
    ext_only: Option<usize>,
}

impl Places {
    /// Where search instruction `name`'s arguments after SearchPoint are, by the
    /// parameter names of its declaration (see `signature.rs`).
    fn of(name: &str) -> Places {
        let sig = rapid_vm::ext::signature(name);
        let ext_only = sig.opt("UseEOffs");
        Places {
            cir: sig.opt("CirPoint"),
            to: sig.first_of(&["ToPoint", "ToJointPos"]),
            id: sig.at("ID"),
            speed: sig.at("Speed"),
            v: sig.at("V"),
            t: sig.at("T"),
            tool: sig.at("Tool"),
            wobj: sig.at("WObj"),
            corr: sig.at("Corr"),
            ext_only,
        }
    }
}

static SEARCH_L: LazyLock<Places> = LazyLock::new(|| Places::of("SearchL"));
static SEARCH_C: LazyLock<Places> = LazyLock::new(|| Places::of("SearchC"));
static SEARCH_EXT_J: LazyLock<Places> = LazyLock::new(|| Places::of("SearchExtJ"));

/// What counts as a hit.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Trigger {
    Rising,
    Falling,
    Both,
    High,
    Low,
}

impl Trigger {
    fn of(args: &[Value]) -> Trigger {
        if present(args.get(HEAD.flanks)) {
            Trigger::Both
        } else if present(args.get(HEAD.neg_flank)) {
            Trigger::Falling
        } else if present(args.get(HEAD.high_level)) {
            Trigger::High
        } else if present(args.get(HEAD.low_level)) {
            Trigger::Low
        } else {
            Trigger::Rising
        }
    }

    /// Whether a change from `old` to `new` is a hit.
    fn hit(self, old: bool, new: bool) -> bool {
        match self {
            Trigger::Rising => !old && new,
            Trigger::Falling => old && !new,
            Trigger::Both => old != new,
            Trigger::High => new,
            Trigger::Low => !new,
        }
    }
}

/// A search under way.
#[derive(Debug, Clone)]
pub struct Search {
    /// The instruction (call depth, pc).
    at: (usize, u32),
    /// When the move ends (the robot at ToPoint).
    end: f64,
    /// How much of the signal change log was looked at; the persistent's last value.
    seen: usize,
    last: bool,
    hits: u32,
}

/// `SearchL`.
pub(crate) fn search_l(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    search(ctx, args, &SEARCH_L)
}

/// `SearchC`: the same along a circle through CirPoint.
pub(crate) fn search_c(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    search(ctx, args, &SEARCH_C)
}

/// `SearchExtJ`: the external axes move to ToJointPos's `extax` while the arm stands;
/// SearchJointPos gets the axes' values at the hit.
pub(crate) fn search_ext_j(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    search(ctx, args, &SEARCH_EXT_J)
}

fn search(ctx: &mut Ctx<'_>, args: &[Value], places: &Places) -> Res {
    // SearchExtJ moves external axes only; SearchL and SearchC move the TCP.
    match places.ext_only.is_some() {
        true => super::moves::require_motion_task(ctx)?,
        false => super::moves::require_robot(ctx)?,
    }
    // uncertain: a search in synchronized movement (`\\ID`) is not coordinated with the
    // other tasks' moves yet.
    if present(args.get(places.id)) {
        return Err(RapidError::fatal("\\ID on a search is not supported by `rapid run` yet"));
    }
    let here = ctx.call_place();
    let search = match ctx.resources.robot_mut().search.take().filter(|s| s.at == here) {
        Some(search) => search,
        None => start(ctx, args, here, places)?,
    };
    look(ctx, args, search)
}

/// Checks the start condition and gives the robot the search move.
fn start(ctx: &mut Ctx<'_>, args: &[Value], at: (usize, u32), places: &Places) -> Result<Search, RapidError> {
    let trigger = Trigger::of(args);
    let (level, seen) = level_now(ctx, args)?;
    let flank = matches!(trigger, Trigger::Rising | Trigger::Falling);
    if flank && trigger.hit(!level, level) {
        // uncertain: the manual raises this when the edge's level is there at the start.
        return Err(ctx.error(Err::SigSupSearch, "the search signal already has its hit value at the start"));
    }
    let (chain, target) = path_of(ctx, args, places)?;
    let mut speed = data::speed(ctx, &ctx.value(&args[places.speed])?)?;
    if let Some(v) = ctx.opt_num(args.get(places.v))? {
        speed.v_tcp = v;
    }
    let (tool, held_object) = super::moves::mount_of(&chain);
    let wobj = super::moves::wobj_frame(&chain);
    let request = MoveRequest { target, speed, zone: rapid_motion::plan::ZoneData::FINE, tool, held_object, wobj };
    super::moves::note_facts(ctx, &request, &chain);
    let mut settings = super::moves::planner_settings(ctx);
    // `\T`: the search move takes this long.
    settings.move_time = ctx.opt_num(args.get(places.t))?;
    let rule = places.ext_only.map_or(EOffsRule::Always, EOffsRule::Only);
    // A 7-axis arm: axis 7 at a robtarget from its arm angle (`arm7.rs`); a
    // jointtarget's (SearchExtJ) eax_a is axis 7 itself.
    ctx.resources.robot_mut().next_axis7 = None;
    if places.ext_only.is_none() {
        let to = ctx.value(&args[places.to])?;
        super::moves::arm_target(ctx, &chain, &to)?;
    }
    let external = super::moves::external_target(ctx, args, places.to, rule)?;
    let now = ctx.time;
    let robot = ctx.resources.robot_mut();
    robot.set_settings(settings);
    robot.next_external = external;
    // `\Corr`: the path follows the corrections of the connected generators.
    robot.corr.next = present(args.get(places.corr));
    let foreign = robot.next_foreign;
    let end = robot.push(now, &request, false, Vec::new()).map_err(super::moves::motion_error)?;
    if let Some(err) = robot.corr.violation.take() {
        return Err(super::moves::motion_error(err));
    }
    robot.active = chain;
    robot.active_foreign = foreign;
    Ok(Search { at, end, seen, last: level, hits: 0 })
}

/// The search's frames and path: the arm standing where it is for SearchExtJ.
fn path_of(
    ctx: &mut Ctx<'_>,
    args: &[Value],
    places: &Places,
) -> Result<(rapid_motion::frames::FrameChain, Target), RapidError> {
    if places.ext_only.is_some() {
        let robot = ctx.resources.robot_mut();
        return Ok((robot.active, Target::Joints(robot.end_joints())));
    }
    let mut chain = super::moves::frames_at(ctx, args, places.tool, places.wobj, true)?;
    super::moves::on_track(ctx, args, places.to, EOffsRule::Always, &mut chain)?;
    let tcp_of = |ctx: &Ctx<'_>, idx: usize| -> Result<rapid_motion::Pose, RapidError> {
        let (target, _) = data::robtarget(ctx, &ctx.value(&args[idx])?)?;
        Ok(super::moves::path_pose(&chain, &target))
    };
    let to = tcp_of(ctx, places.to)?;
    super::moves::check_sing_mode(ctx)?;
    let target = match places.cir {
        Some(cir) => {
            super::moves::check_circle_mode(ctx)?;
            Target::Circular { via: tcp_of(ctx, cir)?, to }
        }
        None => Target::Linear(to),
    };
    Ok((chain, target))
}

/// The signal's (or persistent's) level now, and how long the change log is.
fn level_now(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<(bool, usize), RapidError> {
    if present(args.get(HEAD.pers_bool)) {
        return Ok((matches!(ctx.value(&args[HEAD.pers_bool])?, Value::Bool(true)), 0));
    }
    let id = rapid_signals::signal(ctx, &args[HEAD.signal])?;
    ctx.resources.io_mut().advance(ctx.time);
    let io = ctx.resources.io().system.as_ref();
    let level = io.and_then(|io| io.value(id)).unwrap_or(0.0) != 0.0;
    Ok((level, io.map_or(0, |io| io.changes().len())))
}

/// Looks for hits since the last look; ends the search, or waits on.
fn look(ctx: &mut Ctx<'_>, args: &[Value], mut search: Search) -> Res {
    let trigger = Trigger::of(args);
    let now = ctx.time;
    let mut first_hit = None;
    for (time, old, new) in events(ctx, args, &mut search)? {
        if trigger.hit(old, new) {
            search.hits += 1;
            first_hit.get_or_insert(time);
        }
    }
    let stops = [HEAD.stop, HEAD.pstop, HEAD.sstop].iter().any(|&i| present(args.get(i)));
    if let Some(t) = first_hit {
        if search.hits == 1 {
            store_hit(ctx, args, t)?;
        }
        if stops {
            // The robot brakes on its path from the hit; the instruction ends when it
            // stands still.
            let stands = ctx.resources.robot_mut().brake_at(t, stop_time(args));
            super::moves::wait_for_robot(ctx, stands);
            return Ok(None);
        }
    }
    if now < search.end {
        let next = rapid_vm::ext::next_event(ctx).map_or(search.end, |n| n.min(search.end));
        ctx.wait = Some((next - now).max(1e-6));
        ctx.stop = StopKind::Repeat;
        ctx.resources.robot_mut().search = Some(search);
        return Ok(None);
    }
    finish(ctx, args, &search)
}

/// How long the robot takes to stop after a hit, s: the manual's typical stop
/// distances at a search speed of 50 mm/s are 1-3 mm with `\Stop`, 4-8 mm with `\SStop`
/// and 15-25 mm with `\PStop`; the middle of each, braked at a constant rate
/// (distance = speed · time / 2), gives 0.08 s, 0.24 s and 0.8 s.
// uncertain: the distances are as we remember the manual's table; the stop is taken to
// last the same time at any speed (its distance grows with the speed), on the path for
// all three (\Stop leaves the path a little on the real robot).
fn stop_time(args: &[Value]) -> f64 {
    const AT_50: f64 = 50.0;
    let mm = if present(args.get(HEAD.stop)) {
        2.0
    } else if present(args.get(HEAD.sstop)) {
        6.0
    } else {
        20.0
    };
    2.0 * mm / AT_50
}

/// The robot is at ToPoint: no hit, or (`\Sup`) more than one, are errors.
fn finish(ctx: &mut Ctx<'_>, args: &[Value], search: &Search) -> Res {
    if search.hits == 0 {
        return Err(ctx.error(Err::WhlSearch, "the search reached ToPoint without a hit"));
    }
    if present(args.get(HEAD.sup)) && search.hits > 1 {
        return Err(ctx.error(Err::SigSupSearch, "more than one hit during a supervised search (\\Sup)"));
    }
    Ok(None)
}

/// The level changes since the last look: (time, old, new).
fn events(ctx: &mut Ctx<'_>, args: &[Value], search: &mut Search) -> Result<Vec<(f64, bool, bool)>, RapidError> {
    if present(args.get(HEAD.pers_bool)) {
        let level = matches!(ctx.value(&args[HEAD.pers_bool])?, Value::Bool(true));
        let old = std::mem::replace(&mut search.last, level);
        return Ok(if old != level { vec![(ctx.time, old, level)] } else { Vec::new() });
    }
    let id = rapid_signals::signal(ctx, &args[HEAD.signal])?;
    ctx.resources.io_mut().advance(ctx.time);
    let Some(io) = ctx.resources.io().system.as_ref() else { return Ok(Vec::new()) };
    let changes = io.changes();
    let found = changes
        .get(search.seen..)
        .unwrap_or(&[])
        .iter()
        .filter(|c| c.id == id && c.time <= search.end)
        .map(|c| (c.time, c.old != 0.0, c.new != 0.0))
        .collect();
    search.seen = changes.len();
    Ok(found)
}

/// SearchPoint: where the TCP was at time `t`, in the search's tool and work object,
/// with the external axes then (SearchExtJ: the axis values as a jointtarget).
fn store_hit(ctx: &mut Ctx<'_>, args: &[Value], t: f64) -> Result<(), RapidError> {
    let mut chain = ctx.resources.robot_mut().active;
    chain.base = ctx.resources.robot_mut().track_base_at(t);
    let robot = ctx.resources.robot_mut();
    let joints = robot.joints_at(t);
    let extax = robot.extax_read(t);
    let pose = chain.target_of(&rapid_motion::Kinematics::forward(&robot.kin, &joints));
    let conf = rapid_motion::confdata::confdata_of(&robot.kin, &joints);
    let value = match ctx.value(&args[HEAD.search_point])? {
        Value::Record(r) if r.fields.len() == 2 => data::jointtarget_value(ctx, &joints)?,
        _ => data::robtarget_value(ctx, &pose, conf)?,
    };
    ctx.store(&args[HEAD.search_point], super::frame::with_extax(&value, &extax))
}

#[cfg(test)]
mod layout_tests {
    use super::*;
    use rapid_vm::ext::ABSENT;

    // SearchL [\Stop]|[\PStop]|[\SStop]|[\Sup] Signal|PersBool [\Flanks]|[\PosFlank]|
    // [\NegFlank]|[\HighLevel]|[\LowLevel] SearchPoint ToPoint [\ID] Speed [\V]|[\T] Tool
    // [\WObj] [\Corr]: eleven parameters before SearchPoint (11), then the move's.
    #[test]
    fn places_after_search_point() {
        let l = &*SEARCH_L;
        let expected =
            Places { cir: None, to: 12, id: 13, speed: 14, v: 15, t: 16, tool: 17, wobj: 18, corr: 19, ext_only: None };
        assert_eq!(*l, expected);
        let c = Places {
            cir: Some(12),
            to: 13,
            id: 14,
            speed: 15,
            v: 16,
            t: 17,
            tool: 18,
            wobj: 19,
            corr: 20,
            ext_only: None,
        };
        assert_eq!(*SEARCH_C, c);
        // SearchExtJ … SearchJointPos ToJointPos [\ID] [\UseEOffs] Speed [\T].
        let ext = Places {
            cir: None,
            to: 12,
            id: 13,
            speed: 15,
            v: ABSENT,
            t: 16,
            tool: ABSENT,
            wobj: ABSENT,
            corr: ABSENT,
            ext_only: Some(14),
        };
        assert_eq!(*SEARCH_EXT_J, ext);
    }

    // The eleven parameters before SearchPoint: \Stop|\PStop|\SStop|\Sup (0–3),
    // Signal|PersBool (4, 5), \Flanks|\PosFlank|\NegFlank|\HighLevel|\LowLevel (6–10).
    #[test]
    fn head_is_shared() {
        let head = Head {
            stop: 0,
            pstop: 1,
            sstop: 2,
            sup: 3,
            signal: 4,
            pers_bool: 5,
            flanks: 6,
            neg_flank: 8,
            high_level: 9,
            low_level: 10,
            search_point: 11,
        };
        assert_eq!(*HEAD, head);
        assert_eq!(Head::of("SearchC"), head);
        assert_eq!(Head::of("SearchExtJ"), head);
    }
}
