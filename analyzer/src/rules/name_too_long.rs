crate::declare_rule! {
    /// A name longer than 32 characters.
    ///
    /// ### What it checks
    /// Identifiers in RAPID are at most 32 characters long.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num the_number_of_boxes_on_the_left_pallet;   ! 39 characters
    /// ```
    pub static RULE = ("E410", "name-too-long", Error);
}
