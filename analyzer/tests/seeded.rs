//! Seeded errors: a realistic task (`tests/seeded/`) that the analyzer finds
//! clean, and one mutation per kind of error; each mutated program must be
//! reported with the expected rule on the mutated line.

use rapid_analyzer::diagnostic::Severity;
use rapid_analyzer::text::LineIndex;
use rapid_analyzer::workspace::Workspace;

const CELL: &str = include_str!("seeded/Cell.mod");
const CLOCK: &str = include_str!("seeded/Clock.mod");
const EIO: &str = include_str!("seeded/EIO.cfg");

/// (what to replace, its replacement, the rule expected on that line)
const SEEDS: &[(&str, &str, &str)] = &[
    ("level := l;", "level = l;", "equals-for-assignment"),
    ("ClkReset clock1;", "ClkReset clock1", "missing-token"),
    ("WaitTime 0.3;", "WaitTime 0.3 0.1;", "missing-token"),
    ("WaitTime 0.3;", "WaitTime 0.3 \\;", "syntax-error"),
    ("WaitTime 0.3;", "TPWrite \"waiting;", "syntax-error"),
    (
        "IF stopRequested THEN",
        "IF placed THEN",
        "condition-not-bool",
    ),
    ("level := l;", "level := \"l\";", "type-mismatch"),
    (
        "stackLayer layers{level}",
        "stackLayer layers{\"1\"}",
        "non-numeric-index",
    ),
    (
        "[2,3,100],[1,1,100]]",
        "[2,3,100],[1,1]]",
        "aggregate-arity",
    ),
    (
        "level * lay.height",
        "level * lay.depth",
        "unknown-component",
    ),
    ("pickPart;", "pickPrt;", "unresolved-name"),
    (
        "cycleTime := ClkRead(clock1);",
        "cycleTime := ClkRead(clock1) + \"s\";",
        "invalid-operands",
    ),
    (
        "layers{level}, level",
        "layers{level, 1}, level",
        "index-count",
    ),
    (
        "cycleTime := ClkRead(clock1);",
        "ClkRead clock1;",
        "call-kind-mismatch",
    ),
    ("pickPart;", "cycleTime;", "not-a-routine"),
    ("WaitTime 0.3;", "WaitTime;", "argument-count"),
    (
        "WaitTime \\InPos, 0.2;",
        "WaitTime \\InPosition, 0.2;",
        "unknown-argument",
    ),
    (
        "WaitTime \\InPos, 0.2;",
        "WaitTime \\InPos:=1, 0.2;",
        "switch-argument",
    ),
    (
        "\\MaxTime:=30;",
        "\\MaxTime:=30 \\MaxTime:=20;",
        "duplicate-argument",
    ),
    ("Incr placed;", "Incr 5;", "argument-mode"),
    (
        "stackLayer layers{level}, level",
        "stackLayer layers, level",
        "array-argument",
    ),
    ("level \\Slow;", "level \\Slow, 3;", "argument-count"),
    (
        "level \\Slow;",
        "level \\Slow?stopRequested;",
        "conditional-argument",
    ),
    (
        "stopRequested := TRUE;",
        "MAX_LAYERS := 5;",
        "assign-to-constant",
    ),
    ("RETURN;", "RETURN 1;", "return-value"),
    ("RETURN p;", "p.rot := p.rot;", "missing-return"),
    (
        "      RETRY;",
        "      TRYNEXT;\n      RETRY;",
        "unreachable-code",
    ),
    (
        "    RAISE;\n  ENDPROC",
        "    RAISE;\n    RETRY;\n  ENDPROC",
        "unreachable-code",
    ),
    (
        "CONNECT irStop WITH onStop;",
        "CONNECT irStop WITH pickPart;",
        "connect-target",
    ),
    (
        "    p := pPick;",
        "    p := pPick;\n    VAR num late;",
        "declaration-after-statement",
    ),
    (
        "VAR intnum irStop;",
        "VAR intnum irStop{2,2,2,2};",
        "too-many-dimensions",
    ),
    (
        "VAR bool stopRequested",
        "VAR bool stop_requested_by_the_operator_panel",
        "name-too-long",
    ),
    (
        "\"Stopped after layer \"",
        "\"Stopped after layer, please check the pallet and the conveyor before restarting it\"",
        "string-too-long",
    ),
    ("WaitTime 0.3;", "<SMT>", "incomplete-code"),
    (
        "CONST num MAX_LAYERS := 4;",
        "CONST num MAX_LAYERS;",
        "missing-initializer",
    ),
    (
        "    pickPart;\n",
        "    pickPart;\n    GOTO done;\n",
        "unknown-label",
    ),
    (
        "PROC pickPart()",
        "PROC stackLayer()",
        "duplicate-declaration",
    ),
    (
        "VAR robtarget pPlace;",
        "VAR robtarget pPlace;\n    VAR num unused;",
        "unused-data",
    ),
    (
        "PROC pickPart()\n",
        "LOCAL PROC spare()\n    Stop;\n  ENDPROC\n\n  PROC pickPart()\n",
        "unused-routine",
    ),
    (
        "VAR speeddata vMove := v1000;",
        "VAR speeddata v1000 := v1000;",
        "shadowed-name",
    ),
    (
        "IF ERRNO = ERR_WAIT_MAXTIME THEN",
        "IF cycleTime / 60 = 1 THEN",
        "float-equality",
    ),
    ("SetDO doGrip, 1;", "SetDO doGripper, 1;", "unresolved-name"),
];

fn diagnostics(cell: &str) -> Vec<(usize, Severity, &'static str, String)> {
    let mut ws = Workspace::new();
    ws.set_config("cell/EIO.cfg", EIO);
    ws.set_file("cell/Cell.mod", cell.to_owned());
    ws.set_file("cell/Clock.mod", CLOCK.to_owned());
    let index = LineIndex::new(cell);
    ws.diagnostics("cell/Cell.mod")
        .iter()
        .map(|d| {
            (
                index.human(d.range.start, cell).0,
                d.severity,
                d.rule.name,
                d.message.clone(),
            )
        })
        .collect()
}

#[test]
fn the_unseeded_program_is_clean() {
    let found = diagnostics(CELL);
    assert!(found.is_empty(), "{found:#?}");
    let mut ws = Workspace::new();
    ws.set_file("cell/Cell.mod", CELL.to_owned());
    ws.set_file("cell/Clock.mod", CLOCK.to_owned());
    assert!(ws.diagnostics("cell/Clock.mod").is_empty());
}

#[test]
fn every_seeded_error_is_found_on_its_line() {
    let mut missed = Vec::new();
    for (from, to, rule) in SEEDS {
        let at = CELL
            .find(from)
            .unwrap_or_else(|| panic!("seed {from:?} not in the program"));
        let mutated = CELL.replacen(from, to, 1);
        // The lines the replacement covers.
        let first = CELL[..at].lines().count().max(1) + usize::from(CELL[..at].ends_with('\n'));
        let last = first + to.matches('\n').count();
        let found = diagnostics(&mutated);
        // A missing RETURN is reported at the function's name.
        let anywhere = *rule == "missing-return";
        if !found
            .iter()
            .any(|(line, _, r, _)| r == rule && (anywhere || (first..=last + 1).contains(line)))
        {
            missed.push(format!(
                "{rule} for {to:?} (lines {first}-{last}): found {found:?}"
            ));
        }
    }
    assert!(missed.is_empty(), "{}", missed.join("\n"));
}
