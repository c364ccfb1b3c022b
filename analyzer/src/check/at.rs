//! The oracle of [`crate::sema::typing::type_of`]: the type the checker
//! gives an expression while it checks it.

use tree_sitter::Node;

use super::{Cx, exprs};
use crate::sema::scope::Scope;
use crate::task::Task;
use crate::ty::Ty;

/// The type the checker gives expression `node` of unit `unit`, checked in
/// the scopes around it.
pub(crate) fn checker_type_of(task: &Task, unit: usize, node: Node<'_>) -> Ty {
    let Some(u) = task.unit(unit) else {
        return Ty::Unknown;
    };
    let Some(scope) = Scope::at(task, unit, node.start_byte()) else {
        return Ty::Unknown;
    };
    let mut cx = Cx::new(task, unit, u);
    cx.scope = scope;
    exprs::expr(&mut cx, node, None)
}
