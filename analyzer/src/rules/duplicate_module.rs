crate::declare_rule! {
    /// Two files of one task declare a module of the same name.
    ///
    /// ### What it checks
    /// A task holds one module of each name. When two files of a backup's task
    /// folder (or of one `.pgf` program) declare the same module, only one of
    /// them can be loaded: the later file (by path) is reported once, naming the
    /// other. Each version is checked on its own against the rest of the task,
    /// so their shared names are not reported as ambiguous. In a plain folder,
    /// versions of a module side by side are common and are not reported.
    ///
    /// ### Why
    /// Loading the second file fails, or replaces the first: which version the
    /// controller runs depends on the order of loading.
    ///
    /// ### Example
    /// ```rapid
    /// ! RAPID/TASK1/PROGMOD/MainModule.mod
    /// MODULE MainModule ... ENDMODULE
    /// ! RAPID/TASK1/PROGMOD/MainModule_old.mod
    /// MODULE MainModule ... ENDMODULE     ! the same module again
    /// ```
    pub static RULE = ("W207", "duplicate-module", Warning);
}
