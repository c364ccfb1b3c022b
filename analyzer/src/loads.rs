//! The module files a module loads at run time: the file path of a `Load`
//! or `StartLoad` spelt with string literals or constants
//! (`Load \Dynamic, "HOME:/Part1.mod";`, `StartLoad diskhome
//! \File:="part2.modx", load1;`, `CONST string sGrip := "HOME:/Grip.sys";`
//! then `Load sGrip;`). A string anywhere else (a persistent that lists a
//! project's modules, a message) loads nothing, and neither does a
//! variable or a persistent: its value is known only when the program runs.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use tree_sitter::{Node, Tree};

use crate::items::{FileItems, Storage};
use crate::names::{fold, same};
use crate::syntax::{field, kind};
use crate::task::Unit;

/// What a module loads, as far as its own text tells.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Loads {
    /// The file names (lowercase, without folders) its `Load` and
    /// `StartLoad` calls name with literals or its own constants.
    pub files: Vec<String>,
    /// The names (folded) used in the file paths of those calls that the
    /// module does not declare as constants: constants of other modules of
    /// the task, resolved with [`Loads::consts`] of those.
    pub names: Vec<String>,
    /// The module's module-level string constants whose value names a
    /// module file: folded name and file name.
    pub consts: Vec<(String, String)>,
}

/// The module files some units load, by file name: what their `Load` and
/// `StartLoad` calls name, their constants' included (a constant of one
/// unit may name the file another's call loads).
pub fn loaded_files<'u>(units: impl Iterator<Item = &'u Arc<Unit>> + Clone) -> HashSet<String> {
    let consts: HashMap<&str, &str> = units
        .clone()
        .flat_map(|u| u.loads.consts.iter().map(|(n, f)| (n.as_str(), f.as_str())))
        .collect();
    let mut out = HashSet::new();
    for u in units {
        out.extend(u.loads.files.iter().cloned());
        out.extend(
            u.loads
                .names
                .iter()
                .filter_map(|n| consts.get(n.as_str()).map(|f| (*f).to_owned())),
        );
    }
    out
}

/// The extensions of module files.
const EXTENSIONS: [&str; 5] = [".mod", ".sys", ".modx", ".sysx", ".prg"];

/// The file name (lowercase, without folders and device) a string names,
/// if it names a module file: `"HOME:/Parts/Part1.MOD"` is `part1.mod`.
pub fn module_file_name(path: &str) -> Option<String> {
    let lower = path.trim().to_ascii_lowercase();
    if !EXTENSIONS.iter().any(|e| lower.ends_with(e)) {
        return None;
    }
    let name = lower.rsplit(['/', '\\', ':']).next().unwrap_or_default();
    (!name.is_empty() && !EXTENSIONS.contains(&name)).then(|| name.to_owned())
}

/// The module file the text of a constant's value names: the last string
/// literal in it that names one (`"HOME:/" + "Part1.mod"`).
fn file_in(value: &str) -> Option<String> {
    crate::lex::string_literals(value)
        .into_iter()
        .rev()
        .find_map(|(_, s)| module_file_name(s))
}

/// What the module of `tree` (with its item tree `items`) loads.
pub fn of(tree: &Tree, text: &str, items: &FileItems) -> Loads {
    let mut out = Loads::default();
    let mut own: Vec<(String, String)> = Vec::new();
    for module in &items.modules {
        for d in &module.data {
            let is_string = d.ty.as_ref().is_some_and(|t| same(&t.name, "string"));
            if d.storage != Storage::Const || !is_string || !d.dims.is_empty() {
                continue;
            }
            let value = d.init.clone().and_then(|r| text.get(r)).unwrap_or_default();
            if let Some(file) = file_in(value) {
                own.push((fold(&d.name), file.clone()));
                if d.scope != crate::items::Scope::Local {
                    out.consts.push((fold(&d.name), file));
                }
            }
        }
    }
    // Most modules load nothing: only a text that spells `load` is walked.
    if !contains_ignore_case(text, "load") {
        return out;
    }
    let declared: Vec<String> = items
        .modules
        .iter()
        .flat_map(|m| m.data.iter().map(|d| fold(&d.name)))
        .collect();
    let mut calls = Vec::new();
    crate::syntax_util::walk_pruned(tree.root_node(), &mut |n| match n.kind() {
        kind::PROCEDURE_CALL => {
            let loads = n
                .child_by_field_name(field::NAME)
                .and_then(|name| text.get(name.byte_range()))
                .is_some_and(|name| same(name, "Load") || same(name, "StartLoad"));
            if loads {
                calls.push(n);
            }
            false
        }
        kind::DATA_DECLARATION => {
            if let Some((name, file)) = routine_constant(n, text) {
                own.push((name, file));
            }
            false
        }
        _ => true,
    });
    for call in calls {
        let Some(args) = call.child_by_field_name(field::ARGUMENTS) else {
            continue;
        };
        crate::syntax_util::walk_pruned(args, &mut |n| match n.kind() {
            kind::STRING => {
                let content = text.get(n.byte_range()).unwrap_or_default();
                if let Some(file) = module_file_name(content.trim_matches('"')) {
                    push_new(&mut out.files, file);
                }
                false
            }
            kind::IDENTIFIER if !is_argument_name(n) => {
                let name = fold(text.get(n.byte_range()).unwrap_or_default());
                match own.iter().find(|(c, _)| *c == name) {
                    Some((_, file)) => push_new(&mut out.files, file.clone()),
                    // Data of this module are not another module's constants.
                    None if !declared.contains(&name) => push_new(&mut out.names, name),
                    None => {}
                }
                false
            }
            _ => true,
        });
    }
    out
}

/// A `CONST string` declared in a routine whose value names a module file:
/// its folded name and the file name.
fn routine_constant(decl: Node<'_>, text: &str) -> Option<(String, String)> {
    let storage = decl.child_by_field_name(field::STORAGE)?;
    let ty = decl.child_by_field_name(field::TYPE)?;
    if !same(text.get(storage.byte_range())?, "CONST")
        || !same(text.get(ty.byte_range())?, "string")
    {
        return None;
    }
    let name = decl.child_by_field_name(field::NAME)?;
    let value = decl.child_by_field_name(field::VALUE)?;
    let file = file_in(text.get(value.byte_range())?)?;
    Some((fold(text.get(name.byte_range())?), file))
}

/// Is this identifier the name of an optional or named argument (`\File`),
/// not a value?
fn is_argument_name(n: Node<'_>) -> bool {
    n.parent().is_some_and(|p| {
        p.kind() == kind::ARGUMENT && p.child_by_field_name(field::NAME).is_some_and(|m| m == n)
    })
}

fn push_new(list: &mut Vec<String>, item: String) {
    if !list.contains(&item) {
        list.push(item);
    }
}

/// Does `text` hold `word` in any ASCII letter case?
fn contains_ignore_case(text: &str, word: &str) -> bool {
    let word = word.as_bytes();
    text.as_bytes()
        .windows(word.len())
        .any(|w| w.eq_ignore_ascii_case(word))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn loads(text: &str) -> Loads {
        let unit = crate::task::Unit::new("t/m.mod".into(), text.into(), None);
        unit.loads.clone()
    }

    #[test]
    fn literals_and_constants_in_load_calls_are_loads() {
        let text = "MODULE M\n\
            CONST string sGrip := \"HOME:/Grippers/\" + \"Grip_L.SYS\";\n\
            LOCAL CONST string sTool := \"tool.mod\";\n\
            CONST string diskhome := \"HOME:\";\n\
            PERS string sList{2} := [\"a.mod\", \"b.mod\"];\n\
            VAR string sVar := \"c.mod\";\n\
            VAR loadsession load1;\n\
            PROC main()\n\
              CONST string sLocal := \"HOME:/local.sys\";\n\
              Load \\Dynamic, \"HOME:/Parts/Part1.mod\";\n\
              StartLoad diskhome \\File:=\"part2.MODX\", load1;\n\
              Load sGrip;\n\
              Load \\CheckRef, sTool;\n\
              load sLocal;\n\
              Load sVar;\n\
              Load diskhome \\File:=sOther;\n\
              TPWrite \"d.mod\";\n\
              ! Load \"e.mod\";\n\
            ENDPROC\n\
            ENDMODULE\n";
        let found = loads(text);
        assert_eq!(
            found.files,
            [
                "part1.mod",
                "part2.modx",
                "grip_l.sys",
                "tool.mod",
                "local.sys"
            ]
        );
        // not constants of this module: perhaps of another module of the task
        assert_eq!(found.names, ["sother"]);
        assert_eq!(
            found.consts,
            [("sgrip".to_owned(), "grip_l.sys".to_owned())]
        );
    }

    #[test]
    fn strings_outside_loads_load_nothing() {
        let text = "MODULE M\n\
            PERS string modules{2} := [\"HOME:/a.mod\", \"HOME:/b.mod\"];\n\
            PROC main()\n\
              TPWrite \"Load HOME:/c.mod\";\n\
              UnLoad \"HOME:/d.mod\";\n\
            ENDPROC\n\
            ENDMODULE\n";
        assert_eq!(loads(text), Loads::default());
        assert_eq!(
            module_file_name("HOME:/x/Part1.Mod").as_deref(),
            Some("part1.mod")
        );
        assert_eq!(module_file_name("HOME:/.mod"), None);
        assert_eq!(module_file_name("HOME:/readme.txt"), None);
    }
}
