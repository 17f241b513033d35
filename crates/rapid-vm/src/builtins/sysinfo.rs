//! System information (§1.17) of our virtual controller: GetSysInfo, IsSysId, RobOS,
//! OpMode, RunMode, NonMotionMode, ProgMemFree, GetNextOption, GetNextProduct and
//! EventType. The controller is virtual, so every answer is a documented constant,
//! except OpMode's, which is the controller state `rapid run --mode` set.
//!
//! ExecHandler and ExecLevel are not here: they need to know whether the caller runs in
//! an ERROR/BACKWARD/UNDO handler or a trap routine, which `Ctx` does not tell.

use super::{native, present, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("GetSysInfo", get_sys_info),
        native("IsSysId", is_sys_id),
        native("RobOS", rob_os),
        native("OpMode", op_mode),
        native("RunMode", run_mode),
        native("NonMotionMode", non_motion_mode),
        native("ProgMemFree", prog_mem_free),
        native("GetNextOption", get_next_option),
        native("GetNextProduct", get_next_product),
        native("EventType", event_type),
    ],
};

// uncertain: what a real virtual controller reports is not public; these are ours.
/// The controller's serial number (GetSysInfo \SerialNo, IsSysId).
const SERIAL_NO: &str = "VC-00001";
/// The RobotWare version whose semantics we follow (the spec is RW 6.15.04).
const SW_VERSION: &str = "6.15.04.00";
const SW_VERSION_NAME: &str = "RobotWare 6.15.04";
/// The robot of the virtual controller's motion task.
const ROBOT_TYPE: &str = "IRB 120-3/0.58";
const CTRL_ID: &str = "VC";
/// The loopback address: programs pass `GetSysInfo(\LanIp)` to SocketBind, and on our
/// controller the address they can bind is the host's loopback.
const LAN_IP: &str = "127.0.0.1";
const CTRL_LANG: &str = "en";
const SYSTEM_NAME: &str = "OpenRAPID";
/// Free program memory in bytes (ProgMemFree): the whole of the program memory of the
/// one table of limits (`rapid_limits::PROGRAM_MEMORY_BYTES`, ours: ABB publishes no
/// figure), the figure `rapid check` and Load measure programs against. What the loaded
/// program takes is not subtracted: the interpreter's memory is not the controller's,
/// and how a controller counts a program is not public. 64 MiB (2^26) is exact in a num.
const PROG_MEM_FREE: f32 = rapid_limits::PROGRAM_MEMORY_BYTES as f32;
/// Installed options (GetNextOption), in ABB's "number name" form: the ones whose
/// instructions the interpreter provides (sockets, RMQ between tasks).
const OPTIONS: &[&str] = &["616-1 PC Interface", "623-1 Multitasking", "672-1 Socket Messaging"];
/// Installed products and their versions (GetNextProduct).
const PRODUCTS: &[(&str, &str)] = &[("RobotWare", SW_VERSION)];

/// `GetSysInfo([\SerialNo] | [\SWVersion] | ... | [\SystemName])`: one item of
/// system information, chosen by the switch.
fn get_sys_info(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    const ITEMS: [&str; 8] =
        [SERIAL_NO, SW_VERSION, SW_VERSION_NAME, ROBOT_TYPE, CTRL_ID, LAN_IP, CTRL_LANG, SYSTEM_NAME];
    // uncertain: the manual lists every switch as optional; without one we raise
    // ERR_ARGVALERR rather than guess an item.
    let Some(item) = args.iter().zip(ITEMS).find(|(arg, _)| present(Some(arg))).map(|(_, item)| item) else {
        return Err(ctx.error(Err::ArgValue, "GetSysInfo needs one of its switches"));
    };
    Ok(Some(Value::Str(item.into())))
}

/// `IsSysId(SystemId)`: whether SystemId is this controller's serial number.
fn is_sys_id(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let id = ctx.string(&args[0])?;
    Ok(Some(Value::Bool(id == SERIAL_NO)))
}

/// `RobOS()`: FALSE, execution is on a virtual controller.
fn rob_os(_: &mut Ctx<'_>, _: &[Value]) -> Res {
    Ok(Some(Value::Bool(false)))
}

/// `OpMode()`: the operating mode the run was started in (`rapid run --mode`,
/// OP_AUTO unless told).
fn op_mode(ctx: &mut Ctx<'_>, _: &[Value]) -> Res {
    Ok(Some(Value::Num(ctx.resources.controller.mode.symnum())))
}

/// `RunMode([\Main])`: how the program is being run (continuously, stepped forward
/// or backward, move step), as the controller set it for the task.
// uncertain: `\Main` asks for the mode of the motion task the task is connected to;
// the controller sets the same mode in every NORMAL task, so the task's own answers.
fn run_mode(ctx: &mut Ctx<'_>, _: &[Value]) -> Res {
    Ok(Some(Value::Num(ctx.resources.controller.run_mode.symnum())))
}

/// `NonMotionMode([\Main])`: FALSE; the task executes its movements (virtually).
fn non_motion_mode(_: &mut Ctx<'_>, _: &[Value]) -> Res {
    Ok(Some(Value::Bool(false)))
}

/// `ProgMemFree()`: free program memory in bytes.
fn prog_mem_free(_: &mut Ctx<'_>, _: &[Value]) -> Res {
    Ok(Some(Value::Num(PROG_MEM_FREE)))
}

/// `EventType()`: the event routine running now (EVENT_NONE outside one).
fn event_type(ctx: &mut Ctx<'_>, _: &[Value]) -> Res {
    Ok(Some(Value::Num(f32::from(ctx.resources.tasks.event))))
}

/// `GetNextOption(ListNumber, Name)`: the option at ListNumber (from 0) in Name and
/// TRUE, or FALSE past the end.
fn get_next_option(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let index = next_index(ctx, &args[0])?;
    let Some(name) = OPTIONS.get(index) else { return Ok(Some(Value::Bool(false))) };
    ctx.store(&args[1], Value::Str((*name).into()))?;
    Ok(Some(Value::Bool(true)))
}

crate::builtins::signature::layout! {
    static NEXT_PRODUCT: NextProductArgs = "GetNextProduct" { version: "Version" }
}

/// `GetNextProduct(ListNumber, Name [\Version])`: as GetNextOption, for products.
fn get_next_product(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let index = next_index(ctx, &args[0])?;
    let Some((name, version)) = PRODUCTS.get(index) else { return Ok(Some(Value::Bool(false))) };
    ctx.store(&args[1], Value::Str((*name).into()))?;
    if present(args.get(NEXT_PRODUCT.version)) {
        ctx.store(&args[NEXT_PRODUCT.version], Value::Str((*version).into()))?;
    }
    Ok(Some(Value::Bool(true)))
}

/// The list index in an INOUT ListNumber, which is then advanced by one. Like
/// GetNextMechUnit's, it is incremented on every call (uncertain: also past the end).
fn next_index(ctx: &mut Ctx<'_>, list_number: &Value) -> Result<usize, RapidError> {
    let n = ctx.num(list_number)?;
    if n.fract() != 0.0 || n < 0.0 {
        return Err(ctx.error(Err::ArgValue, format!("ListNumber {n} is not a list position (0, 1, 2 ...)")));
    }
    ctx.store(list_number, Value::Num((n + 1.0) as f32))?;
    Ok(n as usize)
}
