//! What other modules see of a file ([`Interface`]) and what constant
//! evaluation reads of it ([`Constants`]): projections of the item tree
//! without positions, whose derived hashes are the cache keys of
//! cross-module invalidation.
//!
//! The projections destructure every item struct in full, so a field added
//! to an item must be placed here (seen by other modules, or not) before
//! the crate compiles again.

use std::hash::{Hash, Hasher};

use super::{
    AliasDecl, DataDecl, FileItems, Module, ModuleAttributes, ParamDecl, RecordDecl, RoutineDecl,
    RoutineKind, Scope, Storage, TypeRef,
};
use crate::catalogue::Mode;
use crate::names::fold;

/// Everything other modules can see of a file, without positions, names
/// folded.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Interface {
    pub modules: Vec<ModuleInterface>,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ModuleInterface {
    pub name: String,
    pub attributes: ModuleAttributes,
    pub data: Vec<DataInterface>,
    pub routines: Vec<RoutineInterface>,
    pub records: Vec<RecordInterface>,
    pub aliases: Vec<AliasInterface>,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct DataInterface {
    pub name: String,
    pub scope: Scope,
    pub storage: Storage,
    pub ty: Option<String>,
    /// How many dimensions (their sizes are in [`Constants`]).
    pub rank: usize,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RoutineInterface {
    pub kind: RoutineKind,
    pub name: String,
    pub local: bool,
    pub returns: Option<String>,
    pub params: Vec<ParamInterface>,
    pub alt_groups: u32,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ParamInterface {
    pub name: String,
    pub ty: Option<String>,
    pub mode: Mode,
    pub optional: bool,
    pub switch: bool,
    pub dims: u8,
    pub alt_group: Option<u32>,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RecordInterface {
    pub name: String,
    pub local: bool,
    /// Each component's name and type.
    pub components: Vec<(String, Option<String>)>,
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct AliasInterface {
    pub name: String,
    pub local: bool,
    pub of: Option<String>,
}

/// What constant evaluation reads of a file beyond its interface: the
/// initial values of its `CONST` data and the dimensions of all its module
/// data, as written.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Constants {
    /// Each `CONST` with an initial value: its folded name and the value's
    /// text.
    pub values: Vec<(String, Option<String>)>,
    /// Each array datum's folded name and dimension expressions.
    pub dims: Vec<(String, Vec<Option<String>>)>,
}

/// The derived hash of a cache key.
pub fn hash_of(key: &impl Hash) -> u64 {
    let mut h = std::hash::DefaultHasher::new();
    key.hash(&mut h);
    h.finish()
}

fn type_name(ty: Option<&TypeRef>) -> Option<String> {
    ty.map(|TypeRef { name, range: _ }| fold(name))
}

impl FileItems {
    /// What other modules can see of this file.
    pub fn interface(&self) -> Interface {
        Interface {
            modules: self.modules.iter().map(module_interface).collect(),
        }
    }

    /// A hash of [`FileItems::interface`]: equal hashes mean other modules
    /// need not be checked again.
    pub fn interface_hash(&self) -> u64 {
        hash_of(&self.interface())
    }

    /// What constant evaluation reads of this file, whose `text` it is.
    pub fn constants(&self, text: &str) -> Constants {
        let mut out = Constants::default();
        for d in self.modules.iter().flat_map(|m| &m.data) {
            let DataDecl {
                name,
                name_range: _,
                range: _,
                scope: _,
                storage,
                ty: _,
                dims,
                init,
            } = d;
            if *storage == Storage::Const
                && let Some(init) = init
            {
                out.values
                    .push((fold(name), text.get(init.clone()).map(str::to_owned)));
            }
            if !dims.is_empty() {
                out.dims.push((
                    fold(name),
                    dims.iter()
                        .map(|r| text.get(r.clone()).map(str::to_owned))
                        .collect(),
                ));
            }
        }
        out
    }
}

fn module_interface(m: &Module) -> ModuleInterface {
    let Module {
        name,
        name_range: _,
        range: _,
        attributes,
        data,
        routines,
        records,
        aliases,
    } = m;
    ModuleInterface {
        name: fold(name),
        attributes: *attributes,
        data: data.iter().map(data_interface).collect(),
        routines: routines.iter().map(routine_interface).collect(),
        records: records.iter().map(record_interface).collect(),
        aliases: aliases.iter().map(alias_interface).collect(),
    }
}

fn data_interface(d: &DataDecl) -> DataInterface {
    let DataDecl {
        name,
        name_range: _,
        range: _,
        scope,
        storage,
        ty,
        dims,
        // Values are in [`Constants`].
        init: _,
    } = d;
    DataInterface {
        name: fold(name),
        scope: *scope,
        storage: *storage,
        ty: type_name(ty.as_ref()),
        rank: dims.len(),
    }
}

fn routine_interface(r: &RoutineDecl) -> RoutineInterface {
    let RoutineDecl {
        kind,
        name,
        name_range: _,
        range: _,
        local,
        returns,
        params,
        alt_groups,
    } = r;
    RoutineInterface {
        kind: *kind,
        name: fold(name),
        local: *local,
        returns: type_name(returns.as_ref()),
        params: params.iter().map(param_interface).collect(),
        alt_groups: *alt_groups,
    }
}

fn param_interface(p: &ParamDecl) -> ParamInterface {
    let ParamDecl {
        name,
        name_range: _,
        ty,
        mode,
        optional,
        switch,
        dims,
        alt_group,
    } = p;
    ParamInterface {
        name: fold(name),
        ty: type_name(ty.as_ref()),
        mode: *mode,
        optional: *optional,
        switch: *switch,
        dims: *dims,
        alt_group: *alt_group,
    }
}

fn record_interface(r: &RecordDecl) -> RecordInterface {
    let RecordDecl {
        name,
        name_range: _,
        range: _,
        local,
        components,
    } = r;
    RecordInterface {
        name: fold(name),
        local: *local,
        components: components
            .iter()
            .map(|(name, ty, _)| (fold(name), type_name(ty.as_ref())))
            .collect(),
    }
}

fn alias_interface(a: &AliasDecl) -> AliasInterface {
    let AliasDecl {
        name,
        name_range: _,
        range: _,
        local,
        of,
    } = a;
    AliasInterface {
        name: fold(name),
        local: *local,
        of: type_name(of.as_ref()),
    }
}

#[cfg(test)]
mod tests;
