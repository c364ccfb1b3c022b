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
