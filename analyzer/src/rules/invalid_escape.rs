use tree_sitter::Node;

use crate::check::Cx;
use crate::diagnostic::{Applicability, Diagnostic, Fix};

crate::declare_rule! {
    /// A backslash in a string that starts no escape.
    ///
    /// ### What it checks
    /// In a RAPID string a backslash starts an escape: `\\` is one backslash,
    /// and `\` with two hexadecimal digits is the character of that code
    /// (`\0D\0A` is a carriage return and a line feed). A backslash followed
    /// by anything else is not RAPID.
    ///
    /// ### Why
    /// The controller rejects the module. A Windows path or a copied
    /// argument such as `\T:=` is the usual cause: write the backslash twice.
    ///
    /// ### Example
    /// ```rapid
    /// TPWrite "C:\temp";      ! write  "C:\\temp"
    /// ```
    pub static RULE = ("E415", "invalid-escape", Error);
}

/// A string literal's backslashes that start no escape (the grammar keeps
/// each as a `string_content` of its own).
pub(crate) fn check(cx: &mut Cx<'_>, node: Node<'_>) {
    let mut cursor = node.walk();
    for child in node.named_children(&mut cursor) {
        if crate::syntax_util::kind(child) != crate::syntax::kind::STRING_CONTENT
            || cx.node_text(child) != "\\"
        {
            continue;
        }
        let at = child.byte_range();
        let next: String = cx
            .text
            .get(at.end..)
            .unwrap_or_default()
            .chars()
            .take_while(|c| *c != '"' && *c != '\n' && *c != '\r')
            .take(2)
            .collect();
        let fix = Fix::edit(
            "Write the backslash twice",
            at.clone(),
            "\\\\",
            Applicability::Unsafe,
            true,
        );
        cx.report_with(
            Diagnostic::new(
                &RULE,
                at,
                format!(
                    "`\\{next}` is not an escape: a backslash is written `\\\\`, \
                     and `\\` with two hex digits is a character code"
                ),
            )
            .with_fix(fix),
        );
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use crate::task::{Task, Unit};

    /// The checker (the grammar's escape tokens) and the evaluator (which
    /// decodes strings when a program runs) agree on which backslashes
    /// start no escape: one rule, two readings, compared.
    #[test]
    fn the_checker_flags_what_the_evaluator_refuses() {
        let literals = [
            r#""a\\b""#,
            r#""\41""#,
            r#""\0D\0A""#,
            r#""\ff""#,
            r#""\4""#,
            r#""\G1""#,
            r#""C:\temp""#,
            r#""end\""#,
            r#""\\\""#,
            r#""a\\\\b""#,
        ];
        for lit in literals {
            let text = format!("MODULE m\n  CONST string s := {lit};\nENDMODULE\n");
            let unit = Arc::new(Unit::new("m.mod".into(), text, None));
            let task = Task::new(String::new(), vec![unit.clone()], None);
            let flagged = crate::workspace::diagnostics_of(&task, &unit)
                .iter()
                .any(|d| d.rule.code == super::RULE.code);
            let refused = rapid_evaluator::parse_string_literal(lit)
                .is_err_and(|e| e.message.contains("backslash"));
            assert_eq!(flagged, refused, "{lit}");
        }
    }
}
