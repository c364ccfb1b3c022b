//! The end-to-end example of `rapid mcp` (examples/mcp-agent/agent.py): an
//! agent-style script writes a faulty module, calls `check`, applies
//! `fix`, saves the module, checks the task and runs `test`, and ends
//! green. It needs `python3` (only its standard library).

mod support;

use std::process::Command;

use support::{scratch, show};

#[test]
fn the_agent_example_ends_green() {
    let dir = scratch("mcp-agent");
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../examples/mcp-agent/agent.py"
    );
    let out = Command::new("python3")
        .arg(script)
        .args(["--rapid", env!("CARGO_BIN_EXE_rapid"), "--workdir"])
        .arg(&*dir)
        .output()
        .expect("python3 runs (the example needs it)");
    let text = show(&out);
    assert_eq!(out.status.code(), Some(0), "{text}");
    // What the agent went through.
    for step in [
        "error[E003]",
        "applied 1 fix; 0 findings remain",
        "3 files checked: 0 errors, 0 warnings",
        "2 tests: 2 passed, 0 failed, 0 errors",
        "green: 0 errors, 2 of 2 tests passed",
    ] {
        assert!(text.contains(step), "{step}\n{text}");
    }
    let saved = std::fs::read_to_string(dir.join("cell/Counter.mod")).expect("saved");
    assert!(saved.contains("nBoxes := nBoxes + n;"), "{saved}");
}
