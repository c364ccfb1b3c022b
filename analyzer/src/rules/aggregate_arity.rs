crate::declare_rule! {
    /// An aggregate `[...]` with the wrong number of elements for its type.
    ///
    /// ### What it checks
    /// An aggregate takes its type from where it is used; a record type fixes the
    /// number of components, and an array declared with a literal size fixes the
    /// number of elements. Nested aggregates are checked the same way.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// CONST pos p := [100, 200];     ! pos has three components: x, y, z
    /// ```
    pub static RULE = ("E203", "aggregate-arity", Error);
}
