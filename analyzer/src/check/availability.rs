//! Built-ins the task's controller may not have: an option that is not
//! enabled (rule I102, once per name, with the other uses as related
//! locations: [`super::once`]) or a RobotWare version that lacks them (rule W102).

use std::ops::Range;

use super::Cx;
use crate::catalogue::{Availability, Origin};
use crate::rules;
use crate::sema::def::Def;

impl Cx<'_> {
    /// A name resolved to `def` at `range` (a call or data).
    pub(crate) fn def_used(&mut self, def: &Def<'_>, range: Range<usize>) {
        match def {
            Def::BuiltinRoutine(r) => self.builtin_used(&r.name, &r.origin, range),
            Def::BuiltinDatum(d) => self.builtin_used(&d.name, &d.origin, range),
            _ => {}
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
            Availability::NeedsOption(p) => rules::option_routine::report(self, name, p, range),
            other => rules::builtin_version::report(self, name, &other, range),
        }
    }
}
