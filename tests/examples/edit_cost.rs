//! The one-character edit of the `edit_recheck_largest` benchmark (a space
//! inserted at the start of the first statement line of the largest corpus
//! file, then removed, alternately), repeated, for instruction counts that do
//! not depend on machine noise. Only `edit_once` is meant to be counted:
//!
//! ```sh
//! cargo build --release -p rapid-tests --example edit_cost
//! valgrind --tool=callgrind --toggle-collect='*edit_once*' \
//!   --callgrind-out-file=/tmp/cg.edit target/release/examples/edit_cost recheck 20
//! valgrind --tool=callgrind --toggle-collect='*reparse_once*' \
//!   --callgrind-out-file=/tmp/cg.parse target/release/examples/edit_cost reparse 20
//! ```
//!
//! `recheck` is the benchmark's iteration (incremental parse, `Unit`,
//! `Workspace::diagnostics`); `reparse` is tree-sitter's incremental reparse
//! alone. Divide the totals by the count of edits.
use std::process::ExitCode;

use rapid_analyzer::task::Unit;
use rapid_analyzer::workspace::Workspace;

struct Edit<'a> {
    path: &'a str,
    space: rapid_tests::SpaceEdit,
}

fn main() -> ExitCode {
    rapid_tests::alloc::init();
    let Some(dir) = rapid_tests::corpus_dir() else {
        eprintln!("no corpus (set RAPID_CORPUS)");
        return ExitCode::from(2);
    };
    let mut args = std::env::args().skip(1);
    let mode = args.next().unwrap_or_default();
    let count: usize = args.next().and_then(|n| n.parse().ok()).unwrap_or(10);
    let inputs = rapid_tests::workspace_inputs(&dir);
    let Some((path, text)) = inputs.modules.iter().max_by_key(|(_, t)| t.len()) else {
        return ExitCode::from(2);
    };
    let edit = Edit {
        path,
        space: rapid_tests::SpaceEdit::new(text),
    };
    let mut ws = Workspace::new();
    for (p, t) in &inputs.configs {
        if rapid_analyzer::text::is_controller_config_name(p) {
            ws.set_config(p, t);
        }
    }
    for (p, t) in &inputs.programs {
        ws.set_program(p, t);
    }
    for (p, t) in &inputs.modules {
        ws.set_file(p, t.clone());
    }
    for (p, _) in &inputs.modules {
        ws.diagnostics(p);
    }
    let mut parser = rapid_analyzer::syntax::parser();
    let mut total = 0usize;
    for i in 0..count {
        let flip = (i + 1) % 2;
        if mode == "reparse" {
            // Outside `edit_once`: keep the workspace's tree in step.
            if let Some(tree) = reparse_once(&ws, &mut parser, &edit, flip) {
                total += tree.root_node().child_count() as usize;
                let text = edit.space.versions[flip].clone();
                ws.set_unit(Unit::from_tree(edit.path.to_owned(), text, Some(tree)));
            }
        } else {
            total += edit_once(&mut ws, &edit, flip);
        }
    }
    eprintln!("{total} diagnostics over {count} edits");
    ExitCode::SUCCESS
}

/// The old tree of the edited file, edited.
fn edited_tree(ws: &Workspace, edit: &Edit<'_>, flip: usize) -> Option<tree_sitter::Tree> {
    let mut tree = ws.unit(edit.path)?.tree().clone();
    tree.edit(&edit.space.input_edit(flip));
    Some(tree)
}

#[inline(never)]
fn reparse_once(
    ws: &Workspace,
    parser: &mut tree_sitter::Parser,
    edit: &Edit<'_>,
    flip: usize,
) -> Option<tree_sitter::Tree> {
    let tree = edited_tree(ws, edit, flip)?;
    parser.parse(&edit.space.versions[flip], Some(&tree))
}

#[inline(never)]
fn edit_once(ws: &mut Workspace, edit: &Edit<'_>, flip: usize) -> usize {
    let Some(tree) = edited_tree(ws, edit, flip) else {
        return 0;
    };
    let text = edit.space.versions[flip].clone();
    ws.set_unit(Unit::new(edit.path.to_owned(), text, Some(&tree)));
    ws.diagnostics(edit.path).len()
}
