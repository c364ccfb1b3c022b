//! Small helpers over tree-sitter nodes, shared by lowering and checking.

use tree_sitter::Node;

/// The source text of a node ("" if the range is not in `text`).
pub fn text_of<'t>(node: Node<'_>, text: &'t str) -> &'t str {
    text.get(node.byte_range()).unwrap_or_default()
}

/// The grammar's field id for a field name, resolved once per name (tree-
/// sitter's own lookup compares the name with every field name per call).
pub fn field_id(name: &str) -> Option<std::num::NonZeroU16> {
    static IDS: std::sync::OnceLock<std::collections::HashMap<String, std::num::NonZeroU16>> =
        std::sync::OnceLock::new();
    IDS.get_or_init(|| {
        let language = crate::syntax::language();
        (1..=language.field_count())
            .filter_map(|i| {
                let id = u16::try_from(i).ok()?;
                Some((
                    language.field_name_for_id(id)?.to_owned(),
                    std::num::NonZeroU16::new(id)?,
                ))
            })
            .collect()
    })
    .get(name)
    .copied()
}

/// The child in field `name`.
pub fn field<'a>(node: Node<'a>, name: &str) -> Option<Node<'a>> {
    node.child_by_field_id(field_id(name)?.get())
}

/// Every child in field `name`, in order.
pub fn fields<'a>(node: Node<'a>, name: &str) -> Vec<Node<'a>> {
    let Some(id) = field_id(name) else {
        return Vec::new();
    };
    let mut cursor = node.walk();
    node.children_by_field_id(id, &mut cursor).collect()
}

/// Does the node have an anonymous child of this kind (a keyword, which the
/// grammar shows in lower case whatever the source case)?
pub fn has_token(node: Node<'_>, kind: &str) -> bool {
    let mut cursor = node.walk();
    node.children(&mut cursor)
        .any(|c| !c.is_named() && c.kind() == kind)
}

/// Is this node a FlexPendant placeholder such as `<SMT>`?
pub fn is_placeholder(node: Node<'_>) -> bool {
    node.kind() == "placeholder"
}

/// The node's kind, as [`Node::kind`] gives it, from a table built once
/// (`Node::kind` checks the name's UTF-8 on every call, which shows in walks
/// over long routines).
pub fn kind<'a>(node: Node<'a>) -> &'a str {
    static NAMES: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    let names = NAMES.get_or_init(|| {
        let language = crate::syntax::language();
        (0..language.node_kind_count())
            .map(|i| {
                u16::try_from(i)
                    .ok()
                    .and_then(|id| language.node_kind_for_id(id))
                    .unwrap_or_default()
                    .to_owned()
            })
            .collect()
    });
    match names.get(usize::from(node.kind_id())) {
        Some(name) if !name.is_empty() => name.as_str(),
        // ERROR and the like are outside the table.
        _ => node.kind(),
    }
}
