//! The operator of `rapid run`: answers from `--answers FILE` and
//! `--answer VALUE` (in that order, one a question), then, on a terminal,
//! the person at the keyboard (the question shown as the pendant shows
//! it, on stderr); in a pipe nobody answers, and the run stops waiting for
//! the operator.

use std::io::{BufRead, IsTerminal, Write};

use rapid_runtime::world::{Pendant, Question, Reply, ScriptedOperator, parse_answer};

/// Where the operator's answers come from.
#[derive(Clone, Debug, Default)]
pub struct OperatorOptions {
    /// Scripted answers, one a line ([`parse_answer`]'s forms), each with
    /// where it was given (`answers.txt:3`), which an error names.
    pub answers: Vec<(String, String)>,
    /// Ask on the terminal when the script runs out.
    pub terminal: bool,
}

impl OperatorOptions {
    /// The answers of `--answers FILE` then of each `--answer VALUE`; the
    /// terminal is asked when stdin and stderr are terminals.
    pub fn from_args(file: Option<&std::path::Path>, values: &[String]) -> Result<Self, String> {
        let mut answers = Vec::new();
        if let Some(path) = file {
            let text = std::fs::read_to_string(path)
                .map_err(|e| format!("--answers {}: {e}", path.display()))?;
            answers.extend(
                text.lines()
                    .enumerate()
                    .map(|(i, l)| (format!("{}:{}", path.display(), i + 1), l.to_owned())),
            );
        }
        answers.extend(
            values
                .iter()
                .enumerate()
                .map(|(i, v)| (format!("--answer #{}", i + 1), v.clone())),
        );
        let options = OperatorOptions {
            answers,
            terminal: std::io::stdin().is_terminal() && std::io::stderr().is_terminal(),
        };
        options.script().map(|_| options)
    }

    /// Answers given as a list (a request's, a launch's): each from
    /// `answer N`.
    pub fn listed(answers: Vec<String>) -> Self {
        OperatorOptions {
            answers: answers
                .into_iter()
                .enumerate()
                .map(|(i, a)| (format!("answer {}", i + 1), a))
                .collect(),
            terminal: false,
        }
    }

    fn script(&self) -> Result<ScriptedOperator, String> {
        ScriptedOperator::labelled(&self.answers)
            .map_err(|e| format!("the operator's answers: {e}"))
    }

    /// The run's operator.
    pub fn pendant(&self) -> Result<Box<dyn Pendant>, String> {
        Ok(Box::new(Operator {
            script: self.script()?,
            terminal: self.terminal,
        }))
    }
}

/// Where an answer typed at the terminal comes from.
const KEYBOARD: &str = "the keyboard";

struct Operator {
    script: ScriptedOperator,
    terminal: bool,
}

impl Pendant for Operator {
    /// A key pressed wrong at the keyboard: say why and ask again.
    fn ask_again(&mut self, reply: &Reply, why: &str) -> bool {
        if !self.terminal || reply.from != KEYBOARD {
            return false;
        }
        let _ = writeln!(std::io::stderr().lock(), "  {why}; answer again");
        true
    }

    fn ask(&mut self, task: &str, question: &Question) -> Option<Reply> {
        if let Some(answer) = self.script.next_answer() {
            return answer;
        }
        if !self.terminal {
            return None;
        }
        let mut err = std::io::stderr().lock();
        let _ = write!(err, "({task}) {}", question.render());
        let _ = err.flush();
        let mut line = String::new();
        match std::io::stdin().lock().read_line(&mut line) {
            Ok(0) | Err(_) => {
                // End of input: nobody answers any more.
                self.terminal = false;
                None
            }
            // A line as the script's lines read (`-`: no answer), a blank
            // line an empty answer, anything else as typed.
            Ok(_) => match parse_answer(&line) {
                Ok(Some(answer)) => answer.map(|r| Reply {
                    from: KEYBOARD.to_owned(),
                    ..r
                }),
                Ok(None) | Err(_) => Some(Reply {
                    text: line.trim().to_owned(),
                    after: 0.0,
                    from: KEYBOARD.to_owned(),
                }),
            },
        }
    }
}
