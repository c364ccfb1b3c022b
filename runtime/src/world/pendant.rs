//! The operator at the FlexPendant, behind [`Pendant`]: the questions a
//! program asks (`TPReadFK`, `TPReadNum`) and the operator's answers.
//! [`NoOperator`] (the default) answers nothing: such an instruction is
//! not supported in the simulation. Lines the program writes
//! (`TPWrite`) go to the run's [`crate::Output`].

/// A question the program asks the operator.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Question<'a> {
    /// `TPReadFK`: the text and the function keys' labels (empty labels
    /// are keys not shown); the answer is a key.
    FunctionKeys { text: &'a str, keys: &'a [String] },
    /// `TPReadNum`: the text; the answer is a number.
    Number { text: &'a str },
}

/// The operator's answer.
#[derive(Clone, Debug, PartialEq)]
pub enum Answer {
    /// The 0-based index of the key pressed.
    Key(usize),
    Number(f64),
}

/// The operator.
pub trait Pendant: Send {
    /// The answer to `question`, asked by task `task`; `None`: nobody
    /// answers.
    fn ask(&mut self, task: &str, question: &Question<'_>) -> Option<Answer>;
}

/// Nobody at the pendant.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoOperator;

impl Pendant for NoOperator {
    fn ask(&mut self, _task: &str, _question: &Question<'_>) -> Option<Answer> {
        None
    }
}
