//! The checker's scopes entered around one offset, for the editor features
//! and constant evaluation.

use std::ops::Range;

use tree_sitter::Node;

use super::{Cx, RoutineCx, exprs};
use crate::names::{NameMap, fold};
use crate::syntax::{field, kind};
use crate::task::{Task, Unit};
use crate::ty::Ty;

/// Name resolution at a position, for the editor features ([`crate::ide`]):
/// the same scopes as the checker, entered around one offset.
impl<'t> Cx<'t> {
    /// A context whose module and routine scopes are those around `offset`
    /// of unit `unit` (parameters, routine data, and the variables of the
    /// `FOR` loops that enclose the offset).
    pub(crate) fn at(task: &'t Task, unit: usize, offset: usize) -> Option<Cx<'t>> {
        let u: &'t Unit = task.units.get(unit)?;
        let mut cx = Cx::new(task, unit, u);
        let within = |r: &Range<usize>| r.start <= offset && offset <= r.end;
        cx.module = u
            .items
            .modules
            .iter()
            .enumerate()
            .find(|(_, m)| within(&m.range));
        let Some((_, module)) = cx.module else {
            return Some(cx);
        };
        let Some(decl) = module.routines.iter().find(|r| within(&r.range)) else {
            return Some(cx);
        };
        let root = u.tree().root_node();
        let Some(node) = root.named_descendant_for_byte_range(decl.range.start, decl.range.end)
        else {
            return Some(cx);
        };
        let mut params = NameMap::default();
        for p in &decl.params {
            params.entry(fold(&p.name)).or_insert(p);
        }
        let mut locals = NameMap::default();
        // Routine data comes before the first statement: stop there, so that
        // entering a long routine costs its declarations, not its statements
        // (constant evaluation enters the scope once per statement).
        if let Some(body) = crate::syntax_util::field_id(field::BODY) {
            let mut cursor = node.walk();
            for item in node
                .children_by_field_id(body, &mut cursor)
                .take_while(|n| crate::syntax_util::kind(*n) == kind::DATA_DECLARATION)
            {
                if let Some(d) = crate::items::lower_data(item, &u.text) {
                    locals.entry(fold(&d.name)).or_insert(d);
                }
            }
        }
        let mut for_vars = Vec::new();
        let mut at = root.descendant_for_byte_range(offset, offset);
        while let Some(n) = at {
            if n.id() == node.id() {
                break;
            }
            if crate::syntax_util::kind(n) == kind::FOR_STATEMENT
                && let Some(v) = crate::syntax_util::field(n, field::VARIABLE)
            {
                for_vars.push(fold(cx.node_text(v)));
            }
            at = n.parent();
        }
        cx.routine = Some(RoutineCx {
            decl,
            params,
            locals,
            for_vars,
            labels: NameMap::default(),
            in_error_handler: false,
        });
        Some(cx)
    }

    /// The type of an expression in this context (its findings dropped).
    pub(crate) fn type_of_expr(&mut self, node: Node<'t>) -> Ty {
        // Only this expression's findings are dropped: the checker calls
        // this in the middle of a unit (constant evaluation).
        let before = self.diags.len();
        let used = self.used.clone();
        let recorded = self.recording.as_ref().map(Vec::len);
        let ty = exprs::expr(self, node, None);
        self.diags.truncate(before);
        self.used = used;
        // The statement cache records only the uses that stay.
        if let (Some(r), Some(len)) = (&mut self.recording, recorded) {
            r.truncate(len);
        }
        ty
    }
}
