//! The parser and checker, and the editor features, on any text: nothing
//! panics, nothing overflows the stack.
#![no_main]

use std::sync::Arc;

use libfuzzer_sys::fuzz_target;
use rapid_analyzer::ide;
use rapid_analyzer::task::{Task, Unit};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data).into_owned();
    let len = text.len();
    let unit = Arc::new(Unit::new("f/F.mod".to_owned(), text, None));
    let task = Task::new("f".to_owned(), vec![unit.clone()], None);
    let diags = rapid_analyzer::workspace::diagnostics_of(&task, &unit);
    // A few offsets taken from the input itself.
    for &b in data.iter().take(4) {
        let offset = usize::from(b) * len / 255;
        let _ = ide::hover(&task, 0, offset);
        let _ = ide::completions(&task, 0, offset);
        let _ = ide::signature_help(&task, 0, offset);
        let _ = ide::definition(&task, 0, offset);
        let _ = ide::references(&task, 0, offset, true, &[]);
        let _ = ide::rename(&task, 0, offset, "fresh", &[]);
        let _ = rapid_analyzer::consteval::value_at(&task, 0, offset);
        let _ = ide::selection_ranges(&unit, &[offset]);
    }
    let _ = ide::semantic_tokens(&task, 0, None);
    let _ = ide::folding_ranges(&unit);
    let _ = ide::document_symbols(&unit);
    let _ = ide::inlay_hints(&task, 0, 0..len, ide::ParameterHints::All);
    let _ = ide::code_actions(&task, 0, 0..len, &diags);
});
