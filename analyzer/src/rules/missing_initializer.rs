crate::declare_rule! {
    /// A `CONST`, or a `TASK` or `LOCAL` `PERS`, declared without a value.
    ///
    /// ### What it checks
    /// A constant must be given its value where it is declared. A persistent
    /// may leave out its value only when it is system global (plain `PERS`):
    /// the controller then shares the value of another task's declaration of
    /// the same persistent, or starts from the type's default. A `TASK PERS` or
    /// a `LOCAL PERS` has no other declaration to share with and needs its
    /// value.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// CONST num max;            ! write  CONST num max := 10;
    /// TASK PERS num count;      ! write  TASK PERS num count := 0;
    /// PERS num shared;          ! allowed: system global
    /// ```
    pub static RULE = ("E402", "missing-initializer", Error);
}
