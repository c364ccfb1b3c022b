//! The lowered bodies of small routines, printed as an outline and compared
//! with snapshots (`INSTA_UPDATE=always` writes new ones; review them).

use std::fmt::Write;

use rapid_evaluator::{Arg, Expr};

use super::*;
use crate::task::Unit;

/// Prints an expression in RAPID syntax, fully parenthesised.
fn expr(e: &Expr) -> String {
    match e {
        Expr::Num(t) | Expr::Str(t) | Expr::Name(t) => t.clone(),
        Expr::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_owned(),
        Expr::Aggregate(items) => format!("[{}]", list(items)),
        Expr::Unary(op, x) => format!("({op:?} {})", expr(x)),
        Expr::Binary(op, a, b) => format!("({} {} {})", expr(a), op.as_str(), expr(b)),
        Expr::Call { name, args } => {
            let args: Vec<String> = args.iter().map(arg).collect();
            format!("{name}({})", args.join(", "))
        }
        Expr::Component(b, c) => format!("{}.{c}", expr(b)),
        Expr::Index(b, ix) => format!("{}{{{}}}", expr(b), list(ix)),
        Expr::Conditional(n) => format!("?{n}"),
        Expr::Value(v) => format!("<{v}>"),
        Expr::Unknown => "<unknown>".to_owned(),
    }
}

fn arg(a: &Arg) -> String {
    match (&a.name, &a.value) {
        (None, Some(v)) => expr(v),
        (Some(n), Some(v)) => format!("{n}:={}", expr(v)),
        (Some(n), None) => format!("\\{n}"),
        (None, None) => "<broken>".to_owned(),
    }
}

fn list(items: &[Expr]) -> String {
    items.iter().map(expr).collect::<Vec<_>>().join(", ")
}

/// The outline of every routine of `text`: one line a statement, with its
/// line number, nested by indentation.
fn outline(text: &str) -> String {
    let unit = Unit::new("t.mod".into(), text.into(), None);
    let line = |offset: usize| text[..offset].matches('\n').count() + 1;
    let mut out = String::new();
    for body in routine_bodies(&unit) {
        let _ = writeln!(out, "{:?} {}", body.kind, body.name);
        for d in &body.data {
            let dims = if d.dims.is_empty() {
                String::new()
            } else {
                format!("{{{}}}", list(&d.dims))
            };
            let init = d.init.as_ref().map(|e| format!(" := {}", expr(e)));
            let _ = writeln!(
                out,
                "  data {:?} {} {}{dims}{}",
                d.storage,
                d.ty,
                d.name,
                init.unwrap_or_default()
            );
        }
        stmts(&mut out, &body.stmts, 1, &line);
        if let Some(h) = &body.backward {
            let _ = writeln!(out, "  BACKWARD");
            stmts(&mut out, &h.stmts, 2, &line);
        }
        if let Some(h) = &body.error {
            let _ = writeln!(out, "  ERROR ({})", list(&h.errors));
            stmts(&mut out, &h.stmts, 2, &line);
        }
        if let Some(h) = &body.undo {
            let _ = writeln!(out, "  UNDO");
            stmts(&mut out, &h.stmts, 2, &line);
        }
    }
    out
}

fn stmts(out: &mut String, stmts_: &[Stmt], depth: usize, line: &dyn Fn(usize) -> usize) {
    let pad = "  ".repeat(depth);
    for s in stmts_ {
        let at = line(s.range.start);
        let head = match &s.kind {
            StmtKind::Assign { target, value } => format!("{} := {}", expr(target), expr(value)),
            StmtKind::Call(c) => {
                let callee = match &c.callee {
                    Callee::Name(n) => n.clone(),
                    Callee::Late(e) => format!("%{}%", expr(e)),
                };
                let args: Vec<String> = c
                    .args
                    .iter()
                    .map(|a| {
                        let head = match (&a.name, a.optional) {
                            (Some(n), true) => format!("\\{n}"),
                            (Some(n), false) => n.clone(),
                            (None, _) => String::new(),
                        };
                        let value = match &a.value {
                            ArgValue::Expr(e) if head.is_empty() => expr(e),
                            ArgValue::Expr(e) => format!(":={}", expr(e)),
                            ArgValue::Switch => String::new(),
                            ArgValue::Conditional(n) => format!("?{n}"),
                            ArgValue::Star => "*".to_owned(),
                            ArgValue::Invalid => "<invalid>".to_owned(),
                        };
                        format!("{head}{value}")
                    })
                    .collect();
                format!("call {callee} [{}]", args.join(", "))
            }
            StmtKind::If {
                branches,
                otherwise,
                compact,
            } => {
                let _ = writeln!(
                    out,
                    "{pad}{at}: IF{}",
                    if *compact { " (compact)" } else { "" }
                );
                for b in branches {
                    let _ = writeln!(out, "{pad}  when {}", expr(&b.cond));
                    stmts(out, &b.body, depth + 2, line);
                }
                if let Some(o) = otherwise {
                    let _ = writeln!(out, "{pad}  else");
                    stmts(out, o, depth + 2, line);
                }
                continue;
            }
            StmtKind::For {
                var,
                from,
                to,
                step,
                body,
                ..
            } => {
                let step = step.as_ref().map(|s| format!(" STEP {}", expr(s)));
                let _ = writeln!(
                    out,
                    "{pad}{at}: FOR {var} FROM {} TO {}{}",
                    expr(from),
                    expr(to),
                    step.unwrap_or_default()
                );
                stmts(out, body, depth + 1, line);
                continue;
            }
            StmtKind::While { cond, body } => {
                let _ = writeln!(out, "{pad}{at}: WHILE {}", expr(cond));
                stmts(out, body, depth + 1, line);
                continue;
            }
            StmtKind::Test {
                value,
                cases,
                default,
            } => {
                let _ = writeln!(out, "{pad}{at}: TEST {}", expr(value));
                for c in cases {
                    let _ = writeln!(out, "{pad}  CASE {}", list(&c.values));
                    stmts(out, &c.body, depth + 2, line);
                }
                if let Some(d) = default {
                    let _ = writeln!(out, "{pad}  DEFAULT");
                    stmts(out, d, depth + 2, line);
                }
                continue;
            }
            StmtKind::Label(n) => format!("label {n}"),
            StmtKind::Goto(n) => format!("GOTO {n}"),
            StmtKind::Return(v) => format!("RETURN {}", v.as_ref().map(expr).unwrap_or_default()),
            StmtKind::Raise(v) => format!("RAISE {}", v.as_ref().map(expr).unwrap_or_default()),
            StmtKind::Exit => "EXIT".to_owned(),
            StmtKind::Retry => "RETRY".to_owned(),
            StmtKind::TryNext => "TRYNEXT".to_owned(),
            StmtKind::Connect {
                interrupt, trap, ..
            } => format!("CONNECT {} WITH {trap}", expr(interrupt)),
            StmtKind::Invalid => "<invalid>".to_owned(),
        };
        let _ = writeln!(out, "{pad}{at}: {}", head.trim_end());
    }
}

#[test]
fn every_statement_form_is_lowered() {
    let text = r#"MODULE m
  PROC main(num n, \switch fast)
    VAR num x := 1;
    CONST num grid{2, 3} := [[1,2,3],[4,5,6]];
    x := x + 2 * n;
    p.trans.x := a{i, 2};
    IF x > 3 THEN
      TPWrite "big";
    ELSEIF x = 3 THEN
      TPWrite "three"\Num:=x;
    ELSE
      x := 0;
    ENDIF
    IF fast Incr x;
    FOR i FROM 10 TO 1 STEP -2 DO
      WHILE TRUE DO
        EXIT;
      ENDWHILE
    ENDFOR
    TEST x
    CASE 1, 2:
      GOTO done;
    DEFAULT:
      RAISE ERR_DIVZERO;
    ENDTEST
    done:
    MoveL *, v100, z10, tool0\WObj:=wobj0;
    Helper ToPoint:=p10, \Conc, \Dec?fast;
    %"proc" + NumToStr(n, 0)% x;
    CONNECT ir1 WITH onTimer;
    RETURN;
  ERROR (ERR_DIVZERO, 56)
    IF ERRNO = ERR_DIVZERO RETRY;
    TRYNEXT;
  UNDO
    Close dev;
  ENDPROC

  FUNC num twice(num v)
    RETURN Round(v * 2\Dec?d);
  BACKWARD
    MoveL p1, v100, fine, tool0;
  ENDFUNC

  TRAP onTimer
    <SMT>
  ENDTRAP
ENDMODULE
"#;
    insta::assert_snapshot!(outline(text));
}

#[test]
fn broken_statements_become_invalid_with_their_range() {
    let text = "MODULE m\n  PROC main()\n    x := ;\n    y := 2;\n    FOR FROM 1 TO 2 DO\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
    let unit = Unit::new("t.mod".into(), text.into(), None);
    let bodies = routine_bodies(&unit);
    assert_eq!(bodies.len(), 1);
    let lines: Vec<usize> = bodies[0]
        .stmts
        .iter()
        .map(|s| text[..s.range.start].matches('\n').count() + 1)
        .collect();
    // Whatever the parser recovered, every statement keeps a real line and
    // the good assignment is there.
    assert!(lines.iter().all(|l| (3..=6).contains(l)), "{lines:?}");
    assert!(bodies[0].stmts.iter().any(|s| matches!(
        &s.kind,
        StmtKind::Assign { target: Expr::Name(n), value: Expr::Num(v) } if n == "y" && v == "2"
    )));
}

#[test]
fn deep_nesting_is_cut_off_without_overflow() {
    let depth = 2000;
    let mut text = String::from("MODULE m\n  PROC main()\n");
    for _ in 0..depth {
        text.push_str("IF TRUE THEN\n");
    }
    text.push_str("x := 1;\n");
    for _ in 0..depth {
        text.push_str("ENDIF\n");
    }
    text.push_str("  ENDPROC\nENDMODULE\n");
    let unit = Unit::new("t.mod".into(), text, None);
    let bodies = std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || routine_bodies(&unit).len())
        .expect("a thread")
        .join()
        .expect("no panic");
    assert_eq!(bodies, 1);
}

#[test]
fn walk_visits_nested_statements_in_source_order() {
    let text = "MODULE m\n  PROC main()\n    IF a THEN\n      x := 1;\n    ELSE\n      WHILE b DO\n        y := 2;\n      ENDWHILE\n    ENDIF\n  ERROR\n    RETRY;\n  ENDPROC\nENDMODULE\n";
    let unit = Unit::new("t.mod".into(), text.into(), None);
    let body = &routine_bodies(&unit)[0];
    let mut seen = Vec::new();
    body.walk(&mut |s| seen.push(text[..s.range.start].matches('\n').count() + 1));
    assert_eq!(seen, vec![3, 4, 6, 7, 11]);
}

#[test]
fn expressions_parse_alone() {
    assert_eq!(
        expression_of(" a{2}.x + 1 ").map(|e| expr(&e)),
        Ok("(a{2}.x + 1)".to_owned())
    );
    assert!(expression_of("1 +").is_err());
    assert!(expression_of("").is_err());
    assert!(expression_of("x := 1").is_err());
}
