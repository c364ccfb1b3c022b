//! Editor features as plain data with byte ranges: hover, completion,
//! signature help, navigation, rename, symbols, semantic tokens, folding,
//! selection ranges, inlay hints and code actions.
//!
//! Every function takes a task, the index of a unit in it and a byte offset
//! (or range), and never panics: offsets past the end, inside comments or in
//! broken code give empty answers. The language server converts the results
//! to protocol types and positions.

use std::ops::Range;

mod actions;
mod completion;
mod context;
mod hover;
mod inlay;
mod nav;
pub(crate) mod resolve;
mod shared;
pub(crate) mod signature;
pub(crate) mod structure;
mod symbols;
mod tokens;
mod usage;
mod value;

pub use actions::code_actions;
pub use completion::{completion_documentation, completions, completions_for, prepare_completions};
pub use hover::hover;
pub use inlay::{ParameterHints, inlay_hints};
pub use nav::{
    definition, document_highlights, prepare_rename, references, rename, shared_files,
    type_definition,
};
pub use signature::signature_help;
pub use structure::{folding_ranges, selection_ranges};
pub use symbols::{document_symbols, workspace_symbols};
pub use tokens::semantic_tokens;

use crate::diagnostic::Edit;

#[cfg(test)]
mod tests;

/// A place in a file: the name's range and the whole declaration's range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    pub path: String,
    pub range: Range<usize>,
    pub full_range: Range<usize>,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HoverResult {
    pub range: Range<usize>,
    pub markdown: String,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompletionKind {
    Keyword,
    Snippet,
    Procedure,
    Function,
    Trap,
    Variable,
    Persistent,
    Constant,
    Parameter,
    Type,
    Component,
    OptionalArgument,
    Module,
    Label,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompletionItem {
    pub label: String,
    pub kind: CompletionKind,
    pub detail: Option<String>,
    pub insert_text: Option<String>,
    pub is_snippet: bool,
    pub sort_text: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SignatureHelp {
    pub label: String,
    /// Each parameter's range in `label` and its documentation.
    pub parameters: Vec<(Range<usize>, Option<String>)>,
    pub active_parameter: Option<usize>,
    pub documentation: Option<String>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SymbolKind {
    Module,
    Procedure,
    Function,
    Trap,
    Variable,
    Persistent,
    Constant,
    Record,
    Alias,
    Component,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Symbol {
    pub name: String,
    pub kind: SymbolKind,
    pub range: Range<usize>,
    pub selection_range: Range<usize>,
    pub detail: Option<String>,
    pub children: Vec<Symbol>,
}

/// Semantic token types, in the order of [`TOKEN_TYPES`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u32)]
pub enum TokenType {
    Keyword = 0,
    Type,
    Function,
    Method,
    Variable,
    Parameter,
    Property,
    Number,
    String,
    Comment,
    Operator,
    Label,
    Namespace,
    EnumMember,
    Macro,
}

/// The LSP names of [`TokenType`], indexed by its value.
pub const TOKEN_TYPES: &[&str] = &[
    "keyword",
    "type",
    "function",
    "method",
    "variable",
    "parameter",
    "property",
    "number",
    "string",
    "comment",
    "operator",
    "label",
    "namespace",
    "enumMember",
    "macro",
];

/// Modifier bits: `1 << index` into [`TOKEN_MODIFIERS`].
pub const MOD_DECLARATION: u32 = 1;
pub const MOD_READONLY: u32 = 1 << 1;
pub const MOD_DEFAULT_LIBRARY: u32 = 1 << 2;
pub const MOD_STATIC: u32 = 1 << 3;

/// The LSP names of the modifier bits.
pub const TOKEN_MODIFIERS: &[&str] = &["declaration", "readonly", "defaultLibrary", "static"];

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SemanticToken {
    pub range: Range<usize>,
    pub token_type: u32,
    pub modifiers: u32,
}

/// A foldable line range (0-based lines).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FoldingRange {
    pub start_line: usize,
    pub end_line: usize,
    /// `"comment"`, `"region"` or `None`.
    pub kind: Option<&'static str>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InlayKind {
    Parameter,
    Value,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InlayHint {
    pub offset: usize,
    pub label: String,
    pub kind: InlayKind,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CodeAction {
    pub title: String,
    pub edits: Vec<Edit>,
    /// Index into the diagnostics given to [`code_actions`].
    pub diagnostic: Option<usize>,
    pub preferred: bool,
}
