//! Lowering expression nodes of the syntax tree to the evaluator's small
//! [`Expr`] form.
//!
//! Lowering is purely syntactic: names stay names (the evaluator resolves
//! them through an [`rapid_evaluator::Env`]), literals keep their source
//! text. Anything that is not a well-formed expression (a placeholder, a
//! syntax error, a `*` argument, nesting deeper than [`MAX_DEPTH`]) becomes
//! [`Expr::Unknown`], which the evaluator reports as not computable; a
//! conditional argument `\Dec?x` becomes [`Expr::Conditional`], which only
//! a running program can resolve. Never panics.

use rapid_evaluator::{Arg, BinOp, Expr, UnOp};
use tree_sitter::Node;

use crate::syntax::{field, kind};
use crate::syntax_util::{Literal, field, fields, has_token, text_of};

/// Deepest nesting of expression nodes that is lowered; deeper
/// sub-expressions become [`Expr::Unknown`]. Keeps lowering (and dropping
/// the result) well within the stack on any input.
pub const MAX_DEPTH: u32 = 256;

/// The node kinds that are expressions.
pub const EXPRESSION_KINDS: &[&str] = &[
    kind::AGGREGATE,
    kind::BINARY_EXPRESSION,
    kind::BOOLEAN,
    kind::COMPONENT_ACCESS,
    kind::FUNCTION_CALL,
    kind::IDENTIFIER,
    kind::INDEX_EXPRESSION,
    kind::NUMBER,
    kind::PARENTHESIZED_EXPRESSION,
    kind::STRING,
    kind::UNARY_EXPRESSION,
];

/// Is a node of this kind an expression?
pub fn is_expression(kind: &str) -> bool {
    EXPRESSION_KINDS.contains(&kind)
}

/// Lowers an expression node. Every call is kept as a call; the evaluator
/// decides which functions it can compute.
pub fn lower(node: Node<'_>, text: &str) -> Expr {
    lower_with(node, text, &|_| true)
}

/// Lowers an expression node; a call whose name `is_builtin` rejects (a user
/// function that hides or is not a built-in one) becomes [`Expr::Unknown`].
pub fn lower_with(node: Node<'_>, text: &str, is_builtin: &dyn Fn(&str) -> bool) -> Expr {
    Lowering { text, is_builtin }.expr(node, 0)
}

struct Lowering<'a> {
    text: &'a str,
    is_builtin: &'a dyn Fn(&str) -> bool,
}

impl Lowering<'_> {
    fn expr(&self, node: Node<'_>, depth: u32) -> Expr {
        if depth >= MAX_DEPTH || node.is_error() || node.is_missing() {
            return Expr::Unknown;
        }
        let depth = depth + 1;
        let text = text_of(node, self.text);
        match crate::syntax_util::kind(node) {
            kind::NUMBER => Expr::Num(text.to_owned()),
            kind::STRING => Expr::Str(text.to_owned()),
            kind::BOOLEAN => Expr::Bool(has_token(node, "true")),
            kind::IDENTIFIER => Expr::Name(text.to_owned()),
            kind::PARENTHESIZED_EXPRESSION => self.child(node, field::EXPRESSION, depth),
            kind::UNARY_EXPRESSION => {
                let op = match field(node, field::OPERATOR).map(|o| crate::syntax_util::kind(o)) {
                    Some("-") => UnOp::Neg,
                    Some("+") => UnOp::Plus,
                    Some("not") => UnOp::Not,
                    _ => return Expr::Unknown,
                };
                Expr::Unary(op, Box::new(self.child(node, field::OPERAND, depth)))
            }
            kind::BINARY_EXPRESSION => {
                let Some(op) = field(node, field::OPERATOR)
                    .and_then(|o| binary_op(crate::syntax_util::kind(o)))
                else {
                    return Expr::Unknown;
                };
                Expr::Binary(
                    op,
                    Box::new(self.child(node, field::LEFT, depth)),
                    Box::new(self.child(node, field::RIGHT, depth)),
                )
            }
            kind::FUNCTION_CALL => self.call(node, depth),
            kind::COMPONENT_ACCESS => match field(node, field::COMPONENT) {
                Some(c) if crate::syntax_util::kind(c) == kind::IDENTIFIER && !c.is_missing() => {
                    Expr::Component(
                        Box::new(self.child(node, field::OBJECT, depth)),
                        text_of(c, self.text).to_owned(),
                    )
                }
                _ => Expr::Unknown,
            },
            kind::INDEX_EXPRESSION => {
                let indexes: Vec<Expr> = fields(node, field::INDEX)
                    .into_iter()
                    .map(|i| self.expr(i, depth))
                    .collect();
                if indexes.is_empty() {
                    return Expr::Unknown;
                }
                Expr::Index(Box::new(self.child(node, field::OBJECT, depth)), indexes)
            }
            kind::AGGREGATE => {
                // Literal tables and robtargets: read from the text, as the
                // tree would give them, without walking their many nodes.
                if let Some(literal) = crate::syntax_util::literal_aggregate(node, self.text) {
                    return self.literal(&literal);
                }
                let elements = fields(node, field::ELEMENT);
                if elements.is_empty() {
                    return Expr::Unknown;
                }
                Expr::Aggregate(elements.into_iter().map(|e| self.expr(e, depth)).collect())
            }
            _ => Expr::Unknown,
        }
    }

    /// A literal read from the text, lowered as its nodes would be: a
    /// signed number is a unary operation on the number.
    fn literal(&self, literal: &Literal) -> Expr {
        let text = |r: &std::ops::Range<usize>| self.text.get(r.clone()).unwrap_or_default();
        match literal {
            Literal::Number(r) => {
                let t = text(r);
                let op = match t.as_bytes().first() {
                    Some(b'-') => UnOp::Neg,
                    Some(b'+') => UnOp::Plus,
                    _ => return Expr::Num(t.to_owned()),
                };
                let digits = t.get(1..).unwrap_or_default().trim_start();
                Expr::Unary(op, Box::new(Expr::Num(digits.to_owned())))
            }
            Literal::String(r) => Expr::Str(text(r).to_owned()),
            Literal::Boolean(r) => Expr::Bool(text(r).eq_ignore_ascii_case("true")),
            Literal::Aggregate(_, elements) => {
                Expr::Aggregate(elements.iter().map(|e| self.literal(e)).collect())
            }
        }
    }

    fn child(&self, node: Node<'_>, name: &str, depth: u32) -> Expr {
        match field(node, name) {
            Some(c) => self.expr(c, depth),
            None => Expr::Unknown,
        }
    }

    fn call(&self, node: Node<'_>, depth: u32) -> Expr {
        let Some(name) =
            field(node, field::NAME).filter(|n| crate::syntax_util::kind(*n) == kind::IDENTIFIER)
        else {
            return Expr::Unknown;
        };
        let name = text_of(name, self.text);
        if name.is_empty() || !(self.is_builtin)(name) {
            return Expr::Unknown;
        }
        let mut args = Vec::new();
        if let Some(list) = field(node, field::ARGUMENTS) {
            for a in fields(list, field::ARGUMENT) {
                let arg_name = field(a, field::NAME).map(|n| {
                    if crate::syntax_util::kind(n) == kind::IDENTIFIER {
                        text_of(n, self.text).to_owned()
                    } else {
                        String::new()
                    }
                });
                if arg_name.as_deref() == Some("") {
                    return Expr::Unknown;
                }
                let value = if let Some(c) = field(a, field::CONDITIONAL) {
                    // `\Dec?x` passes an optional parameter on: its presence
                    // is only known at run time.
                    Some(conditional(c, self.text))
                } else {
                    field(a, field::VALUE).map(|v| self.expr(v, depth))
                };
                if value.is_none() && !has_token(a, "\\") {
                    // Neither a value nor a switch: a broken argument.
                    return Expr::Unknown;
                }
                args.push(Arg {
                    name: arg_name,
                    value,
                });
            }
        }
        Expr::Call {
            name: name.to_owned(),
            args,
        }
    }
}

/// The argument of a conditional argument `\Opt?x`: the name of the
/// optional parameter `x` passed on, or [`Expr::Unknown`] when it is not a
/// name.
pub fn conditional(node: Node<'_>, text: &str) -> Expr {
    if crate::syntax_util::kind(node) == kind::IDENTIFIER && !node.is_missing() {
        Expr::Conditional(text_of(node, text).to_owned())
    } else {
        Expr::Unknown
    }
}

/// The operator of a binary expression, from the operator node's kind.
pub fn binary_op(kind: &str) -> Option<BinOp> {
    BinOp::parse(kind)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lowers the initial value of `CONST anytype x := <expr>;` and shows it
    /// in the evaluator's `Debug` form, compacted.
    fn lowered(expr: &str) -> String {
        lowered_with(expr, &|_| true)
    }

    fn lowered_with(expr: &str, is_builtin: &dyn Fn(&str) -> bool) -> String {
        let text = format!("MODULE m\n  CONST anytype x := {expr};\nENDMODULE\n");
        let mut parser = crate::syntax::parser();
        let tree = crate::syntax::parse(&mut parser, &text, None).expect("a tree");
        let start = text.find(":= ").expect("the wrapper") + 3;
        let end = start + expr.len();
        let mut node = tree
            .root_node()
            .named_descendant_for_byte_range(start, end)
            .expect("a node");
        while let Some(p) = node.parent() {
            if p.byte_range() != node.byte_range() {
                break;
            }
            node = p;
        }
        assert_eq!(node.byte_range(), start..end, "{expr} is one node");
        format!("{:?}", lower_with(node, &text, is_builtin))
    }

    #[test]
    fn literal_aggregates_read_from_the_text_lower_as_their_nodes() {
        // Each element alone takes the tree's way; the aggregate is read
        // from the text.
        let elements = [
            "1", "-1", "- 2.5", "+ 3", "+.5", "9E+09", "-1.5e-3", "\"a b\"", "TRUE", "false",
        ];
        let expected = elements.iter().map(|e| lowered(e)).collect::<Vec<_>>();
        assert_eq!(
            lowered(&format!("[{}]", elements.join(", "))),
            format!("Aggregate([{}])", expected.join(", "))
        );
        assert_eq!(
            lowered("[[1 , -2],[\"x\"], [[TRUE]]]"),
            r#"Aggregate([Aggregate([Num("1"), Unary(Neg, Num("2"))]), Aggregate([Str("\"x\"")]), Aggregate([Aggregate([Bool(true)])])])"#
        );
    }

    #[test]
    fn literals_keep_their_source_text() {
        assert_eq!(lowered("0xFF"), r#"Num("0xFF")"#);
        assert_eq!(lowered("2.5E-2"), r#"Num("2.5E-2")"#);
        assert_eq!(lowered(r#""a""b\41""#), r#"Str("\"a\"\"b\\41\"")"#);
        assert_eq!(lowered("TRUE"), "Bool(true)");
        assert_eq!(lowered("false"), "Bool(false)");
        assert_eq!(lowered("pHome"), r#"Name("pHome")"#);
    }

    #[test]
    fn operators_follow_the_grammar_precedence() {
        assert_eq!(
            lowered("1 + 2 * 3"),
            r#"Binary(Add, Num("1"), Binary(Mul, Num("2"), Num("3")))"#
        );
        assert_eq!(
            lowered("(1 + 2) DIV 3"),
            r#"Binary(IntDiv, Binary(Add, Num("1"), Num("2")), Num("3"))"#
        );
        assert_eq!(lowered("7 mod 2"), r#"Binary(Mod, Num("7"), Num("2"))"#);
        assert_eq!(lowered("-x"), r#"Unary(Neg, Name("x"))"#);
        assert_eq!(lowered("+1"), r#"Unary(Plus, Num("1"))"#);
        assert_eq!(
            lowered("NOT a = b"),
            r#"Unary(Not, Binary(Eq, Name("a"), Name("b")))"#
        );
        assert_eq!(
            lowered("a <> b XOR c <= d"),
            r#"Binary(Xor, Binary(Ne, Name("a"), Name("b")), Binary(Le, Name("c"), Name("d")))"#
        );
        for (op, name) in [
            ("-", "Sub"),
            ("/", "Div"),
            ("<", "Lt"),
            (">", "Gt"),
            (">=", "Ge"),
            ("AND", "And"),
            ("OR", "Or"),
        ] {
            assert_eq!(
                lowered(&format!("a {op} b")),
                format!(r#"Binary({name}, Name("a"), Name("b"))"#)
            );
        }
    }

    #[test]
    fn calls_keep_every_argument_form() {
        assert_eq!(
            lowered(r"Round(x\Dec:=2)"),
            r#"Call { name: "Round", args: [Arg { name: None, value: Some(Name("x")) }, Arg { name: Some("Dec"), value: Some(Num("2")) }] }"#
        );
        assert_eq!(
            lowered(r"DecToHex(Str:=s)"),
            r#"Call { name: "DecToHex", args: [Arg { name: Some("Str"), value: Some(Name("s")) }] }"#
        );
        assert_eq!(
            lowered(r"ByteToStr(7\Char)"),
            r#"Call { name: "ByteToStr", args: [Arg { name: None, value: Some(Num("7")) }, Arg { name: Some("Char"), value: None }] }"#
        );
        assert_eq!(
            lowered(r"Round(x\Dec?d)"),
            r#"Call { name: "Round", args: [Arg { name: None, value: Some(Name("x")) }, Arg { name: Some("Dec"), value: Some(Conditional("d")) }] }"#
        );
        assert_eq!(lowered("Now()"), r#"Call { name: "Now", args: [] }"#);
    }

    #[test]
    fn calls_of_user_functions_are_not_lowered() {
        let only_abs = |n: &str| n.eq_ignore_ascii_case("abs");
        assert_eq!(
            lowered_with("Abs(Twice(1))", &only_abs),
            r#"Call { name: "Abs", args: [Arg { name: None, value: Some(Unknown) }] }"#
        );
    }

    #[test]
    fn components_indexes_and_aggregates() {
        assert_eq!(
            lowered("p.trans.x"),
            r#"Component(Component(Name("p"), "trans"), "x")"#
        );
        assert_eq!(
            lowered("grid{i, 2}"),
            r#"Index(Name("grid"), [Name("i"), Num("2")])"#
        );
        assert_eq!(
            lowered("[1, [2, 3]]"),
            r#"Aggregate([Num("1"), Aggregate([Num("2"), Num("3")])])"#
        );
    }

    #[test]
    fn broken_code_lowers_to_unknown() {
        assert_eq!(lowered("<EXP>"), "Unknown");
        assert_eq!(lowered("1 + <EXP>"), r#"Binary(Add, Num("1"), Unknown)"#);
    }

    #[test]
    fn deep_nesting_is_cut_off() {
        let depth = 2000;
        let expr = format!("{}1{}", "(".repeat(depth), ")".repeat(depth));
        let text = format!("MODULE m\n  CONST num x := {expr};\nENDMODULE\n");
        let mut parser = crate::syntax::parser();
        let tree = crate::syntax::parse(&mut parser, &text, None).expect("a tree");
        let start = text.find(":= ").expect("the wrapper") + 3;
        let node = tree
            .root_node()
            .named_descendant_for_byte_range(start, start + expr.len())
            .expect("a node");
        let mut node = node;
        while let Some(p) = node.parent() {
            if crate::syntax_util::kind(p) != kind::PARENTHESIZED_EXPRESSION {
                break;
            }
            node = p;
        }
        assert_eq!(lower(node, &text), Expr::Unknown);
    }
}
