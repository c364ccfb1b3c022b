crate::declare_rule! {
    /// `=` or `<>` comparing the result of a floating-point computation.
    ///
    /// ### What it checks
    /// Comparing with `=` or `<>` where an operand is computed with `/` or a
    /// trigonometric or other real-valued function. `num` is a single-precision
    /// value, so such results are rarely exactly equal. Comparing with a literal
    /// (`x = -112.5`) is not reported: the value compared may be taught or
    /// configured, and literals are exact. Neither is comparing a computed value
    /// with `0` (`Distance(p1, p2) = 0` asks whether two points are the same) nor
    /// `Pow` (integer powers of integers are exact).
    ///
    /// ### Why
    /// The comparison can be false when the values are equal for every practical
    /// purpose, so a branch silently never runs.
    ///
    /// ### Example
    /// ```rapid
    /// IF Sqrt(2) * Sqrt(2) = 2 THEN      ! prefer  Abs(Sqrt(2) * Sqrt(2) - 2) < 0.0001
    /// ```
    pub static RULE = ("W206", "float-equality", Warning);
}
