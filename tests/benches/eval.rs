//! Evaluation cost of the expressions a hover shows most (math, an
//! orientation, the offset of a constant robtarget), one at a time.
//!
//! `cargo bench -p rapid-tests --bench eval`

use rapid_evaluator::{Arg, BinOp, Expr, MapEnv, Type, eval_as};

fn main() {
    rapid_tests::alloc::init();
    divan::main();
}

fn num(s: &str) -> Expr {
    Expr::Num(s.into())
}

fn call(name: &str, args: Vec<Expr>) -> Expr {
    Expr::Call {
        name: name.into(),
        args: args.into_iter().map(Arg::positional).collect(),
    }
}

fn env() -> MapEnv {
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
    env
}

#[divan::bench]
fn math(bencher: divan::Bencher<'_, '_>) {
    let env = env();
    let e = Expr::Binary(
        BinOp::Mul,
        Box::new(call("Sqrt", vec![num("2")])),
        Box::new(call("Sin", vec![num("30")])),
    );
    bencher.bench_local(|| divan::black_box(eval_as(&e, None, &env)).is_ok());
}

#[divan::bench]
fn orient_zyx(bencher: divan::Bencher<'_, '_>) {
    let env = env();
    let e = call("OrientZYX", vec![num("90"), num("0"), num("0")]);
    bencher.bench_local(|| divan::black_box(eval_as(&e, None, &env)).is_ok());
}

#[divan::bench]
fn offs_of_a_constant_robtarget(bencher: divan::Bencher<'_, '_>) {
    let env = env();
    let e = call(
        "Offs",
        vec![Expr::Name("pHome".into()), num("0"), num("0"), num("100")],
    );
    bencher.bench_local(|| divan::black_box(eval_as(&e, None, &env)).is_ok());
}
