//! Runs every controller of `tests/controllers/`: several tasks in one
//! file, run together, and compares what they print and how each ends
//! with the expectations written at its end.
//!
//! - `!task NAME [normal|semistatic|static] [entry=ROUTINE] [nomotion]
//!   [timed]`: (`timed`: its moves take time, [`TimedRobot`])
//!   the lines that follow, up to the next `!task` or the expectations,
//!   are the task's module (its lines keep the file's numbers);
//! - `!set NAME=VALUE[@SECONDS]`: a scripted signal change;
//! - `!steps N`: the step budget; `!time SECONDS`: the time budget;
//! - `!> text`: the next line of output (`[TASK] text`, as several tasks
//!   print);
//! - `!! TASK outcome`: how a task ends, when not normally (as in
//!   `tests/programs`: `ERR_WAITSYNCTASK at 12`, `deadlock at 5`...).
//!
//! `UPDATE_EXPECT=1` rewrites the `!>` and `!!` lines with what the runs
//! give (review the diff).

mod support;

use std::sync::{Arc, Mutex};

use rapid_analyzer::task::{Task, TaskKind, Unit};
use rapid_runtime::world::{
    InstantRobot, JointTarget, Motion, MoveRequest, RobTarget, Robot, RobotError, Tool, WObj, World,
};
use rapid_runtime::{Config, Controller, Program, SignalChange, SignalKind, TaskSpec};

struct TaskText {
    name: String,
    kind: TaskKind,
    entry: String,
    motion: bool,
    timed: bool,
    text: String,
}

/// A robot whose moves take time: `\T` seconds when given, else one
/// second (where it arrives is [`InstantRobot`]'s). A stand-in for a
/// robot model, to see `\Conc`, `\InPos` and `StopMove` at work.
struct TimedRobot(InstantRobot, f64);

impl Robot for TimedRobot {
    fn move_to(&mut self, request: &MoveRequest<'_>) -> Result<Motion, RobotError> {
        let mut motion = self.0.move_to(request)?;
        motion.duration = request.time.unwrap_or(1.0);
        self.1 = request.at + motion.duration;
        Ok(motion)
    }

    fn pause(&mut self, at: f64) -> Option<f64> {
        let left = self.1 - at;
        self.1 = at;
        (left > 0.0).then_some(left)
    }

    fn robtarget(&self, tool: &Tool, wobj: &WObj) -> Result<RobTarget, RobotError> {
        self.0.robtarget(tool, wobj)
    }

    fn joints(&self) -> Result<JointTarget, RobotError> {
        self.0.joints()
    }
}

struct Fixture {
    tasks: Vec<TaskText>,
    signals: Vec<SignalChange>,
    steps: Option<u64>,
    time: Option<f64>,
    lines: Vec<String>,
    outcomes: Vec<String>,
}

fn parse(text: &str) -> Fixture {
    let mut f = Fixture {
        tasks: Vec::new(),
        signals: Vec::new(),
        steps: None,
        time: None,
        lines: Vec::new(),
        outcomes: Vec::new(),
    };
    let mut expecting = false;
    for (n, line) in text.lines().enumerate() {
        let t = line.trim_start();
        if let Some(rest) = t.strip_prefix("!task ") {
            let mut words = rest.split_whitespace();
            let mut task = TaskText {
                name: words.next().expect("!task NAME").to_owned(),
                kind: TaskKind::Normal,
                entry: "main".to_owned(),
                motion: true,
                timed: false,
                // Blank lines up to here: the task's lines are the file's.
                text: "\n".repeat(n + 1),
            };
            for w in words {
                match w {
                    "normal" => task.kind = TaskKind::Normal,
                    "semistatic" => task.kind = TaskKind::SemiStatic,
                    "static" => task.kind = TaskKind::Static,
                    "nomotion" => task.motion = false,
                    "timed" => task.timed = true,
                    w => {
                        task.entry = w.strip_prefix("entry=").expect("entry=NAME").to_owned();
                    }
                }
            }
            f.tasks.push(task);
            continue;
        }
        if let Some(rest) = t
            .strip_prefix("!> ")
            .or(t.strip_prefix("!>").filter(|r| r.is_empty()))
        {
            expecting = true;
            f.lines.push(rest.to_owned());
        } else if let Some(rest) = t.strip_prefix("!! ") {
            expecting = true;
            f.outcomes.push(rest.trim().to_owned());
        } else if let Some(rest) = t.strip_prefix("!set ") {
            f.signals.push(support::signal_change(rest));
        } else if let Some(rest) = t.strip_prefix("!steps ") {
            f.steps = Some(rest.trim().parse().expect("a number"));
        } else if let Some(rest) = t.strip_prefix("!time ") {
            f.time = Some(rest.trim().parse().expect("seconds"));
        } else if !expecting && let Some(task) = f.tasks.last_mut() {
            task.text.push_str(line);
            task.text.push('\n');
        }
    }
    f
}

/// What the controller printed, and each task's outcome in the fixtures'
/// words.
fn run(path: &std::path::Path) -> (Vec<String>, Vec<String>) {
    let text = std::fs::read_to_string(path).expect("a fixture");
    let f = parse(&text);
    let lines = Arc::new(Mutex::new(Vec::new()));
    let sink = lines.clone();
    let out = move |_: rapid_runtime::Stream, line: &str| {
        sink.lock().expect("the output").push(line.to_owned())
    };
    let mut config = Config {
        signals: f.signals.clone(),
        ..Config::default()
    };
    if let Some(n) = f.steps {
        config.limits.max_steps = n;
    }
    if let Some(t) = f.time {
        config.limits.max_time = t;
    }
    let world = World::simulated(&config, Box::new(out));
    let mut controller = Controller::new(config, world);
    let signals: Vec<(String, SignalKind)> = f
        .signals
        .iter()
        .map(|s| (s.name.clone(), SignalKind::guess(&s.name)))
        .collect();
    for t in &f.tasks {
        let unit = Arc::new(Unit::new(format!("{}.mod", t.name), t.text.clone(), None));
        let task = Arc::new(Task::new(t.name.clone(), vec![unit], None));
        let errors = rapid_runtime::load_errors(&task);
        assert!(errors.is_empty(), "{}: {errors:?}", path.display());
        let program = Arc::new(Program::new(task, &signals));
        let entry = program.find_routine(&t.entry);
        controller.add_task(TaskSpec {
            name: t.name.clone(),
            program,
            entry,
            kind: t.kind,
            robot: match (t.motion, t.timed) {
                (false, _) => None,
                (true, false) => Some(Box::new(InstantRobot::new()) as Box<dyn Robot>),
                (true, true) => {
                    Some(Box::new(TimedRobot(InstantRobot::new(), 0.0)) as Box<dyn Robot>)
                }
            },
        });
    }
    controller.run();
    let outcomes = controller
        .outcomes()
        .into_iter()
        .filter_map(|(name, o)| Some(format!("{name} {}", support::brief(&o?)?)))
        .collect();
    let lines = lines.lock().expect("the output").clone();
    (lines, outcomes)
}

fn rewrite(path: &std::path::Path, lines: &[String], outcomes: &[String]) {
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
    for o in outcomes {
        out.push(format!("!! {o}"));
    }
    std::fs::write(path, out.join("\n") + "\n").expect("written");
}

#[test]
fn controllers_print_and_end_as_their_expectations_say() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/controllers");
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .expect("the fixtures")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "tasks"))
        .collect();
    paths.sort();
    assert!(!paths.is_empty());
    let update = std::env::var_os("UPDATE_EXPECT").is_some();
    let mut failures = Vec::new();
    for path in &paths {
        let text = std::fs::read_to_string(path).expect("a fixture");
        let f = parse(&text);
        let (lines, outcomes) = run(path);
        // The same program, the same run: a second run prints the same.
        let again = run(path);
        if again != (lines.clone(), outcomes.clone()) {
            failures.push(format!("{}: two runs differ", path.display()));
        }
        if update {
            rewrite(path, &lines, &outcomes);
            continue;
        }
        if lines != f.lines || outcomes != f.outcomes {
            failures.push(format!(
                "{}:\n  expected output {:?}\n  got      output {:?}\n  expected ends {:?}\n  got      ends {:?}",
                path.display(),
                f.lines,
                lines,
                f.outcomes,
                outcomes
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
