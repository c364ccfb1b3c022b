//! The registry against the catalogue: one implementation per pure
//! function and back, and each implementation reads exactly the parameters
//! of its catalogue signature, each as its type allows.

use std::collections::BTreeSet;

use rapid_catalogue::{ANYTYPE, Catalogue, Param, Routine, base};

use super::args::{Pass, Read, bind, pass};
use super::{Impl, REGISTRY, is_function};
use crate::Options;
use crate::env::EmptyEnv;
use crate::eval::Ctx;
use crate::expr::{Arg, Expr};

/// Implemented functions that the catalogue does not call pure, and why
/// they are folded anyway.
const IMPURE_BUT_IMPLEMENTED: &[(&str, &str)] = &[
    (
        "DefAccFrame",
        "also writes the fit errors to MaxErr and MeanErr; the frame it returns is constant",
    ),
    (
        "StrToVal",
        "writes the converted value to Val; the evaluator answers only whether the text converts",
    ),
];

/// Parameters an implementation never reads, and why.
const UNREAD: &[(&str, &str, &str)] = &[
    (
        "DefAccFrame",
        "MaxErr",
        "an output the evaluator does not write",
    ),
    (
        "DefAccFrame",
        "MeanErr",
        "an output the evaluator does not write",
    ),
];

/// Pure catalogue functions without an implementation, and why (none).
const NOT_IMPLEMENTED: &[(&str, &str)] = &[];

#[test]
fn every_pure_function_has_an_implementation_and_back() {
    let cat = base();
    for f in cat.functions.iter().filter(|f| f.pure) {
        let exception = NOT_IMPLEMENTED.iter().any(|(n, _)| *n == f.name);
        assert_eq!(is_function(&f.name), !exception, "{}", f.name);
    }
    let mut seen = BTreeSet::new();
    for (name, _) in REGISTRY {
        assert!(seen.insert(name.to_ascii_lowercase()), "{name} twice");
        let f = cat
            .function(name)
            .unwrap_or_else(|| panic!("{name} is not a catalogue function"));
        assert_eq!(&f.name, name, "spelled as the catalogue does");
        assert!(f.signature_known, "{name}: no documented signature");
        let exception = IMPURE_BUT_IMPLEMENTED.iter().any(|(n, _)| n == name);
        assert_eq!(f.pure, !exception, "{name}: pure in the catalogue");
    }
}

/// A sample argument of a parameter's type: 3 for numbers, a digit string,
/// aggregates built from the catalogue's record layouts (unit orientation).
fn sample(cat: &Catalogue, ty: &str, array: u8) -> Expr {
    if array > 0 {
        return Expr::Aggregate((0..3).map(|_| sample(cat, ty, array - 1)).collect());
    }
    let ty = cat.resolve_alias(ty);
    match ty.to_ascii_lowercase().as_str() {
        "num" | "dnum" => Expr::Num("3".into()),
        "string" => Expr::Str("\"123456\"".into()),
        "bool" => Expr::Bool(true),
        "orient" => Expr::Aggregate(
            ["1", "0", "0", "0"]
                .into_iter()
                .map(|n| Expr::Num(n.into()))
                .collect(),
        ),
        t if t == ANYTYPE => Expr::Aggregate(vec![Expr::Num("1".into()); 2]),
        _ => match cat.datatype(ty) {
            Some(d) if !d.components.is_empty() => {
                Expr::Aggregate(d.components.iter().map(|c| sample(cat, &c.ty, 0)).collect())
            }
            _ => Expr::Num("3".into()),
        },
    }
}

/// Whether reading `p` as `read` is what its catalogue entry allows.
fn allowed(cat: &Catalogue, p: &Param, read: Read) -> bool {
    let base = cat.resolve_alias(&p.ty).to_ascii_lowercase();
    match (pass(p), read) {
        (Pass::Switch, Read::Switch) | (Pass::Reference, Read::Reference) => true,
        (Pass::Value, Read::Value) => true,
        (Pass::Value, Read::Num) => p.array == 0 && (base == "num" || base == "dnum"),
        (Pass::Value, Read::Str) => p.array == 0 && base == "string",
        _ => false,
    }
}

/// The calls that exercise `f`: every non-switch parameter given, with no
/// switch (unless one of a group is required) and with each switch alone.
fn calls(cat: &Catalogue, f: &Routine) -> Vec<Vec<Arg>> {
    let values: Vec<Arg> = f
        .params
        .iter()
        .filter(|p| !p.switch)
        .map(|p| {
            let value = match pass(p) {
                Pass::Reference => Expr::Name("target".into()),
                _ => sample(cat, &p.ty, p.array),
            };
            Arg::named(p.name.clone(), value)
        })
        .collect();
    // Without a switch, unless a group of them is required.
    let mut out = if f.alt_groups.iter().any(|g| g.required) {
        Vec::new()
    } else {
        vec![values.clone()]
    };
    for s in f.params.iter().filter(|p| p.switch) {
        let mut with = values.clone();
        with.push(Arg {
            name: Some(s.name.clone()),
            value: None,
        });
        out.push(with);
    }
    out
}

#[test]
fn every_implementation_reads_its_catalogue_signature() {
    let cat = base();
    for (name, implementation) in REGISTRY {
        let Some(f) = cat.function(name) else {
            panic!("{name} is not a catalogue function");
        };
        let mut read = BTreeSet::new();
        for args in calls(cat, f) {
            let mut ctx = Ctx::new(&Options::default());
            let a = match bind(&mut ctx, name, f, &args, &EmptyEnv) {
                Ok(a) => a,
                Err(e) => panic!("{name}: the sample arguments do not bind: {e}"),
            };
            // Errors are fine (the samples need not be in every domain);
            // what was read is the point.
            let _ = match implementation {
                Impl::Pure(g) => g(&a),
                Impl::Ctx(g) => g(&a, &mut ctx, &EmptyEnv),
            };
            for (param, how) in a.reads.borrow().iter() {
                let Some(p) = f.params.iter().find(|p| p.name == *param) else {
                    panic!("{name} reads {param}, which its catalogue signature does not have");
                };
                assert!(
                    allowed(cat, p, *how),
                    "{name} reads {param} as {how:?}, but the catalogue has {}",
                    f.signature()
                );
                read.insert(param.clone());
            }
        }
        for p in &f.params {
            let excused = UNREAD.iter().any(|(n, q, _)| n == name && *q == p.name);
            assert_eq!(
                read.contains(&p.name),
                !excused,
                "{name}: parameter {} read (or listed unread wrongly)",
                p.name
            );
        }
    }
}

/// The sizes of a `VAR` or `PERS` array are its declaration's: `Dim` of it
/// is known though its values are not.
#[test]
fn dim_of_a_declared_array_is_known() {
    use crate::env::{MapEnv, VarKind};
    use crate::{ErrorCode, Type, Value};
    let mut env = MapEnv::new();
    env.variable("grid", VarKind::Var, Type::array("num", vec![4, 3]), None)
        .variable("open", VarKind::Pers, Type::array("num", vec![0]), None)
        .variable("n", VarKind::Var, Type::named("num"), None);
    let dim = |array: &str, k: &str| {
        let call = Expr::Call {
            name: "Dim".into(),
            args: vec![
                Arg::positional(Expr::Name(array.into())),
                Arg::positional(Expr::Num(k.into())),
            ],
        };
        crate::eval(&call, &env)
    };
    assert_eq!(dim("grid", "1"), Ok(Value::Num(4.0)));
    assert_eq!(dim("GRID", "2"), Ok(Value::Num(3.0)));
    assert_eq!(dim("grid", "3").map_err(|e| e.code), Err(ErrorCode::IllDim));
    // a size that is not known, or no array: as any variable
    assert_eq!(
        dim("open", "1").map_err(|e| e.code),
        Err(ErrorCode::NotConstant)
    );
    assert_eq!(
        dim("n", "1").map_err(|e| e.code),
        Err(ErrorCode::NotConstant)
    );
}
