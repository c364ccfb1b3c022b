//! Built-in record layouts and alias types, as the catalogue has them.

use rapid_catalogue::{Catalogue, Component, TypeKind, base};

/// Layout of a built-in record type in the whole catalogue: its components
/// in declaration order, or `None` if `name` is not a built-in record with a
/// documented layout (case-insensitive).
pub fn builtin_record_layout(name: &str) -> Option<&'static [Component]> {
    record_layout_in(base(), name)
}

/// Layout of a built-in record type in `cat`.
pub(crate) fn record_layout_in<'c>(cat: &'c Catalogue, name: &str) -> Option<&'c [Component]> {
    let t = cat.datatype(name)?;
    (t.kind == TypeKind::Record && !t.components.is_empty()).then_some(t.components.as_slice())
}

/// Built-in alias types of `num` (case-insensitive).
pub fn is_builtin_num_alias(name: &str) -> bool {
    is_alias_of(base(), name, "num")
}

/// Built-in alias types of `string` (case-insensitive).
pub fn is_builtin_string_alias(name: &str) -> bool {
    is_alias_of(base(), name, "string")
}

fn is_alias_of(cat: &Catalogue, name: &str, of: &str) -> bool {
    cat.datatype(name)
        .is_some_and(|t| t.kind == TypeKind::Alias)
        && cat.resolve_alias(name).eq_ignore_ascii_case(of)
}
