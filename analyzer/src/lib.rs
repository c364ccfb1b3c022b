//! The semantic model of a RAPID task: parsing, name resolution, type
//! checking and diagnostics. A plain library: text in, plain results with byte
//! ranges out; no IO, no protocol types, no async; never panics on any input.

pub mod body;
pub mod carry;
pub mod catalogue;
pub mod cfg;
pub mod check;
pub mod consteval;
pub mod controller;
pub mod diagnostic;
pub mod diff;
pub mod edit;
pub mod format;
pub mod ide;
pub mod items;
pub mod layout;
pub mod lex;
pub mod loads;
pub mod lower;
pub mod names;
pub mod nesting;
pub mod robot;
pub mod rules;
mod sema;
pub use sema::resolve;
pub mod syntax;
mod syntax_util;
pub mod task;
pub mod text;
pub mod ty;
pub mod unit_tree;
pub mod workspace;
