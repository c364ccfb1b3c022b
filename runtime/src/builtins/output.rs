//! The FlexPendant and the event log: `TPWrite`, `ErrWrite` (the
//! questions to the operator are [`super::pendant`]'s).

use rapid_evaluator::{Value, format_dnum, format_num};

use super::{Args, Cx, Done};
use crate::Stream;
use crate::machine::{R, fault, invalid, rapid_error};

/// `TPWrite String [\Num] | [\Bool] | [\Pos] | [\Orient] | [\Dnum]`: the
/// text, then the value as the pendant writes it (a num with up to six
/// significant digits, a dnum with up to fifteen, `TRUE`/`FALSE`, a pos or
/// an orient as an aggregate).
pub(crate) fn tp_write(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let mut line = cx.string(a, "String")?;
    line.push_str(&value_suffix(cx, a)?);
    cx.print(Stream::Pendant, &line);
    Ok(Done::Next)
}

/// The optional value of `TPWrite` and `Write`, as text.
pub(crate) fn value_suffix(cx: &mut Cx<'_>, a: &Args) -> R<String> {
    if let Some(x) = cx.opt_num(a, "Num")? {
        return Ok(format_num(x as f32));
    }
    if let Some(x) = cx.opt_num(a, "Dnum")? {
        return Ok(format_dnum(x));
    }
    if let Some(v) = cx.opt(a, "Bool")? {
        return match v {
            Value::Bool(true) => Ok("TRUE".to_owned()),
            Value::Bool(false) => Ok("FALSE".to_owned()),
            other => invalid(format!(
                "{}: \\Bool must be a bool, not {}",
                a.name,
                crate::machine::describe(&other)
            )),
        };
    }
    for p in ["Pos", "Orient"] {
        if let Some(v) = cx.opt(a, p)? {
            return Ok(v.to_string());
        }
    }
    Ok(String::new())
}

/// `ErrWrite [\W] | [\I] Header Reason [\RL2] [\RL3] [\RL4]`: one line for
/// the event log entry: its number (80001 for an error, 80002 for a
/// warning, 80003 for information), the header, then the reason lines.
pub(crate) fn err_write(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let number = if a.given("W") {
        80002
    } else if a.given("I") {
        80003
    } else {
        80001
    };
    let header = cx.string(a, "Header")?;
    let reason = cx.string(a, "Reason")?;
    let mut line = format!("{number} {header}: {reason}");
    let mut lines = vec![reason];
    for p in ["RL2", "RL3", "RL4"] {
        if let Some(s) = cx.opt_string(a, p)? {
            line.push(' ');
            line.push_str(&s);
            lines.push(s);
        }
    }
    cx.print(Stream::EventLog, &line);
    // Event numbers are the domain, then four digits: 80001 is entry 1 of
    // USER_DEF_ERR (8); an error is TYPE_ERR (3), a warning TYPE_WARN (2),
    // information TYPE_STATE (1).
    cx.sh.event_log.push(crate::interrupts::LogEntry {
        domain: number / 10_000,
        number: number % 10_000,
        kind: 4 - number % 10_000,
        title: header,
        lines,
    });
    Ok(Done::Next)
}

/// `TPErase`: the operator window is cleared (traced).
pub(crate) fn tp_erase(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    cx.trace("TPErase: the operator window is cleared");
    Ok(Done::Next)
}

/// `TPShow Window`: the pendant brings a window to the front (traced):
/// `TP_PROGRAM` (1) the Production window, `TP_LATEST` (2) the window
/// shown before, `TP_SCREENVIEWER` (3) the ScreenViewer.
pub(crate) fn tp_show(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let window = cx.num(a, "Window")?;
    let shown = match window as i64 {
        1 => "the Production window",
        2 => "the window shown before",
        3 => "the ScreenViewer",
        _ => return invalid(format!("TPShow: {window} is not a tpnum window (1 to 3)")),
    };
    cx.trace(&format!("TPShow: the pendant shows {shown}"));
    Ok(Done::Next)
}

/// `UIShow AssemblyName, TypeName [\InitCmd] [\InstanceID] [\Status]
/// [\NoCloseBtn]`: a FlexPendant application opens (traced); `\Status`
/// gets 0 (it opened), `\InstanceID` the number of the opened instance.
pub(crate) fn ui_show(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let assembly = cx.string(a, "AssemblyName")?;
    let ty = cx.string(a, "TypeName")?;
    let mut line = format!("UIShow: the pendant opens {ty} of {assembly}");
    if let Some(cmd) = cx.opt_string(a, "InitCmd")? {
        line.push_str(&format!(" ({cmd})"));
    }
    cx.trace(&line);
    cx.sh.ui_instances += 1;
    let instance = cx.sh.ui_instances;
    if let Some(p) = cx.opt_place(a, "InstanceID")? {
        cx.store(&p, Value::Num(instance as f32))?;
    }
    if let Some(p) = cx.opt_place(a, "Status")? {
        cx.store(&p, Value::Num(0.0))?;
    }
    Ok(Done::Next)
}

/// `UIMsgWrite Header, Message`: a message in the operator window, shown
/// without waiting for the operator (a later one replaces it); the run
/// writes it as a line, the header first.
pub(crate) fn ui_msg_write(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let header = cx.string(a, "Header")?;
    let message = cx.string(a, "Message")?;
    cx.print(Stream::Pendant, &format!("{header}: {message}"));
    Ok(Done::Next)
}

/// `UIMsgWriteAbort`: the message of `UIMsgWrite` is removed (traced).
pub(crate) fn ui_msg_write_abort(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    cx.trace("UIMsgWriteAbort: the message of UIMsgWrite is removed");
    Ok(Done::Next)
}

/// `SkipWarn`: the warning of the error just handled is not logged. The
/// simulation logs no warning for a handled error, so there is nothing to
/// skip; it is traced.
pub(crate) fn skip_warn(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    cx.trace("SkipWarn: the handled error's warning is not logged");
    Ok(Done::Next)
}

/// `ErrLog ErrorID [\W] | [\I] Argument1 ... Argument5`: a message of the
/// event log's text tables (whose texts the simulation does not have), as
/// one line: `ErrLog`, its number, then the arguments that are not empty.
pub(crate) fn err_log(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let id = cx.num(a, "ErrorID")?;
    let mut line = format!("ErrLog {}", format_num(id as f32));
    if a.given("W") {
        line.push_str(" (warning)");
    } else if a.given("I") {
        line.push_str(" (information)");
    }
    line.push(':');
    line.push_str(&log_arguments(cx, a)?);
    cx.print(Stream::EventLog, &line);
    Ok(Done::Next)
}

/// The text arguments of `ErrLog` and `ErrRaise` that are not empty, each
/// after a space.
fn log_arguments(cx: &mut Cx<'_>, a: &Args) -> R<String> {
    let mut text = String::new();
    for p in [
        "Argument1",
        "Argument2",
        "Argument3",
        "Argument4",
        "Argument5",
    ] {
        if let Some(s) = cx.opt_string(a, p)?
            && !s.is_empty()
        {
            text.push(' ');
            text.push_str(&s);
        }
    }
    Ok(text)
}

/// `ErrRaise ErrorName, ErrorId, Argument1 ... Argument5`: the error is
/// logged (as `ErrLog` logs), then raised in the routine as `RAISE` would:
/// `ErrorName` names the `errnum` data (booked with `BookErrNo`) or a
/// system error (`ERR_...`).
pub(crate) fn err_raise(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let name = cx.string(a, "ErrorName")?;
    let id = cx.num(a, "ErrorId")?;
    let text = log_arguments(cx, a)?;
    let errno = match super::data::data_named(cx, &name) {
        Ok(place) => match cx.m.load(cx.sh, &place)?.as_f64() {
            Some(x) => x as f32,
            None => return invalid(format!("ErrRaise: {name} is not an errnum")),
        },
        Err(_) if cx.m.prog.errnum_name(cx.m.prog.errnum(&name)).is_some() => {
            cx.m.prog.errnum(&name)
        }
        Err(e) => return Err(e),
    };
    cx.print(
        Stream::EventLog,
        &format!("ErrRaise {name} {}:{text}", format_num(id as f32)),
    );
    let mut raised = match cx.m.raise(Some(Value::Num(errno))) {
        Ok(()) => return Ok(Done::Next),
        Err(f) => f,
    };
    if let crate::machine::FaultKind::Rapid { message, .. } = &mut raised.kind {
        *message = format!("raised by ErrRaise {name}");
    }
    Err(raised)
}

/// `EventLog Domain, ErrorId, Type, Argument1 ... Argument5` (the YuMi
/// SmartGripper driver's): as `ErrLog`, one line with the domain, the
/// number and the type, then the arguments that are not empty.
pub(crate) fn event_log(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let domain = cx.num(a, "Domain")?;
    let id = cx.num(a, "ErrorId")?;
    let kind = match cx.num(a, "Type")? as i64 {
        1 => "information",
        2 => "warning",
        3 => "error",
        _ => "event",
    };
    let text = log_arguments(cx, a)?;
    let line = format!(
        "EventLog {} {} ({kind}):{text}",
        format_num(domain as f32),
        format_num(id as f32)
    );
    cx.print(Stream::EventLog, &line);
    Ok(Done::Next)
}

/// `StrFormat(Format [\Arg1] ... [\Arg10])`: the format with each `{n}`
/// replaced by `\Argn` (an argument not given leaves the text empty; a
/// brace that is no placeholder stays as written).
pub(crate) fn str_format(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let format = cx.string(a, "Format")?;
    let mut out = String::new();
    let mut rest = format.as_str();
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        let number = after
            .find('}')
            .and_then(|close| after[..close].parse::<u8>().ok().map(|n| (n, close)));
        match number {
            Some((n, close)) if (1..=10).contains(&n) => {
                if let Some(s) = cx.opt_string(a, &format!("Arg{n}"))? {
                    out.push_str(&s);
                }
                rest = &after[close + 1..];
            }
            _ => {
                out.push('{');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    if out.chars().count() > 80 {
        return fault(rapid_error(
            &cx.m.prog,
            rapid_evaluator::ErrorCode::StrTooLong,
            format!(
                "StrFormat: the result has {} characters (at most 80)",
                out.chars().count()
            ),
        ));
    }
    Ok(Value::Str(out))
}
