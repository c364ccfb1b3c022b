crate::declare_rule! {
    /// A value of one type where another is expected.
    ///
    /// ### What it checks
    /// Assignments, initial values, arguments, `RETURN` values, `TEST` cases and
    /// `FOR` bounds must have the type the target expects. Alias types count as
    /// their base type, and `num` and `dnum` convert into each other.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num n;
    /// n := "ten";      ! a string is not a num
    /// ```
    pub static RULE = ("E201", "type-mismatch", Error);
}
