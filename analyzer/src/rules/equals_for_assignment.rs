use std::ops::Range;

use crate::diagnostic::{Applicability, Diagnostic, Fix};

crate::declare_rule! {
    /// `=` written where RAPID assigns with `:=`.
    ///
    /// ### What it checks
    /// An assignment statement or a declaration's initial value written with `=`,
    /// the comparison operator, instead of `:=`. The parser reports this case with
    /// its own code so the message can name the fix.
    ///
    /// ### Why
    /// The controller rejects the module. Programmers coming from other languages
    /// write `=` out of habit; the generic syntax error is harder to read.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num count = 0;      ! write  VAR num count := 0;
    /// count = count + 1;      ! write  count := count + 1;
    /// ```
    pub static RULE = ("E003", "equals-for-assignment", Error);
}

/// The finding at an `=` (its range) written where `:=` assigns.
pub(crate) fn diagnostic(eq: Range<usize>) -> Diagnostic {
    Diagnostic::new(
        &RULE,
        eq.clone(),
        "expected `:=` to assign a value, found `=` (the comparison operator)",
    )
    .with_fix(fix(eq, Applicability::Safe))
}

/// `=` (at `eq`) becomes `:=`. Safe where the statement can only be an
/// assignment or an initial value.
pub(crate) fn fix(eq: Range<usize>, applicability: Applicability) -> Fix {
    Fix::edit("Replace `=` with `:=`", eq, ":=", applicability, true)
}
