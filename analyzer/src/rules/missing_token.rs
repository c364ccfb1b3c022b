use crate::diagnostic::Diagnostic;

crate::declare_rule! {
    /// A token that must be there is missing, such as `;` or `ENDIF`.
    ///
    /// ### What it checks
    /// The code around the place is well formed except for one missing
    /// token; the parser assumed it and went on. Typical cases are a missing
    /// `;` at the end of a statement (reported at the end of its line, not
    /// at the start of the next), a missing `,` between two arguments, a
    /// `FOR` or `WHILE` line without `DO`, an `IF` or `ELSEIF` line without
    /// `THEN`, a missing `)` of a call, or an `ENDIF`, `ENDFOR` or `ENDPROC`
    /// that was never written.
    ///
    /// ### Why
    /// The controller refuses to load a module with a syntax error.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     MoveL p10 v100, fine, tool0;    ! missing `,` after p10
    ///     FOR i FROM 1 TO 3               ! missing `DO`
    ///         Incr n;
    ///     ENDFOR
    /// ENDPROC
    /// ```
    pub static RULE = ("E002", "missing-token", Error);
}

/// `what` (a token's description) is missing at byte `at`.
pub(crate) fn diagnostic(at: usize, what: &str) -> Diagnostic {
    Diagnostic::new(&RULE, at..at, format!("missing {what}"))
}
