//! Semantic facts computed from the syntax without reporting anything, for
//! the checker and the editor features alike; [`resolve`] gives them to
//! readers outside the analyzer (the interpreter).

pub(crate) mod def;
pub(crate) mod labels;
pub mod resolve;
pub(crate) mod scope;
pub(crate) mod signature;
pub(crate) mod sync;
pub(crate) mod typing;
