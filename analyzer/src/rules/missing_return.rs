use tree_sitter::Node;

use super::fix_text::{indent_at, line_break, line_start, starts_line};
use crate::diagnostic::{Applicability, Diagnostic, Fix};
use crate::syntax::kind;
use crate::ty::{Ty, Types};

crate::declare_rule! {
    /// A function that can reach its end without `RETURN`.
    ///
    /// ### What it checks
    /// Every path through a function's statements must end in `RETURN value`,
    /// `RAISE`, `EXIT` or a jump. Branches count only when every branch returns (an
    /// `IF` with an `ELSE`, a `TEST` with a `DEFAULT`).
    ///
    /// ### Why
    /// Reaching the end of a function without a value stops the program with an
    /// error at run time. The controller loads the module (real backups hold
    /// such functions, whose last branch is never reached in practice), so this
    /// is a warning, not an error.
    ///
    /// ### Example
    /// ```rapid
    /// FUNC num sign(num x)
    ///     IF x < 0 THEN
    ///         RETURN -1;
    ///     ENDIF
    /// ENDFUNC           ! nothing is returned when x >= 0
    /// ```
    pub static RULE = ("E404", "missing-return", Warning);
}

/// The finding on the name of the function `name` (at `name_range`).
pub(crate) fn diagnostic(name: &str, name_range: std::ops::Range<usize>) -> Diagnostic {
    Diagnostic::new(
        &RULE,
        name_range,
        format!("the function `{name}` can reach its end without RETURN"),
    )
}

/// Inserts `RETURN <default>;` where the function `name` (node `func`,
/// returning `returns`) ends its statements: before its first handler or
/// `ENDFUNC`, indented like its last statement `last` (two spaces
/// more than `ENDFUNC` when it has none). The value is a default of the
/// type: `0`, `FALSE`, `""`, or an aggregate of those for a record; no fix
/// for a type without one. Not safe: the right value is the author's call.
pub(crate) fn fix(
    text: &str,
    types: &Types<'_>,
    func: Node<'_>,
    last: Option<Node<'_>>,
    name: &str,
    returns: &str,
) -> Option<Fix> {
    let is_end = |c: &Node<'_>| {
        matches!(
            c.kind(),
            "endfunc" | kind::ERROR_HANDLER | kind::UNDO_HANDLER | kind::BACKWARD_HANDLER
        )
    };
    let mut cursor = func.walk();
    let end = func.children(&mut cursor).find(is_end)?;
    let value = default_value(types, &Ty::named(returns), 0)?;
    let nl = line_break(text);
    let (at, replacement) = if starts_line(text, end.start_byte()) {
        let indent = match last {
            Some(last) => indent_at(text, last.start_byte()).to_owned(),
            None => format!("{}  ", indent_at(text, end.start_byte())),
        };
        (
            line_start(text, end.start_byte()),
            format!("{indent}RETURN {value};{nl}"),
        )
    } else {
        (end.start_byte(), format!("RETURN {value}; "))
    };
    Some(Fix::edit(
        format!("Add `RETURN {value};` at the end of `{name}`"),
        at..at,
        replacement,
        Applicability::Unsafe,
        true,
    ))
}

/// A default value of a type: `0`, `FALSE`, `""`, or an aggregate of
/// defaults; `None` for a type that has none (a non-value type).
fn default_value(types: &Types<'_>, ty: &Ty, depth: usize) -> Option<String> {
    let base = types.base(ty);
    if base.is("bool") {
        return Some("FALSE".to_owned());
    }
    if base.is("string") {
        return Some("\"\"".to_owned());
    }
    if let Some(comps) = types.components(&base) {
        if depth >= 4 {
            return None;
        }
        let parts = comps
            .iter()
            .map(|(_, t)| default_value(types, t, depth + 1))
            .collect::<Option<Vec<String>>>()?;
        return Some(format!("[{}]", parts.join(", ")));
    }
    types.is_num_like(&base).then(|| "0".to_owned())
}
