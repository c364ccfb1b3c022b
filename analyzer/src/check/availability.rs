//! Built-ins the task's controller may not have: an option that is not
//! enabled (rule I102, once per name, with the other uses as related
//! locations) or a RobotWare version that lacks them (rule W102).

use std::collections::HashMap;
use std::ops::Range;

use super::{Cx, DataSym, RoutineSym};
use crate::catalogue::{Availability, Origin};
use crate::diagnostic::{Diagnostic, Related};
use crate::rules;

impl Cx<'_> {
    /// A call resolved to `sym` at `range`.
    pub(crate) fn routine_used(&mut self, sym: &RoutineSym<'_>, range: Range<usize>) {
        if let RoutineSym::Builtin(r, _) = sym {
            self.builtin_used(&r.name, &r.origin, range);
        }
    }

    /// A data name resolved to `sym` at `range`.
    pub(crate) fn data_used(&mut self, sym: &DataSym<'_>, range: Range<usize>) {
        if let DataSym::Builtin(d) = sym {
            self.builtin_used(&d.name, &d.origin, range);
        }
    }

    /// A type name at `range` that the task does not declare itself.
    pub(crate) fn type_used(&mut self, name: &str, range: Range<usize>) {
        if self.types.user(name).is_none()
            && let Some(t) = self.cat.datatype(name)
        {
            self.builtin_used(&t.name, &t.origin, range);
        }
    }

    fn builtin_used(&mut self, name: &str, origin: &Origin, range: Range<usize>) {
        match self.cat.availability(origin) {
            Availability::Yes => {}
            Availability::NeedsOption(p) => {
                let message = format!(
                    "`{name}` needs the {} option (`{}` in [controller] options), which is not enabled",
                    p.name, p.id
                );
                self.report(&rules::option_routine::RULE, range, message);
            }
            Availability::Newer { since, selected } => {
                let message = format!("`{name}` is not in RobotWare {selected}; added in {since}");
                self.report(&rules::builtin_version::RULE, range, message);
            }
            Availability::Removed { until, selected } => {
                let message =
                    format!("`{name}` is not in RobotWare {selected}; removed in {until}");
                self.report(&rules::builtin_version::RULE, range, message);
            }
        }
    }
}

/// Keeps the first report of each built-in that needs an option or another
/// RobotWare (the diagnostics are sorted by position); the later uses become
/// its related locations.
pub(crate) fn once_per_name(diags: &mut Vec<Diagnostic>) {
    let noted = |d: &Diagnostic| {
        std::ptr::eq(d.rule, &rules::option_routine::RULE)
            || std::ptr::eq(d.rule, &rules::builtin_version::RULE)
    };
    if !diags.iter().any(noted) {
        return;
    }
    let mut first: HashMap<String, usize> = HashMap::new();
    let mut later: Vec<(usize, Range<usize>)> = Vec::new();
    let mut keep = Vec::with_capacity(diags.len());
    for (i, d) in diags.iter().enumerate() {
        if noted(d) {
            match first.get(&d.message) {
                Some(&f) => {
                    later.push((f, d.range.clone()));
                    keep.push(false);
                    continue;
                }
                None => {
                    first.insert(d.message.clone(), i);
                }
            }
        }
        keep.push(true);
    }
    for (f, range) in later {
        if let Some(d) = diags.get_mut(f) {
            d.related.push(Related {
                file: None,
                range,
                message: "also used here".into(),
            });
        }
    }
    let mut k = keep.into_iter();
    diags.retain(|_| k.next().unwrap_or(true));
}
