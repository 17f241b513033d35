//! Configuration data (manual §1.17): ReadCfgData, WriteCfgData and SaveCfgData on the
//! system parameters the run was started with (a backup's `SYSPAR/*.cfg`).
//!
//! An instance path is `/DOMAIN/TYPE/NAME` (the instance whose `-Name` is NAME) or,
//! with `\ListNo`, `/DOMAIN/TYPE/ATTRIBUTE/VALUE` (the instances whose ATTRIBUTE is
//! VALUE; `\ListNo` picks one, 0 first, and comes back as the next one's number or
//! END_OF_LIST, -1, after the last). Attribute values have the type the file gives them:
//! a quoted value is a string, a bare number a num, a flag a bool.
//!
//! GetModalPayLoadMode reads one parameter of it (SYS, ModalPayLoadMode).
//!
//! Writes change the configuration in memory (the controller uses most parameters after
//! a restart); SaveCfgData writes a domain's file, every other byte as it was read.
//!
//! The configuration itself is the controller's: it installs a [`CfgDatabase`] (over
//! its parsed files) in each task, and this module knows no file format. The family
//! is an extension of the interpreter ([`EXTENSION`]); the configuration lives in the
//! task's extension slot, kept at PP to Main.

use std::any::Any;
use std::path::Path;

use rapid_vm::ext::{
    devices, native, present, Ctx, Err, Extension, Family, FileKind, FileSystem, RapidError, Resources, TaskState,
    Value,
};

type Res = Result<Option<Value>, RapidError>;

/// `END_OF_LIST`: what `\ListNo` becomes after the last matching instance.
const END_OF_LIST: f32 = -1.0;

/// Where an instance is within its domain, as the database numbers it.
pub type InstanceAt = (usize, usize);

/// An attribute as the configuration writes it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CfgAttr {
    /// Written without a value (`-Enabled`).
    Flag,
    /// A value in double quotes, quotes taken off.
    Quoted(String),
    /// A value written bare (`-MaxLog 10`).
    Bare(String),
}

/// A change WriteCfgData makes to an instance's attribute.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CfgEdit<'a> {
    /// Write the attribute as a flag (nothing when it is written already).
    SetFlag,
    /// Take the attribute out (nothing when it is not written).
    Remove,
    /// Write the attribute with this value (quoted as the file has it).
    Value(&'a str),
}

/// Why the database refused an edit: the value cannot be written (a string with `"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Unwritable;

/// What ReadCfgData, WriteCfgData, SaveCfgData and GetModalPayLoadMode need of the
/// system parameters. The controller keeps the configuration in its own format and
/// installs an implementation of this in each task; the VM knows no file format.
/// Domains are numbered from 0.
pub trait CfgDatabase: std::fmt::Debug + Send + Sync {
    /// The database itself, for the controller that installed it.
    fn as_any(&self) -> &dyn Any;
    /// How many domains (EIO, SYS, …) the configuration has.
    fn domain_count(&self) -> usize;
    /// The name of domain `domain`, e.g. `EIO`.
    fn domain_name(&self, domain: usize) -> &str;
    /// Domain `domain` as its file is written, every byte as it was read except for
    /// WriteCfgData's changes.
    fn domain_text(&self, domain: usize) -> &str;
    /// The instances of type `type_name` whose attribute `attr` is `value`, in file order.
    fn find(&self, domain: usize, type_name: &str, attr: &str, value: &str) -> Vec<InstanceAt>;
    /// Attribute `name` of an instance, when the instance writes it.
    fn attr(&self, domain: usize, at: InstanceAt, name: &str) -> Option<CfgAttr>;
    /// Attribute `name` as the first instance of the same type that writes it writes it.
    fn attr_of_type(&self, domain: usize, at: InstanceAt, name: &str) -> Option<CfgAttr>;
    /// Changes attribute `name` of an instance.
    fn edit(&mut self, domain: usize, at: InstanceAt, name: &str, edit: CfgEdit<'_>) -> Result<(), Unwritable>;
}

/// The configuration of the run, as the controller installed it.
#[derive(Debug, Default)]
pub struct CfgState {
    database: Option<Box<dyn CfgDatabase>>,
}

/// The configuration built-ins and the task's configuration.
pub static EXTENSION: Extension = Extension { name: "cfgdata", families: &[&FAMILY], hooks: None, init: Some(init) };

fn init(resources: &mut Resources) {
    resources.extensions.insert(CfgState::default());
}

/// Kept at PP to Main: the configuration is the system's, not the program's.
impl TaskState for CfgState {}

/// What a task without a configuration reads: none.
static NO_CONFIG: CfgState = CfgState { database: None };

/// The task's configuration (none installed: empty).
pub fn of(resources: &Resources) -> &CfgState {
    resources.extensions.get::<CfgState>().unwrap_or(&NO_CONFIG)
}

/// The task's configuration, to install one (put in if the task had none).
pub fn of_mut(resources: &mut Resources) -> &mut CfgState {
    resources.extensions.get_or_default::<CfgState>()
}

fn cfg<'a>(ctx: &'a Ctx<'_>) -> &'a CfgState {
    of(ctx.resources)
}

impl CfgState {
    /// Installs the configuration the task reads and writes.
    pub fn set_config(&mut self, database: Box<dyn CfgDatabase>) {
        self.database = Some(database);
    }

    /// The configuration as it stands, WriteCfgData's changes included (what a front
    /// end shows of the system parameters); none when none was installed.
    pub fn database(&self) -> Option<&dyn CfgDatabase> {
        self.database.as_deref()
    }

    fn domain_count(&self) -> usize {
        self.database.as_ref().map_or(0, |db| db.domain_count())
    }

    fn domain(&self, name: &str) -> Option<usize> {
        let db = self.database.as_ref()?;
        (0..db.domain_count()).find(|&d| db.domain_name(d).eq_ignore_ascii_case(name))
    }

    /// The value of ModalPayLoadMode (GetModalPayLoadMode): SYS.cfg's `GENERAL_RAPID`
    /// instance of that `-Name`, its `-Value`; the default without a SYS domain,
    /// without the instance, or with a value that is not a number.
    // uncertain: the SYS.cfg form (type GENERAL_RAPID, one instance per parameter with
    // -Name and -Value) is as RobotWare 6 backups write General Rapid parameters; ABB's
    // system parameters manual gives 0 and 1 as the values and 1 as the default.
    pub fn modal_pay_load_mode(&self) -> f32 {
        let (Some(db), Some(domain)) = (self.database.as_deref(), self.domain("SYS")) else {
            return MODAL_PAY_LOAD_DEFAULT;
        };
        let found = db.find(domain, "GENERAL_RAPID", "Name", "ModalPayLoadMode");
        let value = match found.first().and_then(|&at| db.attr(domain, at, "Value")) {
            Some(CfgAttr::Quoted(text) | CfgAttr::Bare(text)) => text.trim().parse::<f32>().ok(),
            _ => None,
        };
        value.unwrap_or(MODAL_PAY_LOAD_DEFAULT)
    }
}

/// An instance path taken apart.
struct InstancePath {
    domain: String,
    type_name: String,
    /// (attribute, value) the instances must have: `("Name", NAME)` for the short form.
    key: (String, String),
}

// uncertain: a path with another number of parts is not found (ERR_CFG_NOTFND) rather
// than refused some other way. A path without the leading `/` is read as with it: the
// manual's examples all have it, but public production code reads
// "MOC/ROBOT_SERIAL_NUMBER/rob_1" (next to WriteCfgData paths with the slash).
fn parse_path(text: &str) -> Option<InstancePath> {
    let parts: Vec<&str> = text.strip_prefix('/').unwrap_or(text).split('/').collect();
    let (domain, type_name, key) = match parts.as_slice() {
        [domain, type_name, name] => (domain, type_name, ("Name".to_owned(), (*name).to_owned())),
        [domain, type_name, attr, value] => (domain, type_name, ((*attr).to_owned(), (*value).to_owned())),
        _ => return None,
    };
    if domain.is_empty() || type_name.is_empty() {
        return None;
    }
    Some(InstancePath { domain: (*domain).to_owned(), type_name: (*type_name).to_owned(), key })
}

/// Where an instance is: its domain, where in it, and the `\ListNo` to hand back.
struct Found {
    domain: usize,
    at: InstanceAt,
    next: Option<f32>,
}

/// Finds the instance of a path (and `\ListNo`), or raises the error the manual names.
fn find(ctx: &mut Ctx<'_>, path_text: &str, list_no: Option<&Value>) -> Result<Found, RapidError> {
    let Some(path) = parse_path(path_text) else {
        return Err(ctx.error(
            Err::CfgNotFound,
            format!("`{path_text}` is not an instance path such as \"/EIO/EIO_SIGNAL/di1\""),
        ));
    };
    if cfg(ctx).domain_count() == 0 {
        // uncertain: without a configuration nothing is found (the controller always has one).
        return Err(ctx.error(Err::CfgNotFound, "no system configuration is loaded (run a backup folder)"));
    }
    let Some(domain) = cfg(ctx).domain(&path.domain) else {
        return Err(ctx.error(Err::CfgNotFound, format!("no configuration domain `{}`", path.domain)));
    };
    let (attr, wanted) = &path.key;
    let found = cfg(ctx).database().map_or_else(Vec::new, |db| db.find(domain, &path.type_name, attr, wanted));
    if found.is_empty() {
        return Err(ctx.error(Err::CfgNotFound, format!("no instance `{path_text}`")));
    }
    let Some(list_arg) = list_no.filter(|a| present(Some(*a))) else {
        return Ok(Found { domain, at: found[0], next: None });
    };
    // uncertain: a \ListNo that is negative, fractional or past the last match raises
    // ERR_CFG_OUTOFBOUNDS; the manual's loop ends at END_OF_LIST without raising.
    let n = ctx.num(list_arg)?;
    if n.fract() != 0.0 || n < 0.0 || n >= found.len() as f64 {
        let message = format!("\\ListNo {n} is outside 0..{} for `{path_text}`", found.len() - 1);
        return Err(ctx.error(Err::CfgOutOfBounds, message));
    }
    let idx = n as usize;
    let next = if idx + 1 < found.len() { (idx + 1) as f32 } else { END_OF_LIST };
    Ok(Found { domain, at: found[idx], next: Some(next) })
}

/// The kind of value an attribute holds, as the file writes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Text,
    Number,
    Flag,
}

fn kind_of(attr: &CfgAttr) -> Kind {
    match attr {
        CfgAttr::Flag => Kind::Flag,
        CfgAttr::Quoted(_) => Kind::Text,
        CfgAttr::Bare(text) if text.parse::<f64>().is_ok() => Kind::Number,
        // uncertain: bare words that are not numbers (`30,82`) read as strings.
        CfgAttr::Bare(_) => Kind::Text,
    }
}

fn kind_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Text => "string",
        Kind::Number => "num",
        Kind::Flag => "bool",
    }
}

/// The kind a CfgData argument's type asks for.
fn wanted_kind(value: &Value) -> Option<Kind> {
    match value {
        Value::Str(_) => Some(Kind::Text),
        Value::Num(_) | Value::Dnum(_) => Some(Kind::Number),
        Value::Bool(_) => Some(Kind::Flag),
        _ => None,
    }
}

rapid_vm::ext::layout! {
    static CFG_DATA: CfgDataArgs = "ReadCfgData" | "WriteCfgData" { cfg_data: "CfgData", list_no: "ListNo" }
    static SAVE: SaveArgs = "SaveCfgData" { file: "File", domain: "Domain" }
}

/// `ReadCfgData InstancePath, Attribute, CfgData [\ListNo]`.
fn read_cfg_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let path = ctx.string(&args[0])?;
    let attr_name = ctx.string(&args[1])?;
    let at = *CFG_DATA;
    let target = ctx.value(&args[at.cfg_data])?;
    let found = find(ctx, &path, args.get(at.list_no))?;
    let attr = cfg(ctx).database().and_then(|db| db.attr(found.domain, found.at, &attr_name));
    let Some(wanted) = wanted_kind(&target) else {
        return Err(ctx.error(Err::CfgIllType, "CfgData must be num, dnum, bool or string"));
    };
    let value = match attr {
        // uncertain: a flag the instance does not write is FALSE (its default); any
        // other attribute it does not write is not found (we know no defaults).
        None if wanted == Kind::Flag => Value::Bool(false),
        None => return Err(ctx.error(Err::CfgNotFound, format!("`{path}` has no attribute `{attr_name}`"))),
        Some(attr) => {
            let kind = kind_of(&attr);
            if kind != wanted {
                let message = format!(
                    "attribute `{attr_name}` of `{path}` is a {}, CfgData is a {}",
                    kind_name(kind),
                    kind_name(wanted)
                );
                return Err(ctx.error(Err::CfgIllType, message));
            }
            let text = match &attr {
                CfgAttr::Flag => "",
                CfgAttr::Quoted(text) | CfgAttr::Bare(text) => text.as_str(),
            };
            match (kind, &target) {
                (Kind::Flag, _) => Value::Bool(true),
                (Kind::Text, _) => Value::Str(text.into()),
                (Kind::Number, Value::Dnum(_)) => Value::Dnum(text.parse::<f64>().unwrap_or_default()),
                (Kind::Number, _) => Value::Num(text.parse::<f32>().unwrap_or_default()),
            }
        }
    };
    ctx.store(&args[at.cfg_data], value)?;
    if let Some(next) = found.next {
        ctx.store(&args[at.list_no], Value::Num(next))?;
    }
    Ok(None)
}

/// `WriteCfgData InstancePath, Attribute, CfgData [\ListNo]`.
fn write_cfg_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let path = ctx.string(&args[0])?;
    let attr_name = ctx.string(&args[1])?;
    let at = *CFG_DATA;
    let value = ctx.value(&args[at.cfg_data])?;
    let found = find(ctx, &path, args.get(at.list_no))?;
    let Some(wanted) = wanted_kind(&value) else {
        return Err(ctx.error(Err::CfgIllType, "CfgData must be num, dnum, bool or string"));
    };
    let kind = match attribute_kind(cfg(ctx), &found, &attr_name) {
        Some(kind) => kind,
        None => return Err(ctx.error(Err::CfgNotFound, format!("`{path}` has no attribute `{attr_name}`"))),
    };
    if kind != wanted {
        let message =
            format!("attribute `{attr_name}` of `{path}` is a {}, CfgData is a {}", kind_name(kind), kind_name(wanted));
        return Err(ctx.error(Err::CfgIllType, message));
    }
    let number = match &value {
        Value::Num(n) => Some(f64::from(*n)),
        Value::Dnum(d) => Some(*d),
        _ => None,
    };
    // uncertain: without the parameter schema's limits, ERR_CFG_LIMIT is raised only for
    // what no file can hold: a number that is not finite, a string with `"`.
    if number.is_some_and(|n| !n.is_finite()) {
        return Err(ctx.error(Err::CfgLimit, "a configuration number must be finite"));
    }
    let written = match of_mut(ctx.resources).database.as_deref_mut() {
        Some(db) => write_value(db, &found, &attr_name, &value, number),
        None => Ok(()),
    };
    if written.is_err() {
        return Err(ctx.error(Err::CfgLimit, "a configuration string cannot hold `\"`"));
    }
    if let Some(next) = found.next {
        ctx.store(&args[at.list_no], Value::Num(next))?;
    }
    Ok(None)
}

/// Writes a CfgData value into an attribute: a bool as the flag written or taken out,
/// a number as the configuration writes numbers. Only a string can be refused.
fn write_value(
    db: &mut dyn CfgDatabase,
    found: &Found,
    attr_name: &str,
    value: &Value,
    number: Option<f64>,
) -> Result<(), Unwritable> {
    let (domain, at) = (found.domain, found.at);
    match value {
        Value::Bool(true) => _ = db.edit(domain, at, attr_name, CfgEdit::SetFlag),
        Value::Bool(false) => _ = db.edit(domain, at, attr_name, CfgEdit::Remove),
        Value::Str(s) => return db.edit(domain, at, attr_name, CfgEdit::Value(s)),
        _ => {
            if let Some(n) = number {
                _ = db.edit(domain, at, attr_name, CfgEdit::Value(&format_number(n)));
            }
        }
    }
    Ok(())
}

/// The kind of an attribute: as this instance writes it, else as another instance of
/// the same type does (an attribute left at its default is not written).
// uncertain: without ABB's parameter schema, an attribute no instance of the type
// writes is not found.
fn attribute_kind(state: &CfgState, found: &Found, attr_name: &str) -> Option<Kind> {
    let db = state.database()?;
    let attr =
        db.attr(found.domain, found.at, attr_name).or_else(|| db.attr_of_type(found.domain, found.at, attr_name));
    attr.as_ref().map(kind_of)
}

/// A number as the configuration writes it: integers without a point, others in the
/// shortest form that reads back the same.
fn format_number(n: f64) -> String {
    if n.fract() == 0.0 && n.abs() < 1e15 {
        format!("{}", n as i64)
    } else {
        format!("{}", n as f32)
    }
}

/// `SaveCfgData FilePath [\File], Domain`.
fn save_cfg_data(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SAVE;
    let file_path = ctx.string(&args[0])?;
    let file = match args.get(at.file) {
        Some(arg) if present(Some(arg)) => Some(ctx.string(arg)?),
        _ => None,
    };
    let domain = ctx.string(&args[at.domain])?;
    let all = domain.eq_ignore_ascii_case("ALL");
    let chosen: Vec<usize> =
        if all { (0..cfg(ctx).domain_count()).collect() } else { cfg(ctx).domain(&domain).into_iter().collect() };
    if chosen.is_empty() {
        return Err(ctx.error(Err::CfgIllDomain, format!("no configuration domain `{domain}` is loaded")));
    }
    let target = devices::join_object(&file_path, file.as_deref());
    for idx in chosen {
        // ALL_DOMAINS saves each domain as DOMAIN.cfg in the folder FilePath names.
        // uncertain: the file names of ALL_DOMAINS follow the backup's SYSPAR names.
        let text = if all {
            let name = cfg(ctx).database().map_or("", |db| db.domain_name(idx));
            devices::join_object(&target, Some(&format!("{name}.cfg")))
        } else {
            target.clone()
        };
        let resolved =
            ctx.resources.devices.resolve(&text).map_err(|fault| ctx.error(Err::CfgWriteFile, fault.message()))?;
        let fs = ctx.resources.devices.file_system();
        if resolved.is_device_root || fs.metadata(&resolved.path).is_ok_and(|m| m.kind == FileKind::Dir) {
            return Err(ctx.error(Err::CfgWriteFile, format!("`{text}` is a folder, not a file")));
        }
        let contents = cfg(ctx).database().map_or_else(String::new, |db| db.domain_text(idx).to_owned());
        write_atomically(ctx.resources.devices.file_system(), &resolved.path, contents.as_bytes())
            .map_err(|e| ctx.error(Err::CfgWriteFile, format!("cannot write `{text}`: {e}")))?;
    }
    Ok(None)
}

/// `GetModalPayLoadMode()`: the system parameter ModalPayLoadMode (topic Controller,
/// type General Rapid) of the configuration the run was started with: 1 when the
/// payload is modal (GripLoad declares it for the moves that follow), 0 when it is not
/// (each move gives its own with `\TLoad`).
fn get_modal_pay_load_mode(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    Ok(Some(Value::Num(cfg(ctx).modal_pay_load_mode())))
}

/// ModalPayLoadMode's default: payload modal, as a controller without the parameter in
/// its SYS.cfg runs.
const MODAL_PAY_LOAD_DEFAULT: f32 = 1.0;

/// Writes a file so a crash leaves the old or the new contents, never a torn file:
/// a temporary file beside it, flushed to disk, then renamed over it.
fn write_atomically(fs: &dyn FileSystem, path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let Some(parent) = path.parent() else { return Err(std::io::Error::other("the path has no folder")) };
    if !fs.metadata(parent).is_ok_and(|m| m.kind == FileKind::Dir) {
        return Err(std::io::Error::new(std::io::ErrorKind::NotFound, "the folder does not exist"));
    }
    fs.write_atomic(path, bytes)
}

static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("ReadCfgData", read_cfg_data),
        native("WriteCfgData", write_cfg_data),
        native("SaveCfgData", save_cfg_data),
        native("GetModalPayLoadMode", get_modal_pay_load_mode),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths() {
        let p = parse_path("/EIO/EIO_SIGNAL/di1").expect("path");
        assert_eq!(
            (p.domain.as_str(), p.type_name.as_str(), p.key.0.as_str(), p.key.1.as_str()),
            ("EIO", "EIO_SIGNAL", "Name", "di1")
        );
        let p = parse_path("/EIO/EIO_SIGNAL/Device/d652").expect("path");
        assert_eq!((p.key.0.as_str(), p.key.1.as_str()), ("Device", "d652"));
        // Without the leading slash: read as with it.
        let p = parse_path("EIO/EIO_SIGNAL/di1").expect("path");
        assert_eq!((p.domain.as_str(), p.key.1.as_str()), ("EIO", "di1"));
        assert!(parse_path("/EIO/di1").is_none());
        assert!(parse_path("//EIO_SIGNAL/x").is_none());
    }

    #[test]
    fn numbers() {
        assert_eq!(format_number(4.0), "4");
        assert_eq!(format_number(-1.0), "-1");
        assert_eq!(format_number(0.05), "0.05");
    }
}
