crate::declare_rule! {
    /// An array given where a single value is expected, or the reverse.
    ///
    /// ### What it checks
    /// Array parameters (`{*}`) need an array of the same number of dimensions;
    /// other parameters need a single value.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num values{10};
    /// TPWrite "" \Num:=values;    ! one value is expected: values{1}
    /// ```
    pub static RULE = ("E308", "array-argument", Error);
}
