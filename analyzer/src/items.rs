//! The item tree of a file: its modules and their declarations (data,
//! routines with their signatures, records, aliases), without routine bodies.
//!
//! This is the per-module summary the design asks for: other modules see a
//! module only through it ([`FileItems::interface`]), which has no
//! positions, so typing inside a routine body changes nothing that another
//! module depends on.

use std::ops::Range;

use tree_sitter::{Node, Tree};

use crate::catalogue::Mode;
use crate::syntax::{field, kind};
use crate::syntax_util::{field, fields, has_token, is_placeholder, text_of};

mod interface;
pub use interface::{
    AliasInterface, Constants, DataInterface, Interface, ModuleInterface, ParamInterface,
    RecordInterface, RoutineInterface, hash_of,
};

/// The items of one file (a file may hold several modules).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FileItems {
    pub modules: Vec<Module>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Module {
    pub name: String,
    pub name_range: Range<usize>,
    pub range: Range<usize>,
    pub attributes: ModuleAttributes,
    pub data: Vec<DataDecl>,
    pub routines: Vec<RoutineDecl>,
    pub records: Vec<RecordDecl>,
    pub aliases: Vec<AliasDecl>,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ModuleAttributes {
    pub sysmodule: bool,
    pub noview: bool,
    pub nostepin: bool,
    pub viewonly: bool,
    pub readonly: bool,
}

/// Where a declaration is visible.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scope {
    /// The whole task (no prefix).
    Global,
    /// Only its own module (`LOCAL`).
    Local,
    /// A `TASK PERS`: global in the task, not shared with other tasks.
    Task,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Storage {
    Var,
    Pers,
    Const,
}

impl Storage {
    pub fn keyword(self) -> &'static str {
        match self {
            Storage::Var => "VAR",
            Storage::Pers => "PERS",
            Storage::Const => "CONST",
        }
    }
}

/// A type as written in a declaration.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TypeRef {
    pub name: String,
    pub range: Range<usize>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DataDecl {
    pub name: String,
    pub name_range: Range<usize>,
    pub range: Range<usize>,
    pub scope: Scope,
    pub storage: Storage,
    pub ty: Option<TypeRef>,
    /// The dimension expressions (`{3, 4}`), as byte ranges.
    pub dims: Vec<Range<usize>>,
    /// The initialiser expression, if any.
    pub init: Option<Range<usize>>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RoutineKind {
    Proc,
    Func,
    Trap,
}

impl RoutineKind {
    pub fn keyword(self) -> &'static str {
        match self {
            RoutineKind::Proc => "PROC",
            RoutineKind::Func => "FUNC",
            RoutineKind::Trap => "TRAP",
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct RoutineDecl {
    pub kind: RoutineKind,
    pub name: String,
    pub name_range: Range<usize>,
    pub range: Range<usize>,
    pub local: bool,
    pub returns: Option<TypeRef>,
    pub params: Vec<ParamDecl>,
    /// Required members of `|` groups are never required in RAPID: a group
    /// of optional parameters means "at most one of these".
    pub alt_groups: u32,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ParamDecl {
    pub name: String,
    pub name_range: Range<usize>,
    pub ty: Option<TypeRef>,
    pub mode: Mode,
    pub optional: bool,
    /// The parameter's type is `switch`: given as `\Name`, without a value.
    pub switch: bool,
    /// Array dimensions (`{*}` is 1).
    pub dims: u8,
    pub alt_group: Option<u32>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct RecordDecl {
    pub name: String,
    pub name_range: Range<usize>,
    pub range: Range<usize>,
    pub local: bool,
    pub components: Vec<(String, Option<TypeRef>, Range<usize>)>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct AliasDecl {
    pub name: String,
    pub name_range: Range<usize>,
    pub range: Range<usize>,
    pub local: bool,
    pub of: Option<TypeRef>,
}

impl Module {
    /// The names it declares for the whole task (every declaration but a
    /// `LOCAL` one): data, routines, records, aliases.
    pub fn global_names(&self) -> impl Iterator<Item = &str> {
        let data = self
            .data
            .iter()
            .filter(|d| d.scope != Scope::Local)
            .map(|d| d.name.as_str());
        let routines = self
            .routines
            .iter()
            .filter(|r| !r.local)
            .map(|r| r.name.as_str());
        let records = self
            .records
            .iter()
            .filter(|r| !r.local)
            .map(|r| r.name.as_str());
        let aliases = self
            .aliases
            .iter()
            .filter(|a| !a.local)
            .map(|a| a.name.as_str());
        data.chain(routines).chain(records).chain(aliases)
    }
}

impl FileItems {
    /// The index of the module whose text holds `offset` (its end included).
    pub fn module_at(&self, offset: usize) -> Option<usize> {
        self.modules
            .iter()
            .position(|m| m.range.start <= offset && offset <= m.range.end)
    }

    /// Lowers a parsed file. Placeholders and broken declarations are left
    /// out; nothing here fails.
    pub fn lower(tree: &Tree, text: &str) -> FileItems {
        let root = tree.root_node();
        let mut cursor = root.walk();
        let modules = root
            .named_children(&mut cursor)
            .filter(|n| n.kind() == kind::MODULE)
            .filter_map(|n| lower_module(n, fields(n, field::BODY), text))
            .collect();
        FileItems { modules }
    }
}

fn name_of(node: Node<'_>, text: &str) -> Option<(String, Range<usize>)> {
    let name = field(node, field::NAME)?;
    if is_placeholder(name) || name.is_missing() {
        return None;
    }
    Some((text_of(name, text).to_owned(), name.byte_range()))
}

fn type_of(node: Node<'_>, text: &str) -> Option<TypeRef> {
    let ty = field(node, field::TYPE)?;
    if is_placeholder(ty) || ty.is_missing() {
        return None;
    }
    Some(TypeRef {
        name: text_of(ty, text).to_owned(),
        range: ty.byte_range(),
    })
}

fn scope_of(node: Node<'_>) -> Scope {
    match field(node, field::SCOPE).map(|s| s.kind()) {
        Some("local") => Scope::Local,
        Some("task") => Scope::Task,
        _ => Scope::Global,
    }
}

fn lower_module<'t>(node: Node<'t>, body: Vec<Node<'t>>, text: &str) -> Option<Module> {
    let (name, name_range) = name_of(node, text)?;
    let mut attributes = ModuleAttributes::default();
    if let Some(attrs) = field(node, field::ATTRIBUTES) {
        for attr in fields(attrs, field::ATTRIBUTE) {
            match text_of(attr, text).to_ascii_uppercase().as_str() {
                "SYSMODULE" => attributes.sysmodule = true,
                "NOVIEW" => attributes.noview = true,
                "NOSTEPIN" => attributes.nostepin = true,
                "VIEWONLY" => attributes.viewonly = true,
                "READONLY" => attributes.readonly = true,
                _ => {}
            }
        }
    }
    let mut module = Module {
        name,
        name_range,
        range: node.byte_range(),
        attributes,
        data: Vec::new(),
        routines: Vec::new(),
        records: Vec::new(),
        aliases: Vec::new(),
    };
    for item in body {
        match item.kind() {
            kind::DATA_DECLARATION => module.data.extend(lower_data(item, text)),
            kind::PROCEDURE_DECLARATION | kind::FUNCTION_DECLARATION | kind::TRAP_DECLARATION => {
                module.routines.extend(lower_routine(item, text));
            }
            kind::RECORD_DECLARATION => module.records.extend(lower_record(item, text)),
            kind::ALIAS_DECLARATION => module.aliases.extend(lower_alias(item, text)),
            _ => {}
        }
    }
    Some(module)
}

/// Lowers a data declaration (of a module or of a routine).
pub fn lower_data(node: Node<'_>, text: &str) -> Option<DataDecl> {
    let (name, name_range) = name_of(node, text)?;
    let storage = match field(node, field::STORAGE)?.kind() {
        "var" => Storage::Var,
        "pers" => Storage::Pers,
        "const" => Storage::Const,
        _ => return None,
    };
    let dims = field(node, field::DIMENSIONS)
        .map(|d| {
            fields(d, field::DIMENSION)
                .iter()
                .map(|n| n.byte_range())
                .collect()
        })
        .unwrap_or_default();
    Some(DataDecl {
        name,
        name_range,
        range: node.byte_range(),
        scope: scope_of(node),
        storage,
        ty: type_of(node, text),
        dims,
        init: field(node, field::VALUE).map(|v| v.byte_range()),
    })
}

fn lower_routine(node: Node<'_>, text: &str) -> Option<RoutineDecl> {
    let (name, name_range) = name_of(node, text)?;
    let kind = match node.kind() {
        kind::PROCEDURE_DECLARATION => RoutineKind::Proc,
        kind::FUNCTION_DECLARATION => RoutineKind::Func,
        _ => RoutineKind::Trap,
    };
    let mut params = Vec::new();
    let mut alt_groups = 0;
    if let Some(list) = field(node, field::PARAMETERS) {
        for p in fields(list, field::PARAMETER) {
            match p.kind() {
                kind::PARAMETER => params.extend(lower_param(p, text, false, None)),
                kind::OPTIONAL_PARAMETER => {
                    let alternatives: Vec<_> = fields(p, field::ALTERNATIVE)
                        .into_iter()
                        .filter(|a| a.kind() == kind::PARAMETER)
                        .collect();
                    let group = (alternatives.len() > 1).then(|| {
                        alt_groups += 1;
                        alt_groups
                    });
                    for a in alternatives {
                        params.extend(lower_param(a, text, true, group));
                    }
                }
                _ => {}
            }
        }
    }
    Some(RoutineDecl {
        kind,
        name,
        name_range,
        range: node.byte_range(),
        local: scope_of(node) == Scope::Local,
        returns: (kind == RoutineKind::Func)
            .then(|| type_of(node, text))
            .flatten(),
        params,
        alt_groups,
    })
}

fn lower_param(
    node: Node<'_>,
    text: &str,
    optional: bool,
    alt_group: Option<u32>,
) -> Option<ParamDecl> {
    let (name, name_range) = name_of(node, text)?;
    let ty = type_of(node, text);
    let mode = match field(node, field::MODE).map(|m| m.kind()) {
        Some("var") => Mode::Var,
        Some("pers") => Mode::Pers,
        Some("inout") => Mode::InOut,
        _ => Mode::In,
    };
    let dims = field(node, field::DIMENSIONS).map_or(0, |d| {
        let mut cursor = d.walk();
        let n = d.children(&mut cursor).filter(|c| c.kind() == "*").count();
        u8::try_from(n).unwrap_or(u8::MAX)
    });
    let switch = ty
        .as_ref()
        .is_some_and(|t| t.name.eq_ignore_ascii_case("switch"));
    Some(ParamDecl {
        name,
        name_range,
        ty,
        mode,
        optional,
        switch,
        dims,
        alt_group,
    })
}

fn lower_record(node: Node<'_>, text: &str) -> Option<RecordDecl> {
    let (name, name_range) = name_of(node, text)?;
    let components = fields(node, field::COMPONENT)
        .into_iter()
        .filter_map(|c| {
            let (n, r) = name_of(c, text)?;
            Some((n, type_of(c, text), r))
        })
        .collect();
    Some(RecordDecl {
        name,
        name_range,
        range: node.byte_range(),
        local: has_token(node, "local"),
        components,
    })
}

fn lower_alias(node: Node<'_>, text: &str) -> Option<AliasDecl> {
    let (name, name_range) = name_of(node, text)?;
    Some(AliasDecl {
        name,
        name_range,
        range: node.byte_range(),
        local: has_token(node, "local"),
        of: type_of(node, text),
    })
}
