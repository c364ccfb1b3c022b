crate::declare_rule! {
    /// A global name declared in more than one module of the task.
    ///
    /// ### What it checks
    /// Global (not `LOCAL`) data, routines and types are visible in the whole task,
    /// so two modules of one task may not both declare the same global name.
    /// Persistents are the exception: several declarations of one `PERS` name with
    /// the same type denote the same object. In a plain folder, whose grouping into
    /// a task is only a guess, it is a warning, and modules that cannot be meant to
    /// load together are checked apart instead: two files of one module name, two
    /// modules that both declare `main` (versions of a program), and two modules
    /// that declare largely the same globals (copies of one module, such as a left
    /// and a right arm's driver).
    ///
    /// ### Why
    /// The controller refuses to load the second module; which declaration was
    /// meant is ambiguous.
    ///
    /// ### Example
    /// ```rapid
    /// ! in MainModule.mod
    /// PROC init() ... ENDPROC
    /// ! in Tools.mod
    /// PROC init() ... ENDPROC    ! ambiguous
    /// ```
    pub static RULE = ("E107", "ambiguous-global", Error);
}
