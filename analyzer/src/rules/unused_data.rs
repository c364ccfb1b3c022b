crate::declare_rule! {
    /// Routine data, or `LOCAL` module data, that is never used.
    ///
    /// ### What it checks
    /// Data declared in a routine, or declared `LOCAL` in a module, that no
    /// statement of its scope reads or writes.
    ///
    /// ### Why
    /// Unused data is often left over from an edit, or a sign that the wrong name
    /// was used elsewhere. The program works as it is, so this is a hint: editors
    /// show the declaration faded rather than listing a problem.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     VAR num unused;
    ///     TPWrite "Hello";
    /// ENDPROC
    /// ```
    pub static RULE = ("W201", "unused-data", Hint);
}
