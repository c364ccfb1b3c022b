//! The types of RAPID's operators, shared by the checker and the evaluator.
