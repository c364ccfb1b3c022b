//! Runs every program of `tests/programs/` and compares what it prints
//! and how it ends with the expectations written in it:
//!
//! - `!> text`: the next line of output (`TPWrite`, `ErrWrite`);
//! - `!! outcome`: how the run ends, when not normally: `ERR_DIVZERO at 12`
//!   (an unhandled error and its line), `stopped at 7`, `exited`,
//!   `unsupported: NAME at 9`, `invalid at 4`, `budget at 3`,
//!   `deadlock at 5`;
//! - `!set NAME=VALUE[@SECONDS]`: a scripted signal change (a signal of
//!   that name is declared: `di*`/`do*`/`ai*`/`ao*`/`gi*`/`go*` by its
//!   prefix);
//! - `!answer VALUE`: the operator's next answer (`@SECONDS VALUE`: after
//!   a delay; `-`: no answer);
//! - `!entry NAME`: the routine to run (default `main`);
//! - `!steps N`: the step budget;
//! - `!robotware VERSION`: the task's catalogue is that RobotWare version's
//!   view (its signatures and record layouts);
//! - `!cfg LINE`: a line of the controller's configuration (`SYSPAR`): a
//!   header line (`MOC:CFG_1.0:6:0::`) starts a file of that domain;
//!   `ReadCfgData` reads them, `GetSysInfo` answers from them;
//! - `!robot MODEL`: the task moves that modelled arm
//!   ([`rapid_runtime::world::ArmRobot`]), not one whose moves arrive at
//!   once.
//!
//! `UPDATE_EXPECT=1` rewrites the `!>` and `!!` lines with what the runs
//! give (review the diff).

mod support;

use std::sync::{Arc, Mutex};

use rapid_analyzer::catalogue::{Selection, Version};
use rapid_analyzer::task::{Task, Unit};
use rapid_runtime::{Config, Outcome, Program, SignalChange, SignalKind};

struct Expect {
    lines: Vec<String>,
    outcome: Option<String>,
    signals: Vec<SignalChange>,
    entry: String,
    steps: Option<u64>,
    robotware: Option<String>,
    answers: Vec<String>,
    robot: Option<String>,
    /// The configuration files' lines, one text a file.
    cfg: Vec<String>,
}

fn parse(text: &str) -> Expect {
    let mut e = Expect {
        lines: Vec::new(),
        outcome: None,
        signals: Vec::new(),
        entry: "main".to_owned(),
        steps: None,
        robotware: None,
        answers: Vec::new(),
        robot: None,
        cfg: Vec::new(),
    };
    for line in text.lines() {
        let t = line.trim_start();
        if let Some(rest) = t
            .strip_prefix("!> ")
            .or(t.strip_prefix("!>").filter(|r| r.is_empty()))
        {
            e.lines.push(rest.to_owned());
        } else if let Some(rest) = t.strip_prefix("!! ") {
            e.outcome = Some(rest.trim().to_owned());
        } else if let Some(rest) = t.strip_prefix("!set ") {
            e.signals.push(support::signal_change(rest));
        } else if let Some(rest) = t.strip_prefix("!answer ") {
            let answer = rest.trim().to_owned();
            rapid_runtime::world::parse_answer(&answer).expect("an answer");
            e.answers.push(answer);
        } else if let Some(rest) = t.strip_prefix("!entry ") {
            e.entry = rest.trim().to_owned();
        } else if let Some(rest) = t.strip_prefix("!steps ") {
            e.steps = Some(rest.trim().parse().expect("a number"));
        } else if let Some(rest) = t.strip_prefix("!robotware ") {
            e.robotware = Some(rest.trim().to_owned());
        } else if let Some(rest) = t.strip_prefix("!cfg ") {
            if rest.contains("CFG_") || e.cfg.is_empty() {
                e.cfg.push(String::new());
            }
            if let Some(file) = e.cfg.last_mut() {
                file.push_str(rest);
                file.push('\n');
            }
        } else if let Some(rest) = t.strip_prefix("!robot ") {
            e.robot = Some(rest.trim().to_owned());
        }
    }
    e
}

fn run(path: &std::path::Path) -> (Vec<String>, Option<String>, Outcome) {
    let text = std::fs::read_to_string(path).expect("a fixture");
    let e = parse(&text);
    let name = path
        .file_name()
        .unwrap_or_default()
        .to_string_lossy()
        .into_owned();
    let unit = Arc::new(Unit::new(name, text, None));
    let mut task = Task::new(String::new(), vec![unit], None);
    if let Some(v) = &e.robotware {
        let version = Version::parse(v).expect("a RobotWare version");
        task.set_catalogue(&Selection::new(Some(version), Vec::new()));
    }
    let task = Arc::new(task);
    let signals: Vec<(String, SignalKind)> = e
        .signals
        .iter()
        .map(|s| (s.name.clone(), SignalKind::guess(&s.name)))
        .collect();
    // Signals and units no configuration declares are taken from their
    // use, as `rapid run` takes them.
    let check = rapid_runtime::load_check(&task);
    let task = check.with_units(task);
    let mut signals = signals;
    for (n, k) in check.extra_signals() {
        if !signals.iter().any(|(s, _)| s.eq_ignore_ascii_case(&n)) {
            signals.push((n, k));
        }
    }
    let program = Arc::new(Program::new(task, &signals));
    let lines = Arc::new(Mutex::new(Vec::new()));
    let sink = lines.clone();
    let mut config = Config {
        signals: e.signals.clone(),
        trace: true,
        answers: e.answers.clone(),
        ..Config::default()
    };
    for text in &e.cfg {
        let file = rapid_analyzer::cfg::parse(text);
        let domain = rapid_runtime::world::System::domain_of("", &file);
        config.system.domains.push((domain, file));
    }
    if let Some(n) = e.steps {
        config.limits.max_steps = n;
    }
    let sandbox = std::env::temp_dir().join(format!(
        "rapid-runtime-test-{}-{}",
        std::process::id(),
        path.file_stem().unwrap_or_default().to_string_lossy()
    ));
    let _ = std::fs::remove_dir_all(&sandbox);
    std::fs::create_dir_all(&sandbox).expect("a sandbox");
    config.sandbox = Some(sandbox.clone());
    let out = move |_: rapid_runtime::Stream, line: &str| {
        sink.lock().expect("the output").push(line.to_owned())
    };
    let id = program.find_routine(&e.entry).expect("the entry routine");
    let outcome = match &e.robot {
        None => rapid_runtime::run_routine(program, id, config, Box::new(out)).0,
        Some(name) => {
            let model = rapid_robot::find_model(name).expect("a modelled robot");
            let robot = rapid_runtime::world::ArmRobot::new(rapid_robot::Robot::new(model));
            let world = rapid_runtime::world::World::simulated(&config, Box::new(out));
            let mut c = rapid_runtime::Controller::new(config, world);
            c.add_task(rapid_runtime::TaskSpec {
                name: "T_ROB1".to_owned(),
                program,
                entry: Some(id),
                kind: rapid_runtime::TaskKind::Normal,
                robot: Some(Box::new(robot)),
            });
            c.run();
            c.tasks()
                .first()
                .and_then(|t| t.outcome().cloned())
                .expect("the task ended")
        }
    };
    let _ = std::fs::remove_dir_all(&sandbox);
    let lines = lines.lock().expect("the output").clone();
    (lines, support::brief(&outcome), outcome)
}

fn rewrite(path: &std::path::Path, lines: &[String], outcome: &Option<String>) {
    let text = std::fs::read_to_string(path).expect("a fixture");
    let mut out: Vec<String> = text
        .lines()
        .filter(|l| {
            let t = l.trim_start();
            !(t.starts_with("!>") || t.starts_with("!! "))
        })
        .map(str::to_owned)
        .collect();
    while out.last().is_some_and(|l| l.trim().is_empty()) {
        out.pop();
    }
    for l in lines {
        out.push(if l.is_empty() {
            "!>".to_owned()
        } else {
            format!("!> {l}")
        });
    }
    if let Some(o) = outcome {
        out.push(format!("!! {o}"));
    }
    std::fs::write(path, out.join("\n") + "\n").expect("written");
}

#[test]
fn programs_print_and_end_as_their_expectations_say() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs");
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .expect("the fixtures")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "mod"))
        .collect();
    paths.sort();
    assert!(!paths.is_empty());
    let update = std::env::var_os("UPDATE_EXPECT").is_some();
    let mut failures = Vec::new();
    for path in &paths {
        let text = std::fs::read_to_string(path).expect("a fixture");
        let e = parse(&text);
        let (lines, outcome, full) = run(path);
        if update {
            rewrite(path, &lines, &outcome);
            continue;
        }
        if lines != e.lines || outcome != e.outcome {
            failures.push(format!(
                "{}:\n  expected output {:?}\n  got      output {:?}\n  expected end {:?}\n  got      end {:?} ({})",
                path.display(),
                e.lines,
                lines,
                e.outcome,
                outcome,
                full.message
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
