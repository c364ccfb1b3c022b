//! The interpreter's speed: `cargo bench -p rapid-runtime --bench interpreter`.

use std::sync::Arc;

use rapid_analyzer::task::{Task, Unit};
use rapid_runtime::{Config, Program, Status};

fn main() {
    divan::main();
}

fn program(text: &str) -> Arc<Program> {
    let unit = Arc::new(Unit::new("bench.mod".into(), text.into(), None));
    let task = Arc::new(Task::new(String::new(), vec![unit], None));
    Arc::new(Program::new(task, &[]))
}

/// Runs `main` of `text` from a fresh machine at each iteration.
fn bench_main(bencher: divan::Bencher<'_, '_>, text: &str) {
    let p = program(text);
    let entry = p.find_routine("main").expect("main");
    bencher.bench(|| {
        let (o, _) = rapid_runtime::run_routine(
            p.clone(),
            entry,
            Config::default(),
            Box::new(|_, _: &str| {}),
        );
        assert_eq!(o.status, Status::Finished);
    });
}

/// A loop of a million arithmetic assignments (plus the loop's own
/// steps): `x := x * 0.5 + i MOD 7`.
#[divan::bench(sample_count = 10)]
fn million_arithmetic_statements(bencher: divan::Bencher<'_, '_>) {
    bench_main(
        bencher,
        "MODULE bench\n  PROC main()\n    VAR num x := 0;\n    FOR i FROM 1 TO 1000000 DO\n      x := x * 0.5 + i MOD 7;\n    ENDFOR\n  ENDPROC\nENDMODULE\n",
    );
}

/// A million calls of a small function.
#[divan::bench(sample_count = 10)]
fn million_function_calls(bencher: divan::Bencher<'_, '_>) {
    bench_main(
        bencher,
        "MODULE bench\n  PROC main()\n    VAR num x := 0;\n    FOR i FROM 1 TO 1000000 DO\n      x := Twice(i);\n    ENDFOR\n  ENDPROC\n  FUNC num Twice(num v)\n    RETURN v * 2;\n  ENDFUNC\nENDMODULE\n",
    );
}
