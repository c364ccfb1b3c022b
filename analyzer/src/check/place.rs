//! Where a value lives (variable, persistent, constant, parameter,
//! read-only system data), for the parameter-mode checks.

use crate::catalogue::{DatumKind, Mode};
use crate::items::Storage;
use crate::sema::def::Def;
use crate::task::Task;

/// Where a value lives, for the parameter-mode check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Place {
    Var,
    Pers,
    Const,
    ForVar,
    Param(Mode),
    /// Read-only system data such as `ERRNO`.
    ReadOnly,
    /// Not a data reference at all: a literal, a call, an operation.
    Value,
    /// Unresolved: say nothing.
    Unknown,
}

impl Place {
    /// Where the data a name resolved to lives.
    pub(crate) fn of(def: &Def<'_>, task: &Task) -> Place {
        match def {
            Def::Param { decl, .. } => Place::Param(decl.mode),
            Def::Local { .. } | Def::Item(_) => match def.data_decl(task).map(|d| d.storage) {
                Some(Storage::Var) => Place::Var,
                Some(Storage::Pers) => Place::Pers,
                Some(Storage::Const) => Place::Const,
                None => Place::Unknown,
            },
            Def::ForVar { .. } => Place::ForVar,
            Def::BuiltinDatum(d) => match d.kind {
                DatumKind::Const => Place::Const,
                DatumKind::Pers => Place::Pers,
                DatumKind::Var if d.read_only => Place::ReadOnly,
                DatumKind::Var => Place::Var,
            },
            Def::Signal(..) => Place::Var,
            _ => Place::Unknown,
        }
    }

    pub(crate) fn describe(self) -> &'static str {
        match self {
            Place::Var => "a variable",
            Place::Pers => "a persistent",
            Place::Const => "a constant",
            Place::ForVar => "a FOR loop variable",
            Place::Param(Mode::In) => "an input parameter",
            Place::Param(_) => "a reference parameter",
            Place::ReadOnly => "read-only system data",
            Place::Value => "a value",
            Place::Unknown => "unknown",
        }
    }
}
