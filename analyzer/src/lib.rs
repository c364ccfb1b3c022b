//! The semantic model of a RAPID task: parsing, name resolution, type
//! checking and diagnostics. A plain library: text in, plain results with byte
//! ranges out; no IO, no protocol types, no async; never panics on any input.

pub mod diagnostic;
pub mod format;
pub mod rules;
pub mod syntax;
pub mod text;
pub mod catalogue;
