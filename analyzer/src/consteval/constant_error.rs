//! Rule E413 (constant-error): expressions made only of literals, constants
//! and pure built-in functions that always fail with a run-time error.

use super::*;

use crate::syntax::{field, kind};
/// Reports expressions in `node` (a statement or a data declaration) that
/// are made only of literals, constants and pure built-in functions and
/// always fail with a run-time error. Nested statements are left to their
/// own call. Only maximal constant expressions that hold an operation are
/// evaluated, each once.
pub(crate) fn check_constant_errors<'t>(cx: &mut Cx<'t>, node: Node<'t>) {
    if !cx.selection.is_on(&crate::rules::constant_error::RULE) {
        return;
    }
    // Most statements hold no operation at all (`MoveL p10, v100, z10,
    // tool0;`): their text says so without a walk of their nodes.
    if !may_hold_operation(cx.node_text(node)) {
        return;
    }
    let mut found = Vec::new();
    let mut path = vec![(node, None)];
    scan(cx, &mut path, &mut found);
    if found.is_empty() {
        return;
    }
    let task = cx.task;
    let unit = cx.unit;
    let mut reports = Vec::new();
    let at = module_at(task, cx.unit_idx, node.start_byte());
    let routine = cx.routine.clone();
    let inits = cx.inits.take().unwrap_or_else(|| InitCache::new(task));
    with_routine(
        task,
        Some((cx.unit_idx, node.start_byte())),
        EnvOptions::default(),
        routine,
        Some(&inits),
        |env| {
            for path in found {
                let Some((n, _)) = path.last().copied() else {
                    continue;
                };
                let expected = expected_type(cx, &path, env);
                let expr = lower_with(n, &unit.text, &|name| is_builtin_call(task, at, name));
                let Err(e) =
                    rapid_evaluator::eval_with(&expr, expected.as_ref(), env, &Options::default())
                else {
                    continue;
                };
                if !e.code.is_runtime() {
                    continue;
                }
                // Without the type of its context, a literal may be meant as
                // a dnum: do not guess about limits.
                if expected.is_none()
                    && matches!(e.code, ErrorCode::MaxIntVal | ErrorCode::NumLimit)
                {
                    continue;
                }
                // A constant that fails on its own is reported where it is
                // declared, not at every use.
                if names_in(n).into_iter().any(|name| {
                    rapid_evaluator::eval(&Expr::Name(text_of(name, &unit.text).to_owned()), env)
                        .is_err()
                }) {
                    continue;
                }
                reports.push((n.byte_range(), e));
            }
        },
    );
    cx.inits = Some(inits);
    for (range, e) in reports {
        crate::rules::constant_error::report(cx, range, &e);
    }
}

/// Could this text (of a statement or a declaration) hold an operation as
/// [`has_operation`] sees them: a call or a parenthesis, an index, an
/// operator other than the sign of a number literal, an operator keyword?
/// Strings and comments are skipped. `false` is certain; `true` only means
/// that the nodes must be looked at.
pub(super) fn may_hold_operation(text: &str) -> bool {
    let b = text.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    // The digits and points of a number literal end just before `end`.
    let number_before = |end: usize| {
        let run = b[..end]
            .iter()
            .rev()
            .take_while(|c| c.is_ascii_digit() || **c == b'.')
            .count();
        run > 0 && (end == run || !b.get(end - run - 1).copied().is_some_and(is_word))
    };
    let mut prev = b' ';
    let mut i = 0;
    while let Some(&c) = b.get(i) {
        match c {
            b'"' => {
                i += 1;
                while b.get(i).is_some_and(|c| !matches!(c, b'"' | b'\n' | b'\r')) {
                    i += 1;
                }
                i += 1;
                prev = b'"';
                continue;
            }
            b'!' => {
                while b.get(i).is_some_and(|c| !matches!(c, b'\n' | b'\r')) {
                    i += 1;
                }
                continue;
            }
            b'(' | b'{' | b'*' | b'/' | b'<' | b'>' => return true,
            b'=' if prev != b':' => return true,
            b'+' | b'-' => {
                let digit_next = b
                    .get(i + 1)
                    .is_some_and(|d| d.is_ascii_digit() || *d == b'.');
                let sign = digit_next && matches!(prev, b'[' | b',' | b'=');
                let exponent =
                    digit_next && matches!(prev, b'e' | b'E') && i >= 1 && number_before(i - 1);
                if !(sign || exponent) {
                    return true;
                }
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let start = i;
                while b.get(i).copied().is_some_and(is_word) {
                    i += 1;
                }
                let word = &b[start..i];
                if ["div", "mod", "and", "or", "xor", "not"]
                    .iter()
                    .any(|k| word.eq_ignore_ascii_case(k.as_bytes()))
                {
                    return true;
                }
                prev = b[i - 1];
                continue;
            }
            _ => {}
        }
        if !c.is_ascii_whitespace() {
            prev = c;
        }
        i += 1;
    }
    false
}

/// Statements and declarations below a statement are checked on their own.
pub(super) fn is_statement_like(kind: &str) -> bool {
    crate::syntax_util::is_simple_statement(kind)
        || crate::syntax_util::is_compound_statement(kind)
        || matches!(kind, kind::LABEL | kind::DATA_DECLARATION)
}

/// The children of a node with their field names, read with `cursor` (one
/// cursor serves a whole statement: making one allocates).
pub(super) fn children_with_fields<'t>(
    cursor: &mut TreeCursor<'t>,
    node: Node<'t>,
) -> Vec<Step<'t>> {
    cursor.reset(node);
    let mut out = Vec::new();
    if cursor.goto_first_child() {
        loop {
            out.push((cursor.node(), cursor.field_name()));
            if !cursor.goto_next_sibling() {
                break;
            }
        }
    }
    out
}

/// Finds the maximal expressions below the last node of `path`, in source
/// order (one cursor for the whole walk: this runs for every statement).
pub(super) fn scan<'t>(cx: &mut Cx<'t>, path: &mut Vec<Step<'t>>, found: &mut Vec<Vec<Step<'t>>>) {
    let Some((node, _)) = path.last().copied() else {
        return;
    };
    let mut cursor = node.walk();
    if !cursor.goto_first_child() {
        return;
    }
    let mut aux = node.walk();
    // How far the cursor is below `node`; every node between `node` and the
    // cursor is on `path`.
    let mut depth = 1usize;
    loop {
        let child = cursor.node();
        let f = cursor.field_name();
        let mut descend = false;
        if child.is_named()
            && !is_statement_like(crate::syntax_util::kind(child))
            && !f.is_some_and(|f| NOT_VALUES.contains(&f))
        {
            path.push((child, f));
            if is_expression(crate::syntax_util::kind(child)) {
                // Aggregates of number literals (most robtargets) hold no
                // operation: their text says so without a walk.
                if !crate::syntax_util::is_literal_aggregate(child, cx.text)
                    && has_operation(&mut aux, child)
                {
                    let s = shape(cx, &mut aux, path, found, 0);
                    if s.constant && s.operation {
                        found.push(path.clone());
                    }
                }
                path.pop();
            } else {
                descend = true;
            }
        }
        if descend {
            if cursor.goto_first_child() {
                depth += 1;
                continue;
            }
            path.pop();
        }
        // The next node after `child` that is not below it.
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if depth <= 1 || !cursor.goto_parent() {
                return;
            }
            depth -= 1;
            path.pop();
        }
    }
}

/// Does the expression hold an operator, a call or an index (a cheap,
/// syntactic test before names are resolved)?
pub(super) fn has_operation<'t>(cursor: &mut TreeCursor<'t>, node: Node<'t>) -> bool {
    cursor.reset(node);
    loop {
        let n = cursor.node();
        if matches!(
            crate::syntax_util::kind(n),
            kind::BINARY_EXPRESSION | kind::FUNCTION_CALL | kind::INDEX_EXPRESSION
        ) || (crate::syntax_util::kind(n) == kind::UNARY_EXPRESSION && !is_signed_number(n))
        {
            return true;
        }
        if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.node().id() == node.id() {
                return false;
            }
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return false;
            }
        }
    }
}

/// `-1`, `+2.5`: a sign on a number literal.
pub(super) fn is_signed_number(node: Node<'_>) -> bool {
    crate::syntax_util::kind(node) == kind::UNARY_EXPRESSION
        && field(node, field::OPERAND).is_some_and(|o| crate::syntax_util::kind(o) == kind::NUMBER)
        && field(node, field::OPERATOR).is_some_and(|o| crate::syntax_util::kind(o) != "not")
}

/// An operand of an expression, as the steps from the expression to it.
pub(super) enum Part<'t> {
    /// An expression child (an operand, a call's base).
    Operand(Step<'t>),
    /// The value of an argument: the argument list, the argument, the value.
    Argument([Step<'t>; 3]),
}

impl<'t> Part<'t> {
    fn steps(&self) -> &[Step<'t>] {
        match self {
            Part::Operand(s) => std::slice::from_ref(s),
            Part::Argument(s) => s,
        }
    }
}

#[derive(Clone, Copy)]
pub(super) struct Shape {
    constant: bool,
    operation: bool,
}

/// Whether the expression at the end of `path` is made only of constants
/// and has an operation; the maximal constant parts with an operation of a
/// non-constant expression go to `found`.
pub(super) fn shape<'t>(
    cx: &mut Cx<'t>,
    cursor: &mut TreeCursor<'t>,
    path: &mut Vec<Step<'t>>,
    found: &mut Vec<Vec<Step<'t>>>,
    depth: u32,
) -> Shape {
    const NOT: Shape = Shape {
        constant: false,
        operation: false,
    };
    let Some((node, _)) = path.last().copied() else {
        return NOT;
    };
    if depth > crate::lower::MAX_DEPTH || node.has_error() {
        return NOT;
    }
    let (mut constant, operation) = match crate::syntax_util::kind(node) {
        kind::NUMBER | kind::STRING | kind::BOOLEAN => {
            return Shape {
                constant: true,
                operation: false,
            };
        }
        kind::IDENTIFIER => {
            return Shape {
                constant: is_constant_name(cx, cx.node_text(node)),
                operation: false,
            };
        }
        kind::PARENTHESIZED_EXPRESSION | kind::COMPONENT_ACCESS | kind::AGGREGATE => (true, false),
        // `-1` is a number, not a computation that could fail.
        kind::UNARY_EXPRESSION => (true, !is_signed_number(node)),
        kind::BINARY_EXPRESSION | kind::INDEX_EXPRESSION => (true, true),
        kind::FUNCTION_CALL => {
            let pure = field(node, field::NAME).is_some_and(|n| {
                let name = cx.node_text(n);
                rapid_evaluator::is_function(name)
                    && matches!(
                        cx.resolve_routine(name, true),
                        Some(Def::BuiltinRoutine(..))
                    )
            });
            (pure, true)
        }
        _ => return NOT,
    };
    // The operands: expression children, and the values of arguments.
    let mut parts: Vec<Part<'t>> = Vec::new();
    for (child, f) in children_with_fields(cursor, node) {
        if !child.is_named() || f.is_some_and(|f| NOT_VALUES.contains(&f)) {
            continue;
        }
        if is_expression(crate::syntax_util::kind(child)) {
            parts.push(Part::Operand((child, f)));
        } else if crate::syntax_util::kind(child) == kind::ARGUMENT_LIST {
            for (arg, af) in children_with_fields(cursor, child) {
                if crate::syntax_util::kind(arg) != kind::ARGUMENT {
                    continue;
                }
                let arg_parts = crate::syntax_util::argument_parts(arg);
                if arg_parts.conditional.is_some() {
                    constant = false;
                }
                match arg_parts.value {
                    Some(v) if is_expression(crate::syntax_util::kind(v)) => {
                        parts.push(Part::Argument([(child, f), (arg, af), (v, Some("value"))]));
                    }
                    Some(_) => constant = false,
                    None if arg_parts.backslash => {}
                    None => constant = false,
                }
            }
        } else if crate::syntax_util::kind(child) != kind::COMMENT {
            constant = false;
        }
    }
    let mut shapes = Vec::with_capacity(parts.len());
    for part in &parts {
        let steps = part.steps();
        path.extend_from_slice(steps);
        shapes.push(shape(cx, cursor, path, found, depth + 1));
        path.truncate(path.len() - steps.len());
    }
    let mut op = operation;
    for s in &shapes {
        constant &= s.constant;
        op |= s.operation;
    }
    if !constant {
        for (part, s) in parts.iter().zip(&shapes) {
            if s.constant && s.operation {
                let mut p = path.clone();
                p.extend_from_slice(part.steps());
                found.push(p);
            }
        }
        return NOT;
    }
    Shape {
        constant,
        operation: op,
    }
}

/// Does this name denote constant data here (as the checker resolves it)?
pub(super) fn is_constant_name(cx: &mut Cx<'_>, name: &str) -> bool {
    match cx.resolve_data(name) {
        Some(Def::BuiltinDatum(d)) => d.kind == DatumKind::Const,
        Some(def) => def
            .data_decl(cx.task)
            .is_some_and(|d| d.storage == Storage::Const),
        None => rapid_evaluator::predefined(name).is_some(),
    }
}

/// The data names used in an expression (not routine, component or
/// argument names).
pub(super) fn names_in(node: Node<'_>) -> Vec<Node<'_>> {
    let mut cursor = node.walk();
    let mut out = Vec::new();
    let mut stack = vec![(node, None)];
    while let Some((n, f)) = stack.pop() {
        if f.is_some_and(|f| NOT_VALUES.contains(&f)) {
            continue;
        }
        if crate::syntax_util::kind(n) == kind::IDENTIFIER {
            out.push(n);
            continue;
        }
        stack.extend(
            children_with_fields(&mut cursor, n)
                .into_iter()
                .filter(|(c, _)| c.is_named()),
        );
    }
    out
}
