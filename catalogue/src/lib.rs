//! The catalogue of RAPID built-ins: functions, instructions (procedures),
//! data types and predefined data of the base language of RobotWare 5, 6 and
//! 7 and of its options, with their signatures, the RobotWare versions that
//! have them, the option package that brings them, where the facts come from
//! and short documentation in our own words.
//!
//! The data lives in reviewable TOML files under `catalogue/data/`, embedded
//! at compile time. [`Catalogue::load`] parses them; [`view`] gives the
//! catalogue as one controller sees it (a RobotWare version and its options,
//! [`Selection`]): every entry stays known, signatures and record layouts are
//! those of that version, and [`Catalogue::availability`] says whether an
//! entry needs a newer RobotWare or an option that is not installed. Lookups
//! by name are case-insensitive, as RAPID names are.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::sync::{Mutex, OnceLock};

use serde::{Deserialize, Serialize};

pub mod binding;
mod check;
pub mod names;
pub mod operators;
mod raw;
mod select;
mod version;

pub use select::Selection;
pub use version::Version;

/// The TOML sources of the base language, in the order they are loaded:
/// (file name, text).
pub const SOURCES: &[(&str, &str)] = &[
    ("functions.toml", include_str!("../data/functions.toml")),
    (
        "instructions.toml",
        include_str!("../data/instructions.toml"),
    ),
    ("datatypes.toml", include_str!("../data/datatypes.toml")),
    ("data.toml", include_str!("../data/data.toml")),
    ("listed.toml", include_str!("../data/listed.toml")),
];

/// The TOML sources of the option packages, one file per package.
pub const PACKAGE_SOURCES: &[(&str, &str)] = &include!("../data/options/list.rs");

/// The pseudo type name that accepts an argument of any data type.
pub const ANYTYPE: &str = "anytype";

/// Where an entry's facts come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Source {
    /// The RAPID reference manual part 2 (functions and data types,
    /// RobotWare-OS 4.0), the OCR text in `shared/manual`.
    Manual,
    /// The technical reference manual "RAPID Instructions, Functions and Data
    /// types" of RobotWare 5, 6 or 7.
    Reference,
    /// The technical reference manual "RAPID overview" or "RAPID kernel".
    Overview,
    /// The application manual of the option package.
    Application,
    /// Only a public extracted list of names (no documented signature): the
    /// name and its kind are known, its arguments are not checked.
    List,
}

impl Source {
    /// What the source is, for people.
    pub fn describe(self) -> &'static str {
        match self {
            Source::Manual => "the RAPID reference manual part 2 (RobotWare-OS 4.0)",
            Source::Reference => {
                "the technical reference manual RAPID Instructions, Functions and Data types"
            }
            Source::Overview => "the technical reference manuals RAPID overview and RAPID kernel",
            Source::Application => "the application manual of its option",
            Source::List => "public lists of RobotWare names (signature not documented there)",
        }
    }
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

/// The RobotWare versions an entry exists in, and its option package.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Origin {
    /// The first RobotWare version that has it ([`Version::FIRST`] when it
    /// exists in every version the catalogue knows).
    pub since: Version,
    /// The first RobotWare version that no longer has it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub until: Option<Version>,
    /// The option package that brings it (a [`Package::id`]); `None` for the
    /// base language.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub package: Option<String>,
    pub source: Source,
    /// The manual's chapter or section.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub section: Option<String>,
    /// How damaged, contradictory or disagreeing sources were read.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

impl Origin {
    /// `6.10-` or `5.00-7.0` (until is exclusive), for people.
    pub fn versions(&self) -> String {
        match self.until {
            Some(u) => format!("{}-{u} (removed in {u})", self.since),
            None => format!("{}-", self.since),
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
    /// The RobotWare version that added it, when later than its routine.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub since: Option<Version>,
    /// Takes an array of any number of dimensions (`Dim`'s `ArrPar`), which
    /// `array` cannot express.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub any_rank: bool,
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
    /// The parameters are documented: calls are checked against them. When
    /// false, either only the name and kind are known and `params` is
    /// empty, or `params` are those loaded code calls it with: the
    /// simulation binds calls by them, the checker checks none.
    pub signature_known: bool,
    /// The result depends only on the argument values (no state, no side effects).
    pub pure: bool,
    /// A function whose result is a computed real number (a square root, a
    /// sine), which is rarely exactly equal to another. `Pow` is not: real
    /// programs raise integers to integer powers, which a `num` holds
    /// exactly.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub real_valued: bool,
    /// An instruction that ends the routine's execution (`ExitCycle`): no
    /// statement after it runs.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub terminates: bool,
    #[serde(flatten)]
    pub origin: Origin,
    pub summary: String,
    pub doc: String,
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
    /// The RobotWare version that added it, when later than its type.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub since: Option<Version>,
}

/// A built-in data type.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DataType {
    pub name: String,
    pub kind: TypeKind,
    pub alias_of: Option<String>,
    /// The components in order; empty for a record whose layout is not
    /// documented (see `layout_known`).
    pub components: Vec<Component>,
    /// For records: the components are documented. When false the record's
    /// components are not checked.
    pub layout_known: bool,
    pub value_class: Option<ValueClass>,
    #[serde(flatten)]
    pub origin: Origin,
    pub summary: String,
    pub doc: String,
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
    /// System data that programs read but cannot assign or pass as `INOUT`
    /// (`ERRNO`).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub read_only: bool,
    #[serde(flatten)]
    pub origin: Origin,
    pub summary: String,
}

/// A RobotWare option (or an application package that comes as one).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Package {
    /// The short name used in `rapid.toml` (`options = ["arc", "egm"]`).
    pub id: String,
    /// The option's name, for people.
    pub name: String,
    /// Texts that name this option in a controller's list of installed
    /// options (BACKINFO, system.xml): option numbers such as `689-1` and
    /// words of the option's name, matched case-insensitively.
    pub matches: Vec<String>,
    pub summary: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// Other packages (ids) that come with this option: a controller that
    /// has it has them too (RobotWare 6's PC Interface brings Socket
    /// Messaging).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub includes: Vec<String>,
}

/// The whole catalogue, or the view of it that one controller has.
#[derive(Debug, Default, Serialize)]
pub struct Catalogue {
    pub functions: Vec<Routine>,
    pub instructions: Vec<Routine>,
    pub datatypes: Vec<DataType>,
    pub data: Vec<Datum>,
    pub packages: Vec<Package>,
    /// The RobotWare version and options this view was made for.
    #[serde(skip)]
    pub selection: Selection,
    #[serde(skip)]
    index: Index,
}

#[derive(Debug, Default)]
struct Index {
    functions: HashMap<String, usize>,
    instructions: HashMap<String, usize>,
    datatypes: HashMap<String, usize>,
    data: HashMap<String, usize>,
    packages: HashMap<String, usize>,
}

/// Whether one controller has an entry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Availability<'a> {
    /// In this RobotWare version, base language or an enabled option.
    Yes,
    /// Added by a later RobotWare than the selected one.
    Newer { since: Version, selected: Version },
    /// Removed before the selected RobotWare.
    Removed { until: Version, selected: Version },
    /// Brought by an option that is not enabled.
    NeedsOption(&'a Package),
}

/// The catalogue as the controller described by `selection` has it, made
/// once per distinct selection and shared (a view is read-only).
///
/// At most [`MAX_VIEWS`] distinct views are kept; past that, the union view
/// (no version, no option) is returned.
pub fn view(selection: &Selection) -> &'static Catalogue {
    static VIEWS: OnceLock<Mutex<HashMap<Selection, &'static Catalogue>>> = OnceLock::new();
    let views = VIEWS.get_or_init(|| Mutex::new(HashMap::new()));
    let Ok(mut views) = views.lock() else {
        return base();
    };
    if let Some(v) = views.get(selection) {
        return v;
    }
    if *selection == Selection::default() {
        return base();
    }
    if views.len() >= MAX_VIEWS {
        return base();
    }
    let v: &'static Catalogue = Box::leak(Box::new(base().select(selection)));
    views.insert(selection.clone(), v);
    v
}

/// How many distinct views [`view`] keeps.
pub const MAX_VIEWS: usize = 64;

/// The whole catalogue, parsed once: every version's entries with their
/// newest signatures, every package, no option enabled. This is the view of
/// an unknown controller.
pub fn base() -> &'static Catalogue {
    static BASE: OnceLock<Catalogue> = OnceLock::new();
    BASE.get_or_init(|| {
        // The sources are embedded and checked by the tests; should they ever
        // fail to parse, an empty catalogue keeps every caller working.
        Catalogue::load().unwrap_or_default()
    })
}

impl Catalogue {
    /// Parses the embedded TOML sources.
    pub fn load() -> Result<Catalogue, String> {
        let mut cat = Catalogue::default();
        for (file, text) in SOURCES.iter().chain(PACKAGE_SOURCES) {
            raw::load_file(&mut cat, file, text)?;
        }
        cat.reindex();
        Ok(cat)
    }

    /// Rebuilds the name index after the lists changed.
    pub fn reindex(&mut self) {
        self.index = Index {
            functions: index(&self.functions, |r| &r.name),
            instructions: index(&self.instructions, |r| &r.name),
            datatypes: index(&self.datatypes, |t| &t.name),
            data: index(&self.data, |d| &d.name),
            packages: index(&self.packages, |p| &p.id),
        };
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

    /// An option package by id (case-insensitive).
    pub fn package(&self, id: &str) -> Option<&Package> {
        lookup(&self.index.packages, &self.packages, id)
    }

    /// The origin of whatever built-in is called `name` (routine, type or
    /// datum, in that order).
    pub fn origin(&self, name: &str) -> Option<&Origin> {
        self.routine(name)
            .map(|r| &r.origin)
            .or_else(|| self.datatype(name).map(|t| &t.origin))
            .or_else(|| self.datum(name).map(|d| &d.origin))
    }

    /// Whether the controller this view was made for has an entry of this
    /// origin.
    pub fn availability(&self, origin: &Origin) -> Availability<'_> {
        if let Some(selected) = self.selection.robotware {
            if origin.since > selected {
                return Availability::Newer {
                    since: origin.since,
                    selected,
                };
            }
            if let Some(until) = origin.until.filter(|u| *u <= selected) {
                return Availability::Removed { until, selected };
            }
        }
        match origin.package.as_deref() {
            Some(p) if !self.selection.enabled(p) => match self.package(p) {
                Some(package) => Availability::NeedsOption(package),
                None => Availability::Yes,
            },
            _ => Availability::Yes,
        }
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
        check::check(self)
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

fn index<T>(items: &[T], name: impl Fn(&T) -> &String) -> HashMap<String, usize> {
    let mut map = HashMap::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        // Keep the first on duplicates; `check` reports them.
        map.entry(name(item).to_lowercase()).or_insert(i);
    }
    map
}

fn lookup<'a, T>(map: &HashMap<String, usize>, items: &'a [T], name: &str) -> Option<&'a T> {
    const MAX: usize = 40;
    let bytes = name.as_bytes();
    // Names of up to 40 ASCII bytes are folded on the stack (the hot path:
    // the checker looks up every name it meets).
    let index = if name.is_ascii() && bytes.len() <= MAX {
        let mut buf = [0u8; MAX];
        let out = &mut buf[..bytes.len()];
        out.copy_from_slice(bytes);
        out.make_ascii_lowercase();
        std::str::from_utf8(out)
            .ok()
            .and_then(|key| map.get(key).copied())
    } else {
        map.get(&name.to_lowercase()).copied()
    };
    index.and_then(|i| items.get(i))
}

#[cfg(test)]
mod tests;

impl Catalogue {
    /// The reference page `docs/catalogue.md`: one line per entry (name,
    /// kind, RobotWare versions, package), then the packages.
    pub fn reference_page(&self) -> String {
        let mut out = String::from(
            "# Catalogue reference\n\n\
             Generated from `catalogue/data/` by `Catalogue::reference_page`; do not edit \
             (`RAPID_BLESS=1 cargo test -p rapid-catalogue reference_page` rewrites it). \
             Versions are RobotWare versions: `5.00-` means from 5.0 (or earlier) on; \
             `-7.0` means removed in 7.0. `rapid builtins NAME` shows an entry in full.\n\n\
             | Name | Kind | RobotWare | Package |\n|---|---|---|---|\n",
        );
        let mut rows: Vec<(String, &str, &Origin)> = Vec::new();
        for r in &self.functions {
            rows.push((r.name.clone(), "function", &r.origin));
        }
        for r in &self.instructions {
            rows.push((r.name.clone(), "instruction", &r.origin));
        }
        for t in &self.datatypes {
            rows.push((t.name.clone(), "data type", &t.origin));
        }
        for d in &self.data {
            rows.push((d.name.clone(), d.kind.keyword(), &d.origin));
        }
        rows.sort_by(|a, b| {
            a.0.to_lowercase()
                .cmp(&b.0.to_lowercase())
                .then(a.1.cmp(b.1))
        });
        for (name, kind, o) in rows {
            let _ = writeln!(
                out,
                "| `{name}` | {kind} | {} | {} |",
                o.versions(),
                o.package.as_deref().unwrap_or("base")
            );
        }
        out.push_str(
            "\n## Packages\n\n| Id | Option | Found in a backup by | Brings |\n|---|---|---|---|\n",
        );
        for p in &self.packages {
            let brings: Vec<String> = p.includes.iter().map(|i| format!("`{i}`")).collect();
            let _ = writeln!(
                out,
                "| `{}` | {} | {} | {} |",
                p.id,
                p.name,
                p.matches.join(", "),
                brings.join(", ")
            );
        }
        out
    }
}
