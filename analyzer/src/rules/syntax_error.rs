use std::ops::Range;

use crate::diagnostic::{Applicability, Fix};

crate::declare_rule! {
    /// Text that does not fit RAPID's grammar at that place.
    ///
    /// ### What it checks
    /// The parser could not fit some text into any RAPID construct: a
    /// misspelt keyword, a stray character, a statement where a declaration
    /// belongs, a string without its closing `"` (strings end on the line
    /// they start), a file that holds no module (empty, or declarations
    /// without `MODULE name` around them). The message names what the
    /// grammar expected there and what it found instead. The parser
    /// recovers, so one mistake yields one local diagnostic and the rest of
    /// the module is still checked. Syntax errors are always reported, as
    /// errors: no selection, severity setting or suppression hides them.
    ///
    /// ### Why
    /// The controller refuses to load a module with a syntax error, and all of
    /// its routines are then missing from the task.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     TPWrite "Cycle done;     ! the string is never closed
    /// ENDPROC
    /// ```
    pub static RULE = ("E001", "syntax-error", Error);
}

/// A syntax error whose text (at `range`) is a lone `=`: most often `:=`
/// was meant, but the parser could not tell, so the fix is not safe.
pub(crate) fn fix(text: &str, range: &Range<usize>) -> Option<Fix> {
    let t = text.get(range.clone())?;
    if t.trim() != "=" {
        return None;
    }
    let at = range.start + t.find('=')?;
    Some(super::equals_for_assignment::fix(
        at..at + 1,
        Applicability::Unsafe,
    ))
}
