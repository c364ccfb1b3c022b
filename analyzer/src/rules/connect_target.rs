use tree_sitter::Node;

use crate::check::Cx;
use crate::items::RoutineKind;
use crate::syntax::field;
use crate::syntax_util::field;

crate::declare_rule! {
    /// `CONNECT` with something other than an `intnum` variable and a trap routine.
    ///
    /// ### What it checks
    /// `CONNECT intno WITH trap` needs a variable of type `intnum` and the name of
    /// a `TRAP` routine.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num irq;
    /// CONNECT irq WITH main;     ! irq must be an intnum, main a TRAP
    /// ```
    pub static RULE = ("E407", "connect-target", Error);
}

/// `CONNECT interrupt WITH trap`: an intnum variable and a TRAP routine.
pub(crate) fn check<'t>(cx: &mut Cx<'t>, s: Node<'t>) {
    if let Some(target) = field(s, field::INTERRUPT) {
        let (ty, place) = crate::check::exprs::place_or_value(cx, target);
        if cx.types.is_known(&ty) && !ty.is("intnum") {
            cx.report(
                &RULE,
                target.byte_range(),
                format!(
                    "CONNECT needs an intnum variable, found {}",
                    crate::check::exprs::a_type(&ty)
                ),
            );
        } else if matches!(
            place,
            crate::check::Place::Const
                | crate::check::Place::ForVar
                | crate::check::Place::Value
                | crate::check::Place::ReadOnly
        ) {
            cx.report(
                &RULE,
                target.byte_range(),
                format!(
                    "CONNECT needs an intnum variable, found {}",
                    place.describe()
                ),
            );
        }
    }
    if let Some(trap) = field(s, field::TRAP) {
        let name = cx.node_text(trap);
        match cx.resolve_routine(name, false) {
            Some(def)
                if def
                    .routine_decl(cx.task)
                    .is_some_and(|d| d.kind == RoutineKind::Trap) => {}
            Some(_) => cx.report(
                &RULE,
                trap.byte_range(),
                format!("`{name}` is not a TRAP routine"),
            ),
            None => cx.unresolved(name, trap.byte_range(), "routine"),
        }
    }
}
