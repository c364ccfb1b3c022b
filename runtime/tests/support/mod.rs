//! What the fixture tests share: outcomes in the fixtures' words, and
//! `!set` lines.

use rapid_runtime::{Outcome, SignalChange, Status};

/// The outcome in the fixtures' words.
pub fn brief(o: &Outcome) -> Option<String> {
    let line = o.at.as_ref().map_or(0, |l| l.line);
    Some(match o.status {
        Status::Finished => return None,
        Status::Exited => "exited".to_owned(),
        Status::Stopped => format!("stopped at {line}"),
        Status::Halted => format!("halted at {line}"),
        // An error without a RAPID name (the controller's motion event):
        // its event number and title.
        Status::Error => format!(
            "{} at {line}",
            o.errno
                .as_ref()
                .map_or(o.message.split(':').next().unwrap_or("?"), |(_, n)| n
                    .as_str())
        ),
        Status::Unsupported => format!(
            "{} at {line}",
            o.message
                .replace("not supported in simulation", "unsupported")
        ),
        Status::Invalid => format!("invalid at {line}"),
        Status::Budget => format!("budget at {line}"),
        Status::Deadlock => format!("deadlock at {line}"),
        Status::Operator => format!("operator at {line}"),
    })
}

/// A `!set NAME=VALUE[@SECONDS]` line's change.
pub fn signal_change(text: &str) -> SignalChange {
    let (name, value) = text.trim().split_once('=').expect("!set NAME=VALUE");
    let (value, at) = value.split_once('@').unwrap_or((value, "0"));
    SignalChange {
        name: name.to_owned(),
        value: value.parse().expect("a number"),
        at: at.parse().expect("seconds"),
    }
}
