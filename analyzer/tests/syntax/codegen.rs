//! Writes `analyzer/src/syntax/generated.rs` from the grammar's
//! `node-types.json`: a constant per named node kind and per field name, the
//! lists of every kind, token and field, and which fields each kind has with
//! the kinds each field can hold.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde_json::Value;

/// The command that rewrites the generated file.
pub const UPDATE: &str = "UPDATE_EXPECT=1 cargo test -p rapid-analyzer --test syntax";

/// One entry of `node-types.json`, as far as the generated code needs it.
pub struct NodeType {
    pub kind: String,
    pub named: bool,
    /// Field name to (multiple, required, kinds it holds as (kind, named)).
    pub fields: BTreeMap<String, Field>,
}

pub struct Field {
    pub multiple: bool,
    pub required: bool,
    pub types: Vec<(String, bool)>,
}

/// Reads `node-types.json`; the error names what was expected where.
pub fn read(json: &str) -> Result<Vec<NodeType>, String> {
    let value: Value =
        serde_json::from_str(json).map_err(|e| format!("node-types.json: not JSON: {e}"))?;
    let entries = value
        .as_array()
        .ok_or("node-types.json: expected an array of node types")?;
    let mut out = Vec::with_capacity(entries.len());
    for (i, entry) in entries.iter().enumerate() {
        let kind = entry["type"]
            .as_str()
            .ok_or_else(|| format!("node-types.json: entry {i}: expected a string `type`"))?;
        let named = entry["named"]
            .as_bool()
            .ok_or_else(|| format!("node-types.json: `{kind}`: expected a boolean `named`"))?;
        let mut fields = BTreeMap::new();
        if let Some(map) = entry.get("fields") {
            let map = map
                .as_object()
                .ok_or_else(|| format!("node-types.json: `{kind}`: expected an object `fields`"))?;
            for (name, field) in map {
                let flag = |key: &str| {
                    field[key].as_bool().ok_or_else(|| {
                        format!("node-types.json: `{kind}.{name}`: expected a boolean `{key}`")
                    })
                };
                let types = field["types"]
                    .as_array()
                    .ok_or_else(|| {
                        format!("node-types.json: `{kind}.{name}`: expected an array `types`")
                    })?
                    .iter()
                    .map(|t| {
                        Some((t["type"].as_str()?.to_owned(), t["named"].as_bool()?))
                    })
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| {
                        format!("node-types.json: `{kind}.{name}`: expected `type` and `named` in every entry of `types`")
                    })?;
                fields.insert(
                    name.clone(),
                    Field {
                        multiple: flag("multiple")?,
                        required: flag("required")?,
                        types,
                    },
                );
            }
        }
        out.push(NodeType {
            kind: kind.to_owned(),
            named,
            fields,
        });
    }
    out.sort_by(|a, b| (a.kind.as_str(), a.named).cmp(&(b.kind.as_str(), b.named)));
    Ok(out)
}

/// The constant's name for a kind or field name.
fn constant(name: &str) -> String {
    name.to_ascii_uppercase()
}

/// A string literal of `s` (the names hold no quotes or backslashes but the
/// tokens `"` and `\` do).
fn literal(s: &str) -> String {
    format!("{s:?}")
}

/// The generated Rust source.
pub fn generate(json: &str) -> Result<String, String> {
    let types = read(json)?;
    let named: Vec<&NodeType> = types.iter().filter(|t| t.named).collect();
    let tokens: Vec<&NodeType> = types.iter().filter(|t| !t.named).collect();
    let mut field_names: Vec<&str> = types
        .iter()
        .flat_map(|t| t.fields.keys().map(String::as_str))
        .collect();
    field_names.sort_unstable();
    field_names.dedup();

    let mut out = String::new();
    let w = &mut out;
    let _ = writeln!(
        w,
        "//! Node kinds and field names of the RAPID grammar.\n//!\n\
         //! GENERATED from `tree-sitter-rapid/src/node-types.json`: do not edit.\n\
         //! After `tree-sitter generate`, rewrite it with\n\
         //! `{UPDATE}`;\n\
         //! that test fails while this file is stale.\n"
    );
    let _ = writeln!(
        w,
        "/// The named node kinds (`Node::kind` of a named node)."
    );
    let _ = writeln!(w, "pub mod kind {{");
    for t in &named {
        let fields: Vec<&str> = t.fields.keys().map(String::as_str).collect();
        if fields.is_empty() {
            let _ = writeln!(w, "    /// `{}`.", t.kind);
        } else {
            let _ = writeln!(
                w,
                "    /// `{}`, with fields `{}`.",
                t.kind,
                fields.join("`, `")
            );
        }
        let _ = writeln!(
            w,
            "    pub const {}: &str = {};",
            constant(&t.kind),
            literal(&t.kind)
        );
    }
    let _ = writeln!(w, "}}\n");

    let _ = writeln!(w, "/// The field names (`Node::child_by_field_name`).");
    let _ = writeln!(w, "pub mod field {{");
    for f in &field_names {
        let mut owners: Vec<&str> = named
            .iter()
            .filter(|t| t.fields.contains_key(*f))
            .map(|t| t.kind.as_str())
            .collect();
        owners.dedup();
        let _ = writeln!(w, "    /// `{f}`, in `{}`.", owners.join("`, `"));
        let _ = writeln!(w, "    pub const {}: &str = {};", constant(f), literal(f));
    }
    let _ = writeln!(w, "}}\n");

    let _ = writeln!(w, "/// Every named node kind, sorted.");
    let _ = writeln!(w, "pub const NAMED_KINDS: &[&str] = &[");
    for t in &named {
        let _ = writeln!(w, "    kind::{},", constant(&t.kind));
    }
    let _ = writeln!(w, "];\n");

    let _ = writeln!(
        w,
        "/// Every anonymous node kind (keywords in lower case, punctuation), sorted."
    );
    let _ = writeln!(w, "pub const TOKENS: &[&str] = &[");
    for t in &tokens {
        let _ = writeln!(w, "    {},", literal(&t.kind));
    }
    let _ = writeln!(w, "];\n");

    let _ = writeln!(w, "/// Every field name, sorted.");
    let _ = writeln!(w, "pub const FIELDS: &[&str] = &[");
    for f in &field_names {
        let _ = writeln!(w, "    field::{},", constant(f));
    }
    let _ = writeln!(w, "];\n");

    let _ = writeln!(
        w,
        "/// A field of a node kind: its name, whether it can hold several nodes or\n\
         /// must hold one, and the kinds it holds (named ones as they are, anonymous\n\
         /// ones too: keywords in lower case)."
    );
    let _ = writeln!(w, "#[derive(Debug, Clone, Copy)]");
    let _ = writeln!(w, "pub struct FieldInfo {{");
    let _ = writeln!(w, "    pub name: &'static str,");
    let _ = writeln!(w, "    pub multiple: bool,");
    let _ = writeln!(w, "    pub required: bool,");
    let _ = writeln!(w, "    pub kinds: &'static [&'static str],");
    let _ = writeln!(w, "}}\n");
    let _ = writeln!(
        w,
        "/// The fields of each named kind that has fields, sorted by kind."
    );
    let _ = writeln!(w, "pub const KIND_FIELDS: &[(&str, &[FieldInfo])] = &[");
    for t in named.iter().filter(|t| !t.fields.is_empty()) {
        let _ = writeln!(w, "    (");
        let _ = writeln!(w, "        kind::{},", constant(&t.kind));
        let _ = writeln!(w, "        &[");
        for (name, f) in &t.fields {
            let kinds: Vec<String> = f
                .types
                .iter()
                .map(|(k, named)| {
                    if *named {
                        format!("kind::{}", constant(k))
                    } else {
                        literal(k)
                    }
                })
                .collect();
            let _ = writeln!(w, "            FieldInfo {{");
            let _ = writeln!(w, "                name: field::{},", constant(name));
            let _ = writeln!(w, "                multiple: {},", f.multiple);
            let _ = writeln!(w, "                required: {},", f.required);
            let _ = writeln!(w, "                kinds: &[{}],", kinds.join(", "));
            let _ = writeln!(w, "            }},");
        }
        let _ = writeln!(w, "        ],");
        let _ = writeln!(w, "    ),");
    }
    let _ = writeln!(w, "];\n");

    let _ = writeln!(
        w,
        "/// The fields of a named node kind (none for kinds without fields and\n\
         /// for names that are no kind)."
    );
    let _ = writeln!(w, "pub fn fields_of(kind: &str) -> &'static [FieldInfo] {{");
    let _ = writeln!(w, "    KIND_FIELDS");
    let _ = writeln!(w, "        .binary_search_by(|(k, _)| (*k).cmp(kind))");
    let _ = writeln!(w, "        .map_or(&[], |i| KIND_FIELDS[i].1)");
    let _ = writeln!(w, "}}");
    Ok(out)
}
