//! A routine's signature, built-in or declared, and the binding of a call's
//! arguments to its parameters, as data: the checker reports from it,
//! signature help, completion and the constant evaluator read it.

use crate::catalogue::{ANYTYPE, AltGroup, Mode, Routine};
use crate::items::{RoutineDecl, RoutineKind};
use crate::names::same;
use crate::sema::def::Def;
use crate::task::Task;
use crate::ty::Ty;

/// A parameter, of a built-in or a user routine.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Param {
    pub name: String,
    /// The parameter's type with its dimensions: `switch` for switches,
    /// [`Ty::Any`] for `anytype`, [`Ty::Unknown`] when the declaration
    /// names none.
    pub ty: Ty,
    /// The element type's name as written (`anytype`, `switch`), empty when
    /// the declaration names none.
    pub type_name: String,
    pub mode: Mode,
    /// Written `\Name`: may be left out.
    pub optional: bool,
    /// Given as `\Name` without a value.
    pub switch: bool,
    /// Members of one `|` group share it.
    pub alt_group: Option<u32>,
    /// An array of any number of dimensions (`Dim`'s `ArrPar`).
    pub any_rank: bool,
}

impl Param {
    /// Bound by position: neither optional nor an alternative.
    pub fn positional(&self) -> bool {
        crate::catalogue::binding::Parameter::positional(self)
    }
}

/// A routine's signature.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Signature {
    pub name: String,
    pub kind: RoutineKind,
    pub params: Vec<Param>,
    /// The `|` groups; a required one needs one member given.
    pub groups: Vec<AltGroup>,
    /// A function's result type ([`Ty::Unknown`] for `anytype`).
    pub returns: Option<Ty>,
    /// The parameters are known: a built-in known by name only has none,
    /// and its calls are not checked against them.
    pub known: bool,
    /// A built-in's one-line summary.
    pub doc: Option<String>,
}

impl Signature {
    /// The signature of a resolved routine.
    pub(crate) fn of(def: &Def<'_>, task: &Task) -> Option<Signature> {
        match def {
            Def::BuiltinRoutine(r) => Some(Signature::builtin(r)),
            def => def.routine_decl(task).map(Signature::user),
        }
    }

    /// The signature of a catalogue routine.
    pub fn builtin(r: &Routine) -> Signature {
        let params = r
            .params
            .iter()
            .map(|p| Param {
                name: p.name.clone(),
                ty: if p.switch {
                    Ty::named("switch")
                } else if p.ty.eq_ignore_ascii_case(ANYTYPE) {
                    Ty::Any
                } else {
                    Ty::named(&p.ty)
                }
                .array(p.array),
                type_name: p.ty.clone(),
                mode: p.mode.unwrap_or(Mode::In),
                optional: p.optional,
                switch: p.switch,
                alt_group: p.alt_group,
                any_rank: p.any_rank,
            })
            .collect();
        Signature {
            name: r.name.clone(),
            kind: if r.returns.is_some() {
                RoutineKind::Func
            } else {
                RoutineKind::Proc
            },
            params,
            groups: r.alt_groups.clone(),
            returns: r.returns.as_deref().map(|t| {
                if t.eq_ignore_ascii_case(ANYTYPE) {
                    Ty::Unknown
                } else {
                    Ty::named(t)
                }
            }),
            known: r.signature_known,
            doc: Some(r.summary.clone()).filter(|s| !s.is_empty()),
        }
    }

    /// The signature of a routine declared in the task.
    pub fn user(d: &RoutineDecl) -> Signature {
        let params = d
            .params
            .iter()
            .map(|p| Param {
                name: p.name.clone(),
                ty: p
                    .ty
                    .as_ref()
                    .map_or(Ty::Unknown, |t| Ty::named(&t.name))
                    .array(p.dims),
                type_name: p.ty.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                mode: p.mode,
                optional: p.optional,
                switch: p.switch,
                alt_group: p.alt_group,
                any_rank: false,
            })
            .collect();
        Signature {
            name: d.name.clone(),
            kind: d.kind,
            params,
            // A group of optional parameters means "at most one of these".
            groups: (1..=d.alt_groups)
                .map(|id| AltGroup {
                    id,
                    required: false,
                })
                .collect(),
            returns: d.returns.as_ref().map(|t| Ty::named(&t.name)),
            known: true,
            doc: None,
        }
    }

    pub fn is_function(&self) -> bool {
        self.kind == RoutineKind::Func
    }

    /// Whether calls bind to the parameters: documented ones, or ones
    /// taken from loaded code (whose calls the checker does not check).
    pub fn binds(&self) -> bool {
        self.known || !self.params.is_empty()
    }

    /// The index of the parameter called `name`.
    pub fn param(&self, name: &str) -> Option<usize> {
        self.params.iter().position(|p| same(&p.name, name))
    }

    /// The members of group `g`, in order.
    pub fn members(&self, g: u32) -> impl Iterator<Item = &Param> {
        self.params.iter().filter(move |p| p.alt_group == Some(g))
    }
}

pub(crate) use crate::catalogue::binding::{Arg, Binding, BoundArg, Target};

impl crate::catalogue::binding::Parameter for Param {
    fn name(&self) -> &str {
        &self.name
    }
    fn optional(&self) -> bool {
        self.optional
    }
    fn alt_group(&self) -> Option<u32> {
        self.alt_group
    }
}

/// Binds `args` to the parameters of `sig` (the catalogue's
/// [`crate::catalogue::binding::bind_args`], the one binder).
pub(crate) fn bind_args(sig: &Signature, args: &[Arg<'_>]) -> Binding {
    crate::catalogue::binding::bind_args(&sig.params, &sig.groups, args)
}
