//! Measures how the RAPID code of the corpus is laid out, separately for
//! modules of controller backups, modules written by RobotStudio and the
//! rest (see `rapid_tests::layout::Origin`): the blanks around `:=`,
//! operators, commas and `\`, indentation, continuation lines, blank lines,
//! comments, keyword case, statements per line and the form of data values.
//! Then, with `--format` (and `--style tight|spaced`), what `rapid fmt`
//! would change in each group, line by line, the files it would change
//! most and (with `--show N`) N changed lines of each kind, spread over the
//! group; `--no-layout` leaves the first part out.
//!
//! ```sh
//! cargo run --release -p rapid-tests --example layout_survey
//! cargo run --release -p rapid-tests --example layout_survey -- --format --no-layout --show 20
//! ```
//!
//! It prints figures only (and, with `--show`, lines of the corpus to read
//! on the terminal: never copy them into the repository).

#![allow(clippy::print_stdout)]

use std::collections::BTreeMap;
use std::process::ExitCode;

use rapid_analyzer::format::{FormatOptions, Style, format};
use rapid_analyzer::text::{Decoded, decode};
use rapid_tests::layout::{LineChange, LineChanges, Origin, line_changes, origin};
use tree_sitter::Node;

const STRUCTURE: &[&str] = &[
    "module",
    "data_declaration",
    "record_declaration",
    "alias_declaration",
    "procedure_declaration",
    "function_declaration",
    "trap_declaration",
    "assignment",
    "procedure_call",
    "if_statement",
    "compact_if_statement",
    "for_statement",
    "while_statement",
    "test_statement",
    "label",
    "goto_statement",
    "return_statement",
    "raise_statement",
    "exit_statement",
    "retry_statement",
    "trynext_statement",
    "connect_statement",
    "elseif_clause",
    "else_clause",
    "test_case",
    "default_case",
    "error_handler",
    "backward_handler",
    "undo_handler",
    "record_component",
];

const ROUTINES: &[&str] = &[
    "procedure_declaration",
    "function_declaration",
    "trap_declaration",
];
const HANDLERS: &[&str] = &["error_handler", "backward_handler", "undo_handler"];

/// A counter of labelled things.
#[derive(Default)]
struct Counts(BTreeMap<String, usize>);

impl Counts {
    fn add(&mut self, key: impl Into<String>, n: usize) {
        *self.0.entry(key.into()).or_default() += n;
    }
}

#[derive(Default)]
struct Group {
    files: usize,
    lines: usize,
    /// context -> gap kind -> count
    gaps: BTreeMap<String, [usize; 4]>,
    /// context -> files using both no blank and a blank there
    mixed: Counts,
    indent: Counts,
    indent_files: Counts,
    continuation: Counts,
    blank_between_routines: Counts,
    blank_runs: Counts,
    comments: Counts,
    keyword_case: Counts,
    lines_kind: Counts,
    values: Counts,
    changes: LineChanges,
    worst: Vec<(usize, usize, String)>,
    changes_files: usize,
    examples: BTreeMap<&'static str, Vec<String>>,
}

fn gap_kind(gap: &str) -> usize {
    if gap.is_empty() {
        0
    } else if gap.contains('\t') {
        3
    } else if gap == " " {
        1
    } else {
        2
    }
}

/// A leaf of the tree with what the survey needs of its place.
struct Leaf<'t> {
    node: Node<'t>,
    field: Option<&'t str>,
    line: usize,
}

fn leaves<'t>(root: Node<'t>, line_of: &impl Fn(usize) -> usize) -> Vec<Leaf<'t>> {
    let mut out = Vec::new();
    let mut cursor = root.walk();
    loop {
        let node = cursor.node();
        let leaf = node.child_count() == 0 || node.kind() == "string";
        if leaf {
            if !node.byte_range().is_empty() {
                out.push(Leaf {
                    node,
                    field: cursor.field_name(),
                    line: line_of(node.start_byte()),
                });
            }
        } else if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return out;
            }
        }
    }
}

fn parent_kind<'t>(node: Node<'t>) -> &'t str {
    node.parent().map(|p| p.kind()).unwrap_or("")
}

/// The context of the blanks between two tokens on one line.
fn context(a: &Leaf<'_>, b: &Leaf<'_>) -> String {
    let (ka, kb) = (a.node.kind(), b.node.kind());
    let assign = |n: Node<'_>| -> String {
        let Some(p) = n.parent() else {
            return String::new();
        };
        match p.kind() {
            "data_declaration" => {
                let storage = p
                    .child_by_field_name("storage")
                    .map(|s| s.kind())
                    .unwrap_or("");
                format!("declaration ({storage})")
            }
            other => other.to_owned(),
        }
    };
    let list = |n: Node<'_>| -> String {
        let Some(p) = n.parent() else {
            return String::new();
        };
        if p.kind() == "argument_list" {
            format!("{} arguments", parent_kind(p))
        } else {
            p.kind().to_owned()
        }
    };
    if kb == "comment" {
        return "before a trailing comment".into();
    }
    if kb == ":=" {
        return format!("before := ({})", assign(b.node));
    }
    if ka == ":=" {
        return format!("after := ({})", assign(a.node));
    }
    if kb == "," {
        return format!("before , ({})", list(b.node));
    }
    if ka == "," {
        return format!("after , ({})", list(a.node));
    }
    if b.field == Some("operator") && parent_kind(b.node) == "binary_expression" {
        return format!("before binary {kb}");
    }
    if a.field == Some("operator") && parent_kind(a.node) == "binary_expression" {
        return format!("after binary {ka}");
    }
    if a.field == Some("operator") && parent_kind(a.node) == "unary_expression" {
        return format!("after unary {ka}");
    }
    if kb == "\\" && parent_kind(b.node) == "argument" {
        let after = if a.field == Some("name") && parent_kind(a.node) == "procedure_call" {
            "the procedure name"
        } else if ka == "(" {
            "("
        } else {
            "an argument"
        };
        return format!("before \\ (after {after})");
    }
    if ka == "\\" {
        return format!("after \\ ({})", parent_kind(a.node));
    }
    if kb == "(" && parent_kind(b.node) == "argument_list" {
        return "before ( of a function call".into();
    }
    if kb == "(" && parent_kind(b.node) == "parameter_list" {
        return "before ( of parameters".into();
    }
    if matches!(ka, "(" | "[" | "{") {
        return format!("after {ka}");
    }
    if matches!(kb, ")" | "]" | "}") {
        return format!("before {kb}");
    }
    if kb == ";" {
        return "before ;".into();
    }
    if ka == "." || kb == "." {
        return "around .".into();
    }
    if ka == "?" || kb == "?" {
        return "around ?".into();
    }
    if a.field == Some("name") && parent_kind(a.node) == "procedure_call" {
        return "after the procedure name".into();
    }
    if parent_kind(b.node) == "data_declaration" || parent_kind(a.node) == "data_declaration" {
        return "between words of a declaration".into();
    }
    "between other tokens".into()
}

/// The structure node a line starts with (the largest node starting at the
/// leaf that is a statement, declaration or clause).
fn line_node(leaf: Node<'_>) -> Option<Node<'_>> {
    let mut best = None;
    let mut n = leaf;
    while let Some(p) = n.parent() {
        if p.start_byte() != leaf.start_byte() || p.kind() == "source_file" {
            break;
        }
        n = p;
        if STRUCTURE.contains(&n.kind()) {
            best = Some(n);
        }
    }
    best
}

/// The nesting level of a structure node (module body 1, routine body 2...).
fn level(node: Node<'_>) -> usize {
    let mut level = 0;
    let mut child = node;
    while let Some(p) = child.parent() {
        let ck = child.kind();
        level += match p.kind() {
            "module" | "elseif_clause" | "else_clause" | "for_statement" | "while_statement"
            | "test_statement" | "test_case" | "default_case" | "error_handler"
            | "backward_handler" | "undo_handler" | "record_declaration" => 1,
            k if ROUTINES.contains(&k) => usize::from(!HANDLERS.contains(&ck)),
            "if_statement" => usize::from(!matches!(ck, "elseif_clause" | "else_clause")),
            _ => 0,
        };
        child = p;
    }
    level
}

/// The enclosing structure node of a token that continues a line.
fn enclosing(leaf: Node<'_>) -> Option<Node<'_>> {
    let mut n = leaf;
    while let Some(p) = n.parent() {
        if STRUCTURE.contains(&p.kind()) {
            return Some(p);
        }
        n = p;
    }
    None
}

fn columns(indent: &str) -> usize {
    indent.chars().map(|c| if c == '\t' { 4 } else { 1 }).sum()
}

fn survey(group: &mut Group, text: &str) {
    let mut parser = rapid_analyzer::syntax::parser();
    let Some(tree) = rapid_analyzer::syntax::parse(&mut parser, text, None) else {
        return;
    };
    if tree.root_node().has_error() {
        return;
    }
    let lines = rapid_tests::layout::split_lines(text);
    // byte offset of each line start
    let mut starts = vec![0];
    let bytes = text.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        if b == b'\n' || (b == b'\r' && bytes.get(i + 1) != Some(&b'\n')) {
            starts.push(i + 1);
        }
    }
    let line_of = |offset: usize| starts.partition_point(|&s| s <= offset) - 1;
    let leaves = leaves(tree.root_node(), &line_of);

    // gaps between tokens on a line
    let mut file_ctx: BTreeMap<String, [bool; 2]> = BTreeMap::new();
    for w in leaves.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if a.line != b.line || a.node.kind() == "trailing_text" || b.node.kind() == "trailing_text"
        {
            continue;
        }
        let gap = &text[a.node.end_byte()..b.node.start_byte()];
        let ctx = context(a, b);
        let k = gap_kind(gap);
        group.gaps.entry(ctx.clone()).or_default()[k] += 1;
        file_ctx.entry(ctx).or_default()[usize::from(k > 0)] = true;
    }
    for (ctx, seen) in file_ctx {
        if seen[0] && seen[1] {
            group.mixed.add(ctx, 1);
        }
    }

    // first token of each line
    let mut first: Vec<Option<usize>> = vec![None; lines.len()];
    for (i, leaf) in leaves.iter().enumerate() {
        if leaf.line < first.len() && first[leaf.line].is_none() {
            first[leaf.line] = Some(i);
        }
    }
    let indent_of = |line: usize| -> &str {
        let l = lines.get(line).copied().unwrap_or_default();
        &l[..l.len() - l.trim_start_matches([' ', '\t']).len()]
    };

    // indentation of structure lines, by hypothesis (unit, module body level)
    let mut hypotheses: BTreeMap<(&str, usize), usize> = BTreeMap::new();
    let units: [(&str, &str); 4] = [("tab", "\t"), ("2", "  "), ("3", "   "), ("4", "    ")];
    let mut structural = 0;
    let mut line_levels: Vec<Option<usize>> = vec![None; lines.len()];
    for (line, f) in first.iter().enumerate() {
        let Some(f) = *f else { continue };
        let leaf = &leaves[f];
        let kind = leaf.node.kind();
        if kind == "comment" || kind == "trailing_text" {
            continue;
        }
        let lvl = if let Some(n) = line_node(leaf.node) {
            Some(level(n))
        } else if !leaf.node.is_named()
            && kind.bytes().all(|b| b.is_ascii_alphabetic())
            && leaf
                .node
                .parent()
                .is_some_and(|p| STRUCTURE.contains(&p.kind()))
        {
            leaf.node.parent().map(level)
        } else {
            None
        };
        let Some(lvl) = lvl else {
            // a continuation line
            let Some(stmt) = enclosing(leaf.node) else {
                continue;
            };
            let sline = line_of(stmt.start_byte());
            let base = columns(indent_of(sline));
            let here = columns(indent_of(line));
            // columns after an open bracket or the procedure name on the
            // statement's lines before this one
            let mut aligned = false;
            for l in &leaves {
                if l.node.start_byte() < stmt.start_byte() || l.line >= line {
                    continue;
                }
                let k = l.node.kind();
                let name = l.field == Some("name") && parent_kind(l.node) == "procedure_call";
                if matches!(k, "(" | "[" | "{" | ",") || name {
                    let lstart = starts[l.line];
                    let col = columns(&text[lstart..l.node.end_byte()]) + usize::from(name);
                    if col == here {
                        aligned = true;
                    }
                }
            }
            let key = if aligned && here != base + 4 && here != base + 8 {
                "aligned under an opening or an argument".to_owned()
            } else if here >= base {
                format!("+{}", here - base)
            } else {
                format!("-{}", base - here)
            };
            group.continuation.add(key, 1);
            continue;
        };
        line_levels[line] = Some(lvl);
        structural += 1;
        let indent = indent_of(line);
        for (name, unit) in units {
            for body in [0usize, 1] {
                let expected = unit.repeat(lvl.saturating_sub(1 - body));
                let expected = if lvl == 0 { String::new() } else { expected };
                if indent == expected {
                    *hypotheses.entry((name, body)).or_default() += 1;
                }
            }
        }
    }
    if let Some((&(unit, body), &n)) = hypotheses.iter().max_by_key(|(_, n)| **n) {
        let module_body = if body == 1 {
            "module body indented"
        } else {
            "module body at column 0"
        };
        group
            .indent_files
            .add(format!("unit {unit}, {module_body}"), 1);
        group.indent.add(
            format!("structure lines fitting their file's best ({unit}, {module_body})"),
            n,
        );
    }
    group.indent.add("structure lines", structural);
    group.indent.add(
        "structure lines fitting 4 spaces, module body indented",
        hypotheses.get(&("4", 1)).copied().unwrap_or(0),
    );
    group.indent.add(
        "structure lines indented with tabs",
        (0..lines.len())
            .filter(|&l| line_levels[l].is_some() && indent_of(l).contains('\t'))
            .count(),
    );

    // own-line comments: indented like the next code line, the previous, 0
    for (line, f) in first.iter().enumerate() {
        let Some(f) = *f else { continue };
        if leaves[f].node.kind() != "comment" {
            if leaves[f..]
                .iter()
                .take_while(|l| l.line == line)
                .any(|l| l.node.kind() == "comment")
            {
                group.comments.add("trailing comments", 1);
            }
            continue;
        }
        let here = indent_of(line);
        let next = leaves[f..]
            .iter()
            .find(|l| l.node.kind() != "comment")
            .map(|l| indent_of(l.line));
        let prev = leaves[..f]
            .iter()
            .rev()
            .find(|l| l.node.kind() != "comment")
            .map(|l| indent_of(l.line));
        let key = if Some(here) == next {
            "own line, indented as the next code line"
        } else if Some(here) == prev {
            "own line, indented as the code line before"
        } else if here.is_empty() {
            "own line, at column 0"
        } else {
            "own line, elsewhere"
        };
        group.comments.add(key, 1);
    }

    // blank lines
    let mut run = 0;
    for l in &lines {
        if l.trim().is_empty() {
            run += 1;
        } else {
            if run > 0 {
                group.blank_runs.add(format!("{run}"), 1);
            }
            run = 0;
        }
    }
    let mut cursor = tree.root_node().walk();
    for module in tree.root_node().children(&mut cursor) {
        let mut c = module.walk();
        let body: Vec<Node<'_>> = module.children_by_field_name("body", &mut c).collect();
        for w in body.windows(2) {
            if ROUTINES.contains(&w[0].kind()) && ROUTINES.contains(&w[1].kind()) {
                let between = &text[w[0].end_byte()..w[1].start_byte()];
                let blank = between.matches('\n').count().saturating_sub(1);
                group
                    .blank_between_routines
                    .add(format!("{blank} blank lines"), 1);
            }
        }
    }

    // keyword case
    for leaf in &leaves {
        let k = leaf.node.kind();
        if leaf.node.is_named() || !k.bytes().all(|b| b.is_ascii_alphabetic()) {
            continue;
        }
        let t = &text[leaf.node.byte_range()];
        let key = if t.bytes().all(|b| !b.is_ascii_lowercase()) {
            "UPPER"
        } else if t.bytes().all(|b| !b.is_ascii_uppercase()) {
            "lower"
        } else {
            "Mixed"
        };
        let what = if matches!(k, "true" | "false") {
            "TRUE/FALSE"
        } else {
            "keywords"
        };
        group.keyword_case.add(format!("{what} {key}"), 1);
    }

    // lines: trailing blanks, several statements
    for (line, l) in lines.iter().enumerate() {
        if l.ends_with([' ', '\t']) {
            let what = if l.trim().is_empty() {
                "blank line with blanks"
            } else if leaves
                .iter()
                .rev()
                .find(|x| x.line == line)
                .is_some_and(|x| x.node.kind() == "comment")
            {
                "comment line with trailing blanks"
            } else {
                "code line with trailing blanks"
            };
            group.lines_kind.add(what, 1);
        }
    }
    let mut starts_per_line: BTreeMap<usize, usize> = BTreeMap::new();
    walk(tree.root_node(), &mut |n| {
        if STRUCTURE.contains(&n.kind())
            && n.kind() != "module"
            && parent_kind(n) != "compact_if_statement"
        {
            *starts_per_line.entry(line_of(n.start_byte())).or_default() += 1;
        }
    });
    group.lines_kind.add(
        "lines starting two or more statements or declarations",
        starts_per_line.values().filter(|&&n| n > 1).count(),
    );

    // data values: tight or spaced aggregates
    walk(tree.root_node(), &mut |n| {
        if n.kind() != "data_declaration" {
            return;
        }
        let Some(value) = n.child_by_field_name("value") else {
            return;
        };
        if value.kind() != "aggregate" {
            return;
        }
        let storage = n
            .child_by_field_name("storage")
            .map(|s| s.kind())
            .unwrap_or("");
        let vt = &text[value.byte_range()];
        let shape = if vt.contains(['\n', '\r']) {
            "over several lines"
        } else if vt.contains([' ', '\t']) {
            "with blanks"
        } else {
            "tight"
        };
        group
            .values
            .add(format!("{} aggregate {shape}", storage.to_uppercase()), 1);
    });
}

fn walk<'t>(root: Node<'t>, f: &mut impl FnMut(Node<'t>)) {
    let mut cursor = root.walk();
    loop {
        f(cursor.node());
        if cursor.goto_first_child() {
            continue;
        }
        loop {
            if cursor.goto_next_sibling() {
                break;
            }
            if !cursor.goto_parent() {
                return;
            }
        }
    }
}

fn print_counts(title: &str, counts: &Counts) {
    if counts.0.is_empty() {
        return;
    }
    println!("  {title}:");
    let total: usize = counts.0.values().sum();
    let mut v: Vec<_> = counts.0.iter().collect();
    v.sort_by(|a, b| b.1.cmp(a.1));
    for (k, n) in v {
        println!(
            "    {n:>7} {:>5.1}%  {k}",
            100.0 * *n as f64 / total.max(1) as f64
        );
    }
}

fn main() -> ExitCode {
    rapid_tests::alloc::init();
    let Some(files) = rapid_tests::corpus_files() else {
        eprintln!("no corpus (set RAPID_CORPUS)");
        return ExitCode::from(2);
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let do_format = args.iter().any(|a| a == "--format");
    let style = args
        .iter()
        .position(|a| a == "--style")
        .and_then(|i| args.get(i + 1))
        .and_then(|s| Style::from_name(s))
        .unwrap_or_default();
    let show: usize = args
        .iter()
        .position(|a| a == "--show")
        .and_then(|i| args.get(i + 1))
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    let layout = !args.iter().any(|a| a == "--no-layout");
    let options = FormatOptions {
        style,
        ..FormatOptions::default()
    };
    let mut groups: BTreeMap<Origin, Group> = BTreeMap::new();
    let mut slowest = Vec::new();
    let mut parse_time = std::time::Duration::ZERO;
    for (path, bytes) in &files {
        let Decoded::Text { text, .. } = decode(bytes) else {
            continue;
        };
        let origin = origin(path, &text);
        let group = groups.entry(origin).or_default();
        group.files += 1;
        group.lines += rapid_tests::layout::split_lines(&text).len();
        if layout {
            survey(group, &text);
        }
        if do_format {
            let started = std::time::Instant::now();
            let mut parser = rapid_analyzer::syntax::parser();
            let _ = rapid_analyzer::syntax::parse(&mut parser, &text, None);
            parse_time += started.elapsed();
        }
        let started = std::time::Instant::now();
        let formatted = if do_format {
            format(&text, &options).ok()
        } else {
            None
        };
        slowest.push((started.elapsed(), path.display().to_string()));
        if let Some(out) = formatted {
            let mut file_changed = false;
            let changes = line_changes(&text, &out, |line, old, new, kind| {
                file_changed = true;
                let label = match kind {
                    Some(LineChange::Indentation) => "indentation",
                    Some(LineChange::Trailing) => "trailing",
                    Some(LineChange::Case) => "case",
                    Some(LineChange::Spacing) => "spacing",
                    None => "structure",
                };
                let list = group.examples.entry(label).or_default();
                if show > 0 {
                    list.push(format!(
                        "{}:{}\n      - {old:?}\n      + {:?}",
                        path.display(),
                        line + 1,
                        new.unwrap_or("(gone or split)")
                    ));
                }
            });
            group
                .worst
                .push((changes.changed(), changes.lines, path.display().to_string()));
            group.changes.add(&changes);
            group.changes_files += usize::from(file_changed);
        }
    }
    if do_format {
        slowest.sort_by(|a, b| b.cmp(a));
        let total: std::time::Duration = slowest.iter().map(|(t, _)| *t).sum();
        println!(
            "formatting took {:.3} s (parsing alone {:.3} s); the slowest files:",
            total.as_secs_f64(),
            parse_time.as_secs_f64()
        );
        for (t, path) in slowest.iter().take(5) {
            println!("  {:>8.1} ms  {path}", t.as_secs_f64() * 1000.0);
        }
    }
    for origin in Origin::ALL {
        let Some(g) = groups.get(&origin) else {
            continue;
        };
        println!(
            "== {} ({} files, {} lines)",
            origin.name(),
            g.files,
            g.lines
        );
        if layout {
            println!(
                "  blanks between tokens (none / one space / more / tab; files mixing none and some):"
            );
            let mut v: Vec<_> = g.gaps.iter().collect();
            v.sort_by_key(|(_, c)| std::cmp::Reverse(c.iter().sum::<usize>()));
            for (ctx, c) in v {
                let total: usize = c.iter().sum();
                if total < 20 {
                    continue;
                }
                let pct = |n: usize| 100.0 * n as f64 / total as f64;
                println!(
                    "    {total:>7}  {:>5.1}% {:>5.1}% {:>5.1}% {:>5.1}%  mixed in {:>3} files  {ctx}",
                    pct(c[0]),
                    pct(c[1]),
                    pct(c[2]),
                    pct(c[3]),
                    g.mixed.0.get(ctx).copied().unwrap_or(0)
                );
            }
            print_counts("indentation (lines)", &g.indent);
            print_counts("indentation (files, best fit)", &g.indent_files);
            print_counts(
                "continuation lines (from the statement's indentation)",
                &g.continuation,
            );
            print_counts("blank lines between routines", &g.blank_between_routines);
            print_counts("runs of blank lines", &g.blank_runs);
            print_counts("comments", &g.comments);
            print_counts("keyword case", &g.keyword_case);
            print_counts("lines", &g.lines_kind);
            print_counts("aggregate values of declarations", &g.values);
        }
        if do_format {
            let c = &g.changes;
            let pct = |n: usize| 100.0 * n as f64 / c.lines.max(1) as f64;
            println!(
                "  rapid fmt ({}) changes {} of {} files, {} of {} lines ({:.2}%): indentation {} ({:.2}%), trailing blanks {} ({:.2}%), keyword case {} ({:.2}%), spacing {} ({:.2}%), line structure {} ({:.2}%)",
                style.name(),
                g.changes_files,
                g.files,
                c.changed(),
                c.lines,
                pct(c.changed()),
                c.indentation,
                pct(c.indentation),
                c.trailing,
                pct(c.trailing),
                c.case,
                pct(c.case),
                c.spacing,
                pct(c.spacing),
                c.structure,
                pct(c.structure),
            );
            let mut worst = g.worst.clone();
            worst.sort_by(|a, b| b.cmp(a));
            if show > 0 {
                println!("  files with the most changed lines:");
                for (changed, lines, path) in worst.iter().take(show) {
                    println!("    {changed:>6} of {lines:>6}  {path}");
                }
            }
            for (label, list) in &g.examples {
                let step = (list.len() / show.max(1)).max(1);
                println!("  {label} (every {step}th of {}):", list.len());
                for e in list.iter().step_by(step).take(show) {
                    println!("    {e}");
                }
            }
        }
    }
    ExitCode::SUCCESS
}
