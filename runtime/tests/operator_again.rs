//! A person at the keyboard who presses a key that does not fit the
//! question is told why and asked again (the pendant's `ask_again`); a
//! scripted answer that does not fit stops the run, naming where it was
//! given.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex};

use rapid_analyzer::task::{Task, TaskKind, Unit};
use rapid_runtime::world::{Pendant, Question, Reply, World};
use rapid_runtime::{Config, Controller, Program, TaskSpec};

const PROGRAM: &str = "MODULE m
  PROC main()
    VAR num key;
    TPReadFK key, \"Next?\", \"Weld\", \"Paint\", stEmpty, stEmpty, stEmpty;
    TPWrite \"key \"\\Num:=key;
  ENDPROC
ENDMODULE
";

/// Answers in turn from `from`; remembers why an answer was refused.
struct Person {
    answers: VecDeque<&'static str>,
    from: &'static str,
    refused: Arc<Mutex<Vec<String>>>,
}

impl Pendant for Person {
    fn ask(&mut self, _task: &str, _question: &Question) -> Option<Reply> {
        self.answers.pop_front().map(|a| Reply {
            text: a.to_owned(),
            after: 0.0,
            from: self.from.to_owned(),
        })
    }

    fn ask_again(&mut self, reply: &Reply, why: &str) -> bool {
        self.refused
            .lock()
            .expect("the refusals")
            .push(format!("{}: {why}", reply.text));
        reply.from == "the keyboard"
    }
}

/// The run's output lines and how it ended, with `from`'s answers.
fn run(answers: &[&'static str], from: &'static str) -> (Vec<String>, Vec<String>, String) {
    let unit = Arc::new(Unit::new("m.mod".into(), PROGRAM.into(), None));
    let task = Arc::new(Task::new(String::new(), vec![unit], None));
    let program = Arc::new(Program::new(task, &[]));
    let entry = program.find_routine("main");
    let lines = Arc::new(Mutex::new(Vec::new()));
    let sink = lines.clone();
    let out = move |_: rapid_runtime::Stream, line: &str| {
        sink.lock().expect("the output").push(line.to_owned());
    };
    let config = Config::default();
    let mut world = World::simulated(&config, Box::new(out));
    let refused = Arc::new(Mutex::new(Vec::new()));
    world.pendant = Box::new(Person {
        answers: answers.iter().copied().collect(),
        from,
        refused: refused.clone(),
    });
    let mut c = Controller::new(config, world);
    c.add_task(TaskSpec {
        name: "T_ROB1".to_owned(),
        program,
        entry,
        kind: TaskKind::Normal,
        robot: None,
    });
    c.run();
    let end = c
        .tasks()
        .first()
        .and_then(|t| t.outcome().cloned())
        .map(|o| o.message)
        .unwrap_or_default();
    let lines = lines.lock().expect("the output").clone();
    let refused = refused.lock().expect("the refusals").clone();
    (lines, refused, end)
}

#[test]
fn a_key_that_does_not_fit_is_asked_again_at_the_keyboard() {
    let (lines, refused, end) = run(&["9", "Paint"], "the keyboard");
    assert_eq!(lines, ["key 2"], "{end}");
    assert_eq!(refused, ["9: expected one of 1) Weld, 2) Paint"]);
}

#[test]
fn a_scripted_answer_that_does_not_fit_stops_the_run() {
    let (lines, refused, end) = run(&["9", "Paint"], "answers.txt:1");
    assert!(lines.is_empty(), "{lines:?}");
    assert_eq!(refused.len(), 1);
    assert!(
        end.contains("the answer \"9\" (answers.txt:1) to TPReadFK"),
        "{end}"
    );
}
