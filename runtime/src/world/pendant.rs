//! The operator at the FlexPendant, behind [`Pendant`]: the questions a
//! program asks (`TPReadFK`, `TPReadNum`, `UIMessageBox`, `UINumEntry`,
//! `UIAlphaEntry`, `UIListView`...) and the operator's answers, as text
//! the runtime reads for the question (a key's number or label, a number,
//! a button, a list item, text). [`NoOperator`] (the default) answers
//! nothing; [`ScriptedOperator`] answers from a script (`--answers`).
//! Lines the program writes (`TPWrite`) go to the run's
//! [`crate::Output`].

/// What kind of answer a question takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expect {
    /// One of [`Question::choices`]: its 1-based number or its label.
    Choice,
    /// A number.
    Number,
    /// Any text.
    Text,
}

/// A question the program asks the operator.
#[derive(Clone, Debug, PartialEq)]
pub struct Question {
    /// The instruction or function that asks (`TPReadFK`).
    pub instruction: &'static str,
    /// Where it asks (`path:line`).
    pub at: String,
    /// The header of a `UI` dialog (empty for none).
    pub header: String,
    /// The text shown, one entry a line.
    pub lines: Vec<String>,
    /// The keys, buttons or list items to choose from, in order (an empty
    /// label is a function key not shown).
    pub choices: Vec<String>,
    pub expect: Expect,
    /// What the dialog starts with (`\InitValue`, `\InitString`), as text.
    pub initial: Option<String>,
}

impl Question {
    /// The question as the pendant shows it, for a person at a terminal.
    pub fn render(&self) -> String {
        let mut out = format!("[{} at {}]", self.instruction, self.at);
        if !self.header.is_empty() {
            out.push_str(&format!(" {}", self.header));
        }
        for l in &self.lines {
            out.push_str(&format!("\n  {l}"));
        }
        let shown: Vec<String> = self
            .choices
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_empty())
            .map(|(i, c)| format!("{}) {c}", i + 1))
            .collect();
        if !shown.is_empty() {
            out.push_str(&format!("\n  {}", shown.join("  ")));
        }
        if let Some(init) = &self.initial {
            out.push_str(&format!("\n  (now {init})"));
        }
        out.push_str(match self.expect {
            Expect::Choice => "\n  choose (number or label): ",
            Expect::Number => "\n  number: ",
            Expect::Text => "\n  text: ",
        });
        out
    }
}

/// The operator's answer: the text entered (or the key, button or item
/// chosen, by number or label), `after` simulated seconds; `from` says
/// where it was given (`answers.txt:3`), empty when nothing says.
#[derive(Clone, Debug, PartialEq)]
pub struct Reply {
    pub text: String,
    pub after: f64,
    pub from: String,
}

/// The operator.
pub trait Pendant: Send {
    /// The answer to `question`, asked by task `task`; `None`: nobody
    /// answers (the question stays open until its `\MaxTime` or break
    /// signal, else the run stops waiting for the operator).
    fn ask(&mut self, task: &str, question: &Question) -> Option<Reply>;

    /// `reply` does not fit its question (`why`): whether the operator is
    /// asked again (a person at the keyboard, who sees why), rather than
    /// the run stopping on the answer.
    fn ask_again(&mut self, reply: &Reply, why: &str) -> bool {
        let _ = (reply, why);
        false
    }
}

/// Nobody at the pendant.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoOperator;

impl Pendant for NoOperator {
    fn ask(&mut self, _task: &str, _question: &Question) -> Option<Reply> {
        None
    }
}

/// An operator who answers from a script, one answer a line, in order
/// (see [`parse_answer`] for a line's forms); when the script runs out,
/// nobody answers.
#[derive(Clone, Debug, Default)]
pub struct ScriptedOperator {
    answers: std::collections::VecDeque<Option<Reply>>,
}

impl ScriptedOperator {
    /// The script of `lines` (comments and blank lines left out), each
    /// answer from `line N`.
    pub fn new<S: AsRef<str>>(lines: &[S]) -> Result<ScriptedOperator, String> {
        let labelled: Vec<(String, &str)> = lines
            .iter()
            .enumerate()
            .map(|(i, l)| (format!("line {}", i + 1), l.as_ref()))
            .collect();
        Self::labelled(&labelled)
    }

    /// The script of `lines`, each with where it was given
    /// (`answers.txt:3`, `--answer #2`), which an error names.
    pub fn labelled<S: AsRef<str>>(lines: &[(String, S)]) -> Result<ScriptedOperator, String> {
        let mut answers = std::collections::VecDeque::new();
        for (from, l) in lines {
            let answer = parse_answer(l.as_ref()).map_err(|e| format!("{from}: {e}"))?;
            if let Some(mut a) = answer {
                if let Some(reply) = &mut a {
                    from.clone_into(&mut reply.from);
                }
                answers.push_back(a);
            }
        }
        Ok(ScriptedOperator { answers })
    }

    /// Is the script used up?
    pub fn is_empty(&self) -> bool {
        self.answers.is_empty()
    }

    /// The next scripted answer: `None` when the script is used up,
    /// `Some(None)` for a scripted silence (`-`).
    pub fn next_answer(&mut self) -> Option<Option<Reply>> {
        self.answers.pop_front()
    }
}

impl Pendant for ScriptedOperator {
    fn ask(&mut self, _task: &str, _question: &Question) -> Option<Reply> {
        self.next_answer().flatten()
    }
}

/// One line of an answer script: `VALUE` (answered at once), `@SECONDS
/// VALUE` (answered after that many simulated seconds), `-` (the operator
/// does not answer this question: its `\MaxTime` runs out), `"TEXT"` (the
/// text as written, for an empty answer or one with leading blanks or a
/// `#`). `Ok(None)`: a blank line or a comment (`# ...`).
pub fn parse_answer(line: &str) -> Result<Option<Option<Reply>>, String> {
    let t = line.trim();
    if t.is_empty() || t.starts_with('#') {
        return Ok(None);
    }
    if t == "-" {
        return Ok(Some(None));
    }
    let (after, rest) = match t.strip_prefix('@') {
        Some(r) => {
            let (secs, value) = r.split_once(char::is_whitespace).unwrap_or((r, ""));
            let after: f64 = secs
                .parse()
                .ok()
                .filter(|s: &f64| s.is_finite() && *s >= 0.0)
                .ok_or_else(|| format!("{secs:?} is not a delay in seconds (@SECONDS VALUE)"))?;
            (after, value.trim())
        }
        None => (0.0, t),
    };
    if rest == "-" {
        return Ok(Some(None));
    }
    let text = match rest.strip_prefix('"').and_then(|r| r.strip_suffix('"')) {
        Some(inner) => inner.to_owned(),
        None => rest.to_owned(),
    };
    Ok(Some(Some(Reply {
        text,
        after,
        from: String::new(),
    })))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answer_lines_parse_or_say_what_is_wrong() {
        let r = |text: &str, after| {
            Some(Some(Reply {
                text: text.into(),
                after,
                from: String::new(),
            }))
        };
        assert_eq!(parse_answer("2"), Ok(r("2", 0.0)));
        assert_eq!(parse_answer("  Yes  "), Ok(r("Yes", 0.0)));
        assert_eq!(parse_answer("@2.5 Yes"), Ok(r("Yes", 2.5)));
        assert_eq!(parse_answer("\"\""), Ok(r("", 0.0)));
        assert_eq!(parse_answer("\"# x\""), Ok(r("# x", 0.0)));
        assert_eq!(parse_answer("-"), Ok(Some(None)));
        assert_eq!(parse_answer("# a comment"), Ok(None));
        assert_eq!(parse_answer("   "), Ok(None));
        assert!(parse_answer("@x 1").expect_err("invalid").contains("delay"));
        assert!(parse_answer("@-1 1").is_err());
        let mut s = ScriptedOperator::new(&["1", "", "-", "@1 OK"]).expect("valid");
        assert_eq!(s.answers.len(), 3);
        let first = s.next_answer().flatten().expect("an answer");
        assert_eq!((first.text.as_str(), first.from.as_str()), ("1", "line 1"));
        assert!(
            ScriptedOperator::new(&["1", "@z"])
                .expect_err("invalid")
                .starts_with("line 2:")
        );
    }
}
