//! The FlexPendant and the event log: `TPWrite`, `ErrWrite`.

use rapid_evaluator::{Value, format_dnum, format_num};

use super::Args;
use crate::Stream;
use crate::machine::{Machine, R, invalid};

/// `TPWrite String [\Num] | [\Bool] | [\Pos] | [\Orient] | [\Dnum]`: the
/// text, then the value as the pendant writes it (a num with up to six
/// significant digits, a dnum with up to fifteen, `TRUE`/`FALSE`, a pos or
/// an orient as an aggregate).
pub(crate) fn tp_write(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let mut line = m.string(a, "String")?;
    line.push_str(&value_suffix(m, a)?);
    m.out.line(Stream::Pendant, &line);
    Ok(())
}

/// The optional value of `TPWrite` and `Write`, as text.
pub(crate) fn value_suffix(m: &mut Machine, a: &Args<'_>) -> R<String> {
    if let Some(x) = m.opt_num(a, "Num")? {
        return Ok(format_num(x as f32));
    }
    if let Some(x) = m.opt_num(a, "Dnum")? {
        return Ok(format_dnum(x));
    }
    if let Some(v) = m.opt(a, "Bool")? {
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
        if let Some(v) = m.opt(a, p)? {
            return Ok(v.to_string());
        }
    }
    Ok(String::new())
}

/// `ErrWrite [\W] | [\I] Header Reason [\RL2] [\RL3] [\RL4]`: one line for
/// the event log entry: its number (80001 for an error, 80002 for a
/// warning, 80003 for information), the header, then the reason lines.
pub(crate) fn err_write(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let number = if m.given(a, "W") {
        80002
    } else if m.given(a, "I") {
        80003
    } else {
        80001
    };
    let header = m.string(a, "Header")?;
    let mut line = format!("{number} {header}: {}", m.string(a, "Reason")?);
    for p in ["RL2", "RL3", "RL4"] {
        if let Some(s) = m.opt_string(a, p)? {
            line.push(' ');
            line.push_str(&s);
        }
    }
    m.out.line(Stream::EventLog, &line);
    Ok(())
}

/// Instructions that change only what the pendant shows.
pub(crate) fn nothing(_: &mut Machine, _: &Args<'_>) -> R<()> {
    Ok(())
}
