//! Constant folding with RAPID semantics.
