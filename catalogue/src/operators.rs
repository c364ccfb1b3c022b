//! The types of RAPID's binary operators, shared by the checker (which types
//! expressions with it) and the evaluator (which refuses exactly what it
//! refuses).
//!
//! Each [`Row`] says: `left OP right` is an operator whose result has type
//! `result`. Operand and result types are the base types `num`, `dnum`,
//! `string`, `bool`, `pos` and `orient` (aliases are resolved first: a
//! `byte` is a `num`). A pair of operand types with no row is not an
//! operator. Equality (`=`, `<>`) is the exception: it applies to any two
//! values of one type (see [`EQUALITY`]), so it has no rows.
//!
//! Source: the operator tables of the RAPID overview and kernel manuals;
//! what they leave open is decided in each row's `note` (`pos / num` is
//! one). `pose * pose` is not an operator (`PoseMult` is the function).

/// A binary operator, as RAPID writes it (keywords in upper case).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Op {
    Add,
    Sub,
    Mul,
    Div,
    IntDiv,
    Mod,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Xor,
}

impl Op {
    /// Every operator.
    pub const ALL: [Op; 15] = [
        Op::Add,
        Op::Sub,
        Op::Mul,
        Op::Div,
        Op::IntDiv,
        Op::Mod,
        Op::Lt,
        Op::Le,
        Op::Gt,
        Op::Ge,
        Op::Eq,
        Op::Ne,
        Op::And,
        Op::Or,
        Op::Xor,
    ];

    /// The operator as written in RAPID.
    pub fn as_str(self) -> &'static str {
        match self {
            Op::Add => "+",
            Op::Sub => "-",
            Op::Mul => "*",
            Op::Div => "/",
            Op::IntDiv => "DIV",
            Op::Mod => "MOD",
            Op::Lt => "<",
            Op::Le => "<=",
            Op::Gt => ">",
            Op::Ge => ">=",
            Op::Eq => "=",
            Op::Ne => "<>",
            Op::And => "AND",
            Op::Or => "OR",
            Op::Xor => "XOR",
        }
    }

    /// The operator written `text` (case-insensitive), if any.
    pub fn parse(text: &str) -> Option<Op> {
        Op::ALL
            .into_iter()
            .find(|op| op.as_str().eq_ignore_ascii_case(text))
    }

    /// `=` or `<>`: typed by [`EQUALITY`], not by rows.
    pub fn is_equality(self) -> bool {
        matches!(self, Op::Eq | Op::Ne)
    }
}

/// One operator on one pair of operand types.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Row {
    pub op: Op,
    pub left: &'static str,
    pub right: &'static str,
    pub result: &'static str,
    /// Why, where the manuals leave the choice open.
    pub note: &'static str,
}

/// How `=` and `<>` are typed: any two values of one type (records and
/// arrays compared component by component), num with dnum; the result is a
/// bool.
pub const EQUALITY: &str = "two values of one type, or num with dnum: bool";

const fn row(op: Op, left: &'static str, right: &'static str, result: &'static str) -> Row {
    Row {
        op,
        left,
        right,
        result,
        note: "",
    }
}

const fn noted(
    op: Op,
    left: &'static str,
    right: &'static str,
    result: &'static str,
    note: &'static str,
) -> Row {
    Row {
        op,
        left,
        right,
        result,
        note,
    }
}

/// `num` and `dnum` mix; the result is a dnum when either operand is one.
macro_rules! numeric {
    ($op:expr, $num:literal, $dnum:literal) => {
        [
            row($op, "num", "num", $num),
            row($op, "num", "dnum", $dnum),
            row($op, "dnum", "num", $dnum),
            row($op, "dnum", "dnum", $dnum),
        ]
    };
}

const CROSS: &str = "the manuals list pos * pos without saying what it is: the cross product";
const COMPOSE: &str = "the manuals list orient * orient without a formula: the rotations are composed (quaternion product)";
const INTEGER: &str = "integer operands only (ERR_NOTINTVAL); DIV truncates towards zero, MOD takes the sign of the dividend";

/// Every binary operator but equality, by operator.
pub const BINARY: &[Row] = &{
    let add = numeric!(Op::Add, "num", "dnum");
    let sub = numeric!(Op::Sub, "num", "dnum");
    let mul = numeric!(Op::Mul, "num", "dnum");
    let div = numeric!(Op::Div, "num", "dnum");
    let int_div = numeric!(Op::IntDiv, "num", "dnum");
    let modulo = numeric!(Op::Mod, "num", "dnum");
    let lt = numeric!(Op::Lt, "bool", "bool");
    let le = numeric!(Op::Le, "bool", "bool");
    let gt = numeric!(Op::Gt, "bool", "bool");
    let ge = numeric!(Op::Ge, "bool", "bool");
    [
        add[0],
        add[1],
        add[2],
        add[3],
        row(Op::Add, "string", "string", "string"),
        row(Op::Add, "pos", "pos", "pos"),
        sub[0],
        sub[1],
        sub[2],
        sub[3],
        row(Op::Sub, "pos", "pos", "pos"),
        mul[0],
        mul[1],
        mul[2],
        mul[3],
        row(Op::Mul, "num", "pos", "pos"),
        row(Op::Mul, "pos", "num", "pos"),
        noted(Op::Mul, "pos", "pos", "pos", CROSS),
        noted(Op::Mul, "orient", "orient", "orient", COMPOSE),
        div[0],
        div[1],
        div[2],
        div[3],
        noted(
            Op::Div,
            "pos",
            "num",
            "pos",
            "not in the manuals' operator table, which lists / for num and dnum only, but \
             controller backups divide a pos by a num (`(p1.trans + p2.trans) / 2`) and \
             the controllers loaded them: each coordinate is divided, ERR_DIVZERO for zero",
        ),
        noted(Op::IntDiv, "num", "num", "num", INTEGER),
        int_div[1],
        int_div[2],
        int_div[3],
        noted(Op::Mod, "num", "num", "num", INTEGER),
        modulo[1],
        modulo[2],
        modulo[3],
        lt[0],
        lt[1],
        lt[2],
        lt[3],
        le[0],
        le[1],
        le[2],
        le[3],
        gt[0],
        gt[1],
        gt[2],
        gt[3],
        ge[0],
        ge[1],
        ge[2],
        ge[3],
        row(Op::And, "bool", "bool", "bool"),
        row(Op::Or, "bool", "bool", "bool"),
        row(Op::Xor, "bool", "bool", "bool"),
    ]
};

/// The result type of `left op right` (base type names, lower case), or
/// `None` when it is not an operator. Equality: see [`EQUALITY`].
pub fn binary(op: Op, left: &str, right: &str) -> Option<&'static str> {
    if op.is_equality() {
        let numeric = |t: &str| t == "num" || t == "dnum";
        return (left.eq_ignore_ascii_case(right) || (numeric(left) && numeric(right)))
            .then_some("bool");
    }
    binary_by(
        op,
        |t| t.eq_ignore_ascii_case(left),
        |t| t.eq_ignore_ascii_case(right),
    )
}

/// Whether `op` takes operands of the numeric types given (`num` or
/// `dnum` each): [`binary`] for them, looked up in the table once and
/// kept, for interpreters that ask at every operation.
pub fn numeric(op: Op, left_dnum: bool, right_dnum: bool) -> bool {
    static TABLE: std::sync::OnceLock<[[bool; 4]; Op::ALL.len()]> = std::sync::OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let name = |dnum: bool| if dnum { "dnum" } else { "num" };
        let mut t = [[false; 4]; Op::ALL.len()];
        for (i, op) in Op::ALL.into_iter().enumerate() {
            for (k, slot) in t[i].iter_mut().enumerate() {
                *slot = binary(op, name(k >= 2), name(k % 2 == 1)).is_some();
            }
        }
        t
    });
    // `ALL` lists the operators in their declaration order (tested).
    table[op as usize][usize::from(left_dnum) * 2 + usize::from(right_dnum)]
}

/// The first row of `op` whose operand types the predicates accept: for
/// callers whose operand types are not single names (the checker takes an
/// unknown operand to be a num and a bool at once). Equality has no rows.
pub fn binary_by(
    op: Op,
    left_is: impl Fn(&str) -> bool,
    right_is: impl Fn(&str) -> bool,
) -> Option<&'static str> {
    BINARY
        .iter()
        .find(|r| r.op == op && left_is(r.left) && right_is(r.right))
        .map(|r| r.result)
}

/// The operand types the table knows, for tests that walk it.
pub const OPERAND_TYPES: &[&str] = &["num", "dnum", "string", "bool", "pos", "orient"];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numeric_is_the_table_for_num_and_dnum() {
        for (i, op) in Op::ALL.into_iter().enumerate() {
            assert_eq!(op as usize, i, "Op::ALL is in declaration order");
            for (l, r) in [(false, false), (false, true), (true, false), (true, true)] {
                let name = |dnum: bool| if dnum { "dnum" } else { "num" };
                assert_eq!(
                    numeric(op, l, r),
                    binary(op, name(l), name(r)).is_some(),
                    "{op:?} {l} {r}"
                );
            }
        }
    }

    #[test]
    fn no_pair_has_two_rows() {
        for (i, a) in BINARY.iter().enumerate() {
            for b in &BINARY[i + 1..] {
                assert!(
                    !(a.op == b.op && a.left == b.left && a.right == b.right),
                    "{a:?} and {b:?}"
                );
            }
        }
    }

    #[test]
    fn every_type_in_the_table_is_an_operand_type() {
        for r in BINARY {
            for t in [r.left, r.right, r.result] {
                assert!(OPERAND_TYPES.contains(&t), "{r:?}");
            }
            assert!(!r.op.is_equality(), "{r:?}");
        }
    }

    #[test]
    fn operators_parse_back() {
        for op in Op::ALL {
            assert_eq!(Op::parse(op.as_str()), Some(op));
            assert_eq!(Op::parse(&op.as_str().to_lowercase()), Some(op));
        }
        assert_eq!(Op::parse("**"), None);
    }

    #[test]
    fn a_few_rows() {
        assert_eq!(binary(Op::Add, "num", "dnum"), Some("dnum"));
        assert_eq!(binary(Op::Add, "pos", "num"), None);
        assert_eq!(binary(Op::Mul, "num", "pos"), Some("pos"));
        assert_eq!(binary(Op::Div, "num", "pos"), None);
        assert_eq!(binary(Op::Div, "pos", "num"), Some("pos"));
        assert_eq!(binary(Op::Eq, "pos", "pos"), Some("bool"));
        assert_eq!(binary(Op::Eq, "num", "dnum"), Some("bool"));
        assert_eq!(binary(Op::Ne, "pos", "orient"), None);
        assert_eq!(binary(Op::And, "bool", "num"), None);
    }
}
