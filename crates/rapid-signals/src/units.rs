//! I/O devices (units) and networks (buses) (§1.9 "禁用和启用I/O模块", "获取 I/O 网络和
//! 设备状态", "I/O网络的启动"): IODisable, IOEnable, IOUnitState, IOBusState, IOBusStart,
//! IOEventMessage.
//!
//! The devices and networks are those of EIO.cfg, kept in the I/O system every task
//! shares. A simulated device switches at once while it answers on its network; the
//! stimulus can disconnect it (`at T disconnect DEVICE`, a tool uncoupled) and connect
//! it again: IOEnable then waits for it, at most MaxTime (ERR_IOENABLE). Disabling
//! needs no answer from the device, so IODisable never runs out of MaxTime
//! (ERR_IODISABLE cannot happen; uncertain). Every network runs, so IOBusStart has
//! nothing to start. Unknown names raise ERR_NAME_INVALID.

use rapid_vm::ext::{native, present, Ctx, Err, Family, RapidError, StopKind, Value};

use crate::io::IoAccess;

type Res = Result<Option<Value>, RapidError>;

/// iounit_state values, as the catalogue declares them (public programs confirm them).
const IOUNIT_RUNNING: f32 = 1.0;
const IOUNIT_RUNERROR: f32 = 2.0;
const IOUNIT_DISABLE: f32 = 3.0;
const IOUNIT_LOG_STATE_DISABLED: f32 = 10.0;
const IOUNIT_LOG_STATE_ENABLED: f32 = 11.0;
const IOUNIT_PHYS_STATE_DEACTIVATED: f32 = 20.0;
const IOUNIT_PHYS_STATE_RUNNING: f32 = 21.0;
const IOUNIT_PHYS_STATE_ERROR: f32 = 22.0;

/// busstate values, as the catalogue declares them.
// uncertain: BUSSTATE_RUN = 1 is what public programs quote; the numbers of the
// IOBUS_LOG_STATE_* and IOBUS_PHYS_STATE_* constants are not public.
const BUSSTATE_RUN: f32 = 1.0;
const IOBUS_LOG_STATE_STARTED: f32 = 12.0;
const IOBUS_PHYS_STATE_RUNNING: f32 = 22.0;

/// The I/O device name argument, checked to be a configured device (ERR_NAME_INVALID).
fn device_name(ctx: &mut Ctx<'_>, arg: &Value) -> Result<String, RapidError> {
    let name = ctx.string(arg)?;
    let known = ctx.resources.io().system.as_ref().is_some_and(|io| io.units().device(&name).is_some());
    if !known {
        return Err(ctx.error(Err::NameInvalid, format!("no I/O device `{name}` is configured")));
    }
    Ok(name)
}

/// The network name argument, checked to be a network of the configuration
/// (ERR_NAME_INVALID).
fn network_name(ctx: &mut Ctx<'_>, arg: &Value) -> Result<String, RapidError> {
    let name = ctx.string(arg)?;
    // Without an I/O configuration there is still the controller's own network.
    let known = match ctx.resources.io().system.as_ref() {
        Some(io) => io.units().has_network(&name),
        None => name.eq_ignore_ascii_case(rapid_io::LOCAL_NETWORK),
    };
    if !known {
        return Err(ctx.error(Err::NameInvalid, format!("no I/O network `{name}` is configured")));
    }
    Ok(name)
}

/// MaxTime of IODisable/IOEnable: how long the program may wait for the device.
// uncertain: a negative or non-finite MaxTime is refused with ERR_ARGVALERR; the manual
// only describes the timeout.
fn max_time(ctx: &mut Ctx<'_>, arg: &Value) -> Result<f64, RapidError> {
    let max = ctx.num(arg)?;
    if !max.is_finite() || max < 0.0 {
        return Err(ctx.error(Err::ArgValue, format!("MaxTime {max} s is not a time")));
    }
    Ok(max)
}

/// `IODisable UnitName MaxTime` / `IOEnable UnitName MaxTime`. The simulated device
/// switches at once, inside any MaxTime; an order for the state it has already changes
/// nothing.
fn switch_device(ctx: &mut Ctx<'_>, args: &[Value], enabled: bool) -> Res {
    let name = device_name(ctx, &args[0])?;
    let max = max_time(ctx, &args[1])?;
    let time = ctx.time;
    ctx.resources.io_mut().advance(time);
    if enabled && !connected(ctx, &name) {
        return wait_for_device(ctx, &name, max);
    }
    ctx.resources.waiting = None;
    let result = match ctx.resources.io_mut().system.as_mut() {
        Some(io) => io.set_device_enabled(&name, enabled, time).map_err(|e| e.to_string()),
        None => Err(format!("no I/O device `{name}` is configured")),
    };
    result.map_err(|message| ctx.error(Err::NameInvalid, message))?;
    Ok(None)
}

fn connected(ctx: &Ctx<'_>, name: &str) -> bool {
    ctx.resources.io().system.as_ref().is_none_or(|io| io.units().is_connected(name).unwrap_or(true))
}

/// IOEnable of a device that does not answer: waits for the stimulus to connect it
/// (the instruction runs again then), at most `max` seconds from the first try.
fn wait_for_device(ctx: &mut Ctx<'_>, name: &str, max: f64) -> Res {
    let here = rapid_vm::ext::call_site(ctx);
    let now = ctx.time;
    let started = match ctx.resources.waiting {
        Some((depth, pc, at)) if (depth, pc) == here => at,
        _ => now,
    };
    let deadline = started + max;
    if now >= deadline {
        ctx.resources.waiting = None;
        return Err(ctx.error(Err::IoEnable, format!("I/O device `{name}` did not answer within MaxTime {max} s")));
    }
    ctx.resources.waiting = Some((here.0, here.1, started));
    let next = rapid_vm::ext::next_event(ctx).map_or(deadline, |t| t.min(deadline));
    ctx.wait = Some((next - now).max(1e-6));
    ctx.stop = StopKind::Repeat;
    Ok(None)
}

fn io_disable(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    switch_device(ctx, args, false)
}

fn io_enable(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    switch_device(ctx, args, true)
}

/// `IOUnitState(UnitName [\Phys] | [\Logic])`: without a switch IOUNIT_RUNNING or
/// IOUNIT_DISABLE; `\Logic` IOUNIT_LOG_STATE_ENABLED/DISABLED; `\Phys`
/// IOUNIT_PHYS_STATE_RUNNING/DEACTIVATED.
fn io_unit_state(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = device_name(ctx, &args[0])?;
    let now = ctx.time;
    ctx.resources.io_mut().advance(now);
    let enabled = ctx.resources.io().system.as_ref().and_then(|io| io.units().is_enabled(&name).ok()).unwrap_or(false);
    // uncertain: an enabled device that does not answer is taken to be in error
    // (IOUNIT_RUNERROR, physically IOUNIT_PHYS_STATE_ERROR); logically still enabled.
    let answers = connected(ctx, &name);
    let state = match (present(args.get(1)), present(args.get(2)), enabled) {
        (true, _, true) if answers => IOUNIT_PHYS_STATE_RUNNING,
        (true, _, true) => IOUNIT_PHYS_STATE_ERROR,
        (true, _, false) => IOUNIT_PHYS_STATE_DEACTIVATED,
        (_, true, true) => IOUNIT_LOG_STATE_ENABLED,
        (_, true, false) => IOUNIT_LOG_STATE_DISABLED,
        (_, _, true) if answers => IOUNIT_RUNNING,
        (_, _, true) => IOUNIT_RUNERROR,
        (_, _, false) => IOUNIT_DISABLE,
    };
    Ok(Some(Value::Num(state)))
}

/// `IOBusState BusName State [\Phys] | [\Logic]`: every network runs.
fn io_bus_state(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    network_name(ctx, &args[0])?;
    let state = if present(args.get(2)) {
        IOBUS_PHYS_STATE_RUNNING
    } else if present(args.get(3)) {
        IOBUS_LOG_STATE_STARTED
    } else {
        BUSSTATE_RUN
    };
    ctx.store(&args[1], Value::Num(state))?;
    Ok(None)
}

/// `IOBusStart BusName`: the network runs already.
fn io_bus_start(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    network_name(ctx, &args[0])?;
    Ok(None)
}

rapid_vm::ext::layout! {
    static EVENT_MESSAGE: EventMessageArgs = "IOEventMessage" { device_name: "DeviceName" }
}

/// `IOEventMessage [\On] | [\Off] DeviceName`: the simulated devices log no events, so
/// only the name is checked.
fn io_event_message(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    device_name(ctx, &args[EVENT_MESSAGE.device_name])?;
    Ok(None)
}

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("IODisable", io_disable),
        native("IOEnable", io_enable),
        native("IOUnitState", io_unit_state),
        native("IOBusState", io_bus_state),
        native("IOBusStart", io_bus_start),
        native("IOEventMessage", io_event_message),
    ],
};
