//! An embedder's extension (`rapid_vm::embed`) seen from outside the crate: a family
//! of built-ins defined here, with state of its own in the task's resources and a
//! hook the core loop calls, run by a RAPID program. `GetUASUserName` and
//! `HollowWristReset` are catalogue routines the core does not run (`not_yet.rs`): an
//! extension may bring them.

use std::sync::Arc;

use rapid_sema::{Options, SourceInput};
use rapid_vm::builtins::{native, Builtins, Ctx, Family};
use rapid_vm::embed::{Extension, PendingEvent, TaskHooks, TaskState};
use rapid_vm::error::RapidError;
use rapid_vm::value::Value;
use rapid_vm::{load_in, Exit, LoadError, RecordingHost};

/// The extension's per-task state: how often HollowWristReset ran.
#[derive(Default)]
struct Resets(u32);

impl TaskState for Resets {}

fn user_name(_: &mut Ctx<'_>, _: &[Value]) -> Result<Option<Value>, RapidError> {
    Ok(Some(Value::Str("operator".into())))
}

fn hollow_wrist_reset(ctx: &mut Ctx<'_>, _: &[Value]) -> Result<Option<Value>, RapidError> {
    let resets = ctx.resources.extensions.get_mut::<Resets>().ok_or_else(|| RapidError::fatal("no state"))?;
    resets.0 += 1;
    Ok(None)
}

static FAMILY: Family = Family {
    file: file!(),
    builtins: &[native("GetUASUserName", user_name), native("HollowWristReset", hollow_wrist_reset)],
};

/// Logs one warning for every reset it has not logged yet.
struct Hooks;

impl TaskHooks for Hooks {
    fn take_events(&self, resources: &mut rapid_vm::builtins::Resources, now: f64) -> Vec<PendingEvent> {
        let Some(resets) = resources.extensions.get_mut::<Resets>() else { return Vec::new() };
        std::mem::take(&mut resets.0)
            .checked_sub(1)
            .map(|_| PendingEvent {
                event: rapid_vm::events::Event {
                    seq: 0,
                    domain: rapid_vm::events::MOTION_DOMAIN,
                    number: 999,
                    kind: rapid_vm::events::EventKind::Warning,
                    time: now,
                    title: "wrist reset".to_string(),
                    details: Vec::new(),
                    lines: Vec::new(),
                    place: None,
                },
                at: None,
            })
            .into_iter()
            .collect()
    }
}

static EXTENSION: Extension = Extension {
    name: "test",
    families: &[&FAMILY],
    hooks: Some(&Hooks),
    init: Some(|resources| resources.extensions.insert(Resets::default())),
};

const PROGRAM: &str = "MODULE t\nPROC main()\n  TPWrite GetUASUserName();\n  HollowWristReset;\n  HollowWristReset;\n  TPWrite \"done\";\nENDPROC\nENDMODULE";

fn load(builtins: Arc<Builtins>) -> Result<rapid_vm::Loaded, LoadError> {
    load_in(&[SourceInput::from_text("t.mod", PROGRAM)], "main", &Options::default(), builtins)
}

#[test]
fn a_family_from_outside_the_core_runs_with_its_state_and_hooks() {
    let mut loaded = load(Arc::new(Builtins::new(&[&EXTENSION]))).unwrap_or_else(|e| panic!("{e:?}"));
    let mut host = RecordingHost::default();
    let exit = loaded.vm.run(&mut host, 10_000);
    assert!(matches!(exit, Exit::Done), "{exit:?}");
    assert_eq!(host.lines, ["operator", "done"]);
    // Each reset was logged by the hook after its call, then the counter went back.
    let warnings = loaded.vm.event_log().iter().filter(|e| e.number == 999).count();
    assert_eq!(warnings, 2);
    assert_eq!(loaded.vm.resources().extensions.get::<Resets>().map(|r| r.0), Some(0));
}

#[test]
fn without_the_extension_its_routines_are_refused_at_load() {
    match load(Builtins::core()) {
        Err(LoadError::Unsupported(errors)) => {
            assert!(errors.iter().any(|e| e.message.contains("GetUASUserName")), "{errors:?}");
        }
        Err(other) => panic!("refused for another reason: {other:?}"),
        Ok(_) => panic!("GetUASUserName is not the core's"),
    }
}

#[test]
fn a_set_with_the_extension_is_not_in_step_with_not_yet() {
    // The catalogue check sees the two routines both run and listed as not run yet.
    let wrong = rapid_vm::builtins::out_of_step(&Builtins::new(&[&EXTENSION]));
    assert!(wrong.iter().any(|w| w.starts_with("GetUASUserName: registered and listed")), "{wrong:?}");
    assert!(wrong.iter().any(|w| w.starts_with("HollowWristReset: registered and listed")), "{wrong:?}");
}
