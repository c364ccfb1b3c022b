//! Bounded evaluation, scopes across modules and the API surface.

use std::borrow::Cow;

use rapid_evaluator::{
    Arg, BinOp, EmptyEnv, Env, ErrorCode, Expr, Lookup, MapEnv, Options, Type, UnOp, Value,
    VarKind, eval, eval_as, eval_with,
};

fn num(s: &str) -> Expr {
    Expr::Num(s.into())
}

fn name(s: &str) -> Expr {
    Expr::Name(s.into())
}

fn add(a: Expr, b: Expr) -> Expr {
    Expr::Binary(BinOp::Add, Box::new(a), Box::new(b))
}

fn code(r: Result<Value, rapid_evaluator::EvalError>) -> String {
    match r {
        Ok(v) => v.to_string(),
        Err(e) => e.code.name().to_string(),
    }
}

#[test]
fn limits() {
    // Each row: what is built, what evaluation must end with.
    let mut deep = num("1");
    for _ in 0..5000 {
        deep = Expr::Unary(UnOp::Neg, Box::new(deep));
    }
    let mut deep_agg = num("1");
    for _ in 0..5000 {
        deep_agg = Expr::Aggregate(vec![deep_agg]);
    }
    let huge = Expr::Aggregate((0..1_000_000).map(|_| num("1")).collect());

    // A chain of 10000 constants, each referring to the previous one.
    let mut chain = MapEnv::new();
    chain.constant("c0", Type::named("num"), num("1"));
    for i in 1..10_000 {
        chain.constant(
            &format!("c{i}"),
            Type::named("num"),
            add(name(&format!("c{}", i - 1)), num("1")),
        );
    }
    // Doubling: c_i = c_{i-1} + c_{i-1}; exponential without sharing.
    let mut doubling = MapEnv::new();
    doubling.constant("d0", Type::named("num"), num("1"));
    doubling.constant("s0", Type::named("string"), Expr::Str("\"ab\"".into()));
    for i in 1..60 {
        let p = format!("d{}", i - 1);
        doubling.constant(
            &format!("d{i}"),
            Type::named("num"),
            add(name(&p), name(&p)),
        );
        let p = format!("s{}", i - 1);
        doubling.constant(
            &format!("s{i}"),
            Type::named("string"),
            add(name(&p), name(&p)),
        );
    }

    let rows: Vec<(&str, Result<Value, _>, &str)> = vec![
        ("5000 nested negations", eval(&deep, &EmptyEnv), "too-deep"),
        (
            "5000 nested aggregates",
            eval(&deep_agg, &EmptyEnv),
            "too-deep",
        ),
        ("a million elements", eval(&huge, &EmptyEnv), "too-complex"),
        (
            "a chain of 10000 constants",
            eval(&name("c9999"), &chain),
            "too-deep",
        ),
        ("a chain of 50 constants", eval(&name("c49"), &chain), "50"),
        (
            "doubling 59 times",
            eval(&name("d59"), &doubling),
            "5.76461E+17",
        ),
        (
            "string doubling",
            eval(&name("s59"), &doubling),
            "ERR_STRTOOLNG",
        ),
        (
            "string doubling, short",
            eval(&name("s4"), &doubling),
            "\"abababababababababababababababab\"",
        ),
    ];
    let mut failures = Vec::new();
    for (what, got, want) in rows {
        let got = code(got);
        if got != want {
            failures.push(format!("{what}: expected {want}, got {got}"));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");

    // Tighter limits through Options.
    let opts = Options {
        max_steps: 50,
        ..Options::default()
    };
    let wide = Expr::Aggregate((0..100).map(|_| num("1")).collect());
    let r = eval_with(&wide, None, &EmptyEnv, &opts);
    assert_eq!(
        r.map(|e| e.value).map_err(|e| e.code),
        Err(ErrorCode::TooComplex)
    );
    let opts = Options {
        max_depth: 3,
        ..Options::default()
    };
    let r = eval_with(
        &add(num("1"), add(num("1"), add(num("1"), num("1")))),
        None,
        &EmptyEnv,
        &opts,
    );
    assert_eq!(
        r.map(|e| e.value).map_err(|e| e.code),
        Err(ErrorCode::TooDeep)
    );
}

/// Two modules: names inside a constant's definition resolve in the
/// declaring module, which has its own `k`.
struct Module {
    consts: Vec<(&'static str, Expr)>,
    other: Option<&'static Module>,
}

impl Env for Module {
    fn lookup(&self, n: &str) -> Lookup<'_> {
        if let Some((_, e)) = self.consts.iter().find(|(k, _)| k.eq_ignore_ascii_case(n)) {
            return Lookup::Constant {
                expr: Cow::Borrowed(e),
                ty: Type::named("num"),
                scope: None,
            };
        }
        match self.other {
            Some(m) => match m.consts.iter().find(|(k, _)| k.eq_ignore_ascii_case(n)) {
                Some((_, e)) => Lookup::Constant {
                    expr: Cow::Borrowed(e),
                    ty: Type::named("num"),
                    scope: Some(m),
                },
                None => Lookup::Unknown,
            },
            None => Lookup::Unknown,
        }
    }
}

#[test]
fn constants_resolve_in_their_declaring_module() {
    let b: &'static Module = Box::leak(Box::new(Module {
        consts: vec![
            ("k", num("5")),
            ("fromb", add(name("k"), num("1"))),
            ("loop", name("loop")),
        ],
        other: None,
    }));
    let a = Module {
        consts: vec![("k", num("100"))],
        other: Some(b),
    };
    assert_eq!(code(eval(&name("fromB"), &a)), "6");
    assert_eq!(code(eval(&add(name("k"), name("FROMB")), &a)), "106");
    assert_eq!(code(eval(&name("loop"), &a)), "cycle");
}

#[test]
fn variables_and_initial_values() {
    let mut env = MapEnv::new();
    env.variable("reg1", VarKind::Var, Type::named("num"), None);
    env.variable(
        "p",
        VarKind::Pers,
        Type::named("pos"),
        Some(Expr::Aggregate(vec![num("1"), num("2"), num("3")])),
    );
    let e = Expr::Component(Box::new(name("p")), "y".into());
    let err = eval(&e, &env).expect_err("PERS is not constant");
    assert_eq!(err.code, ErrorCode::NotConstant);
    assert!(err.message.contains("PERS"), "{}", err.message);
    assert!(!err.code.is_runtime());
    let opts = Options {
        allow_initial_values: true,
        ..Options::default()
    };
    let ev = eval_with(&e, None, &env, &opts).expect("initial value");
    assert_eq!(ev.value, Value::Num(2.0));
    assert_eq!(ev.initial_values_used, vec!["p".to_string()]);
    let err = eval_with(&name("reg1"), None, &env, &opts).expect_err("no initial value");
    assert_eq!(err.code, ErrorCode::NotConstant);
}

#[test]
fn every_listed_function_is_implemented() {
    for f in rapid_evaluator::FUNCTIONS {
        let e = Expr::Call {
            name: (*f).into(),
            args: vec![],
        };
        let err = eval(&e, &EmptyEnv).expect_err("no arguments");
        assert_eq!(err.code, ErrorCode::BadArguments, "{f}: {err}");
        let upper = Expr::Call {
            name: f.to_uppercase(),
            args: vec![],
        };
        assert_eq!(
            eval(&upper, &EmptyEnv).map_err(|e| e.code),
            Err(ErrorCode::BadArguments),
            "{f}"
        );
    }
}

#[test]
fn error_codes_name_the_controller_errors() {
    let runtime = [
        (ErrorCode::DivZero, "ERR_DIVZERO"),
        (ErrorCode::OutOfBnd, "ERR_OUTOFBND"),
        (ErrorCode::StrTooLong, "ERR_STRTOOLNG"),
        (ErrorCode::IllQuat, "ERR_ILLQUAT"),
        (ErrorCode::NotIntVal, "ERR_NOTINTVAL"),
        (ErrorCode::MaxIntVal, "ERR_MAXINTVAL"),
        (ErrorCode::ArgValErr, "ERR_ARGVALERR"),
        (ErrorCode::NumLimit, "ERR_NUM_LIMIT"),
        (ErrorCode::Frame, "ERR_FRAME"),
        (ErrorCode::IllDim, "ERR_ILLDIM"),
    ];
    for (c, n) in runtime {
        assert_eq!(c.name(), n);
        assert!(c.is_runtime(), "{n}");
    }
    let e = Expr::Binary(BinOp::Div, Box::new(num("1")), Box::new(num("0")));
    let err = eval(&e, &EmptyEnv).expect_err("division by zero");
    assert_eq!(err.to_string(), "ERR_DIVZERO: division by zero");
}

#[test]
fn euler_helper_and_literal_parsers() {
    let e = rapid_evaluator::euler_zyx_deg([0.5, 0.5, 0.5, 0.5]);
    let want = [90.0, 0.0, 90.0];
    assert!(
        e.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-9),
        "{e:?}"
    );
    assert_eq!(rapid_evaluator::euler_zyx_deg([0.0; 4]), [0.0; 3]);
    let pose = Value::pose([1.0, 2.0, 3.0], [0.5, 0.5, 0.5, 0.5]);
    let e = pose.euler_zyx().expect("a pose has a rotation");
    assert!(
        e.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-6),
        "{e:?}"
    );
    assert_eq!(Value::Num(1.0).euler_zyx(), None);
    // unnormalised input is normalised first
    let e = rapid_evaluator::euler_zyx_deg([2.0, 0.0, 0.0, 2.0]);
    assert!(
        (e[0] - 90.0).abs() < 1e-9 && e[1].abs() < 1e-9 && e[2].abs() < 1e-9,
        "{e:?}"
    );

    let ok = [
        ("1.", 1.0),
        (".5", 0.5),
        ("2E3", 2000.0),
        ("2e-3", 0.002),
        ("0xFF", 255.0),
        ("0o17", 15.0),
        ("0b101", 5.0),
        ("1.E2", 100.0),
    ];
    for (s, v) in ok {
        assert_eq!(rapid_evaluator::parse_num_literal(s).ok(), Some(v), "{s}");
    }
    for s in [
        "", ".", "E3", "1E", "0x", "0xG", "1.2.3", "12a", "-1", "0b102",
    ] {
        assert!(rapid_evaluator::parse_num_literal(s).is_err(), "{s}");
    }
    let strings = [
        ("\"\"", Some("")),
        ("\"a\"\"b\"", Some("a\"b")),
        ("\"\\\\\"", Some("\\")),
        ("\"\\41\\e9\"", Some("A\u{e9}")),
        ("\"Väster\"", Some("Väster")),
        ("\"a\"b\"", None),
        ("\"\\4\"", None),
        ("\"\\\"", None),
        ("\"€\"", None),
        ("abc", None),
        ("\"", None),
    ];
    for (s, want) in strings {
        assert_eq!(
            rapid_evaluator::parse_string_literal(s).ok().as_deref(),
            want,
            "{s}"
        );
    }
}

#[test]
fn hover_expressions_give_their_values() {
    // What a hover evaluates most: math, orientations, offsets of a
    // constant target. Their speed is measured by the `eval` benchmark.
    let mut env = MapEnv::new();
    env.constant(
        "pHome",
        Type::named("robtarget"),
        Expr::Aggregate(vec![
            Expr::Aggregate(vec![num("500"), num("0"), num("600")]),
            Expr::Aggregate(vec![num("1"), num("0"), num("0"), num("0")]),
            Expr::Aggregate(vec![num("0"), num("0"), num("0"), num("0")]),
            Expr::Aggregate((0..6).map(|_| num("9E9")).collect()),
        ]),
    );
    let call = |n: &str, args: Vec<Expr>| Expr::Call {
        name: n.into(),
        args: args.into_iter().map(Arg::positional).collect(),
    };
    let cases = [
        (
            Expr::Binary(
                BinOp::Mul,
                Box::new(call("Sqrt", vec![num("2")])),
                Box::new(call("Sin", vec![num("30")])),
            ),
            "0.707107",
        ),
        (
            call("OrientZYX", vec![num("90"), num("0"), num("0")]),
            "[0.707107,0,0,0.707107]",
        ),
        (
            call("Offs", vec![name("pHome"), num("0"), num("0"), num("100")]),
            "[[500,0,700],[1,0,0,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]",
        ),
    ];
    for (e, want) in cases {
        assert_eq!(code(eval_as(&e, None, &env)), want, "{e:?}");
    }
}

#[test]
fn catalogue_values_read_as_data_literals() {
    use rapid_evaluator::parse_data_literal;
    let mut env = MapEnv::new();
    env.known("inpos", Value::Num(1.0));
    let rows = [
        ("[100,500,5000,1000]", "speeddata", "[100,500,5000,1000]"),
        (
            "[TRUE,[[0,0,0],[1,0,0,0]],[0.001,[0,0,0.001],[1,0,0,0],0,0,0]]",
            "tooldata",
            "[TRUE,[[0,0,0],[1,0,0,0]],[0.001,[0,0,0.001],[1,0,0,0],0,0,0]]",
        ),
        (
            "[inpos,TRUE,[20,20,0,20],0,0,\"\",0,0]",
            "stoppointdata",
            "[1,TRUE,[20,20,0,20],0,0,\"\",0,0]",
        ),
        (
            "\" \\09\\0A\\0B\\0C\\0D\"",
            "string",
            "\" \\09\\0A\\0B\\0C\\0D\"",
        ),
        ("-1", "num", "-1"),
        ("9.998E36", "num", "9.998E+36"),
        ("3.1415926", "num", "3.14159"),
    ];
    for (text, ty, want) in rows {
        let e = parse_data_literal(text).unwrap_or_else(|| panic!("{text} reads"));
        let v = eval_as(&e, Some(&Type::named(ty)), &env).unwrap_or_else(|e| panic!("{text}: {e}"));
        assert_eq!(v.to_string(), want, "{text}");
    }
    for bad in ["", "[1,2", "1+2", "Abs(1)", "[1,,2]", "[]", "\"open"] {
        assert_eq!(parse_data_literal(bad), None, "{bad}");
    }
}
