//! Fixture tests: small RAPID sources with a cursor marker `$0`; several
//! files are separated by lines `==> path`.

use std::sync::Arc;

use crate::task::{Task, Unit};

mod actions;
mod completion;
mod hover;
mod navigation;
mod robustness;
mod shared;
mod structure;
mod tokens;
mod uses_oracle;

/// The task of a fixture, the index of the unit holding the cursor, and the
/// cursor's offset.
pub(super) fn fixture(src: &str) -> (Task, usize, usize) {
    let mut files: Vec<(String, String)> = Vec::new();
    if src.starts_with("==> ") {
        for chunk in src.split("==> ").skip(1) {
            let (path, text) = chunk.split_once('\n').unwrap_or((chunk, ""));
            files.push((format!("t/{}", path.trim()), text.to_owned()));
        }
    } else {
        files.push(("t/main.mod".to_owned(), src.to_owned()));
    }
    let mut cursor = (0, 0);
    let mut units = Vec::new();
    for (i, (path, text)) in files.into_iter().enumerate() {
        let text = match text.find("$0") {
            Some(at) => {
                cursor = (i, at);
                text.replacen("$0", "", 1)
            }
            None => text,
        };
        units.push(Arc::new(Unit::new(path, text, None)));
    }
    (Task::new("t".to_owned(), units, None), cursor.0, cursor.1)
}

/// The text at a range of a fixture's unit.
pub(super) fn slice(task: &Task, unit: usize, range: std::ops::Range<usize>) -> String {
    task.units[unit].text[range].to_owned()
}

/// Unit index of a path.
pub(super) fn unit_of(task: &Task, path: &str) -> usize {
    task.units
        .iter()
        .position(|u| u.path == path)
        .unwrap_or_else(|| panic!("no unit {path}"))
}
