//! The FlexPendant and the event log: `TPWrite`, `ErrWrite` (the
//! questions to the operator are [`super::pendant`]'s).

use rapid_evaluator::{Value, format_dnum, format_num};

use super::{Args, Cx, Done};
use crate::Stream;
use crate::machine::{R, invalid};

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
    let mut line = format!("{number} {header}: {}", cx.string(a, "Reason")?);
    for p in ["RL2", "RL3", "RL4"] {
        if let Some(s) = cx.opt_string(a, p)? {
            line.push(' ');
            line.push_str(&s);
        }
    }
    cx.print(Stream::EventLog, &line);
    Ok(Done::Next)
}

/// Instructions that change only what the pendant shows.
pub(crate) fn nothing(_: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    Ok(Done::Next)
}
