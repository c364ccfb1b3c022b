//! Typed syntax: `src/syntax/generated.rs` is what the generator makes of
//! the grammar's `node-types.json` (`UPDATE_EXPECT=1 cargo test -p
//! rapid-analyzer --test syntax` rewrites it), and every node kind and field
//! name the analyzer's sources spell as a string literal is one of the
//! grammar's.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

#[path = "syntax/codegen.rs"]
mod codegen;
#[path = "syntax/names.rs"]
mod names;

use names::{Role, Use};

fn generated_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src/syntax/generated.rs")
}

#[test]
fn generated_syntax_is_current() {
    let want = codegen::generate(tree_sitter_rapid::NODE_TYPES).expect("node-types.json reads");
    let path = generated_path();
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    if have == want {
        return;
    }
    if std::env::var_os("UPDATE_EXPECT").is_some() {
        std::fs::write(&path, &want).expect("write the generated file");
        return;
    }
    panic!(
        "{} is stale (it differs from what tree-sitter-rapid/src/node-types.json gives): \
         run `{}` and commit it",
        path.display(),
        codegen::UPDATE
    );
}

/// The grammar's names: kinds (named and anonymous) and fields.
struct Grammar {
    kinds: BTreeSet<String>,
    fields: BTreeSet<String>,
}

fn grammar() -> Grammar {
    let types = codegen::read(tree_sitter_rapid::NODE_TYPES).expect("node-types.json reads");
    let mut kinds: BTreeSet<String> = types.iter().map(|t| t.kind.clone()).collect();
    // Kinds tree-sitter gives every grammar.
    kinds.insert("ERROR".to_owned());
    let fields = types
        .iter()
        .flat_map(|t| t.fields.keys().cloned())
        .collect();
    Grammar { kinds, fields }
}

/// The uses in `text` that name no kind or field of the grammar, as
/// `file:line: role "name"`.
fn unknown(grammar: &Grammar, file: &str, text: &str) -> Vec<String> {
    names::uses(text)
        .into_iter()
        .filter(|u| {
            let kind = grammar.kinds.contains(&u.name);
            let field = grammar.fields.contains(&u.name);
            !match u.role {
                Role::Kind => kind,
                Role::Field => field,
                Role::KindOrField => kind || field,
            }
        })
        .map(|u| format!("{file}:{}: {:?} {:?}", u.line, u.role, u.name))
        .collect()
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("read the source directory")
        .map(|e| e.expect("a directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn every_kind_and_field_named_in_the_sources_is_the_grammars() {
    let grammar = grammar();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    let mut bad = Vec::new();
    let mut found = 0;
    for path in &files {
        let text = std::fs::read_to_string(path).expect("read a source file");
        let name = path
            .strip_prefix(root)
            .unwrap_or(path)
            .display()
            .to_string();
        found += names::uses(&text).len();
        bad.extend(unknown(&grammar, &name, &text));
    }
    // The walk reads the sources (the forms themselves are tested on a
    // sample below; as code moves to the generated constants, fewer
    // literals remain to find).
    assert!(files.len() > 50, "only {} source files found", files.len());
    assert!(found > 0, "no kind or field names found");
    assert!(
        bad.is_empty(),
        "names that are no node kind or field of the grammar \
         (tree-sitter-rapid/src/node-types.json):\n{}",
        bad.join("\n")
    );
}

#[test]
fn the_scan_finds_misspelt_kinds_and_fields() {
    let sample = r##"
fn f(n: Node<'_>) {
    let a = field(n, "name");
    let b = fields(n, "bodi");
    if kind(n) == "procedure_cal" || n.kind() != "if_statement" {}
    if matches!(kind(n), "assignment" | "asignment") {}
    let c = n.child_by_field_name("argumnts");
    match n.kind() {
        "for_statement" => {}
        "whle_statement" if a.is_some() => {}
        _ => {}
    }
    match (p.kind(), f) {
        ("module", Some("nam")) => {}
        _ => {}
    }
    if kind_of(n) == "labl" || field == Some("bdy") {}
    let e = self.opt_expr(n, "valu");
    let s = "procedure_cal"; // not a kind in any form: not reported
    let r = r#"kind(n) == "raw_text" "#; // inside a raw string: not reported
    let (q, u) = ('"', '\u{22}'); // char literals with quotes do not open strings
    if 1usize > 0 && kind(n) == "numbr" {}
}
"##;
    let uses = names::uses(sample);
    let found: Vec<(usize, Role, &str)> = uses
        .iter()
        .map(|Use { line, role, name }| (*line, *role, name.as_str()))
        .collect();
    assert_eq!(
        found,
        [
            (3, Role::Field, "name"),
            (4, Role::Field, "bodi"),
            (5, Role::Kind, "procedure_cal"),
            (5, Role::Kind, "if_statement"),
            (6, Role::Kind, "assignment"),
            (6, Role::Kind, "asignment"),
            (7, Role::Field, "argumnts"),
            (9, Role::Kind, "for_statement"),
            (10, Role::Kind, "whle_statement"),
            (14, Role::KindOrField, "module"),
            (14, Role::KindOrField, "nam"),
            (17, Role::Kind, "labl"),
            (17, Role::Field, "bdy"),
            (18, Role::Field, "valu"),
            (22, Role::Kind, "numbr"),
        ]
    );
    assert_eq!(
        unknown(&grammar(), "sample.rs", sample),
        [
            r#"sample.rs:4: Field "bodi""#,
            r#"sample.rs:5: Kind "procedure_cal""#,
            r#"sample.rs:6: Kind "asignment""#,
            r#"sample.rs:7: Field "argumnts""#,
            r#"sample.rs:10: Kind "whle_statement""#,
            r#"sample.rs:14: KindOrField "nam""#,
            r#"sample.rs:17: Kind "labl""#,
            r#"sample.rs:17: Field "bdy""#,
            r#"sample.rs:18: Field "valu""#,
            r#"sample.rs:22: Kind "numbr""#,
        ]
    );
}

#[test]
fn the_generated_constants_are_the_languages() {
    use rapid_analyzer::syntax::generated::{FIELDS, NAMED_KINDS, TOKENS, fields_of};
    let language: tree_sitter::Language = tree_sitter_rapid::LANGUAGE.into();
    for kind in NAMED_KINDS {
        assert_ne!(language.id_for_node_kind(kind, true), 0, "kind {kind}");
    }
    for token in TOKENS {
        assert_ne!(language.id_for_node_kind(token, false), 0, "token {token}");
    }
    for field in FIELDS {
        assert!(language.field_id_for_name(field).is_some(), "field {field}");
    }
    let names: Vec<&str> = fields_of("procedure_call").iter().map(|f| f.name).collect();
    assert_eq!(names, ["arguments", "name"]);
    assert!(fields_of("no_such_kind").is_empty());
    assert!(fields_of("comment").is_empty());
}
