use std::ops::Range;

use crate::check::Cx;
use crate::items::RoutineKind;
use crate::sema::signature::Signature;

crate::declare_rule! {
    /// A function called as an instruction, or an instruction called as a function.
    ///
    /// ### What it checks
    /// A function returns a value and is called inside an expression with
    /// parentheses; an instruction (procedure) is a statement of its own. Calling a
    /// function as a statement throws its result away, which RAPID does not allow;
    /// calling a procedure in an expression has no value to use.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// Abs reg1;             ! Abs is a function: reg1 := Abs(reg1);
    /// reg2 := MoveL(p10);  ! MoveL is an instruction
    /// ```
    pub static RULE = ("E207", "call-kind-mismatch", Error);
}

/// A procedure call statement of the routine of `sig` (its name at
/// `range`). A built-in known by name only may be either kind: real code
/// decides, and nothing of its call is checked.
pub(crate) fn check_procedure_call(cx: &mut Cx<'_>, sig: &Signature, range: Range<usize>) {
    let message = match sig.kind {
        _ if !sig.known => return,
        RoutineKind::Func => format!(
            "`{}` is a function: use its result, e.g. x := {}(...);",
            sig.name, sig.name
        ),
        RoutineKind::Trap => format!(
            "`{}` is a TRAP: it is run by an interrupt (CONNECT), not called",
            sig.name
        ),
        RoutineKind::Proc => return,
    };
    cx.report(&RULE, range, message);
}

/// A function call of the routine of `sig` (its name at `range`).
pub(crate) fn check_function_call(cx: &mut Cx<'_>, sig: &Signature, range: Range<usize>) {
    if sig.kind != RoutineKind::Func && sig.known {
        cx.report(
            &RULE,
            range,
            format!(
                "`{}` is {}, not a function: it has no value",
                sig.name,
                if sig.kind == RoutineKind::Trap {
                    "a TRAP"
                } else {
                    "a procedure"
                }
            ),
        );
    }
}
