use tree_sitter::Node;

use crate::check::Cx;

crate::declare_rule! {
    /// A string literal longer than 80 characters.
    ///
    /// ### What it checks
    /// A RAPID string holds at most 80 characters (escape sequences such as `\\`,
    /// `""` and `\hh` count as one).
    ///
    /// ### Why
    /// The controller rejects the module; at run time such a string cannot exist.
    ///
    /// ### Example
    /// ```rapid
    /// TPWrite "A message so long that it goes on and on past the eighty characters a string holds";
    /// ```
    pub static RULE = ("E411", "string-too-long", Error);
}

/// The most characters a RAPID string holds.
pub(crate) const MAX_STRING: usize = rapid_evaluator::MAX_STRING_LEN;

/// A string literal: its length counts an escape sequence as one
/// character.
pub(crate) fn check(cx: &mut Cx<'_>, node: Node<'_>) {
    let len = string_length(cx, node);
    if len > MAX_STRING {
        cx.report(
            &RULE,
            node.byte_range(),
            format!("this string has {len} characters; a RAPID string holds at most {MAX_STRING}"),
        );
    }
}

/// The number of characters of a string literal's value (escapes count one).
fn string_length(cx: &Cx<'_>, node: Node<'_>) -> usize {
    let mut cursor = node.walk();
    node.named_children(&mut cursor)
        .map(|c| match crate::syntax_util::kind(c) {
            crate::syntax::kind::ESCAPE_SEQUENCE => 1,
            _ => cx.node_text(c).chars().count(),
        })
        .sum()
}
