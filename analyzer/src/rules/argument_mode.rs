use std::ops::Range;

use crate::catalogue::Mode;
use crate::check::{Cx, Place};
use crate::sema::signature::Param;

crate::declare_rule! {
    /// An argument that cannot be passed to a VAR, PERS or INOUT parameter.
    ///
    /// ### What it checks
    /// A `VAR` parameter needs a variable, a `PERS` parameter a persistent, and an
    /// `INOUT` parameter a variable or a persistent: something the routine can
    /// write to. A literal, an expression, a constant or a `FOR` loop variable
    /// cannot be passed.
    ///
    /// ### Why
    /// The controller rejects the module; the routine would have nowhere to store
    /// its result.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num limit := 10;
    /// Incr limit;      ! Incr changes its argument: limit is a constant
    /// ```
    pub static RULE = ("E307", "argument-mode", Error);
}

/// The place `place` passed at `range` to parameter `p`: whether its mode
/// takes it (`false` when reported).
pub(crate) fn check(cx: &mut Cx<'_>, p: &Param, place: Place, range: Range<usize>) -> bool {
    let mode_ok = match p.mode {
        Mode::In | Mode::Ref => true,
        // Real programs pass persistents to VAR parameters of built-ins
        // (e.g. a PERS btnres as \\Result), and controllers accept them.
        Mode::Var => matches!(
            place,
            Place::Var | Place::Pers | Place::Unknown | Place::Param(_)
        ),
        Mode::Pers => matches!(
            place,
            Place::Pers | Place::Unknown | Place::Param(Mode::Pers | Mode::InOut)
        ),
        Mode::InOut => matches!(
            place,
            Place::Var | Place::Pers | Place::Unknown | Place::Param(_)
        ),
    };
    if !mode_ok {
        let wanted = match p.mode {
            Mode::Var => "a variable",
            Mode::Pers => "a persistent",
            _ => "a variable or a persistent",
        };
        cx.report(
            &RULE,
            range,
            format!(
                "{} is {} {} parameter and needs {wanted}, found {}",
                p.name,
                if p.mode.keyword().starts_with('I') {
                    "an"
                } else {
                    "a"
                },
                p.mode.keyword(),
                place.describe()
            ),
        );
        return false;
    }
    true
}
