//! Constant evaluation as `rapid eval` does it: the input is an expression
//! in a constant's declaration, lowered and evaluated; nothing panics,
//! overflows the stack or runs away.
#![no_main]

use std::sync::Arc;

use libfuzzer_sys::fuzz_target;
use rapid_analyzer::task::{Task, Unit};

fuzz_target!(|data: &[u8]| {
    let expr = String::from_utf8_lossy(data);
    let prefix = "MODULE Eval\n  CONST num base := 2;\n  CONST pose p := [[1,2,3],[1,0,0,0]];\n  CONST num c := ";
    let text = format!("{prefix}{expr};\nENDMODULE\n");
    let end = prefix.len() + expr.len();
    let unit = Arc::new(Unit::new("f/Eval.mod".to_owned(), text, None));
    let task = Task::new("f".to_owned(), vec![unit], None);
    for offset in [prefix.len(), end, (prefix.len() + end) / 2] {
        let _ = rapid_analyzer::consteval::value_at(&task, 0, offset);
    }
});
