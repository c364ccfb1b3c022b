use tree_sitter::Node;

use crate::check::Cx;
use crate::check::exprs::a_type;
use crate::sema::typing::{self, ComponentError};
use crate::ty::Ty;

crate::declare_rule! {
    /// A record component that the record type does not have, or `.` on a value that is not a record.
    ///
    /// ### What it checks
    /// Component access `a.b` on a value whose type is known: the type must be a
    /// record (built-in or `RECORD`) with a component of that name.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR robtarget p;
    /// p.pos.x := 10;        ! robtarget has trans, rot, robconf, extax: write p.trans.x
    /// ```
    pub static RULE = ("E105", "unknown-component", Error);
}

pub(crate) fn component_type(cx: &mut Cx<'_>, obj_ty: &Ty, comp: Node<'_>) -> Ty {
    let name = cx.node_text(comp);
    let message = match typing::component(&cx.types, obj_ty, name) {
        Ok(ty) => return ty,
        Err(ComponentError::OnArray) => format!("`.{name}` on an array {obj_ty}: index it first"),
        Err(ComponentError::NoSuch(list)) => format!(
            "{obj_ty} has no component `{name}`; its components are {}",
            list.join(", ")
        ),
        Err(ComponentError::NotRecord) => format!(
            "{} is not a record and has no component `{name}`",
            a_type(obj_ty)
        ),
    };
    cx.report(&RULE, comp.byte_range(), message);
    Ty::Unknown
}
