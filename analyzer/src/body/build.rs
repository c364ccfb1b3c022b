//! Building [`Body`]s from the syntax tree.

use rapid_evaluator::Expr;
use tree_sitter::Node;

use super::{
    ArgValue, Body, Branch, Call, CallArg, Callee, Case, ErrorHandler, Handler, LocalData,
    MAX_NESTING, Stmt, StmtKind,
};
use crate::items::{RoutineDecl, Storage};
use crate::lower::{conditional, lower};
use crate::syntax::{field, kind};
use crate::syntax_util::{argument_parts, field, fields, kind, text_of};
use crate::task::Unit;

/// The bodies of every routine of a unit, module by module, in source
/// order.
pub fn routine_bodies(unit: &Unit) -> Vec<Body> {
    unit.items
        .modules
        .iter()
        .flat_map(|m| m.routines.iter())
        .filter_map(|r| lower_routine(unit, r))
        .collect()
}

/// The body of the routine `routine` of `unit` (`None` when its node
/// cannot be found, which a unit's own item never causes).
pub fn lower_routine(unit: &Unit, routine: &RoutineDecl) -> Option<Body> {
    let range = routine.range.clone();
    let tree = unit.tree();
    let mut node = tree
        .root_node()
        .descendant_for_byte_range(range.start, range.end)?;
    while !is_routine(node) || node.byte_range() != range {
        node = node.parent()?;
        if node.start_byte() < range.start {
            return None;
        }
    }
    let items = fields(node, field::BODY);
    let b = Builder { text: &unit.text };
    let mut data = Vec::new();
    let mut stmts = Vec::new();
    for item in items {
        if kind(item) == kind::DATA_DECLARATION {
            data.extend(b.data(item));
        } else {
            stmts.push(b.stmt(item, 0));
        }
    }
    let handler = |name: &str| {
        field(node, name).map(|h| Handler {
            range: h.byte_range(),
            stmts: b.list(h, 0),
        })
    };
    Some(Body {
        kind: routine.kind,
        name: routine.name.clone(),
        range,
        data,
        stmts,
        backward: handler(field::BACKWARD),
        undo: handler(field::UNDO),
        error: field(node, field::ERROR).map(|h| ErrorHandler {
            range: h.byte_range(),
            errors: fields(h, field::ERROR)
                .into_iter()
                .map(|e| b.expr(e))
                .collect(),
            stmts: b.list(h, 0),
        }),
    })
}

fn is_routine(node: Node<'_>) -> bool {
    matches!(
        kind(node),
        kind::PROCEDURE_DECLARATION | kind::FUNCTION_DECLARATION | kind::TRAP_DECLARATION
    )
}

/// The expression of `unit` that spans exactly `range` (a data
/// declaration's initial value or dimension, as [`crate::items`] records
/// them), lowered.
pub fn expression_at(unit: &Unit, range: std::ops::Range<usize>) -> Option<Expr> {
    let tree = unit.tree();
    let mut node = tree
        .root_node()
        .descendant_for_byte_range(range.start, range.end)?;
    loop {
        if node.byte_range() == range && crate::lower::is_expression(kind(node)) {
            return Some(lower(node, &unit.text));
        }
        node = node.parent()?;
        if node.start_byte() < range.start || node.end_byte() > range.end {
            return None;
        }
    }
}

/// Parses `text` as one RAPID expression (for a debugger's evaluate, or a
/// value given on a command line): the expression, or why it is not one.
pub fn expression_of(text: &str) -> Result<Expr, String> {
    const PREFIX: &str = "MODULE expression_\n  CONST anytype expression_ := ";
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err("the expression is empty".to_owned());
    }
    let source = format!("{PREFIX}{trimmed};\nENDMODULE\n");
    let unit = Unit::new(String::new(), source, None);
    if let Some(d) = unit.syntax.first() {
        let column = d.range.start.saturating_sub(PREFIX.len()) + 1;
        return Err(format!("at column {column}: {}", d.message));
    }
    let (start, end) = (PREFIX.len(), PREFIX.len() + trimmed.len());
    let tree = unit.tree();
    let mut node = tree
        .root_node()
        .named_descendant_for_byte_range(start, end)
        .ok_or("not an expression")?;
    loop {
        if node.byte_range() == (start..end) && crate::lower::is_expression(kind(node)) {
            return Ok(lower(node, &unit.text));
        }
        node = node.parent().ok_or("not a single expression")?;
        if node.start_byte() < start || node.end_byte() > end {
            return Err("not a single expression".to_owned());
        }
    }
}

struct Builder<'a> {
    text: &'a str,
}

impl Builder<'_> {
    fn expr(&self, node: Node<'_>) -> Expr {
        lower(node, self.text)
    }

    fn opt_expr(&self, node: Node<'_>, name: &str) -> Option<Expr> {
        field(node, name).map(|n| self.expr(n))
    }

    fn req_expr(&self, node: Node<'_>, name: &str) -> Expr {
        self.opt_expr(node, name).unwrap_or(Expr::Unknown)
    }

    fn name(&self, node: Node<'_>, name: &str) -> Option<(String, std::ops::Range<usize>)> {
        field(node, name)
            .filter(|n| kind(*n) == kind::IDENTIFIER && !n.is_missing())
            .map(|n| (text_of(n, self.text).to_owned(), n.byte_range()))
    }

    /// The statements in the `body` fields of `node`.
    fn list(&self, node: Node<'_>, depth: u32) -> Vec<Stmt> {
        fields(node, field::BODY)
            .into_iter()
            .filter(|n| kind(*n) != kind::DATA_DECLARATION)
            .map(|n| self.stmt(n, depth))
            .collect()
    }

    fn data(&self, node: Node<'_>) -> Option<LocalData> {
        let (name, name_range) = self.name(node, field::NAME)?;
        let storage = match field(node, field::STORAGE).map(kind) {
            Some("pers") => Storage::Pers,
            Some("const") => Storage::Const,
            _ => Storage::Var,
        };
        let dims = field(node, field::DIMENSIONS)
            .map(|d| {
                fields(d, field::DIMENSION)
                    .into_iter()
                    .map(|e| self.expr(e))
                    .collect()
            })
            .unwrap_or_default();
        Some(LocalData {
            name,
            name_range,
            range: node.byte_range(),
            storage,
            ty: field(node, field::TYPE)
                .map(|t| text_of(t, self.text).to_owned())
                .unwrap_or_default(),
            dims,
            init: self.opt_expr(node, field::VALUE),
        })
    }

    fn stmt(&self, node: Node<'_>, depth: u32) -> Stmt {
        let range = node.byte_range();
        let kind = if depth >= MAX_NESTING || node.is_error() || node.is_missing() {
            StmtKind::Invalid
        } else {
            self.stmt_kind(node, depth + 1)
        };
        Stmt { range, kind }
    }

    fn stmt_kind(&self, node: Node<'_>, depth: u32) -> StmtKind {
        match kind(node) {
            kind::ASSIGNMENT => StmtKind::Assign {
                target: self.req_expr(node, field::LEFT),
                value: self.req_expr(node, field::RIGHT),
            },
            kind::PROCEDURE_CALL => match self.call(node) {
                Some(c) => StmtKind::Call(c),
                None => StmtKind::Invalid,
            },
            kind::IF_STATEMENT => {
                let mut branches = vec![Branch {
                    cond: self.req_expr(node, field::CONDITION),
                    body: self.list(node, depth),
                }];
                let mut otherwise = None;
                for alt in fields(node, field::ALTERNATIVE) {
                    match kind(alt) {
                        kind::ELSEIF_CLAUSE => branches.push(Branch {
                            cond: self.req_expr(alt, field::CONDITION),
                            body: self.list(alt, depth),
                        }),
                        kind::ELSE_CLAUSE => otherwise = Some(self.list(alt, depth)),
                        // `<EIT>`: a branch nobody wrote yet.
                        _ => branches.push(Branch {
                            cond: Expr::Unknown,
                            body: vec![Stmt {
                                range: alt.byte_range(),
                                kind: StmtKind::Invalid,
                            }],
                        }),
                    }
                }
                StmtKind::If {
                    branches,
                    otherwise,
                    compact: false,
                }
            }
            kind::COMPACT_IF_STATEMENT => StmtKind::If {
                branches: vec![Branch {
                    cond: self.req_expr(node, field::CONDITION),
                    body: field(node, field::BODY)
                        .map(|b| vec![self.stmt(b, depth)])
                        .unwrap_or_default(),
                }],
                otherwise: None,
                compact: true,
            },
            kind::FOR_STATEMENT => match self.name(node, field::VARIABLE) {
                Some((var, var_range)) => StmtKind::For {
                    var,
                    var_range,
                    from: self.req_expr(node, field::FROM),
                    to: self.req_expr(node, field::TO),
                    step: self.opt_expr(node, field::STEP),
                    body: self.list(node, depth),
                },
                None => StmtKind::Invalid,
            },
            kind::WHILE_STATEMENT => StmtKind::While {
                cond: self.req_expr(node, field::CONDITION),
                body: self.list(node, depth),
            },
            kind::TEST_STATEMENT => StmtKind::Test {
                value: self.req_expr(node, field::VALUE),
                cases: fields(node, field::CASE)
                    .into_iter()
                    .map(|c| Case {
                        range: c.byte_range(),
                        values: fields(c, field::VALUE)
                            .into_iter()
                            .map(|v| self.expr(v))
                            .collect(),
                        body: self.list(c, depth),
                    })
                    .collect(),
                default: field(node, field::DEFAULT).map(|d| self.list(d, depth)),
            },
            kind::LABEL => match self.name(node, field::NAME) {
                Some((n, _)) => StmtKind::Label(n),
                None => StmtKind::Invalid,
            },
            kind::GOTO_STATEMENT => match self.name(node, field::LABEL) {
                Some((n, _)) => StmtKind::Goto(n),
                None => StmtKind::Invalid,
            },
            kind::RETURN_STATEMENT => StmtKind::Return(self.opt_expr(node, field::VALUE)),
            kind::RAISE_STATEMENT => StmtKind::Raise(self.opt_expr(node, field::VALUE)),
            kind::EXIT_STATEMENT => StmtKind::Exit,
            kind::RETRY_STATEMENT => StmtKind::Retry,
            kind::TRYNEXT_STATEMENT => StmtKind::TryNext,
            kind::CONNECT_STATEMENT => match self.name(node, field::TRAP) {
                Some((trap, trap_range)) => StmtKind::Connect {
                    interrupt: self.req_expr(node, field::INTERRUPT),
                    trap,
                    trap_range,
                },
                None => StmtKind::Invalid,
            },
            _ => StmtKind::Invalid,
        }
    }

    fn call(&self, node: Node<'_>) -> Option<Call> {
        let name = field(node, field::NAME)?;
        let callee = match kind(name) {
            kind::IDENTIFIER if !name.is_missing() => {
                Callee::Name(text_of(name, self.text).to_owned())
            }
            kind::LATE_BINDING => Callee::Late(self.req_expr(name, field::EXPRESSION)),
            _ => return None,
        };
        let args = field(node, field::ARGUMENTS)
            .map(|list| {
                fields(list, field::ARGUMENT)
                    .into_iter()
                    .map(|a| self.argument(a))
                    .collect()
            })
            .unwrap_or_default();
        Some(Call {
            callee,
            callee_range: name.byte_range(),
            args,
        })
    }

    fn argument(&self, node: Node<'_>) -> CallArg {
        let parts = argument_parts(node);
        let name = parts
            .name
            .filter(|n| kind(*n) == kind::IDENTIFIER && !n.is_missing())
            .map(|n| text_of(n, self.text).to_owned());
        let broken = parts.name.is_some() && name.is_none();
        let value = if broken || node.has_error() {
            ArgValue::Invalid
        } else if let Some(c) = parts.conditional {
            match conditional(c, self.text) {
                Expr::Conditional(n) => ArgValue::Conditional(n),
                _ => ArgValue::Invalid,
            }
        } else if let Some(v) = parts.value {
            if kind(v) == kind::STAR {
                ArgValue::Star
            } else {
                ArgValue::Expr(self.expr(v))
            }
        } else if parts.backslash {
            ArgValue::Switch
        } else {
            ArgValue::Invalid
        };
        CallArg {
            range: node.byte_range(),
            name,
            optional: parts.backslash,
            value,
        }
    }
}
