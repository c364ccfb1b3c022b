//! The issue-16 depth cases through the built binary: files of 100,000
//! nested expressions, statements, calls, indexes and aggregates give a
//! nesting warning (W001) and a normal exit from `rapid check`, and `rapid
//! fmt` leaves them as they are with a message naming the file. (The
//! server's side is `server_robust.rs`; the analyzer's, every feature on
//! every kind, `tests/tests/adversarial.rs`.)

use serde_json::Value;

mod support;
use support::{rapid, scratch};

#[path = "../../tests/src/adversarial.rs"]
#[allow(dead_code)]
mod adversarial;

/// The five shapes the issue names, by the generator's names.
const SHAPES: [&str; 5] = ["sum", "ifs", "calls", "indexes", "aggregates"];

#[test]
fn check_warns_and_fmt_refuses_on_each_deep_shape() {
    let inputs: Vec<adversarial::Input> = adversarial::deep(100_000)
        .into_iter()
        .filter(|i| SHAPES.iter().any(|s| i.name == format!("deep-{s}-100000")))
        .collect();
    assert_eq!(inputs.len(), SHAPES.len());
    for input in inputs {
        let name = &input.name;
        let dir = scratch(name);
        std::fs::write(dir.join("Deep.mod"), &input.text).expect("written");

        let out = rapid(&dir, &["check", "--format", "json", "."]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        // A warning only: the run succeeds.
        assert_eq!(out.status.code(), Some(0), "{name}: {stderr}");
        let found: Value =
            serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{name}: {e}: {stderr}"));
        let codes: Vec<&str> = found
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(|d| d["code"].as_str())
            .collect();
        assert!(codes.contains(&"W001"), "{name}: {codes:?}");

        let out = rapid(&dir, &["fmt", "Deep.mod"]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains("Deep.mod") && stderr.contains("nests deeper"),
            "{name}: {stderr}"
        );
        assert_ne!(out.status.code(), None, "{name}: killed by a signal");
        let after = std::fs::read_to_string(dir.join("Deep.mod")).expect("read");
        assert!(after == input.text, "{name}: the file changed");
    }
}
