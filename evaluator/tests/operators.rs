//! The evaluator against the shared operator table: every operator on every
//! pair of the table's operand types is computed exactly when the table has
//! it, with a result of the table's type, and refused (a type mismatch)
//! otherwise.

use rapid_catalogue::operators::{self, OPERAND_TYPES, Op};
use rapid_evaluator::{BinOp, EmptyEnv, ErrorCode, Value, apply_binary};

const BIN_OPS: [BinOp; 15] = [
    BinOp::Add,
    BinOp::Sub,
    BinOp::Mul,
    BinOp::Div,
    BinOp::IntDiv,
    BinOp::Mod,
    BinOp::Eq,
    BinOp::Ne,
    BinOp::Lt,
    BinOp::Le,
    BinOp::Gt,
    BinOp::Ge,
    BinOp::And,
    BinOp::Or,
    BinOp::Xor,
];

/// A value of each operand type, chosen so that every operator the table
/// has succeeds on it (no zero divisor, integers for DIV and MOD).
fn sample(ty: &str) -> Value {
    match ty {
        "num" => Value::Num(2.0),
        "dnum" => Value::Dnum(4.0),
        "string" => Value::Str("ab".into()),
        "bool" => Value::Bool(true),
        "pos" => Value::pos(1.0, 2.0, 3.0),
        "orient" => Value::orient([1.0, 0.0, 0.0, 0.0]),
        other => panic!("no sample of {other}"),
    }
}

#[test]
fn every_operator_in_the_evaluator_is_the_tables() {
    let mut checked = 0;
    for op in BIN_OPS {
        let Some(table_op) = Op::parse(op.as_str()) else {
            panic!("{} is not in the table's operators", op.as_str());
        };
        for l in OPERAND_TYPES {
            for r in OPERAND_TYPES {
                let got = apply_binary(op, sample(l), sample(r), &EmptyEnv);
                match (operators::binary(table_op, l, r), got) {
                    (Some(result), Ok(v)) => assert!(
                        v.type_name()
                            .is_some_and(|t| t.eq_ignore_ascii_case(result)),
                        "{l} {} {r}: the table says {result}, the evaluator gives {v:?}",
                        op.as_str()
                    ),
                    (Some(result), Err(e)) => panic!(
                        "{l} {} {r}: the table says {result}, the evaluator refuses: {e}",
                        op.as_str()
                    ),
                    (None, Ok(v)) => panic!(
                        "{l} {} {r}: not in the table, the evaluator gives {v:?}",
                        op.as_str()
                    ),
                    (None, Err(e)) => assert_eq!(
                        e.code,
                        ErrorCode::TypeMismatch,
                        "{l} {} {r}: {e}",
                        op.as_str()
                    ),
                }
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 15 * OPERAND_TYPES.len() * OPERAND_TYPES.len());
}

/// Every row of the table is reached by the walk above (its operand types
/// are among the sampled ones), and every operator of the table is one of
/// the evaluator's.
#[test]
fn the_walk_covers_the_table() {
    for row in operators::BINARY {
        assert!(OPERAND_TYPES.contains(&row.left) && OPERAND_TYPES.contains(&row.right));
    }
    for op in Op::ALL {
        assert!(BIN_OPS.iter().any(|b| b.as_str() == op.as_str()), "{op:?}");
    }
}
