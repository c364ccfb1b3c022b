use tree_sitter::Node;

use crate::check::Cx;
use crate::items::RoutineKind;
use crate::syntax::field;
use crate::syntax_util::field;
use crate::ty::Ty;

crate::declare_rule! {
    /// `RETURN` without a value in a function, or with one in a procedure or trap.
    ///
    /// ### What it checks
    /// A function returns a value of its type with `RETURN value;`; procedures and
    /// traps end with a plain `RETURN;`.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// FUNC num twice(num x)
    ///     RETURN;        ! the value is missing
    /// ENDFUNC
    /// ```
    pub static RULE = ("E403", "return-value", Error);
}

/// A `RETURN`: with a value of the function's type in a function, without
/// one elsewhere.
pub(crate) fn check<'t>(cx: &mut Cx<'t>, s: Node<'t>) {
    let Some(r) = &cx.routine else {
        return;
    };
    let kind = r.decl.kind;
    let returns = r.decl.returns.as_ref().map(|t| Ty::named(&t.name));
    match (kind, field(s, field::VALUE)) {
        (RoutineKind::Func, None) => cx.report(
            &RULE,
            s.byte_range(),
            format!(
                "a function must return a value: RETURN {};",
                returns
                    .as_ref()
                    .map_or("value".to_owned(), |t| format!("<{t}>"))
            ),
        ),
        (RoutineKind::Func, Some(v)) => {
            let ty = returns.unwrap_or(Ty::Unknown);
            crate::check::exprs::check_expected(cx, v, &ty, "the returned value");
        }
        (_, Some(v)) => {
            cx.report(
                &RULE,
                v.byte_range(),
                format!("a {} returns no value: write RETURN;", kind.keyword()),
            );
            crate::check::exprs::expr(cx, v, None);
        }
        (_, None) => {}
    }
}
