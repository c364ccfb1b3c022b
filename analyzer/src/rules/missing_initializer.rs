use crate::check::Cx;
use crate::items::{DataDecl, Scope, Storage};

crate::declare_rule! {
    /// A `CONST`, or a `TASK` or `LOCAL` `PERS`, declared without a value.
    ///
    /// ### What it checks
    /// A constant must be given its value where it is declared. A persistent
    /// may leave out its value only when it is system global (plain `PERS`):
    /// the controller then shares the value of another task's declaration of
    /// the same persistent, or starts from the type's default. A `TASK PERS` or
    /// a `LOCAL PERS` has no other declaration to share with and needs its
    /// value.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num max;            ! write  CONST num max := 10;
    /// TASK PERS num count;      ! write  TASK PERS num count := 0;
    /// PERS num shared;          ! allowed: system global
    /// ```
    pub static RULE = ("E402", "missing-initializer", Error);
}

/// A data declaration without a value (one the parser could read).
pub(crate) fn check(cx: &mut Cx<'_>, decl: &DataDecl) {
    let ty = decl.ty.as_ref().map_or("<type>", |t| t.name.as_str());
    let message = match (decl.storage, decl.scope) {
        (Storage::Const, _) => format!(
            "the constant `{}` needs a value: CONST {ty} {} := ...;",
            decl.name, decl.name
        ),
        // Only system-global persistents may leave out the value: the
        // controller then takes it from another task's declaration of the
        // same persistent, or the type's default. TASK and LOCAL persistents
        // have no other declaration to take it from.
        (Storage::Pers, Scope::Task | Scope::Local) => {
            let kind = if decl.scope == Scope::Task {
                "TASK"
            } else {
                "LOCAL"
            };
            format!(
                "the {kind} persistent `{}` needs a value: {kind} PERS {ty} {} := ...;",
                decl.name, decl.name
            )
        }
        _ => return,
    };
    cx.report(&RULE, decl.name_range.clone(), message);
}
