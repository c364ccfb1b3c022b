//! What a name denotes: one [`Def`] for every kind of declaration, with
//! where it is declared. The resolver ([`super::scope::Scope`]) answers
//! with it; the checker reads the declaration and the type from it, the
//! editor features its location and identity.

use std::ops::Range;

use crate::catalogue::{DataType, Datum, Routine};
use crate::items::{DataDecl, ParamDecl, RoutineDecl};
use crate::names::fold;
use crate::task::{Item, ItemRef, Task};
use crate::ty::{Ty, Types};

/// A declaration a name resolves to.
#[derive(Clone, Debug)]
pub(crate) enum Def<'t> {
    /// A module's data, routine, record or alias.
    Item(ItemRef),
    /// A parameter of `routine`, declared in unit `unit`.
    Param {
        unit: usize,
        decl: &'t ParamDecl,
        routine: &'t RoutineDecl,
    },
    /// Routine data.
    Local {
        unit: usize,
        decl: DataDecl,
        routine: &'t RoutineDecl,
    },
    /// A `FOR` loop variable: its name's range in its loop.
    ForVar {
        unit: usize,
        range: Range<usize>,
    },
    /// A label: its name's range.
    Label {
        unit: usize,
        name: String,
        range: Range<usize>,
    },
    /// Component `index` of a user record.
    Component(ItemRef, usize),
    /// Component `index` of a built-in record type.
    BuiltinComponent(&'static DataType, usize),
    Module {
        unit: usize,
        module: usize,
    },
    BuiltinRoutine(&'static Routine),
    /// Parameter `index` of a built-in routine.
    BuiltinParam(&'static Routine, usize),
    BuiltinDatum(&'static Datum),
    BuiltinType(&'static DataType),
    /// An I/O signal from the configuration, with its type.
    Signal(String, &'static str),
}

impl<'t> Def<'t> {
    /// The declaration of data (module or routine data).
    pub(crate) fn data_decl<'a>(&'a self, task: &'t Task) -> Option<&'a DataDecl>
    where
        't: 'a,
    {
        match self {
            Def::Item(r) => task.data(*r),
            Def::Local { decl, .. } => Some(decl),
            _ => None,
        }
    }

    /// The declaration of a routine of the task.
    pub(crate) fn routine_decl(&self, task: &'t Task) -> Option<&'t RoutineDecl> {
        match self {
            Def::Item(r) => task.routine(*r),
            _ => None,
        }
    }

    /// The type of data, a parameter, a `FOR` variable or a configured
    /// name; a type name the task does not know is unknown (reported once
    /// where it is declared), so nothing else is reported against it.
    pub(crate) fn ty(&self, task: &Task, types: &Types<'_>) -> Ty {
        let ty = match self {
            Def::Param { decl: p, .. } => {
                p.ty.as_ref()
                    .map_or(Ty::Unknown, |t| Ty::named(&t.name))
                    .array(p.dims)
            }
            Def::Local { decl, .. } => decl_ty(decl),
            Def::Item(r) => task.data(*r).map_or(Ty::Unknown, decl_ty),
            Def::ForVar { .. } => Ty::num(),
            Def::BuiltinDatum(d) => Ty::named(&d.ty),
            Def::Signal(_, ty) => Ty::named(ty),
            _ => Ty::Unknown,
        };
        if types.is_known(&ty) { ty } else { Ty::Unknown }
    }
}

/// The declared type of data.
pub(crate) fn decl_ty(d: &DataDecl) -> Ty {
    let dims = u8::try_from(d.dims.len()).unwrap_or(u8::MAX);
    d.ty.as_ref()
        .map_or(Ty::Unknown, |t| Ty::named(&t.name))
        .array(dims)
}

/// The identity of a declaration, to compare resolutions.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) enum DefKey {
    /// Declared in the task: unit and start of the name.
    At(usize, usize),
    /// Built in or configured: a kind letter and the folded name.
    Named(char, String),
}

impl Def<'_> {
    /// Where the declaration is: unit, name range, whole declaration.
    pub(crate) fn location(&self, task: &Task) -> Option<(usize, Range<usize>, Range<usize>)> {
        match self {
            Def::Item(r) => {
                let (_, name) = task.item_name(*r)?;
                let m = task.module(*r)?;
                let full = match r.item {
                    Item::Data(i) => m.data.get(i)?.range.clone(),
                    Item::Routine(i) => m.routines.get(i)?.range.clone(),
                    Item::Record(i) => m.records.get(i)?.range.clone(),
                    Item::Alias(i) => m.aliases.get(i)?.range.clone(),
                };
                Some((r.unit, name, full))
            }
            Def::Param { unit, decl, .. } => {
                Some((*unit, decl.name_range.clone(), decl.name_range.clone()))
            }
            Def::Local { unit, decl, .. } => {
                Some((*unit, decl.name_range.clone(), decl.range.clone()))
            }
            Def::ForVar { unit, range, .. } | Def::Label { unit, range, .. } => {
                Some((*unit, range.clone(), range.clone()))
            }
            Def::Component(r, i) => {
                let rec = task.record(*r)?;
                let (_, _, range) = rec.components.get(*i)?;
                Some((r.unit, range.clone(), range.clone()))
            }
            Def::Module { unit, module } => {
                let m = task.unit(*unit)?.items.modules.get(*module)?;
                Some((*unit, m.name_range.clone(), m.range.clone()))
            }
            _ => None,
        }
    }

    pub(crate) fn key(&self, task: &Task) -> DefKey {
        if let Some((unit, range, _)) = self.location(task) {
            return DefKey::At(unit, range.start);
        }
        match self {
            Def::BuiltinRoutine(r) => DefKey::Named('r', fold(&r.name)),
            Def::BuiltinParam(r, i) => DefKey::Named('p', format!("{}.{i}", fold(&r.name))),
            Def::BuiltinDatum(d) => DefKey::Named('d', fold(&d.name)),
            Def::BuiltinType(t) => DefKey::Named('t', fold(&t.name)),
            Def::BuiltinComponent(t, i) => DefKey::Named('c', format!("{}.{i}", fold(&t.name))),
            Def::Signal(n, _) => DefKey::Named('s', fold(n)),
            _ => DefKey::Named('?', String::new()),
        }
    }

    pub(crate) fn is_builtin(&self) -> bool {
        matches!(
            self,
            Def::BuiltinRoutine(_)
                | Def::BuiltinParam(..)
                | Def::BuiltinDatum(_)
                | Def::BuiltinType(_)
                | Def::BuiltinComponent(..)
        )
    }

    /// The declared name.
    pub(crate) fn name(&self, task: &Task) -> String {
        match self {
            Def::Item(r) => task
                .item_name(*r)
                .map(|(n, _)| n.to_owned())
                .unwrap_or_default(),
            Def::Param { decl, .. } => decl.name.clone(),
            Def::Local { decl, .. } => decl.name.clone(),
            Def::ForVar { unit, range } => task
                .units
                .get(*unit)
                .and_then(|u| u.text.get(range.clone()))
                .unwrap_or_default()
                .to_owned(),
            Def::Label { name, .. } | Def::Signal(name, _) => name.clone(),
            Def::Component(r, i) => task
                .record(*r)
                .and_then(|rec| rec.components.get(*i))
                .map(|c| c.0.clone())
                .unwrap_or_default(),
            Def::BuiltinComponent(t, i) => t
                .components
                .get(*i)
                .map(|c| c.name.clone())
                .unwrap_or_default(),
            Def::Module { unit, module } => task
                .units
                .get(*unit)
                .and_then(|u| u.items.modules.get(*module))
                .map(|m| m.name.clone())
                .unwrap_or_default(),
            Def::BuiltinRoutine(r) => r.name.clone(),
            Def::BuiltinParam(r, i) => r.params.get(*i).map(|p| p.name.clone()).unwrap_or_default(),
            Def::BuiltinDatum(d) => d.name.clone(),
            Def::BuiltinType(t) => t.name.clone(),
        }
    }
}
