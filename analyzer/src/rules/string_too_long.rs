crate::declare_rule! {
    /// A string literal longer than 80 characters.
    ///
    /// ### What it checks
    /// A RAPID string holds at most 80 characters (escape sequences such as `\\`,
    /// `""` and `\hh` count as one).
    ///
    /// ### Why
    /// The controller rejects the module; at run time such a string cannot exist.
    ///
    /// ### Example
    /// ```rapid
    /// TPWrite "A message so long that it goes on and on past the eighty characters a string holds";
    /// ```
    pub static RULE = ("E411", "string-too-long", Error);
}
