crate::declare_rule! {
    /// A name that no module of the task and no built-in declares.
    ///
    /// ### What it checks
    /// A data object, routine or data type that is declared nowhere in the task's
    /// modules, in the built-in catalogue, or in the controller's configuration
    /// (signals from `EIO.cfg`, mechanical units from `MOC.cfg`, the `taskid`
    /// RobotWare declares for each task, such as `T_ROB1Id`, from `SYS.cfg` or the
    /// backup's task folders). It may be a typing mistake, or it may be declared
    /// in a module or a RobotWare option that is not part of the checked files; this is why it
    /// is a warning, reported once per name with its other uses as related
    /// locations (once per file in the editor, once per task in `rapid check`). In
    /// a task of a complete controller backup (the backup has its `SYSPAR`, every
    /// module of the task could be read, and every module `SYS.cfg` loads into the
    /// task is there) nothing can be missing, and it is an error. In a module of a
    /// controller's `HOME/` folder that no task here loads, the task it is loaded
    /// into at run time is not among the checked files, and it is a note.
    /// The message proposes close matches of the same kind when there are any.
    ///
    /// ### Why
    /// A module that uses an undeclared name fails to link when it is loaded on the
    /// controller.
    ///
    /// ### Example
    /// ```rapid
    /// PROC main()
    ///     MoveL pHome, v1000, fine, tGriper;   ! tGripper was meant
    /// ENDPROC
    /// ```
    pub static RULE = ("W101", "unresolved-name", Warning);
}
