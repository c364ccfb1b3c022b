//! Statements: assignments, calls, control flow, labels and jumps, error
//! handling statements and `CONNECT`.

use tree_sitter::Node;

use super::{Cx, calls, exprs};
use crate::names::fold;
use crate::rules;
use crate::sema::labels::Label;
use crate::syntax::{field, kind};
use crate::syntax_util::{field, fields, kind as kind_of};
use crate::ty::Ty;

/// Records the labels of the routine being checked ([`labels::find`]) and
/// reports those declared twice.
pub(super) fn collect_labels(cx: &mut Cx<'_>, found: Vec<Label>) {
    let mut dups = Vec::new();
    if cx.routine.is_some() {
        for (name, range, list) in found {
            match cx.labels.get(&fold(&name)) {
                Some((first, _)) => dups.push((name, range, first.clone())),
                None => {
                    cx.labels.insert(fold(&name), (range, list));
                }
            }
        }
    }
    for (name, range, first) in dups {
        rules::duplicate_declaration::report_label(cx, &name, range, first);
    }
}

/// Checks a statement list, and reports the statements no path reaches.
pub(super) fn check_block<'t>(cx: &mut Cx<'t>, statements: &[Node<'t>]) {
    let mut ended_by: Option<&str> = None;
    for (i, s) in statements.iter().enumerate() {
        if kind_of(*s) == kind::LABEL {
            ended_by = None;
        } else if let Some(by) = ended_by.take() {
            let end = statements
                .iter()
                .skip(i)
                .take_while(|n| kind_of(**n) != kind::LABEL)
                .last()
                .map_or(s.end_byte(), |n| n.end_byte());
            rules::unreachable_code::report(cx, s.start_byte()..end, by);
        }
        check_statement(cx, *s);
        if ended_by.is_none() {
            ended_by = leaves_list(*s);
        }
    }
}

/// The keyword of a statement that always leaves its statement list.
fn leaves_list(s: Node<'_>) -> Option<&'static str> {
    Some(match kind_of(s) {
        kind::RETURN_STATEMENT => "RETURN",
        kind::EXIT_STATEMENT => "EXIT",
        kind::RAISE_STATEMENT => "RAISE",
        kind::GOTO_STATEMENT => "GOTO",
        kind::RETRY_STATEMENT => "RETRY",
        kind::TRYNEXT_STATEMENT => "TRYNEXT",
        _ => return None,
    })
}

fn check_statement<'t>(cx: &mut Cx<'t>, s: Node<'t>) {
    // Statements go through the statement cache (an edit elsewhere in the
    // routine does not check them again). Simple ones always; compound ones
    // whole when no GOTO inside depends on the routine's labels (which the
    // cache key leaves out), else part by part, their simple statements
    // cached in turn.
    let kind = kind_of(s);
    if matches!(kind, kind::ASSIGNMENT | kind::PROCEDURE_CALL) {
        cx.cached_statement(s, |cx| {
            crate::consteval::check_constant_errors(cx, s);
            if kind == kind::ASSIGNMENT {
                assignment(cx, s);
            } else {
                calls::procedure_call(cx, s);
            }
        });
        if kind == kind::PROCEDURE_CALL && cx.task.robot.is_some() {
            super::motion::check(cx, s);
        }
        return;
    }
    if crate::syntax_util::is_compound_statement(kind)
        && !s.has_error()
        && !mentions_goto(cx.node_text(s))
    {
        cx.cached_statement(s, |cx| check_uncached(cx, s));
        return;
    }
    check_uncached(cx, s);
}

/// Could this text hold a GOTO statement? (Any `goto` in any case, comments
/// and strings included.)
fn mentions_goto(text: &str) -> bool {
    text.as_bytes()
        .windows(4)
        .any(|w| w.eq_ignore_ascii_case(b"goto"))
}

fn check_uncached<'t>(cx: &mut Cx<'t>, s: Node<'t>) {
    crate::consteval::check_constant_errors(cx, s);
    match kind_of(s) {
        kind::IF_STATEMENT => {
            if let Some(c) = field(s, field::CONDITION) {
                rules::condition_not_bool::check(cx, c);
            }
            check_block(cx, &fields(s, field::BODY));
            for alt in fields(s, field::ALTERNATIVE) {
                if let Some(c) = field(alt, field::CONDITION) {
                    rules::condition_not_bool::check(cx, c);
                }
                check_block(cx, &fields(alt, field::BODY));
            }
        }
        kind::COMPACT_IF_STATEMENT => {
            if let Some(c) = field(s, field::CONDITION) {
                rules::condition_not_bool::check(cx, c);
            }
            if let Some(b) = field(s, field::BODY) {
                check_statement(cx, b);
            }
        }
        kind::FOR_STATEMENT => for_statement(cx, s),
        kind::WHILE_STATEMENT => {
            if let Some(c) = field(s, field::CONDITION) {
                rules::condition_not_bool::check(cx, c);
            }
            check_block(cx, &fields(s, field::BODY));
        }
        kind::TEST_STATEMENT => test_statement(cx, s),
        kind::GOTO_STATEMENT => rules::unknown_label::check(cx, s),
        kind::RETURN_STATEMENT => rules::return_value::check(cx, s),
        kind::RAISE_STATEMENT => match field(s, field::VALUE) {
            Some(v) => exprs::check_expected(cx, v, &Ty::named("errnum"), "the error number"),
            None => rules::handler_only_statement::check(cx, s, "RAISE without an error number"),
        },
        kind::RETRY_STATEMENT => rules::handler_only_statement::check(cx, s, "RETRY"),
        kind::TRYNEXT_STATEMENT => rules::handler_only_statement::check(cx, s, "TRYNEXT"),
        kind::CONNECT_STATEMENT => rules::connect_target::check(cx, s),
        _ => {}
    }
}

fn assignment<'t>(cx: &mut Cx<'t>, s: Node<'t>) {
    let (Some(left), Some(right)) = (field(s, field::LEFT), field(s, field::RIGHT)) else {
        return;
    };
    let (ty, place) = exprs::place_or_value(cx, left);
    rules::assign_to_constant::check(cx, left.byte_range(), place);
    exprs::check_expected(cx, right, &ty, "the assigned value");
}

fn for_statement<'t>(cx: &mut Cx<'t>, s: Node<'t>) {
    for bound in [field::FROM, field::TO, field::STEP] {
        if let Some(b) = field(s, bound) {
            exprs::check_expected(
                cx,
                b,
                &Ty::num(),
                &format!("the FOR {} value", bound.to_ascii_uppercase()),
            );
        }
    }
    let var = field(s, field::VARIABLE).map(|v| (fold(cx.node_text(v)), v.byte_range()));
    if let (Some(r), Some(v)) = (&mut cx.routine, &var) {
        r.for_vars.push(v.clone());
    }
    check_block(cx, &fields(s, field::BODY));
    if let (Some(r), Some(_)) = (&mut cx.routine, &var) {
        r.for_vars.pop();
    }
}

fn test_statement<'t>(cx: &mut Cx<'t>, s: Node<'t>) {
    let values: Vec<Node<'t>> = fields(s, field::CASE)
        .iter()
        .flat_map(|c| fields(*c, field::VALUE))
        .collect();
    let ty = match field(s, field::VALUE) {
        Some(v) => match exprs::tested_signal(cx, v, &values) {
            Some(signal) => {
                let name = cx.node_text(v);
                cx.unknown_signal(v, name, &signal);
                signal
            }
            None => exprs::expr(cx, v, None),
        },
        None => Ty::Unknown,
    };
    let ty = cx.types.value_type(&ty);
    for case in fields(s, field::CASE) {
        for v in fields(case, field::VALUE) {
            exprs::check_expected(cx, v, &ty, "the CASE value");
        }
        check_block(cx, &fields(case, field::BODY));
    }
    if let Some(d) = field(s, field::DEFAULT) {
        check_block(cx, &fields(d, field::BODY));
    }
}

/// Does every path through this list end in RETURN, RAISE, EXIT or a jump?
pub(super) fn block_terminates(cx: &Cx<'_>, statements: &[Node<'_>]) -> bool {
    statements.iter().any(|s| terminates(cx, *s))
}

fn terminates(cx: &Cx<'_>, s: Node<'_>) -> bool {
    match s.kind() {
        kind::RETURN_STATEMENT
        | kind::RAISE_STATEMENT
        | kind::EXIT_STATEMENT
        | kind::GOTO_STATEMENT
        | kind::RETRY_STATEMENT
        | kind::TRYNEXT_STATEMENT => true,
        kind::IF_STATEMENT => {
            let alts = fields(s, field::ALTERNATIVE);
            alts.iter().any(|a| a.kind() == kind::ELSE_CLAUSE)
                && block_terminates(cx, &fields(s, field::BODY))
                && alts
                    .iter()
                    .all(|a| block_terminates(cx, &fields(*a, field::BODY)))
        }
        kind::TEST_STATEMENT => {
            field(s, field::DEFAULT).is_some_and(|d| block_terminates(cx, &fields(d, field::BODY)))
                && fields(s, field::CASE)
                    .iter()
                    .all(|c| block_terminates(cx, &fields(*c, field::BODY)))
        }
        kind::WHILE_STATEMENT => field(s, field::CONDITION).is_some_and(|c| {
            c.kind() == kind::BOOLEAN && cx.node_text(c).eq_ignore_ascii_case("true")
        }),
        // An instruction that ends execution (`ExitCycle`).
        kind::PROCEDURE_CALL => field(s, field::NAME)
            .and_then(|n| cx.cat.instruction(cx.node_text(n)))
            .is_some_and(|r| r.terminates),
        _ => false,
    }
}
