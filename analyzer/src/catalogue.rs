//! The built-in catalogue of RAPID: functions, instructions (procedures), data types and
//! predefined data, with their signatures and short documentation.
//!
//! The data lives in reviewable TOML files under `analyzer/catalogue/`, embedded at compile
//! time and parsed once. [`catalogue()`] returns the shared instance; lookups by name are
//! case-insensitive, as RAPID names are.

use std::collections::HashMap;

use crate::names::NameMap;
use std::fmt::Write as _;
use std::sync::OnceLock;

use serde::{Deserialize, Serialize};

mod raw;

/// The TOML sources, in the order they are loaded: (file name, text).
pub const SOURCES: &[(&str, &str)] = &[
    (
        "functions.toml",
        include_str!("../catalogue/functions.toml"),
    ),
    (
        "instructions.toml",
        include_str!("../catalogue/instructions.toml"),
    ),
    (
        "datatypes.toml",
        include_str!("../catalogue/datatypes.toml"),
    ),
    ("data.toml", include_str!("../catalogue/data.toml")),
];

/// Routines deliberately not in the catalogue: option and vendor packages (reviewed list).
pub const OPTION_ROUTINES_TOML: &str = include_str!("../catalogue/option_routines.toml");

/// The pseudo type name that accepts an argument of any data type.
pub const ANYTYPE: &str = "anytype";

/// Where an entry's facts come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Source {
    /// The RAPID reference manual part 2 (functions and data types, RobotWare-OS 4.0).
    Manual,
    /// Other RobotWare manuals (instructions, newer functions and types).
    Other,
}

/// Parameter access mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Mode {
    /// Input value (the default).
    #[serde(rename = "IN")]
    In,
    /// Variable reference.
    #[serde(rename = "VAR")]
    Var,
    /// Persistent reference.
    #[serde(rename = "PERS")]
    Pers,
    /// Variable or persistent reference.
    #[serde(rename = "INOUT")]
    InOut,
    /// Reference to any entire data object (built-in routines only).
    #[serde(rename = "REF")]
    Ref,
}

impl Mode {
    /// The keyword as RAPID writes it.
    pub fn keyword(self) -> &'static str {
        match self {
            Mode::In => "IN",
            Mode::Var => "VAR",
            Mode::Pers => "PERS",
            Mode::InOut => "INOUT",
            Mode::Ref => "REF",
        }
    }
}

/// One parameter of a built-in routine.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Param {
    pub name: String,
    /// Data type name, or [`ANYTYPE`]; `switch` for switches.
    #[serde(rename = "type")]
    pub ty: String,
    /// Access mode; `None` for switches.
    pub mode: Option<Mode>,
    /// Written `\Name`: may be left out.
    pub optional: bool,
    /// A switch: given (`\Name`) or not, without a value.
    pub switch: bool,
    /// Number of array dimensions (`{*}` = 1, `{*,*}` = 2), 0 for none.
    pub array: u8,
    /// Mutually exclusive alternatives (`|`) share a group id.
    pub alt_group: Option<u32>,
    /// Not in the RobotWare-OS 4.0 manual: added by a later RobotWare version (only
    /// marked on entries whose `source` is the manual).
    pub later: bool,
}

/// A group of mutually exclusive parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct AltGroup {
    pub id: u32,
    /// One member must be given.
    pub required: bool,
}

/// A built-in function or instruction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Routine {
    pub name: String,
    /// Return type; `None` for instructions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub returns: Option<String>,
    pub params: Vec<Param>,
    pub alt_groups: Vec<AltGroup>,
    /// The result depends only on the argument values (no state, no side effects).
    pub pure: bool,
    pub source: Source,
    /// The manual chapter (for manual entries).
    pub section: Option<String>,
    pub summary: String,
    pub doc: String,
    /// How damaged or contradictory manual text was resolved.
    pub note: Option<String>,
}

/// How a data type is built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum TypeKind {
    Atomic,
    Record,
    Alias,
}

/// Value, semi-value or non-value data type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ValueClass {
    Value,
    SemiValue,
    NonValue,
}

/// One component of a record type.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Component {
    pub name: String,
    #[serde(rename = "type")]
    pub ty: String,
    /// Not in the RobotWare-OS 4.0 manual: added by a later RobotWare version.
    pub later: bool,
}

/// A built-in data type.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DataType {
    pub name: String,
    pub kind: TypeKind,
    pub alias_of: Option<String>,
    pub components: Vec<Component>,
    pub value_class: Option<ValueClass>,
    pub source: Source,
    pub section: Option<String>,
    pub summary: String,
    pub doc: String,
    pub note: Option<String>,
}

/// Declaration kind of predefined data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "UPPERCASE")]
pub enum DatumKind {
    Const,
    Var,
    Pers,
}

impl DatumKind {
    /// The keyword as RAPID writes it.
    pub fn keyword(self) -> &'static str {
        match self {
            DatumKind::Const => "CONST",
            DatumKind::Var => "VAR",
            DatumKind::Pers => "PERS",
        }
    }
}

/// A predefined data object.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Datum {
    pub name: String,
    #[serde(rename = "type")]
    pub ty: String,
    pub kind: DatumKind,
    /// The value as a RAPID literal or aggregate, where known.
    pub value: Option<String>,
    pub source: Source,
    pub section: Option<String>,
    pub summary: String,
    pub note: Option<String>,
}

/// A routine that the catalogue deliberately leaves out (option or vendor package).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OptionRoutine {
    pub name: String,
    /// The RobotWare option or vendor package that provides it.
    pub package: String,
    pub reason: String,
}

/// The whole catalogue.
#[derive(Debug, Default, Serialize)]
pub struct Catalogue {
    pub functions: Vec<Routine>,
    pub instructions: Vec<Routine>,
    pub datatypes: Vec<DataType>,
    pub data: Vec<Datum>,
    #[serde(skip)]
    index: Index,
}

#[derive(Debug, Default)]
struct Index {
    functions: NameMap<usize>,
    instructions: NameMap<usize>,
    datatypes: NameMap<usize>,
    data: NameMap<usize>,
}

/// The shared catalogue, parsed on first use.
pub fn catalogue() -> &'static Catalogue {
    static CATALOGUE: OnceLock<Catalogue> = OnceLock::new();
    CATALOGUE.get_or_init(|| {
        // The sources are embedded and checked by the tests; should they ever fail to
        // parse, an empty catalogue keeps every caller working.
        Catalogue::load().unwrap_or_default()
    })
}

impl Catalogue {
    /// Parses the embedded TOML sources.
    pub fn load() -> Result<Catalogue, String> {
        let mut cat = Catalogue::default();
        for (file, text) in SOURCES {
            let file_data: raw::File = toml::from_str(text).map_err(|e| format!("{file}: {e}"))?;
            for f in file_data.function {
                cat.functions.push(f.into_routine(true)?);
            }
            for i in file_data.instruction {
                cat.instructions.push(i.into_routine(false)?);
            }
            for t in file_data.datatype {
                cat.datatypes.push(t.into_datatype()?);
            }
            for d in file_data.datum {
                cat.data.push(d.into_datum());
            }
        }
        cat.index = Index {
            functions: index(&cat.functions, |r| &r.name),
            instructions: index(&cat.instructions, |r| &r.name),
            datatypes: index(&cat.datatypes, |t| &t.name),
            data: index(&cat.data, |d| &d.name),
        };
        Ok(cat)
    }

    /// A built-in function by name (case-insensitive).
    pub fn function(&self, name: &str) -> Option<&Routine> {
        lookup(&self.index.functions, &self.functions, name)
    }

    /// A built-in instruction (procedure) by name (case-insensitive).
    pub fn instruction(&self, name: &str) -> Option<&Routine> {
        lookup(&self.index.instructions, &self.instructions, name)
    }

    /// A built-in function or instruction by name (case-insensitive); functions first.
    pub fn routine(&self, name: &str) -> Option<&Routine> {
        self.function(name).or_else(|| self.instruction(name))
    }

    /// A built-in data type by name (case-insensitive).
    pub fn datatype(&self, name: &str) -> Option<&DataType> {
        lookup(&self.index.datatypes, &self.datatypes, name)
    }

    /// A predefined data object by name (case-insensitive).
    pub fn datum(&self, name: &str) -> Option<&Datum> {
        lookup(&self.index.data, &self.data, name)
    }

    /// Follows alias types to the type they stand for (`errnum` -> `num`,
    /// `wzstationary` -> `wztemporary`). Unknown names are returned unchanged.
    pub fn resolve_alias<'a>(&'a self, name: &'a str) -> &'a str {
        let mut current = name;
        // Bounded: alias chains are short and a cycle must not hang the caller.
        for _ in 0..8 {
            match self.datatype(current).and_then(|t| t.alias_of.as_deref()) {
                Some(next) => current = next,
                None => break,
            }
        }
        current
    }

    /// Checks the catalogue against itself; returns one message per problem.
    pub fn check(&self) -> Vec<String> {
        let mut problems = Vec::new();
        let type_known = |ty: &str| ty == ANYTYPE || self.datatype(ty).is_some();

        let mut seen: HashMap<String, &str> = HashMap::new();
        let mut unique = |name: &str, what: &'static str, problems: &mut Vec<String>| {
            if let Some(prev) = seen.insert(name.to_lowercase(), what) {
                problems.push(format!("{what} `{name}`: name already used by a {prev}"));
            }
        };
        for r in &self.functions {
            unique(&r.name, "function", &mut problems);
        }
        for r in &self.instructions {
            unique(&r.name, "instruction", &mut problems);
        }
        for t in &self.datatypes {
            unique(&t.name, "data type", &mut problems);
        }
        for d in &self.data {
            unique(&d.name, "datum", &mut problems);
        }

        for r in self.functions.iter().chain(&self.instructions) {
            if let Some(ret) = &r.returns
                && !type_known(ret)
            {
                problems.push(format!("{}: unknown return type `{ret}`", r.name));
            }
            let mut names: HashMap<String, ()> = HashMap::new();
            for p in &r.params {
                if !type_known(&p.ty) {
                    problems.push(format!(
                        "{}: parameter {}: unknown type `{}`",
                        r.name, p.name, p.ty
                    ));
                }
                if names.insert(p.name.to_lowercase(), ()).is_some() {
                    problems.push(format!("{}: duplicate parameter {}", r.name, p.name));
                }
                if p.switch && (p.ty != "switch" || p.mode.is_some() || !p.optional) {
                    problems.push(format!(
                        "{}: switch {} must be optional, of type switch, without mode",
                        r.name, p.name
                    ));
                }
                if !p.switch && (p.mode.is_none() || p.ty == "switch") {
                    problems.push(format!(
                        "{}: parameter {} needs a mode and a non-switch type",
                        r.name, p.name
                    ));
                }
                if p.array > 3 {
                    problems.push(format!(
                        "{}: parameter {} has {} dimensions",
                        r.name, p.name, p.array
                    ));
                }
            }
            for g in &r.alt_groups {
                let members: Vec<usize> = r
                    .params
                    .iter()
                    .enumerate()
                    .filter(|(_, p)| p.alt_group == Some(g.id))
                    .map(|(i, _)| i)
                    .collect();
                if members.len() < 2 {
                    problems.push(format!(
                        "{}: alternative group {} has fewer than 2 members",
                        r.name, g.id
                    ));
                }
                if members.windows(2).any(|w| w[1] != w[0] + 1) {
                    problems.push(format!(
                        "{}: members of alternative group {} are not adjacent",
                        r.name, g.id
                    ));
                }
                let optional: Vec<bool> = members.iter().map(|&i| r.params[i].optional).collect();
                if optional.iter().any(|&o| o != optional[0]) {
                    problems.push(format!(
                        "{}: alternative group {} mixes optional and required",
                        r.name, g.id
                    ));
                }
                if !optional.first().copied().unwrap_or(true) {
                    problems.push(format!(
                        "{}: alternatives of group {} must be written optional (`\\`); use required_alts",
                        r.name, g.id
                    ));
                }
            }
        }

        for t in &self.datatypes {
            match t.kind {
                TypeKind::Alias => match &t.alias_of {
                    Some(target) if self.datatype(target).is_some() => {
                        if self.resolve_alias(&t.name).eq_ignore_ascii_case(&t.name) {
                            problems.push(format!("type {}: alias cycle", t.name));
                        }
                    }
                    Some(target) => {
                        problems.push(format!("type {}: alias of unknown `{target}`", t.name))
                    }
                    None => problems.push(format!("type {}: alias without alias_of", t.name)),
                },
                TypeKind::Record => {
                    if t.components.is_empty() {
                        problems.push(format!("type {}: record without components", t.name));
                    }
                    if t.alias_of.is_some() {
                        problems.push(format!("type {}: record with alias_of", t.name));
                    }
                }
                TypeKind::Atomic => {
                    if !t.components.is_empty() || t.alias_of.is_some() {
                        problems.push(format!(
                            "type {}: atomic with components or alias_of",
                            t.name
                        ));
                    }
                }
            }
            let mut names: HashMap<String, ()> = HashMap::new();
            for c in &t.components {
                if self.datatype(&c.ty).is_none() {
                    problems.push(format!(
                        "type {}: component {}: unknown type `{}`",
                        t.name, c.name, c.ty
                    ));
                }
                if names.insert(c.name.to_lowercase(), ()).is_some() {
                    problems.push(format!("type {}: duplicate component {}", t.name, c.name));
                }
            }
        }

        for d in &self.data {
            if self.datatype(&d.ty).is_none() {
                problems.push(format!("datum {}: unknown type `{}`", d.name, d.ty));
            }
        }
        problems
    }
}

impl Routine {
    /// Whether this is a function (has a return type).
    pub fn is_function(&self) -> bool {
        self.returns.is_some()
    }

    /// The signature written like a RAPID routine declaration, e.g.
    /// `FUNC num Round(num Val, \num Dec)` or
    /// `PROC MoveL(\switch Conc, robtarget ToPoint, ..., \num V | \num T, ...)`.
    ///
    /// Optional parameters carry `\` (as the caller writes them); mutually exclusive
    /// alternatives are joined by ` | ` (whether one of them is required is in
    /// [`Routine::alt_groups`]); arrays get `{*}`; modes other than IN precede the type.
    pub fn signature(&self) -> String {
        let mut out = String::new();
        match &self.returns {
            Some(ret) => {
                let _ = write!(out, "FUNC {ret} {}(", self.name);
            }
            None => {
                let _ = write!(out, "PROC {}(", self.name);
            }
        }
        let mut first = true;
        let mut prev_group: Option<u32> = None;
        for p in &self.params {
            let same_group = p.alt_group.is_some() && p.alt_group == prev_group;
            if same_group {
                out.push_str(" | ");
            } else if !first {
                out.push_str(", ");
            }
            first = false;
            prev_group = p.alt_group;
            if p.optional {
                out.push('\\');
            }
            if let Some(mode) = p.mode
                && mode != Mode::In
            {
                out.push_str(mode.keyword());
                out.push(' ');
            }
            out.push_str(&p.ty);
            out.push(' ');
            out.push_str(&p.name);
            if p.array > 0 {
                out.push('{');
                for i in 0..p.array {
                    if i > 0 {
                        out.push(',');
                    }
                    out.push('*');
                }
                out.push('}');
            }
        }
        out.push(')');
        out
    }
}

impl DataType {
    /// A one-line description of the type's shape, e.g. `RECORD pos (num x, num y, num z)`.
    pub fn signature(&self) -> String {
        match self.kind {
            TypeKind::Atomic => format!("ATOMIC {}", self.name),
            TypeKind::Alias => {
                format!(
                    "ALIAS {} {}",
                    self.alias_of.as_deref().unwrap_or("?"),
                    self.name
                )
            }
            TypeKind::Record => {
                let comps: Vec<String> = self
                    .components
                    .iter()
                    .map(|c| format!("{} {}", c.ty, c.name))
                    .collect();
                format!("RECORD {} ({})", self.name, comps.join(", "))
            }
        }
    }
}

impl Datum {
    /// The declaration as RAPID writes it, e.g. `CONST num pi := 3.1415926`.
    pub fn signature(&self) -> String {
        match &self.value {
            Some(v) => format!("{} {} {} := {v}", self.kind.keyword(), self.ty, self.name),
            None => format!("{} {} {}", self.kind.keyword(), self.ty, self.name),
        }
    }
}

/// The reviewed list of option/vendor routines that are intentionally not catalogued.
pub fn option_routines() -> Result<Vec<OptionRoutine>, String> {
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    struct File {
        #[serde(default)]
        routine: Vec<OptionRoutine>,
    }
    toml::from_str::<File>(OPTION_ROUTINES_TOML)
        .map(|f| f.routine)
        .map_err(|e| format!("option_routines.toml: {e}"))
}

fn index<T>(items: &[T], name: impl Fn(&T) -> &String) -> NameMap<usize> {
    let mut map = NameMap::with_capacity_and_hasher(items.len(), Default::default());
    for (i, item) in items.iter().enumerate() {
        // Keep the first on duplicates; `check` reports them.
        map.entry(name(item).to_lowercase()).or_insert(i);
    }
    map
}

fn lookup<'a, T>(map: &NameMap<usize>, items: &'a [T], name: &str) -> Option<&'a T> {
    // Catalogue names are ASCII; other names keep the Unicode lowercasing.
    let index = if name.is_ascii() {
        crate::names::with_folded(name, |key| map.get(key).copied())
    } else {
        map.get(&name.to_lowercase()).copied()
    };
    index.and_then(|i| items.get(i))
}

#[cfg(test)]
mod tests;
