crate::declare_rule! {
    /// Text that does not fit RAPID's grammar at that place.
    ///
    /// ### What it checks
    /// The parser could not fit some text into any RAPID construct: a
    /// misspelt keyword, a stray character, a statement where a declaration
    /// belongs. The message names what the grammar expected there and what it
    /// found instead. The parser recovers, so one mistake yields one local
    /// diagnostic and the rest of the module is still checked.
    ///
    /// ### Why
    /// The controller refuses to load a module with a syntax error, and all of
    /// its routines are then missing from the task.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     reg1 = 5;     ! `=` is a comparison; assignment is `:=`
    /// ENDPROC
    /// ```
    pub static RULE = ("E001", "syntax-error", Error);
}
