//! The program's modules as a whole: loading one more while the program
//! runs (`Load`), and the module data a symbol search goes through.

use std::sync::Arc;

use rapid_analyzer::items::{Scope, Storage};
use rapid_analyzer::task::{Item, ItemRef, Unit};
use rapid_analyzer::text::LineIndex;

use super::{Home, Program};

/// Why a module could not be loaded while the program runs
/// ([`Program::with_module`]).
#[derive(Clone, Debug)]
pub(crate) enum LoadFailure {
    /// Its text is not a RAPID module (`ERR_SYNTAX`): the first error.
    Syntax(String),
    /// The task has a module of that name already (`ERR_LOADED`).
    Loaded(String),
    /// It uses names declared nowhere (`ERR_LINKREF`, with `\CheckRef`).
    Link(String),
}

/// A module data object, for a symbol search (`SetDataSearch`).
#[derive(Clone, Debug)]
pub(crate) struct Symbol {
    /// Its module's index in [`Program::modules`].
    pub module: usize,
    pub name: String,
    pub storage: Storage,
    /// Not `LOCAL`.
    pub global: bool,
    /// Its type's name.
    pub ty: String,
    /// An array.
    pub array: bool,
    pub home: Home,
}

impl Program {
    /// This program with the module file `path` (its text `text`) loaded
    /// after its own modules, as `Load` loads it while the program runs:
    /// every module, data object and routine already laid out keeps its
    /// place, so the running code goes on. A name the module uses that is
    /// declared nowhere is an error only with `check_refs` (`\CheckRef`):
    /// otherwise the statement that uses it fails when it runs.
    pub(crate) fn with_module(
        &self,
        path: &str,
        text: &str,
        check_refs: bool,
    ) -> Result<Program, LoadFailure> {
        let unit = Arc::new(Unit::new(path.to_owned(), text.to_owned(), None));
        if let Some(m) = unit
            .items
            .modules
            .iter()
            .find(|m| self.module_named(&m.name).is_some())
        {
            return Err(LoadFailure::Loaded(m.name.clone()));
        }
        let task = Arc::new(self.task.with_extra_units([unit.clone()]));
        let lines = LineIndex::new(&unit.text);
        for d in rapid_analyzer::workspace::diagnostics_of(&task, &unit) {
            let run_time = matches!(d.rule.code, "E413" | "E601" | "E602");
            if d.severity != rapid_analyzer::diagnostic::Severity::Error || run_time {
                continue;
            }
            let (line, column) = lines.human(d.range.start, &unit.text);
            let what = format!("{path}:{line}:{column}: {}", d.message);
            if d.rule.code.starts_with("E00") {
                return Err(LoadFailure::Syntax(what));
            }
            if check_refs {
                return Err(LoadFailure::Link(what));
            }
        }
        if unit.items.modules.is_empty() {
            return Err(LoadFailure::Syntax(format!(
                "{path}: no module in the file"
            )));
        }
        Ok(Program::new(task, &[]))
    }

    /// The names of the modules laid out from module index `from` on.
    pub(crate) fn module_names_from(&self, from: usize) -> Vec<String> {
        self.modules
            .iter()
            .skip(from)
            .map(|m| m.name.clone())
            .collect()
    }

    /// How many modules the program has.
    pub(crate) fn module_count(&self) -> usize {
        self.modules.len()
    }

    /// The data objects declared in the modules, in module order then
    /// declaration order (what a symbol search goes through).
    pub(crate) fn module_symbols(&self) -> Vec<Symbol> {
        let mut out = Vec::new();
        for (k, m) in self.modules.iter().enumerate() {
            let Some(decl) = self
                .task
                .units
                .get(m.unit)
                .and_then(|u| u.items.modules.get(m.index))
            else {
                continue;
            };
            for (i, d) in decl.data.iter().enumerate() {
                let item = ItemRef {
                    unit: m.unit,
                    module: m.index,
                    item: Item::Data(i),
                };
                if let Some(&home) = self.items.get(&item) {
                    out.push(Symbol {
                        module: k,
                        name: d.name.clone(),
                        storage: d.storage,
                        global: d.scope != Scope::Local,
                        ty: d.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                        array: !d.dims.is_empty(),
                        home,
                    });
                }
            }
        }
        out
    }

    /// The index of the module named `name`.
    pub(crate) fn module_named(&self, name: &str) -> Option<usize> {
        self.modules
            .iter()
            .position(|m| m.name.eq_ignore_ascii_case(name))
    }
}
