//! How much real programs call each built-in, for completion's order:
//! `usage.txt` lists the instructions and functions the test corpus calls
//! most, in that order (names only; written by
//! `tests/examples/builtin_usage.rs`).

use std::collections::HashMap;

use crate::names::fold;

/// How much real programs call each built-in: a rank (0 = called most)
/// for the instructions and functions in `usage.txt`, by folded name.
struct Usage {
    instructions: HashMap<String, usize>,
    functions: HashMap<String, usize>,
}

fn usage() -> &'static Usage {
    static CACHE: std::sync::OnceLock<Usage> = std::sync::OnceLock::new();
    CACHE.get_or_init(|| {
        let mut usage = Usage {
            instructions: HashMap::new(),
            functions: HashMap::new(),
        };
        let mut section = None;
        for line in include_str!("usage.txt").lines().map(str::trim) {
            match line {
                "" => {}
                l if l.starts_with('#') => {}
                "[instructions]" => section = Some(&mut usage.instructions),
                "[functions]" => section = Some(&mut usage.functions),
                name => {
                    if let Some(map) = section.as_mut() {
                        let rank = map.len();
                        map.entry(fold(name)).or_insert(rank);
                    }
                }
            }
        }
        usage
    })
}

/// The instructions offered before the program's own procedures at a
/// statement start: the most called ones.
const TOP_INSTRUCTIONS: usize = 10;

/// The sort key of a built-in instruction at a statement start: the most
/// called first (before the program's procedures, `1`), then the other
/// ranked ones by rank, then the rest.
pub(crate) fn instruction_rank(key: &str) -> String {
    match usage().instructions.get(key) {
        Some(&r) if r < TOP_INSTRUCTIONS => format!("0{r:03}"),
        Some(&r) => format!("2{r:03}"),
        None => "2999".to_owned(),
    }
}

/// The rank part of a built-in function's sort key.
pub(crate) fn function_rank(key: &str) -> String {
    match usage().functions.get(key) {
        Some(&r) => format!("{r:03}"),
        None => "999".to_owned(),
    }
}

/// Reads the table ahead of the first completion.
pub(crate) fn prepare() {
    usage();
}
