crate::declare_rule! {
    /// An expression or statement nested deeper than rapid analyses (256 levels of the syntax tree).
    ///
    /// ### What it checks
    /// rapid reads at most 256 levels of nesting (a sum of hundreds of terms,
    /// calls inside calls, `IF` inside `IF` hundreds of times, nested
    /// aggregates). Real programs stay far below that; generated code may
    /// not. The statement of the routine that holds such nesting (or the
    /// value of a declaration) is left out of the analysis, with everything
    /// it holds: no other finding is reported inside it, and names written
    /// there count neither as uses nor as unused. The rest of the module is
    /// checked as usual.
    ///
    /// ### Why
    /// Deeper trees would exhaust the analyzer's stack and take the language
    /// server down with every open file's features. Code that deep is
    /// also hard to read and to review: a table, a loop or a helper routine
    /// usually says the same thing.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     ! ... 300 `IF`s, each inside the one before
    ///     IF a THEN IF b THEN IF c THEN ... ENDIF ENDIF ENDIF
    /// ENDPROC
    /// ```
    pub static RULE = ("W001", "nesting-too-deep", Warning);
}
