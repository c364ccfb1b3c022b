//! I/O signals (through the world's [`crate::world::Io`]), waits for them,
//! and interrupts.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::SignalKind;
use crate::machine::{R, SignalTest, Timeout, Wait, WaitKind, fault, invalid, named_error};

/// The signal a signal argument stands for: its name and kind.
fn signal(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<(String, SignalKind)> {
    let v = signal_arg(cx, a, param)?;
    cx.m.signal_of(cx.sh, &v)
}

/// A signal argument's value (a signal data object), checked to be one.
fn signal_arg(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<Value> {
    let v = cx.req(a, param)?;
    if !crate::machine::is_signal(&v) {
        return invalid(format!(
            "{}: {param} must be a signal, not {}",
            a.name,
            crate::machine::describe(&v)
        ));
    }
    Ok(v)
}

fn digital(cx: &Cx<'_>, a: &Args, value: f64) -> R<f64> {
    if value == 0.0 || value == 1.0 {
        Ok(value)
    } else {
        fault(named_error(
            &cx.m.prog,
            "ERR_ARGVALERR",
            format!("{}: {value} is not a digital value (0 or 1)", a.name),
        ))
    }
}

fn check_output(a: &Args, name: &str, kind: SignalKind) -> R<()> {
    if kind.is_output() {
        Ok(())
    } else {
        invalid(format!(
            "{}: {name} is an input; only outputs can be set",
            a.name
        ))
    }
}

/// `SetDO Signal, Value [\SDelay]` and `SetGO Signal, Value`.
pub(crate) fn set_do(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, kind) = signal(cx, a, "Signal")?;
    check_output(a, &name, kind)?;
    let mut value = cx.num(a, "Value")?;
    if kind == SignalKind::DigitalOut {
        value = digital(cx, a, value)?;
    } else if value < 0.0 || value.fract() != 0.0 {
        return fault(named_error(
            &cx.m.prog,
            "ERR_ARGVALERR",
            format!("{}: {value} is not a group value", a.name),
        ));
    }
    match cx.opt_num(a, "SDelay")? {
        Some(delay) => cx.sh.set_signal_later(&name, value, delay),
        None => cx.sh.set_signal(&name, value),
    }
    Ok(Done::Next)
}

/// `Set Signal`.
pub(crate) fn set(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, kind) = signal(cx, a, "Signal")?;
    check_output(a, &name, kind)?;
    cx.sh.set_signal(&name, 1.0);
    Ok(Done::Next)
}

/// `Reset Signal`.
pub(crate) fn reset(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, kind) = signal(cx, a, "Signal")?;
    check_output(a, &name, kind)?;
    cx.sh.set_signal(&name, 0.0);
    Ok(Done::Next)
}

/// `InvertDO Signal`.
pub(crate) fn invert_do(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, kind) = signal(cx, a, "Signal")?;
    check_output(a, &name, kind)?;
    let v = cx.sh.io.read(&name).unwrap_or(0.0);
    cx.sh.set_signal(&name, 1.0 - v);
    Ok(Done::Next)
}

/// `PulseDO [\High] [\PLength] Signal`: 1 now, back after the pulse
/// (0.2 s unless given).
pub(crate) fn pulse_do(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, kind) = signal(cx, a, "Signal")?;
    check_output(a, &name, kind)?;
    let length = cx.opt_num(a, "PLength")?.unwrap_or(0.2);
    let before = cx.sh.io.read(&name).unwrap_or(0.0);
    cx.sh.set_signal(&name, 1.0);
    if !(a.given("High") && before == 1.0) {
        cx.sh.set_signal_later(&name, before, length);
    }
    Ok(Done::Next)
}

/// `SetAO Signal, Value`.
pub(crate) fn set_ao(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, kind) = signal(cx, a, "Signal")?;
    check_output(a, &name, kind)?;
    let value = cx.num(a, "Value")?;
    cx.sh.set_signal(&name, value);
    Ok(Done::Next)
}

/// `AliasIO FromSignal, ToSignal`: a signal variable stands for a
/// configured signal (named by a string or given as a signal).
pub(crate) fn alias_io(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let from = cx.req(a, "FromSignal")?;
    let name = match &from {
        Value::Str(s) => s.clone(),
        v if crate::machine::is_signal(v) => match v.field("name") {
            Some(Value::Str(s)) => s.clone(),
            _ => String::new(),
        },
        other => {
            return invalid(format!(
                "AliasIO: FromSignal must be a signal or its name, not {}",
                crate::machine::describe(other)
            ));
        }
    };
    let Some((canonical, _)) = cx.sh.io.signal(&name) else {
        return fault(named_error(
            &cx.m.prog,
            "ERR_ALIASIO_DEF",
            format!("AliasIO: there is no signal {name}"),
        ));
    };
    let p = cx.place_arg(a, "ToSignal")?;
    let ty = match cx.m.get(cx.sh, &p) {
        Some(Value::Record { ty, .. }) => ty.clone(),
        _ => return invalid("AliasIO: ToSignal must be a signal variable"),
    };
    cx.store(&p, crate::program::signal_value(&ty, &canonical))?;
    Ok(Done::Next)
}

/// `GetSignalOrigin(Signal, SignalName)`: `SIGORIG_CFG` for a signal of
/// the I/O configuration (or one the run takes from its use),
/// `SIGORIG_ALIAS` for a signal variable `AliasIO` connected, `SIGORIG_NONE`
/// for one connected to nothing; `SignalName` gets the configured signal's
/// name (empty for none).
pub(crate) fn get_signal_origin(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let v = signal_arg(cx, a, "Signal")?;
    let name = match v.field("name") {
        Some(Value::Str(s)) => s.clone(),
        _ => String::new(),
    };
    let configured = matches!(
        a.place_of("Signal"),
        Some(crate::machine::Place { root: crate::machine::Root::Global(g), path })
            if path.is_empty()
                && cx.m.prog.globals.get(*g as usize).is_some_and(|g| matches!(g.origin, crate::program::Origin::Signal))
    );
    let origin = if name.is_empty() {
        "SIGORIG_NONE"
    } else if configured {
        "SIGORIG_CFG"
    } else {
        "SIGORIG_ALIAS"
    };
    let to = cx.place_arg(a, "SignalName")?;
    cx.store(&to, Value::Str(name))?;
    cx.predefined(origin)
}

/// `AliasIOReset Signal`: the signal variable stands for no signal again.
pub(crate) fn alias_io_reset(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let p = cx.place_arg(a, "Signal")?;
    let ty = match cx.m.get(cx.sh, &p) {
        Some(v @ Value::Record { ty, .. }) if crate::machine::is_signal(v) => ty.clone(),
        _ => return invalid("AliasIOReset: Signal must be a signal variable"),
    };
    cx.store(&p, crate::program::signal_value(&ty, ""))?;
    Ok(Done::Next)
}

/// `DInput`, `DOutput`, `AInput`, `AOutput`, `GInput`, `GOutput`: the
/// signal's value.
pub(crate) fn input(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let v = cx.req(a, "Signal")?;
    cx.m.signal_value(cx.sh, &v).map(Value::Num)
}

/// `GInputDnum(Signal)`, `GOutputDnum(Signal)`: a group signal's value
/// as a dnum (up to 32 bits).
pub(crate) fn input_dnum(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let (name, _) = signal(cx, a, "Signal")?;
    Ok(Value::Dnum(cx.sh.io.read(&name).unwrap_or(0.0)))
}

/// `TestDI(Signal)`: whether a digital input is 1.
pub(crate) fn test_di(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let v = cx.req(a, "Signal")?;
    cx.m.signal_value(cx.sh, &v).map(|x| Value::Bool(x == 1.0))
}

/// The time flag of a wait that may time out is cleared; what happens at
/// the time-out: the flag set, or `ERR_WAIT_MAXTIME`.
fn timeout(cx: &mut Cx<'_>, a: &Args, what: &str) -> R<Timeout> {
    match cx.opt_place(a, "TimeFlag")? {
        Some(p) => {
            cx.store(&p, Value::Bool(false))?;
            Ok(Timeout::Flag(p))
        }
        None => Ok(Timeout::Error(
            "ERR_WAIT_MAXTIME",
            format!("{}: {what} did not happen within \\MaxTime", a.name),
        )),
    }
}

/// A wait for a signal, which ends when the signal passes `test`.
fn wait_signal(cx: &mut Cx<'_>, a: &Args, name: String, test: SignalTest, what: String) -> R<Done> {
    if cx.sh.io.read(&name).is_some_and(|v| test.holds(v)) {
        if let Some(p) = cx.opt_place(a, "TimeFlag")? {
            cx.store(&p, Value::Bool(false))?;
        }
        return Ok(Done::Next);
    }
    let max = cx.opt_num(a, "MaxTime")?;
    let on_timeout = timeout(cx, a, &what)?;
    Ok(Done::Wait(Box::new(Wait {
        kind: WaitKind::Signal { name, test },
        deadline: max.map(|m| cx.now() + m.max(0.0)),
        on_timeout,
        what,
    })))
}

/// `WaitDI Signal, Value [\MaxTime] [\TimeFlag]` (and `WaitDO`, `WaitGI`,
/// `WaitGO`): waits until the signal has the value.
pub(crate) fn wait_di(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, _) = signal(cx, a, "Signal")?;
    let value = cx.num(a, "Value")?;
    let what = format!("{} {name}, {value}", a.name);
    wait_signal(cx, a, name, SignalTest::Equal(value), what)
}

/// `WaitAI Signal, [\LT] | [\GT], Value` (and `WaitAO`).
pub(crate) fn wait_ai(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, _) = signal(cx, a, "Signal")?;
    let value = cx.num(a, "Value")?;
    let test = if a.given("LT") {
        SignalTest::Below(value)
    } else if a.given("GT") {
        SignalTest::Above(value)
    } else {
        SignalTest::Equal(value)
    };
    let what = format!("{} {name}", a.name);
    wait_signal(cx, a, name, test, what)
}

pub(crate) fn interrupt_number(cx: &mut Cx<'_>, a: &Args) -> R<i32> {
    let v = cx.req(a, "Interrupt")?;
    let id = v.as_f64().unwrap_or(0.0) as i32;
    if !cx.m.interrupts.is_connected(id) {
        return fault(named_error(
            &cx.m.prog,
            "ERR_CNTNOTVAR",
            format!(
                "{}: the interrupt is not connected to a trap routine (CONNECT)",
                a.name
            ),
        ));
    }
    Ok(id)
}

/// `ISignalDI [\Single] Signal, TriggValue, Interrupt` (and `ISignalDO`):
/// an interrupt each time the signal changes to the value.
pub(crate) fn i_signal(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, _) = signal(cx, a, "Signal")?;
    let value = cx.num(a, "TriggValue")?;
    let id = interrupt_number(cx, a)?;
    let single = a.given("Single") || a.given("SingleSafe");
    cx.m.interrupts.add_watch(id, &name, Some(value), single);
    Ok(Done::Next)
}

/// `ISignalGI` and `ISignalGO`: an interrupt at every change.
pub(crate) fn i_signal_any(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, _) = signal(cx, a, "Signal")?;
    let id = interrupt_number(cx, a)?;
    let single = a.given("Single") || a.given("SingleSafe");
    cx.m.interrupts.add_watch(id, &name, None, single);
    Ok(Done::Next)
}

/// `ISignalAI` and `ISignalAO`: an interrupt at the values that meet the
/// condition and move the signal far enough from the last reference
/// ([`crate::interrupts::AnalogTrigger`]).
pub(crate) fn i_signal_analog(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (name, _) = signal(cx, a, "Signal")?;
    let condition = cx.num(a, "Condition")? as i32;
    let high = cx.num(a, "HighValue")?;
    let low = cx.num(a, "LowValue")?;
    let delta = cx.num(a, "DeltaValue")?;
    let direction = if a.given("DPos") {
        1
    } else if a.given("DNeg") {
        -1
    } else {
        0
    };
    let id = interrupt_number(cx, a)?;
    let single = a.given("Single") || a.given("SingleSafe");
    let trigger = crate::interrupts::AnalogTrigger {
        condition,
        high,
        low,
        delta: delta.max(0.0),
        direction,
        reference: cx.sh.io.read(&name).unwrap_or(0.0),
    };
    cx.m.interrupts.add_analog_watch(id, &name, trigger, single);
    Ok(Done::Next)
}

/// `IPers [\Single] | [\SingleSafe] Name, Interrupt`: an interrupt each
/// time the persistent `Name` changes value (any task's write, as the
/// tasks share it), seen between statements.
pub(crate) fn i_pers(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let place = cx.place_arg(a, "Name")?;
    let now = cx.m.load(cx.sh, &place)?;
    let id = interrupt_number(cx, a)?;
    let single = a.given("Single") || a.given("SingleSafe");
    cx.m.interrupts.add_pers(id, place, now, single);
    Ok(Done::Next)
}

/// `IError ErrorDomain [\ErrorId] ErrorType, Interrupt`: an interrupt at
/// each entry of the controller's event log of that domain (`COMMON_ERR`:
/// any), number and type (`TYPE_ALL`: any). The simulated event log holds
/// what `ErrWrite` writes.
pub(crate) fn i_error(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let domain = cx.num(a, "ErrorDomain")?.max(0.0) as u32;
    let number = cx.opt_num(a, "ErrorId")?.map(|n| n.max(0.0) as u32);
    let kind = cx.num(a, "ErrorType")?.max(0.0) as u32;
    let id = interrupt_number(cx, a)?;
    cx.m.interrupts.add_error_watch(id, domain, number, kind);
    Ok(Done::Next)
}

/// `GetTrapData TrapEvent`: in the trap routine of an `IError`
/// interrupt, the event log entry it was raised for.
pub(crate) fn get_trap_data(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id =
        cx.m.prog
            .intno
            .and_then(|g| cx.m.globals.get(g as usize))
            .and_then(Value::as_f64)
            .unwrap_or(0.0) as i32;
    let Some(entry) = cx.m.interrupts.error_entry(id).filter(|_| cx.m.in_trap()) else {
        return invalid("GetTrapData: not in the trap routine of an IError interrupt");
    };
    let p = cx.place_arg(a, "TrapEvent")?;
    cx.store(
        &p,
        Value::Record {
            ty: "trapdata".to_owned(),
            fields: vec![("entry".to_owned(), Value::Num(entry as f32))],
        },
    )?;
    Ok(Done::Next)
}

/// `ReadErrData TrapEvent, ErrorDomain, ErrorId, ErrorType [\Title]
/// [\Str1] ... [\Str5]`: the event log entry `GetTrapData` got.
pub(crate) fn read_err_data(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let v = cx.req(a, "TrapEvent")?;
    let entry = v
        .field("entry")
        .and_then(Value::as_f64)
        .and_then(|i| cx.sh.event_log.get(i as usize))
        .cloned();
    let Some(e) = entry else {
        return invalid("ReadErrData: the trapdata holds no error (GetTrapData first)");
    };
    for (param, value) in [
        ("ErrorDomain", e.domain),
        ("ErrorId", e.number),
        ("ErrorType", e.kind),
    ] {
        let p = cx.place_arg(a, param)?;
        cx.store(&p, Value::Num(value as f32))?;
    }
    if let Some(p) = cx.opt_place(a, "Title")? {
        cx.store(&p, Value::Str(e.title.clone()))?;
    }
    for (i, param) in ["Str1", "Str2", "Str3", "Str4", "Str5"].iter().enumerate() {
        if let Some(p) = cx.opt_place(a, param)? {
            let s = e.lines.get(i).cloned().unwrap_or_default();
            cx.store(&p, Value::Str(s))?;
        }
    }
    Ok(Done::Next)
}

/// `ITimer [\Single] Time, Interrupt`.
pub(crate) fn i_timer(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let t = cx.num(a, "Time")?;
    if t <= 0.0 {
        return fault(named_error(
            &cx.m.prog,
            "ERR_ARGVALERR",
            format!(
                "ITimer: {} is not a positive time",
                crate::world::num_text(t)
            ),
        ));
    }
    let id = interrupt_number(cx, a)?;
    let single = a.given("Single") || a.given("SingleSafe");
    let now = cx.now();
    cx.m.interrupts.add_timer(id, now, t, single);
    Ok(Done::Next)
}

/// `IDelete Interrupt`.
pub(crate) fn i_delete(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let v = cx.req(a, "Interrupt")?;
    cx.m.interrupts.delete(v.as_f64().unwrap_or(0.0) as i32);
    Ok(Done::Next)
}

/// `IDisable`: interrupts wait until `IEnable`.
pub(crate) fn i_disable(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    cx.m.interrupts.disabled = true;
    Ok(Done::Next)
}

/// `IEnable`.
pub(crate) fn i_enable(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    cx.m.interrupts.disabled = false;
    Ok(Done::Next)
}

/// `ISleep Interrupt`: the interrupt is ignored until `IWatch`.
pub(crate) fn i_sleep(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id = interrupt_number(cx, a)?;
    cx.m.interrupts.sleep(id, true);
    Ok(Done::Next)
}

/// `IWatch Interrupt`.
pub(crate) fn i_watch(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id = interrupt_number(cx, a)?;
    cx.m.interrupts.sleep(id, false);
    Ok(Done::Next)
}

/// `ValidIO(Signal)`: whether the signal can be used: FALSE for a signal
/// variable that `AliasIO` has not connected, TRUE for a signal (the
/// simulation's I/O devices are always running).
pub(crate) fn valid_io(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let v = signal_arg(cx, a, "Signal")?;
    Ok(Value::Bool(cx.m.signal_of(cx.sh, &v).is_ok()))
}

/// `IOUnitState(UnitName [\Phys] | [\Logic])`: an I/O device is running
/// unless `IODisable` disabled it: `IOUNIT_RUNNING`/`IOUNIT_DISABLE`, with
/// `\Logic` `IOUNIT_LOG_STATE_ENABLED`/`_DISABLED`, with `\Phys`
/// `IOUNIT_PHYS_STATE_RUNNING`/`_DEACTIVATED`.
pub(crate) fn io_unit_state(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let unit = cx.string(a, "UnitName")?.to_ascii_lowercase();
    let disabled = cx.sh.disabled_io_units.contains(&unit);
    let name = match (a.given("Phys"), a.given("Logic"), disabled) {
        (true, _, false) => "IOUNIT_PHYS_STATE_RUNNING",
        (true, _, true) => "IOUNIT_PHYS_STATE_DEACTIVATED",
        (_, true, false) => "IOUNIT_LOG_STATE_ENABLED",
        (_, true, true) => "IOUNIT_LOG_STATE_DISABLED",
        (_, _, false) => "IOUNIT_RUNNING",
        (_, _, true) => "IOUNIT_DISABLE",
    };
    match rapid_evaluator::predefined(name) {
        Some(v) => Ok(v),
        None => invalid(format!(
            "IOUnitState: the catalogue has no value for {name}"
        )),
    }
}

/// `IOEnable UnitName, MaxTime` (`IOActivate`): the I/O device runs again
/// (at once).
pub(crate) fn io_enable(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let unit = cx.string(a, "UnitName")?.to_ascii_lowercase();
    cx.num(a, "MaxTime")?;
    cx.sh.disabled_io_units.retain(|u| *u != unit);
    Ok(Done::Next)
}

/// `IODisable UnitName, MaxTime` (`IODeactivate`): the I/O device stops (at once);
/// `IOUnitState` reports it disabled until `IOEnable`. Its signals keep
/// their values.
pub(crate) fn io_disable(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let unit = cx.string(a, "UnitName")?.to_ascii_lowercase();
    cx.num(a, "MaxTime")?;
    if !cx.sh.disabled_io_units.contains(&unit) {
        cx.sh.disabled_io_units.push(unit);
    }
    Ok(Done::Next)
}
