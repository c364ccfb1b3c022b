//! Where a value lives (variable, persistent, constant, parameter,
//! read-only system data), for the parameter-mode checks.

use super::DataSym;
use crate::catalogue::{DatumKind, Mode};
use crate::items::{DataDecl, Storage};

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
    pub(crate) fn of(sym: &DataSym<'_>) -> Place {
        match sym {
            DataSym::Param(p) => Place::Param(p.mode),
            DataSym::Local(DataDecl { storage, .. })
            | DataSym::Module(DataDecl { storage, .. }, _) => match storage {
                Storage::Var => Place::Var,
                Storage::Pers => Place::Pers,
                Storage::Const => Place::Const,
            },
            DataSym::ForVar => Place::ForVar,
            DataSym::Builtin(d) => match d.kind {
                DatumKind::Const => Place::Const,
                DatumKind::Pers => Place::Pers,
                DatumKind::Var if d.read_only => Place::ReadOnly,
                DatumKind::Var => Place::Var,
            },
            DataSym::Signal(_) => Place::Var,
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
