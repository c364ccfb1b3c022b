use std::ops::Range;

use tree_sitter::Node;

use super::fix_text::{indent_at, line_break, line_start};
use crate::check::Kind;
use crate::diagnostic::{Applicability, Diagnostic, Fix};
use crate::names::fold;
use crate::syntax::{field, kind};
use crate::syntax_util::fields;
use crate::task::Task;
use crate::ty::Ty;

crate::declare_rule! {
    /// A name that no module of the task and no built-in declares.
    ///
    /// ### What it checks
    /// A data object, routine or data type that is declared nowhere in the task's
    /// modules, in the built-in catalogue, or in the controller's configuration
    /// (signals from `EIO.cfg`, mechanical units from `MOC.cfg`, the `taskid`
    /// RobotWare declares for each task, such as `T_ROB1Id`, from `SYS.cfg` or the
    /// backup's task folders). It is reported once per name with its other uses
    /// as related locations (once per file in the editor, once per task in
    /// `rapid check`), and the message proposes close matches of the same kind
    /// when there are any. How sure the finding is decides its severity:
    ///
    /// - In a task of a complete controller backup (the backup has its `SYSPAR`,
    ///   every module of the task could be read, and every module `SYS.cfg` loads
    ///   into the task is there) nothing can be missing: an error.
    /// - Anywhere else the name may be declared in a module, station data or a
    ///   RobotWare option that the checked files do not hold (a partial backup, a
    ///   repository of program modules): a note. When it is one edit (a letter
    ///   added, left out, changed, or two swapped) away from a declared name of
    ///   the same kind, it is more likely a typing mistake: a warning that says
    ///   which name was meant. Names that differ only in digits (`p10`, `p20`)
    ///   are a numbered family, not a typing mistake.
    /// - In a module of a controller's `HOME/` folder that no task here loads,
    ///   the task it is loaded into at run time is not among the checked files:
    ///   a note, always.
    ///
    /// ### Why
    /// A module that uses an undeclared name fails to link when it is loaded on the
    /// controller.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     MoveL pHome, v1000, fine, tGriper;   ! tGripper was meant
    /// ENDPROC
    /// ```
    pub static RULE = ("W101", "unresolved-name", Warning);
}

/// The fix of an unresolved data name while the unit is being checked:
/// its edit goes to the top of the routine, outside the statement, so it
/// is completed by [`declare_fix`] once the unit's findings are known.
pub(crate) fn pending_declare_fix() -> Fix {
    Fix {
        title: String::new(),
        edits: Vec::new(),
        applicability: Applicability::Unsafe,
        preferred: true,
    }
}

/// Declares the unresolved data name at `range` of unit `unit`: `VAR
/// <type> name;` before the first item of the routine around it, indented
/// like that item (two spaces more than the routine after a header with
/// nothing under it). The type is the other side's of an assignment, the
/// parameter's the name is passed to, `num` for a FOR variable, and `num`
/// when none of these tells. Not safe: the type (and VAR) are guesses.
/// `None` outside a routine.
pub(crate) fn declare_fix(task: &Task, unit: usize, range: Range<usize>) -> Option<Fix> {
    let u = task.unit(unit)?;
    let name = u.text.get(range.clone())?;
    let routine = routine_around(u.tree().root_node(), range.start)?;
    let ty = infer_type(task, unit, range).unwrap_or_else(|| "num".to_owned());
    let nl = line_break(&u.text);
    let (at, indent) = match fields(routine, field::BODY).first() {
        Some(first) => (
            line_start(&u.text, first.start_byte()),
            indent_at(&u.text, first.start_byte()).to_owned(),
        ),
        None => {
            // After the header line.
            let header_end = u
                .text
                .get(routine.start_byte()..)
                .and_then(|t| t.find('\n'))
                .map_or(routine.end_byte(), |i| routine.start_byte() + i + 1);
            (
                header_end,
                format!("{}  ", indent_at(&u.text, routine.start_byte())),
            )
        }
    };
    Some(Fix::edit(
        format!("Declare `VAR {ty} {name};` in this routine"),
        at..at,
        format!("{indent}VAR {ty} {name};{nl}"),
        Applicability::Unsafe,
        true,
    ))
}

/// The routine node around `offset`.
fn routine_around(root: Node<'_>, offset: usize) -> Option<Node<'_>> {
    let mut at = root.descendant_for_byte_range(offset, offset);
    while let Some(n) = at {
        if matches!(
            n.kind(),
            kind::PROCEDURE_DECLARATION | kind::FUNCTION_DECLARATION | kind::TRAP_DECLARATION
        ) {
            return Some(n);
        }
        at = n.parent();
    }
    None
}

/// The type a name at `range` must have: from an assignment's other side,
/// or the parameter it is passed to.
fn infer_type(task: &Task, unit: usize, range: Range<usize>) -> Option<String> {
    let u = task.unit(unit)?;
    let node = u
        .tree()
        .root_node()
        .named_descendant_for_byte_range(range.start, range.end)?;
    let parent = node.parent()?;
    match parent.kind() {
        kind::ASSIGNMENT => {
            let other = match crate::ide::resolve::field_in_parent(node) {
                Some(field::LEFT) => parent.child_by_field_name(field::RIGHT)?,
                _ => parent.child_by_field_name(field::LEFT)?,
            };
            let cx = crate::sema::scope::Scope::at(task, unit, range.start)?;
            match crate::sema::typing::type_of(&cx, other, None) {
                Ty::Named(n) => Some(n),
                _ => None,
            }
        }
        kind::FOR_STATEMENT => Some("num".to_owned()),
        kind::ARGUMENT => {
            use crate::ide::signature::{active, call_sig};
            let (sig, call) = call_sig(task, unit, range.end)?;
            let p = sig.params.get(active(&sig, &call)?)?;
            if p.type_name.eq_ignore_ascii_case(crate::catalogue::ANYTYPE) || p.type_name.is_empty()
            {
                return None;
            }
            Some(p.type_name.clone())
        }
        _ => None,
    }
}

/// Are the two names the same once their digits are left out?
fn same_but_digits(a: &str, b: &str) -> bool {
    let letters = |s: &str| {
        s.chars()
            .filter(|c| !c.is_ascii_digit())
            .map(crate::names::fold_char)
            .collect::<String>()
    };
    letters(a) == letters(b)
}

/// Reporting an unresolved name: the checker calls these where its
/// resolver finds nothing.
impl crate::check::Cx<'_> {
    /// Reports a name that resolves to nothing, with the most helpful code.
    pub(crate) fn unresolved(&mut self, name: &str, range: Range<usize>, what: &str) {
        if let Some(r) = self.local_elsewhere(name) {
            super::local_not_visible::report(self, name, range, r);
            return;
        }
        let mut message = format!("no {what} named `{name}` is declared in this task or built in");
        let kind = Kind::of(what);
        let memo_key = (kind, fold(name));
        let close = match self.close_memo.get(&memo_key) {
            Some(close) => close.clone(),
            None => {
                let close = self.close_match(name, kind);
                self.close_memo.insert(memo_key, close.clone());
                close
            }
        };
        if let Some((_, close)) = &close {
            message.push_str(&format!("; did you mean `{close}`?"));
        } else if what == "data" && self.task.signals.is_none() {
            message.push_str(" (if it is an I/O signal, give the controller's EIO.cfg)");
        }
        let mut d = self.unresolved_diagnostic(range, message);
        // Outside a complete backup, a name one edit from a declared one is
        // likely a typing mistake; any other may be declared elsewhere. Names
        // that differ only in their digits are a numbered family (`p10`,
        // `p20`; `id_A073_Start`, `id_A083_Start`), not a slip of the keys.
        let typo = close
            .as_ref()
            .is_some_and(|(distance, near)| *distance == 1 && !same_but_digits(name, near));
        if !self.task.complete && !self.task.loaded_elsewhere && !typo {
            d.severity = crate::diagnostic::Severity::Info;
        }
        if kind == Kind::Data {
            d = d.with_fix(pending_declare_fix());
        }
        self.report_with(d);
    }

    /// Reports a name nothing declares: an error in a complete backup's
    /// task (every module is here, so the controller would refuse to load
    /// it), a note in `HOME/` modules that no task here loads (the task
    /// they are loaded into is not here), a warning anywhere else (the
    /// declaration may be in a module or an option that is not part of the
    /// checked files).
    pub(crate) fn report_unresolved(&mut self, range: Range<usize>, message: String) {
        let d = self.unresolved_diagnostic(range, message);
        self.report_with(d);
    }

    pub(crate) fn unresolved_diagnostic(&self, range: Range<usize>, message: String) -> Diagnostic {
        let mut d = Diagnostic::new(&RULE, range, message);
        if self.task.complete {
            d.severity = crate::diagnostic::Severity::Error;
        } else if self.task.loaded_elsewhere {
            d.severity = crate::diagnostic::Severity::Info;
        }
        d
    }
}
