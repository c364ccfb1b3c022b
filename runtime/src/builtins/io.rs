//! I/O signals, waits and interrupts.

use rapid_evaluator::Value;

use super::Args;
use crate::machine::{Machine, R, fault, invalid, named_error};
use crate::program::SignalKind;

/// The signal a signal argument stands for: its folded name and kind.
fn signal(m: &mut Machine, a: &Args<'_>, param: &str) -> R<(String, SignalKind)> {
    let v = m.req(a, param)?;
    if !m.is_signal(&v) {
        return invalid(format!(
            "{}: {param} must be a signal, not {}",
            a.name,
            crate::machine::describe(&v)
        ));
    }
    let s = m.signal_of(&v)?;
    Ok((s.name.clone(), s.kind))
}

fn write_signal(m: &mut Machine, a: &Args<'_>, name: &str, value: f64) -> R<()> {
    let _ = a;
    m.ctl.set_signal_value(name, value);
    Ok(())
}

fn digital(m: &Machine, a: &Args<'_>, value: f64) -> R<f64> {
    if value == 0.0 || value == 1.0 {
        Ok(value)
    } else {
        fault(named_error(
            &m.prog,
            "ERR_ARGVALERR",
            format!("{}: {value} is not a digital value (0 or 1)", a.name),
        ))
    }
}

fn check_output(m: &Machine, a: &Args<'_>, name: &str, kind: SignalKind) -> R<()> {
    let _ = m;
    match kind {
        SignalKind::DigitalOut | SignalKind::AnalogOut | SignalKind::GroupOut => Ok(()),
        _ => invalid(format!(
            "{}: {name} is an input; only outputs can be set",
            a.name
        )),
    }
}

/// `SetDO Signal, Value` and `SetGO Signal, Value`.
pub(crate) fn set_do(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, kind) = signal(m, a, "Signal")?;
    check_output(m, a, &name, kind)?;
    let mut value = m.num(a, "Value")?;
    if kind == SignalKind::DigitalOut {
        value = digital(m, a, value)?;
    } else if value < 0.0 || value.fract() != 0.0 {
        return fault(named_error(
            &m.prog,
            "ERR_ARGVALERR",
            format!("{}: {value} is not a group value", a.name),
        ));
    }
    if let Some(delay) = m.opt_num(a, "SDelay")? {
        schedule(m, &name, value, delay);
        return Ok(());
    }
    write_signal(m, a, &name, value)
}

/// A signal change `delay` seconds from now.
fn schedule(m: &mut Machine, name: &str, value: f64, delay: f64) {
    let at = m.ctl.clock + delay.max(0.0);
    let pos = m.ctl.script.partition_point(|c| c.at <= at);
    m.ctl.script.insert(
        pos,
        crate::SignalChange {
            name: name.to_owned(),
            value,
            at,
        },
    );
}

/// `Set Signal`.
pub(crate) fn set(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, kind) = signal(m, a, "Signal")?;
    check_output(m, a, &name, kind)?;
    write_signal(m, a, &name, 1.0)
}

/// `Reset Signal`.
pub(crate) fn reset(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, kind) = signal(m, a, "Signal")?;
    check_output(m, a, &name, kind)?;
    write_signal(m, a, &name, 0.0)
}

/// `InvertDO Signal`.
pub(crate) fn invert_do(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, kind) = signal(m, a, "Signal")?;
    check_output(m, a, &name, kind)?;
    let v = m
        .ctl
        .signals
        .get(&name.to_ascii_lowercase())
        .map_or(0.0, |s| s.value);
    write_signal(m, a, &name, 1.0 - v)
}

/// `PulseDO [\High] [\PLength] Signal`: 1 now, back after the pulse
/// (0.2 s unless given).
pub(crate) fn pulse_do(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, kind) = signal(m, a, "Signal")?;
    check_output(m, a, &name, kind)?;
    let length = m.opt_num(a, "PLength")?.unwrap_or(0.2);
    let before = m
        .ctl
        .signals
        .get(&name.to_ascii_lowercase())
        .map_or(0.0, |s| s.value);
    write_signal(m, a, &name, 1.0)?;
    if !(m.given(a, "High") && before == 1.0) {
        schedule(m, &name, before, length);
    }
    Ok(())
}

/// `SetAO Signal, Value`.
pub(crate) fn set_ao(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, kind) = signal(m, a, "Signal")?;
    check_output(m, a, &name, kind)?;
    let value = m.num(a, "Value")?;
    write_signal(m, a, &name, value)
}

/// `AliasIO FromSignal, ToSignal`: a signal variable stands for a
/// configured signal (named by a string or given as a signal).
pub(crate) fn alias_io(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let from = m.req(a, "FromSignal")?;
    let name = match &from {
        Value::Str(s) => s.clone(),
        v if m.is_signal(v) => match v.field("name") {
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
    let Some(s) = m.ctl.signals.get(&name.to_ascii_lowercase()) else {
        return fault(named_error(
            &m.prog,
            "ERR_ALIASIO_DEF",
            format!("AliasIO: there is no signal {name}"),
        ));
    };
    let canonical = s.name.clone();
    let p = m.place_arg(a, "ToSignal")?;
    let ty = match m.get(&p) {
        Some(Value::Record { ty, .. }) => ty.clone(),
        _ => return invalid("AliasIO: ToSignal must be a signal variable"),
    };
    m.store(
        &p,
        Value::Record {
            ty,
            fields: vec![("name".to_owned(), Value::Str(canonical))],
        },
    )
}

/// `AliasIOReset Signal`: the signal variable stands for no signal again.
pub(crate) fn alias_io_reset(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let p = m.place_arg(a, "Signal")?;
    let ty = match m.get(&p) {
        Some(v @ Value::Record { ty, .. }) if m.is_signal(v) => ty.clone(),
        _ => return invalid("AliasIOReset: Signal must be a signal variable"),
    };
    m.store(
        &p,
        Value::Record {
            ty,
            fields: vec![("name".to_owned(), Value::Str(String::new()))],
        },
    )
}

/// `DInput`, `DOutput`, `AInput`, `AOutput`, `GInput`, `GOutput`: the
/// signal's value.
pub(crate) fn input(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let v = m.req(a, "Signal")?;
    m.signal_value(&v).map(Value::Num)
}

/// `TestDI(Signal)`: whether a digital input is 1.
pub(crate) fn test_di(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let v = m.req(a, "Signal")?;
    m.signal_value(&v).map(|x| Value::Bool(x == 1.0))
}

/// The end of a wait that may time out: `ERR_WAIT_MAXTIME`, or the time
/// flag set when one is given.
fn timed_out(m: &mut Machine, a: &Args<'_>, what: &str) -> R<()> {
    if let Some(p) = m.opt_place(a, "TimeFlag")? {
        return m.store(&p, Value::Bool(true));
    }
    fault(named_error(
        &m.prog,
        "ERR_WAIT_MAXTIME",
        format!("{}: {what} did not happen within \\MaxTime", a.name),
    ))
}

fn clear_flag(m: &mut Machine, a: &Args<'_>) -> R<()> {
    if let Some(p) = m.opt_place(a, "TimeFlag")? {
        m.store(&p, Value::Bool(false))?;
    }
    Ok(())
}

/// `WaitUntil Cond [\MaxTime] [\TimeFlag] [\PollRate]`: the condition is
/// checked again every `PollRate` seconds of simulated time (0.1 s).
pub(crate) fn wait_until(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let Some(cond) = a.expr("Cond") else {
        return invalid("WaitUntil: the condition is missing");
    };
    let max = m.opt_num(a, "MaxTime")?;
    let poll = m.opt_num(a, "PollRate")?.unwrap_or(0.1).max(0.01);
    clear_flag(m, a)?;
    let ok = m.wait_until("WaitUntil", max, poll, false, &mut |m| m.truth(cond))?;
    if ok {
        Ok(())
    } else {
        timed_out(m, a, "the condition")
    }
}

/// `WaitDI Signal, Value [\MaxTime] [\TimeFlag]` (and `WaitDO`, `WaitGI`,
/// `WaitGO`): waits until the signal has the value.
pub(crate) fn wait_di(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, _) = signal(m, a, "Signal")?;
    let value = m.num(a, "Value")?;
    let max = m.opt_num(a, "MaxTime")?;
    clear_flag(m, a)?;
    let key = name.to_ascii_lowercase();
    let what = format!("{} {name}, {value}", a.name);
    let ok = m.wait_until(&what, max, 0.1, true, &mut |m| {
        Ok(m.ctl.signals.get(&key).is_some_and(|s| s.value == value))
    })?;
    if ok {
        Ok(())
    } else {
        timed_out(m, a, &format!("{name} = {value}"))
    }
}

/// `WaitAI Signal, [\LT] | [\GT], Value` (and `WaitAO`).
pub(crate) fn wait_ai(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, _) = signal(m, a, "Signal")?;
    let value = m.num(a, "Value")?;
    let lt = m.given(a, "LT");
    let gt = m.given(a, "GT");
    let max = m.opt_num(a, "MaxTime")?;
    clear_flag(m, a)?;
    let key = name.to_ascii_lowercase();
    let what = format!("{} {name}", a.name);
    let ok = m.wait_until(&what, max, 0.1, true, &mut |m| {
        let v = m.ctl.signals.get(&key).map_or(0.0, |s| s.value);
        Ok(if lt {
            v < value
        } else if gt {
            v > value
        } else {
            v == value
        })
    })?;
    if ok {
        Ok(())
    } else {
        timed_out(m, a, "the value")
    }
}

fn interrupt_number(m: &mut Machine, a: &Args<'_>) -> R<i32> {
    let v = m.req(a, "Interrupt")?;
    let id = v.as_f64().unwrap_or(0.0) as i32;
    if !m.ctl.interrupts.is_connected(id) {
        return fault(named_error(
            &m.prog,
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
pub(crate) fn i_signal(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, _) = signal(m, a, "Signal")?;
    let value = m.num(a, "TriggValue")?;
    let id = interrupt_number(m, a)?;
    let single = m.given(a, "Single") || m.given(a, "SingleSafe");
    m.ctl.interrupts.add_watch(id, &name, Some(value), single);
    Ok(())
}

/// `ISignalGI` and `ISignalGO`: an interrupt at every change.
pub(crate) fn i_signal_any(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let (name, _) = signal(m, a, "Signal")?;
    let id = interrupt_number(m, a)?;
    let single = m.given(a, "Single") || m.given(a, "SingleSafe");
    m.ctl.interrupts.add_watch(id, &name, None, single);
    Ok(())
}

/// `ITimer [\Single] Time, Interrupt`.
pub(crate) fn i_timer(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let t = m.num(a, "Time")?;
    if t <= 0.0 {
        return fault(named_error(
            &m.prog,
            "ERR_ARGVALERR",
            format!("ITimer: {t} is not a positive time"),
        ));
    }
    let id = interrupt_number(m, a)?;
    let single = m.given(a, "Single") || m.given(a, "SingleSafe");
    let now = m.ctl.clock;
    m.ctl.interrupts.add_timer(id, now, t, single);
    Ok(())
}

/// `IDelete Interrupt`.
pub(crate) fn i_delete(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let v = m.req(a, "Interrupt")?;
    m.ctl.interrupts.delete(v.as_f64().unwrap_or(0.0) as i32);
    Ok(())
}

/// `IDisable`: interrupts wait until `IEnable`.
pub(crate) fn i_disable(m: &mut Machine, _: &Args<'_>) -> R<()> {
    m.ctl.interrupts.disabled = true;
    Ok(())
}

/// `IEnable`.
pub(crate) fn i_enable(m: &mut Machine, _: &Args<'_>) -> R<()> {
    m.ctl.interrupts.disabled = false;
    Ok(())
}

/// `ISleep Interrupt`: the interrupt is ignored until `IWatch`.
pub(crate) fn i_sleep(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let id = interrupt_number(m, a)?;
    m.ctl.interrupts.sleep(id, true);
    Ok(())
}

/// `IWatch Interrupt`.
pub(crate) fn i_watch(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let id = interrupt_number(m, a)?;
    m.ctl.interrupts.sleep(id, false);
    Ok(())
}
