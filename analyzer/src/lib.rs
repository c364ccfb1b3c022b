//! The semantic model of a RAPID task.
