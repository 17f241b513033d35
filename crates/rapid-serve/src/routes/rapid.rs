//! `/rw/rapid`: execution (state, start, stop, PP to Main), tasks (list, activate,
//! deactivate, program pointer), symbol data (get and set as RAPID literals), symbol
//! search and the modules of a task.

use std::sync::Arc;

use axum::http::Method;
use rapid_controller::api::{StartFrom, StepKind};
use rapid_controller::StopKind;

use super::{not_found, Req, Res};
use crate::core::Core;
use crate::model::{Item, Reply, RwsError};
use crate::App;

const BASE: &str = "/rw/rapid/";

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    let rest: Vec<&str> = req.segs[2..].iter().map(String::as_str).collect();
    match rest.as_slice() {
        ["execution"] => execution(app, req).await,
        ["tasks"] if req.is(Method::GET) => {
            let items = app.controller.call(|core| task_items(core, None)).await?;
            Ok(Reply::Items { base: BASE.into(), items })
        }
        ["tasks", task] => task_route(app, req, task).await,
        ["tasks", task, "pcp"] if req.is(Method::GET) && req.action().is_none() => program_pointer(app, task).await,
        ["tasks", task, "pcp"] if req.is(Method::POST) && req.action() == Some("set-pp-routine") => {
            // uncertain: the action and its `routine` field as we read the RWS manual.
            let (task, routine) = ((*task).to_owned(), req.need("routine")?.to_owned());
            app.controller
                .call(move |core| core.session.pp_to_routine(&task, &routine))
                .await?
                .map_err(|e| RwsError::from_api(&e))?;
            Ok(Reply::NoContent)
        }
        ["symbol", "data", "RAPID", path @ ..] if (2..=3).contains(&path.len()) => {
            symbol_data(app, req, path.join("/")).await
        }
        ["symbol", "properties", "RAPID", path @ ..] if (2..=3).contains(&path.len()) && req.is(Method::GET) => {
            properties(app, path.iter().map(|p| (*p).to_owned()).collect()).await
        }
        ["symbols"] if req.action() == Some("search-symbols") && req.is(Method::POST) => search_symbols(app, req).await,
        ["modules"] if req.is(Method::GET) => modules(app, req).await,
        ["modules", module] if req.is(Method::GET) && req.action().is_none() => module_text(app, req, module).await,
        _ => Err(not_found(req)),
    }
}

/// `GET /rw/rapid/execution` and its actions.
async fn execution(app: &Arc<App>, req: &Req) -> Res {
    match (req.action(), &req.method) {
        (None, &Method::GET) => {
            let (state, cycle) = app.controller.call(|core| (core.exec_state(), core.cycle.clone())).await?;
            let item = Item::new("rap-execution", "execution").with("ctrlexecstate", state).with("cycle", cycle);
            Ok(Reply::Items { base: BASE.into(), items: vec![item] })
        }
        (Some("start"), &Method::POST) => {
            let order = StartOrder::parse(req)?;
            app.controller.call(move |core| start(core, &order)).await??;
            Ok(Reply::NoContent)
        }
        (Some("stop"), &Method::POST) => {
            let kind = match req.field("stopmode").unwrap_or("stop") {
                "stop" | "instr" => StopKind::Stop,
                "qstop" => StopKind::Quick,
                "cycle" => StopKind::Cycle,
                other => return Err(RwsError::bad_request(format!("stopmode `{other}`: stop, qstop, cycle or instr"))),
            };
            app.controller.call(move |core| stop(core, kind)).await??;
            Ok(Reply::NoContent)
        }
        (Some("setcycle"), &Method::POST) => {
            let (cycles, name) = match req.need("cycle")? {
                "once" => (1, "once"),
                "forever" => (0, "forever"),
                other => return Err(RwsError::bad_request(format!("cycle `{other}`: once or forever"))),
            };
            app.controller
                .call(move |core| {
                    core.session.set_cycles(cycles);
                    core.cycle = name.to_owned();
                })
                .await?;
            Ok(Reply::NoContent)
        }
        (Some("resetpp"), &Method::POST) => {
            app.controller.call(reset_pp).await??;
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}

/// A start's `execmode` other than `continue`.
#[derive(Debug, Clone, Copy)]
enum Step {
    /// `stepin`, `stepover`, `stepout`: one step forward; `stepmotion`: forward
    /// until a motion instruction has run.
    Forward(StepKind),
    /// `stepback`: one statement backward (the manual's §1.21 rules).
    Back,
}

/// The fields of a start, checked.
struct StartOrder {
    step: Option<Step>,
    cycles: Option<(u64, &'static str)>,
}

impl StartOrder {
    fn parse(req: &Req) -> Result<StartOrder, RwsError> {
        let bad = |field: &str, value: &str, allowed: &str| {
            RwsError::bad_request(format!("{field} `{value}`: expected {allowed}"))
        };
        match req.field("regain").unwrap_or("continue") {
            "continue" | "regain" | "clear" => {}
            other => return Err(bad("regain", other, "continue, regain or clear")),
        }
        let step = match req.field("execmode").unwrap_or("continue") {
            "continue" => None,
            "stepin" => Some(Step::Forward(StepKind::Into)),
            "stepover" => Some(Step::Forward(StepKind::Over)),
            "stepout" => Some(Step::Forward(StepKind::Out)),
            "stepback" => Some(Step::Back),
            // The PC SDK's ExecutionMode.StepMotion, "execute to next motion
            // instruction": on until a motion instruction has run.
            "stepmotion" => Some(Step::Forward(StepKind::Motion)),
            // The PC SDK's ExecutionMode leaves out its number (6): what it does is
            // not in the public record, so it is not guessed.
            "steplast" => {
                return Err(RwsError::unsupported("execmode `steplast` (its meaning is not in the public record)"))
            }
            other => {
                return Err(bad(
                    "execmode",
                    other,
                    "continue, stepin, stepover, stepout, stepback, steplast or stepmotion",
                ))
            }
        };
        let cycles = match req.field("cycle").unwrap_or("asis") {
            "asis" => None,
            "once" => Some((1, "once")),
            "forever" => Some((0, "forever")),
            other => return Err(bad("cycle", other, "asis, once or forever")),
        };
        match req.field("condition").unwrap_or("none") {
            "none" => {}
            "callchain" => return Err(RwsError::unsupported("condition `callchain`")),
            other => return Err(bad("condition", other, "none")),
        }
        match req.field("stopatbp").unwrap_or("enabled") {
            "enabled" | "disabled" => {}
            other => return Err(bad("stopatbp", other, "enabled or disabled")),
        }
        match req.field("alltaskbytsp").unwrap_or("false") {
            "true" | "false" => {}
            other => return Err(bad("alltaskbytsp", other, "true or false")),
        }
        Ok(StartOrder { step, cycles })
    }
}

/// Starts the program (or steps its first NORMAL task). After a cycle has ended the
/// program starts from Main, as the controller's PP has gone back there.
fn start(core: &mut Core, order: &StartOrder) -> Result<(), RwsError> {
    if core.exec_state() == "running" {
        return Err(RwsError::wrong_state("the program is running already"));
    }
    if !core.session.motors_on() {
        return Err(RwsError::wrong_state("the motors are off"));
    }
    let tasks = core.session.tasks();
    if let Some(off) = tasks.iter().find(|t| t.kind == "NORMAL" && core.inactive.iter().any(|n| n == &t.name)) {
        return Err(RwsError::unsupported(format!(
            "starting with NORMAL task {} deactivated (it would run all the same)",
            off.name
        )));
    }
    if let Some((cycles, name)) = order.cycles {
        core.session.set_cycles(cycles);
        core.cycle = name.to_owned();
    }
    let result = match order.step {
        Some(kind) => {
            let task = tasks.iter().find(|t| t.kind == "NORMAL").map(|t| t.name.clone());
            let task = task.ok_or_else(|| RwsError::wrong_state("no NORMAL task to step"))?;
            match kind {
                Step::Forward(kind) => core.session.step(&task, kind),
                Step::Back => core.session.step_backward(&task).map(|_| ()),
            }
        }
        None if core.session.all_normal_ended() => core.session.start(StartFrom::Main),
        None => core.session.start(StartFrom::Pointer),
    };
    result.map_err(|e| RwsError::from_api(&e))
}

/// PP to Main. A program whose NORMAL tasks have all ended (a `Stop` or the end of a
/// cycle) is shown to clients as stopped, while the session still counts it as
/// running: it is stopped first, so that PP to Main is accepted as the state shown
/// says it should be.
fn reset_pp(core: &mut Core) -> Result<(), RwsError> {
    use rapid_controller::ProgramState as P;
    let running = matches!(core.session.program_state(), P::Running | P::Stopping { .. } | P::Stepping { .. });
    if running && core.exec_state() == "stopped" {
        core.session.stop(StopKind::Stop).map_err(|e| RwsError::from_api(&e))?;
    }
    core.session.pp_to_main().map_err(|e| RwsError::from_api(&e))
}

/// Stops the program; a program that is not running stays as it is (no error, as a
/// client that stops before it starts expects).
fn stop(core: &mut Core, kind: StopKind) -> Result<(), RwsError> {
    if core.exec_state() != "running" {
        return Ok(());
    }
    core.session.stop(kind).map_err(|e| RwsError::from_api(&e))
}

/// The tasks (or the one named) as `rap-task-li` items.
fn task_items(core: &Core, only: Option<&str>) -> Vec<Item> {
    let running = core.exec_state() == "running";
    core.session
        .tasks()
        .into_iter()
        .filter(|t| only.is_none_or(|name| t.name.eq_ignore_ascii_case(name)))
        .map(|t| {
            let ended = t.state != "active";
            // NORMAL tasks follow the program; STATIC and SEMISTATIC run on.
            let excstate = match (ended, t.kind == "NORMAL", running) {
                (true, _, _) => "ready",
                (false, false, _) | (false, true, true) => "started",
                (false, true, false) => "stopped",
            };
            let active = if core.inactive.iter().any(|n| n.eq_ignore_ascii_case(&t.name)) { "Off" } else { "On" };
            Item::new("rap-task-li", &t.name)
                .with("name", t.name.clone())
                .with("type", t.kind.to_ascii_lowercase())
                // uncertain: "linked" is the state of a task whose program is loaded
                // and linked, as we read the RWS manual.
                .with("taskstate", "linked")
                .with("excstate", excstate)
                .with("active", active)
                .with("motiontask", if t.motion { "TRUE" } else { "FALSE" })
        })
        .collect()
}

async fn task_route(app: &Arc<App>, req: &Req, task: &str) -> Res {
    let name = task.to_owned();
    match (req.action(), &req.method) {
        (None, &Method::GET) => {
            let items = app.controller.call(move |core| task_items(core, Some(&name))).await?;
            if items.is_empty() {
                return Err(RwsError::not_found(format!("no task `{task}`")));
            }
            Ok(Reply::Items { base: BASE.into(), items })
        }
        (Some(action @ ("activate" | "deactivate")), &Method::POST) => {
            let on = action == "activate";
            app.controller.call(move |core| activate(core, &name, on)).await??;
            Ok(Reply::NoContent)
        }
        (Some("loadmod"), &Method::POST) => {
            let path = rapid_path(req.need("modulepath")?)?;
            let replace = req.field("replace").unwrap_or("false") == "true";
            let replaced = if replace { module_in(app, &path).await } else { None };
            app.controller
                .call(move |core| {
                    if let Some(module) = replaced {
                        let loaded = core.session.modules(&name).unwrap_or_default();
                        if loaded.iter().any(|m| m.eq_ignore_ascii_case(&module)) {
                            core.session.unload_module(&name, &module)?;
                        }
                    }
                    core.module_changes += 1;
                    core.session.load_module(&name, &path)
                })
                .await?
                .map_err(|e| RwsError::from_api(&e))?;
            Ok(Reply::NoContent)
        }
        (Some("unloadmod"), &Method::POST) => {
            let module = req.need("module")?.to_owned();
            app.controller
                .call(move |core| {
                    core.module_changes += 1;
                    core.session.unload_module(&name, &module)
                })
                .await?
                .map_err(|e| RwsError::from_api(&e))?;
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}

/// Marks a task active or not (the task selection panel).
fn activate(core: &mut Core, task: &str, on: bool) -> Result<(), RwsError> {
    let Some(view) = core.session.tasks().into_iter().find(|t| t.name.eq_ignore_ascii_case(task)) else {
        return Err(RwsError::not_found(format!("no task `{task}`")));
    };
    if core.exec_state() == "running" {
        return Err(RwsError::wrong_state("tasks are selected while the program is stopped"));
    }
    core.inactive.retain(|n| !n.eq_ignore_ascii_case(&view.name));
    if !on {
        core.inactive.push(view.name);
    }
    Ok(())
}

/// `GET /rw/rapid/tasks/{task}/pcp`: where the program pointer stands.
async fn program_pointer(app: &Arc<App>, task: &str) -> Res {
    let name = task.to_owned();
    let at = app.controller.call(move |core| core.session.program_pointer(&name)).await?;
    let at = at.map_err(|e| RwsError::from_api(&e))?;
    let mut item = Item::new("pcp-info", "progpointer");
    if let Some(at) = at {
        let module =
            std::path::Path::new(&at.file).file_stem().map_or_else(String::new, |s| s.to_string_lossy().into());
        item = item
            .with("beginposition", format!("{},{}", at.line, at.column))
            .with("endposition", format!("{},{}", at.line, at.column))
            .with("modulemame", module)
            .with("routinename", at.routine);
    }
    Ok(Reply::Items { base: BASE.into(), items: vec![item] })
}

/// `/rw/rapid/symbol/data/RAPID/{task}[/{module}]/{name}[;value]`: get, or set.
async fn symbol_data(app: &Arc<App>, req: &Req, path: String) -> Res {
    let path = path.strip_suffix(";value").map(str::to_owned).unwrap_or(path);
    let title = format!("RAPID/{path}");
    match (req.action(), &req.method) {
        (None, &Method::GET) => {
            let value = app.controller.call(move |core| core.session.read_data(&path)).await?;
            let value = value.map_err(|e| RwsError::from_api(&e))?;
            let item = Item::new("rap-data", &title).with("value", value.value);
            Ok(Reply::Items { base: BASE.into(), items: vec![item] })
        }
        (Some("set"), &Method::POST) => {
            let literal = req.need("value")?.to_owned();
            let written = app.controller.call(move |core| core.session.write_data(&path, &literal)).await?;
            written.map_err(|e| RwsError::from_api(&e))?;
            Ok(Reply::NoContent)
        }
        _ => Err(not_found(req)),
    }
}

/// `POST /rw/rapid/symbols?action=search-symbols`: the data of a task (or of one of
/// its modules), filtered by kind (`symtyp` per, var, con or any).
async fn search_symbols(app: &Arc<App>, req: &Req) -> Res {
    let block = req.field("blockurl").unwrap_or("RAPID").to_owned();
    let kinds: &'static [&'static str] = match req.field("symtyp").unwrap_or("any") {
        "per" => &["PERS"],
        "var" => &["VAR"],
        "con" => &["CONST"],
        "any" | "dat" => &["PERS", "VAR", "CONST"],
        other => return Err(RwsError::unsupported(format!("symtyp `{other}`: only data (per, var, con, any)"))),
    };
    let parts: Vec<String> = block.split('/').map(str::to_owned).collect();
    if parts.first().map(String::as_str) != Some("RAPID") || parts.len() > 3 {
        return Err(RwsError::bad_request(format!("blockurl `{block}`: RAPID[/TASK[/MODULE]]")));
    }
    let items = app
        .controller
        .call(move |core| {
            let tasks: Vec<String> = match parts.get(1) {
                Some(task) => vec![task.clone()],
                None => core.session.tasks().into_iter().map(|t| t.name).collect(),
            };
            let mut items = Vec::new();
            for task in tasks {
                let data = core.session.list_data(&task).map_err(|e| RwsError::from_api(&e))?;
                for d in data {
                    let in_module = parts.get(2).is_none_or(|m| m.eq_ignore_ascii_case(&d.module));
                    if !in_module || !kinds.contains(&d.kind) {
                        continue;
                    }
                    items.push(symbol_item(&task, &d));
                }
            }
            Ok::<_, RwsError>(items)
        })
        .await??;
    Ok(Reply::Items { base: BASE.into(), items })
}

/// `GET /rw/rapid/modules?task=T`: the modules of a task.
async fn modules(app: &Arc<App>, req: &Req) -> Res {
    let task = req.query("task").unwrap_or("T_ROB1").to_owned();
    let items = app
        .controller
        .call(move |core| {
            let names = core.session.modules(&task).map_err(|e| RwsError::from_api(&e))?;
            Ok(names
                .into_iter()
                .map(|name| Item::new("rap-module-info-li", &name).with("name", name).with("type", "ProgMod"))
                .collect())
        })
        .await??;
    Ok(Reply::Items { base: BASE.into(), items })
}

/// `GET /rw/rapid/modules/{module}?task=T&resource=module-text`: the module's text as
/// program memory holds it (class `rap-module-text`, title `moduletext`, fields
/// `change-count` and `module-text`, as RobotWare 6's answers in the public record
/// show them). RobotWare hands a long module over as a file (`file-path` under
/// `/TEMP`) instead; the length where it does so is not in the public record, so the
/// text always comes inline here. Without `resource`: the module's attributes.
async fn module_text(app: &Arc<App>, req: &Req, module: &str) -> Res {
    match req.query("resource") {
        Some("module-text") => {}
        None => return module_attributes(app, req, module).await,
        Some(other) => return Err(RwsError::unsupported(format!("module resource `{other}`"))),
    }
    let task = req.query("task").unwrap_or("T_ROB1").to_owned();
    let module = module.to_owned();
    let (text, changes) = app
        .controller
        .call(move |core| core.session.module_text(&task, &module).map(|text| (text, core.module_changes)))
        .await?
        .map_err(|e| RwsError::from_api(&e))?;
    let item = Item::new("rap-module-text", "moduletext")
        // uncertain: RobotWare's count of the task's program changes; ours counts the
        // modules loaded and unloaded through RWS.
        .with("change-count", changes.to_string())
        .with("module-length", text.len().to_string())
        .with("module-text", text);
    Ok(Reply::Items { base: BASE.into(), items: vec![item] })
}

/// `GET /rw/rapid/modules/{module}?task=T`: the module's attributes as the RWS manual
/// gives them: `rap-module` titled `TASK/module`, with `modname`, `filename` (the
/// file's name, without its folder) and `attribute` (the module attributes in RAPID's
/// order, as `sysmod`, `noview`, `nostepin`, `viewonly`, `readonly`, joined by commas;
/// empty for a module without any).
async fn module_attributes(app: &Arc<App>, req: &Req, module: &str) -> Res {
    let task = req.query("task").unwrap_or("T_ROB1").to_owned();
    let module = module.to_owned();
    let (task, info) = app
        .controller
        .call(move |core| {
            let info = core.session.module_info(&task, &module)?;
            // The task's name as the controller spells it.
            let name = core.session.tasks().into_iter().find(|t| t.name.eq_ignore_ascii_case(&task));
            Ok::<_, rapid_controller::api::ApiError>((name.map_or(task, |t| t.name), info))
        })
        .await?
        .map_err(|e| RwsError::from_api(&e))?;
    let file = std::path::Path::new(&info.file).file_name().map_or_else(String::new, |f| f.to_string_lossy().into());
    let words: Vec<&str> = info
        .attributes
        .iter()
        .map(|a| match *a {
            "SYSMODULE" => "sysmod",
            "NOVIEW" => "noview",
            "NOSTEPIN" => "nostepin",
            "VIEWONLY" => "viewonly",
            _ => "readonly",
        })
        .collect();
    let item = Item::new("rap-module", &format!("{task}/{}", info.name))
        .with("modname", info.name)
        .with("filename", file)
        .with("attribute", words.join(","));
    Ok(Reply::Items { base: BASE.into(), items: vec![item] })
}

/// A datum as symbol search and symbol properties show it.
fn symbol_item(task: &str, d: &rapid_controller::api::DataInfo) -> Item {
    let (class, symtyp) = match d.kind {
        "PERS" => ("rap-symproppers", "per"),
        "VAR" => ("rap-sympropvar", "var"),
        _ => ("rap-sympropconstant", "con"),
    };
    let url = format!("RAPID/{task}/{}/{}", d.module, d.name);
    Item::new(class, &url)
        .with("symburl", url.clone())
        .with("name", d.name.clone())
        .with("symtyp", symtyp)
        .with("dattyp", d.type_name.clone())
        .with("local", if d.local { "true" } else { "false" })
        .with("rdonly", if d.kind == "CONST" { "true" } else { "false" })
}

/// `GET /rw/rapid/symbol/properties/RAPID/{task}[/{module}]/{name}`: a datum's kind,
/// type and module.
async fn properties(app: &Arc<App>, path: Vec<String>) -> Res {
    let item = app
        .controller
        .call(move |core| {
            let (task, module, name) = match path.as_slice() {
                [task, name] => (task, None, name),
                [task, module, name] => (task, Some(module), name),
                _ => return Err(RwsError::bad_request("RAPID/TASK[/MODULE]/NAME")),
            };
            let data = core.session.list_data(task).map_err(|e| RwsError::from_api(&e))?;
            let found = data.iter().find(|d| {
                d.name.eq_ignore_ascii_case(name)
                    && match module {
                        Some(m) => d.module.eq_ignore_ascii_case(m),
                        None => !d.local,
                    }
            });
            let d = found.ok_or_else(|| RwsError::not_found(format!("no data `{name}` in task {task}")))?;
            Ok(symbol_item(task, d))
        })
        .await??;
    Ok(Reply::Items { base: BASE.into(), items: vec![item] })
}

/// A module path as RWS clients give it (`$HOME/x.mod`, `HOME:/x.mod`, `/hd0a/…` is not
/// ours) as the RAPID path the task loads (`HOME:/x.mod`).
fn rapid_path(text: &str) -> Result<String, RwsError> {
    let text = text.trim();
    if let Some(rest) = text.strip_prefix('$') {
        let (device, tail) = rest.split_once('/').unwrap_or((rest, ""));
        let device = super::files::device_name(device)
            .ok_or_else(|| RwsError::bad_request(format!("modulepath `{text}`: no such device")))?;
        return Ok(format!("{device}:/{tail}"));
    }
    if text.contains(':') {
        return Ok(text.to_owned());
    }
    Err(RwsError::bad_request(format!("modulepath `{text}`: a device is needed ($HOME/…, HOME:/…)")))
}

/// The name of the module in the file at RAPID path `path`, read through the file
/// service's folders (for `replace=true`); None when it cannot be told.
async fn module_in(app: &Arc<App>, path: &str) -> Option<String> {
    let (device, tail) = path.split_once(':')?;
    let root = app.file_root.clone()?;
    let segs: Vec<String> = std::iter::once(device.to_owned())
        .chain(tail.split('/').filter(|s| !s.is_empty()).map(str::to_owned))
        .collect();
    let host = super::files::resolve(&root, &segs).ok()?;
    let bytes = tokio::task::spawn_blocking(move || std::fs::read(host)).await.ok()?.ok()?;
    let text = String::from_utf8_lossy(&bytes);
    let mut words = text.split_whitespace().skip_while(|w| !w.eq_ignore_ascii_case("MODULE"));
    words.next()?;
    let name: String = words.next()?.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
    Some(name).filter(|n| !n.is_empty())
}
