crate::declare_rule! {
    /// A persistent that another task of the controller declares differently.
    ///
    /// Another task of the same controller declares the persistent with a
    /// different type or different dimensions.
    ///
    /// ### What it checks
    /// A system-global `PERS` (without `TASK` or `LOCAL`) is one datum for
    /// the whole controller: every task that declares it shares its value.
    /// In a backup (`RAPID/TASKn` folders), each such persistent must have
    /// the same data type and the same array sizes in every task. An `ALIAS`
    /// and its base type count as the same type. `TASK PERS` data are not
    /// shared and are not compared.
    ///
    /// ### Why
    /// The controller refuses to load the second module: one datum cannot
    /// have two types.
    ///
    /// ### Example
    /// ```rapid
    /// ! RAPID/TASK1/PROGMOD/Main.mod
    /// PERS num partCount := 0;
    /// ! RAPID/TASK2/PROGMOD/Main.mod
    /// PERS dnum partCount := 0;   ! the same persistent as a dnum
    /// ```
    pub static RULE = ("E109", "shared-persistent-mismatch", Error);
}
