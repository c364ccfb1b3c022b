//! Property tests for the pose math, checked against independent matrix
//! formulas written here, and for robustness on arbitrary expressions.

use proptest::prelude::*;
use rapid_evaluator::{Arg, BinOp, EmptyEnv, Expr, Type, UnOp, Value, eval, eval_as};

fn n(x: f64) -> Expr {
    // f32 Display is the shortest text that reads back as the same f32.
    let x = x as f32;
    if x < 0.0 {
        Expr::Unary(UnOp::Neg, Box::new(Expr::Num(format!("{}", -x))))
    } else {
        Expr::Num(format!("{x}"))
    }
}

fn call(name: &str, args: Vec<Arg>) -> Expr {
    Expr::Call {
        name: name.into(),
        args,
    }
}

fn pos_arg(args: Vec<Expr>) -> Vec<Arg> {
    args.into_iter().map(Arg::positional).collect()
}

fn agg(items: Vec<Expr>) -> Expr {
    Expr::Aggregate(items)
}

fn zyx(z: f64, y: f64, x: f64) -> Expr {
    call("OrientZYX", pos_arg(vec![n(z), n(y), n(x)]))
}

fn pose(t: [f64; 3], a: [f64; 3]) -> Expr {
    agg(vec![
        agg(t.iter().map(|v| n(*v)).collect()),
        zyx(a[0], a[1], a[2]),
    ])
}

fn robtarget(t: [f64; 3], a: [f64; 3]) -> Expr {
    let nines = agg((0..6).map(|_| Expr::Num("9E9".into())).collect());
    let conf = agg((0..4).map(|_| Expr::Num("0".into())).collect());
    agg(vec![
        agg(t.iter().map(|v| n(*v)).collect()),
        zyx(a[0], a[1], a[2]),
        conf,
        nines,
    ])
}

fn nums(v: &Value) -> Vec<f64> {
    match v {
        Value::Num(x) => vec![f64::from(*x)],
        Value::Dnum(x) => vec![*x],
        Value::Record { fields, .. } => fields.iter().flat_map(|(_, v)| nums(v)).collect(),
        Value::Array(items) => items.iter().flat_map(nums).collect(),
        _ => vec![],
    }
}

/// Rotation matrix of a unit quaternion [w, x, y, z] (row-major).
fn matrix(q: &[f64]) -> [[f64; 3]; 3] {
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

fn mat_vec(m: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2])
}

fn mat_mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut r = [[0.0; 3]; 3];
    for (i, row) in r.iter_mut().enumerate() {
        for (j, c) in row.iter_mut().enumerate() {
            *c = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    r
}

fn rot_z(deg: f64) -> [[f64; 3]; 3] {
    let (s, c) = deg.to_radians().sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

fn angle() -> impl Strategy<Value = f64> {
    -179.0f64..179.0
}

fn coord() -> impl Strategy<Value = f64> {
    -2000.0f64..2000.0
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn posemult_with_poseinv_is_identity(
        t in [coord(), coord(), coord()],
        a in (angle(), -89.0f64..89.0, angle()).prop_map(|(z, y, x)| [z, y, x]),
    ) {
        let p = pose(t, a);
        for e in [
            call("PoseMult", pos_arg(vec![p.clone(), call("PoseInv", pos_arg(vec![p.clone()]))])),
            call("PoseMult", pos_arg(vec![call("PoseInv", pos_arg(vec![p.clone()])), p.clone()])),
        ] {
            let v = eval(&e, &EmptyEnv).expect("evaluates");
            let c = nums(&v);
            prop_assert!(close(&c[..3], &[0.0; 3], 2e-3), "trans {:?}", c);
            let q: Vec<f64> = if c[3] < 0.0 { c[3..].iter().map(|x| -x).collect() } else { c[3..].to_vec() };
            prop_assert!(close(&q, &[1.0, 0.0, 0.0, 0.0], 1e-6), "rot {:?}", q);
        }
    }

    #[test]
    fn eulerzyx_inverts_orientzyx(z in angle(), y in -85.0f64..85.0, x in angle()) {
        let q = zyx(z, y, x);
        for (sw, want) in [("Z", z), ("Y", y), ("X", x)] {
            let e = call("EulerZYX", vec![Arg::switch(sw), Arg::positional(q.clone())]);
            let got = nums(&eval(&e, &EmptyEnv).expect("evaluates"))[0];
            let want = f64::from(want as f32);
            let diff = (got - want + 540.0).rem_euclid(360.0) - 180.0;
            prop_assert!(diff.abs() < 0.01, "{sw}: got {got}, want {want}");
        }
    }

    #[test]
    fn orientzyx_matches_the_matrix_product(z in angle(), y in angle(), x in angle()) {
        let q = nums(&eval(&zyx(z, y, x), &EmptyEnv).expect("evaluates"));
        prop_assert!(q[0] >= 0.0, "q1 is not negative: {:?}", q);
        // Rz(z) * Ry(y) * Rx(x), written out independently.
        let (sz, cz) = f64::from(z as f32).to_radians().sin_cos();
        let (sy, cy) = f64::from(y as f32).to_radians().sin_cos();
        let (sx, cx) = f64::from(x as f32).to_radians().sin_cos();
        let rz = [[cz, -sz, 0.0], [sz, cz, 0.0], [0.0, 0.0, 1.0]];
        let ry = [[cy, 0.0, sy], [0.0, 1.0, 0.0], [-sy, 0.0, cy]];
        let rx = [[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]];
        let want = mat_mul(&mat_mul(&rz, &ry), &rx);
        let got = matrix(&q);
        prop_assert!(close(&got.concat(), &want.concat(), 1e-6));
    }

    #[test]
    fn norient_is_idempotent(
        q in [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0],
        scale in 0.92f64..1.08,
    ) {
        let norm = q.iter().map(|c| c * c).sum::<f64>().sqrt();
        prop_assume!(norm > 0.1);
        let q = q.map(|c| c / norm * scale);
        let lit = agg(q.iter().map(|c| n(*c)).collect());
        let once = call("NOrient", pos_arg(vec![lit]));
        let twice = call("NOrient", pos_arg(vec![once.clone()]));
        let a = eval(&once, &EmptyEnv).expect("evaluates");
        let b = eval(&twice, &EmptyEnv).expect("evaluates");
        prop_assert_eq!(&a, &b);
        let c = nums(&a);
        let norm: f64 = c.iter().map(|x| x * x).sum::<f64>().sqrt();
        prop_assert!((norm - 1.0).abs() <= 1e-5, "norm {}", norm);
    }

    #[test]
    fn reltool_and_offs_agree_with_matrix_formulas(
        t in [coord(), coord(), coord()],
        a in (angle(), -89.0f64..89.0, angle()).prop_map(|(z, y, x)| [z, y, x]),
        d in [-500.0f64..500.0, -500.0f64..500.0, -500.0f64..500.0],
        rz in angle(),
    ) {
        let p = robtarget(t, a);
        let q = nums(&eval(&zyx(a[0], a[1], a[2]), &EmptyEnv).expect("evaluates"));
        let m = matrix(&q);
        let t32 = t.map(|v| f64::from(v as f32));
        let d32 = d.map(|v| f64::from(v as f32));

        // RelTool: trans + R * d, orientation unchanged
        let e = call("RelTool", pos_arg(vec![p.clone(), n(d[0]), n(d[1]), n(d[2])]));
        let v = nums(&eval(&e, &EmptyEnv).expect("evaluates"));
        let rd = mat_vec(&m, d32);
        let want: Vec<f64> = (0..3).map(|i| t32[i] + rd[i]).collect();
        prop_assert!(close(&v[..3], &want, 1e-3 * (1.0 + want.iter().map(|x| x.abs()).fold(0.0, f64::max))));
        prop_assert!(close(&v[3..7], &q, 0.0));

        // RelTool \Rz: R' = R * Rz
        let mut args = pos_arg(vec![p.clone(), n(0.0), n(0.0), n(0.0)]);
        args.push(Arg::named("Rz", n(rz)));
        let v = nums(&eval(&call("RelTool", args), &EmptyEnv).expect("evaluates"));
        let want = mat_mul(&m, &rot_z(f64::from(rz as f32)));
        prop_assert!(close(&matrix(&v[3..7]).concat(), &want.concat(), 1e-5));

        // Offs: trans + d, everything else unchanged
        let e = call("Offs", pos_arg(vec![p.clone(), n(d[0]), n(d[1]), n(d[2])]));
        let v = nums(&eval(&e, &EmptyEnv).expect("evaluates"));
        let want: Vec<f64> = (0..3).map(|i| f64::from((t32[i] + d32[i]) as f32)).collect();
        prop_assert!(close(&v[..3], &want, 0.0));
        let orig = nums(&eval_as(&p, Some(&Type::named("robtarget")), &EmptyEnv).expect("evaluates"));
        prop_assert!(close(&v[3..], &orig[3..], 0.0));

        // PoseVect: R * v + t
        let pv = call("PoseVect", pos_arg(vec![pose(t, a), agg(d.iter().map(|x| n(*x)).collect())]));
        let v = nums(&eval(&pv, &EmptyEnv).expect("evaluates"));
        let want: Vec<f64> = (0..3).map(|i| t32[i] + rd[i]).collect();
        prop_assert!(close(&v, &want, 1e-3 * (1.0 + want.iter().map(|x| x.abs()).fold(0.0, f64::max))));
    }

    #[test]
    fn printed_num_reads_back_within_six_digits(x in -1e7f64..1e7) {
        let x = x as f32;
        let s = Value::Num(x).to_string();
        let back: f64 = s.parse().expect("printed num parses");
        let tol = f64::from(x).abs() * 5e-6 + 5e-6;
        prop_assert!((back - f64::from(x)).abs() <= tol, "{} printed as {}", x, s);
    }
}

/// Arbitrary expressions: any mix of literals, names, operators and calls.
fn any_expr() -> impl Strategy<Value = Expr> {
    let names: Vec<String> = rapid_evaluator::FUNCTIONS
        .iter()
        .map(|s| s.to_string())
        .collect();
    let leaf = prop_oneof![
        "[0-9]{1,12}(\\.[0-9]{0,8})?(E-?[0-9]{1,3})?".prop_map(Expr::Num),
        "0x[0-9A-F]{1,20}".prop_map(Expr::Num),
        "\"[a-z\\\\0-9\"]{0,90}\"".prop_map(Expr::Str),
        any::<bool>().prop_map(Expr::Bool),
        prop_oneof![Just("pi"), Just("STR_UPPER"), Just("nothing"), Just("GT")]
            .prop_map(|s| Expr::Name(s.into())),
        Just(Expr::Unknown),
    ];
    leaf.prop_recursive(6, 64, 6, move |inner| {
        let names = names.clone();
        let op = prop_oneof![
            Just(BinOp::Add),
            Just(BinOp::Sub),
            Just(BinOp::Mul),
            Just(BinOp::Div),
            Just(BinOp::IntDiv),
            Just(BinOp::Mod),
            Just(BinOp::Eq),
            Just(BinOp::Lt),
            Just(BinOp::And),
            Just(BinOp::Xor),
        ];
        let arg = (
            prop::option::of(prop_oneof![
                Just("Dec"),
                Just("Hex"),
                Just("X"),
                Just("Rz"),
                Just("Origin")
            ]),
            prop::option::of(inner.clone()),
        )
            .prop_map(|(name, value)| match (name, value) {
                (None, None) => Arg::positional(Expr::Num("1".into())),
                (None, Some(v)) => Arg::positional(v),
                (Some(n), v) => Arg {
                    name: Some(n.to_string()),
                    value: v,
                },
            });
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..8).prop_map(Expr::Aggregate),
            (
                prop_oneof![Just(UnOp::Neg), Just(UnOp::Not), Just(UnOp::Plus)],
                inner.clone()
            )
                .prop_map(|(o, e)| Expr::Unary(o, Box::new(e))),
            (op, inner.clone(), inner.clone()).prop_map(|(o, a, b)| Expr::Binary(
                o,
                Box::new(a),
                Box::new(b)
            )),
            (
                prop::sample::select(names),
                prop::collection::vec(arg, 0..7)
            )
                .prop_map(|(name, args)| Expr::Call { name, args }),
            (inner.clone(), "[a-z0-9_]{1,6}").prop_map(|(e, f)| Expr::Component(Box::new(e), f)),
            (inner.clone(), prop::collection::vec(inner, 0..3))
                .prop_map(|(e, i)| Expr::Index(Box::new(e), i)),
        ]
    })
}

fn any_type() -> impl Strategy<Value = Option<Type>> {
    prop::option::of(prop_oneof![
        Just(Type::named("num")),
        Just(Type::named("dnum")),
        Just(Type::named("pose")),
        Just(Type::named("robtarget")),
        Just(Type::named("string")),
        Just(Type::array("num", vec![3])),
        Just(Type::named("unknowntype")),
    ])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Evaluation returns (a value or an error) for every input; a panic
    /// would fail the test.
    #[test]
    fn evaluation_never_panics(e in any_expr(), ty in any_type()) {
        let r = eval_as(&e, ty.as_ref(), &EmptyEnv);
        if let Ok(Value::Str(s)) = &r {
            prop_assert!(s.chars().count() <= 80);
            prop_assert!(s.chars().all(|c| (c as u32) <= 0xff));
        }
        if let Err(err) = &r {
            prop_assert!(!err.message.is_empty());
        }
    }
}

/// `is_function` answers for exactly the names in `FUNCTIONS`, in any case.
#[test]
fn is_function_matches_the_list() {
    for name in rapid_evaluator::FUNCTIONS {
        assert!(rapid_evaluator::is_function(name), "{name}");
        assert!(
            rapid_evaluator::is_function(&name.to_ascii_uppercase()),
            "{name}"
        );
        assert!(
            rapid_evaluator::is_function(&name.to_ascii_lowercase()),
            "{name}"
        );
    }
    for name in ["", "MoveL", "Ab", "Abss", "Sqrt2", "NumToSt"] {
        assert!(!rapid_evaluator::is_function(name), "{name}");
    }
}
