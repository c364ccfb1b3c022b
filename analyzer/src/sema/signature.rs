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
        !self.optional && self.alt_group.is_none()
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

    /// The index of the parameter called `name`.
    pub fn param(&self, name: &str) -> Option<usize> {
        self.params.iter().position(|p| same(&p.name, name))
    }

    /// The members of group `g`, in order.
    pub fn members(&self, g: u32) -> impl Iterator<Item = &Param> {
        self.params.iter().filter(move |p| p.alt_group == Some(g))
    }
}

/// An argument of a call, as far as binding needs it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Arg<'a> {
    /// A value without a name: it goes to the next positional parameter.
    Positional,
    /// `\Name`, `\Name:=value` or `Name:=value`.
    Named(&'a str),
}

/// Where an argument goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Target {
    /// The parameter of this index.
    Param(usize),
    /// A name the routine has no parameter of.
    UnknownName,
    /// A positional argument after every positional parameter was bound.
    TooMany,
}

/// One argument's binding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BoundArg {
    pub target: Target,
    /// The previous argument bound to the same parameter (a duplicate).
    pub repeats: Option<usize>,
    /// Another member of the parameter's `|` group, given before: the
    /// two exclude each other.
    pub excludes: Option<usize>,
}

/// A call's arguments bound to a signature's parameters.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Binding {
    /// One per argument, in order.
    pub args: Vec<BoundArg>,
    /// The positional parameters no argument is bound to: those after the
    /// last bound one first, then those skipped before it.
    pub missing: Vec<usize>,
    /// The required `|` groups of which no member is given.
    pub missing_groups: Vec<u32>,
}

impl Binding {
    /// The parameter after the last one an argument is bound to (where the
    /// next argument goes, when arguments come in the parameters' order).
    pub fn next_param(&self) -> usize {
        self.args
            .iter()
            .filter_map(|a| match a.target {
                Target::Param(i) => Some(i + 1),
                _ => None,
            })
            .max()
            .unwrap_or(0)
    }
}

/// Binds `args` to the parameters of `sig`: a positional argument goes to
/// the next positional parameter, a named one to its own (and positional
/// ones after it continue after it).
pub(crate) fn bind_args(sig: &Signature, args: &[Arg<'_>]) -> Binding {
    let positional: Vec<usize> = sig
        .params
        .iter()
        .enumerate()
        .filter(|(_, p)| p.positional())
        .map(|(i, _)| i)
        .collect();
    let mut next = 0;
    let mut last_given: Vec<Option<usize>> = vec![None; sig.params.len()];
    let mut group_given: Vec<(u32, usize)> = Vec::new();
    let mut out = Binding::default();
    for (k, arg) in args.iter().enumerate() {
        let target = match arg {
            Arg::Positional => match positional.get(next) {
                Some(&i) => {
                    next += 1;
                    Target::Param(i)
                }
                None => Target::TooMany,
            },
            Arg::Named(name) => match sig.param(name) {
                Some(i) => {
                    if let Some(at) = positional.iter().position(|&r| r == i) {
                        next = next.max(at + 1);
                    }
                    Target::Param(i)
                }
                None => Target::UnknownName,
            },
        };
        let mut bound = BoundArg {
            target,
            repeats: None,
            excludes: None,
        };
        if let Target::Param(i) = target {
            if let Some(slot) = last_given.get_mut(i) {
                bound.repeats = slot.replace(k);
            }
            if let Some(g) = sig.params.get(i).and_then(|p| p.alt_group) {
                match group_given.iter().find(|(h, _)| *h == g) {
                    Some(&(_, other)) if other != i => bound.excludes = Some(other),
                    Some(_) => {}
                    None => group_given.push((g, i)),
                }
            }
        }
        out.args.push(bound);
    }
    let unbound = |i: &&usize| last_given.get(**i).is_some_and(Option::is_none);
    let split = next.min(positional.len());
    out.missing = positional[split..]
        .iter()
        .filter(unbound)
        .chain(positional[..split].iter().filter(unbound))
        .copied()
        .collect();
    out.missing_groups = sig
        .groups
        .iter()
        .filter(|g| g.required && !group_given.iter().any(|(h, _)| *h == g.id))
        .map(|g| g.id)
        .collect();
    out
}

#[cfg(test)]
#[path = "signature_tests.rs"]
mod tests;
