crate::declare_rule! {
    /// A record component that the record type does not have, or `.` on a value that is not a record.
    ///
    /// ### What it checks
    /// Component access `a.b` on a value whose type is known: the type must be a
    /// record (built-in or `RECORD`) with a component of that name.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR robtarget p;
    /// p.pos.x := 10;        ! robtarget has trans, rot, robconf, extax: write p.trans.x
    /// ```
    pub static RULE = ("E105", "unknown-component", Error);
}
