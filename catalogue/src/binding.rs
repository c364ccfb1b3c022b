//! The binding of a call's arguments to a routine's parameters, as data:
//! the one rule every reader of a call applies (the checker, signature
//! help, the constant evaluator, the interpreter).
//!
//! A positional argument goes to the next positional parameter (one that
//! is neither optional nor a member of a `|` group); a named one (`\Name`,
//! `\Name:=value`, `Name:=value`) goes to its own, and positional ones
//! after it continue after it. Nothing is reported here: the binding says
//! where each argument goes or why it goes nowhere, which parameters are
//! missing, and which required groups have no member given; each reader
//! decides what to make of it.

use crate::{AltGroup, Param};

/// What binding needs to know of a parameter.
pub trait Parameter {
    fn name(&self) -> &str;
    /// Written `\Name`: may be left out.
    fn optional(&self) -> bool;
    /// Members of one `|` group share it.
    fn alt_group(&self) -> Option<u32>;
    /// Bound by position: neither optional nor an alternative.
    fn positional(&self) -> bool {
        !self.optional() && self.alt_group().is_none()
    }
}

impl Parameter for Param {
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

/// An argument of a call, as far as binding needs it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arg<'a> {
    /// A value without a name: it goes to the next positional parameter.
    Positional,
    /// `\Name`, `\Name:=value` or `Name:=value`.
    Named(&'a str),
}

/// Where an argument goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// The parameter of this index.
    Param(usize),
    /// A name the routine has no parameter of.
    UnknownName,
    /// A positional argument after every positional parameter was bound.
    TooMany,
}

/// One argument's binding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BoundArg {
    pub target: Target,
    /// The previous argument bound to the same parameter (a duplicate).
    pub repeats: Option<usize>,
    /// Another member of the parameter's `|` group, given before: the
    /// two exclude each other.
    pub excludes: Option<usize>,
}

/// A call's arguments bound to a signature's parameters.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Binding {
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

    /// The parameter argument `k` is bound to, if any.
    pub fn param_of(&self, k: usize) -> Option<usize> {
        match self.args.get(k)?.target {
            Target::Param(i) => Some(i),
            _ => None,
        }
    }

    /// Is every argument bound to a parameter of its own, and every
    /// positional parameter and required group given?
    pub fn is_complete(&self) -> bool {
        self.missing.is_empty()
            && self.missing_groups.is_empty()
            && self.args.iter().all(|a| {
                matches!(a.target, Target::Param(_)) && a.repeats.is_none() && a.excludes.is_none()
            })
    }
}

/// Binds `args` to `params` (with the `|` groups `groups`): a positional
/// argument goes to the next positional parameter, a named one to its own
/// (and positional ones after it continue after it). Names compare without
/// case.
pub fn bind_args<P: Parameter>(params: &[P], groups: &[AltGroup], args: &[Arg<'_>]) -> Binding {
    let positional: Vec<usize> = params
        .iter()
        .enumerate()
        .filter(|(_, p)| p.positional())
        .map(|(i, _)| i)
        .collect();
    let mut next = 0;
    let mut last_given: Vec<Option<usize>> = vec![None; params.len()];
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
            Arg::Named(name) => match params
                .iter()
                .position(|p| crate::names::same(p.name(), name))
            {
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
            if let Some(g) = params.get(i).and_then(Parameter::alt_group) {
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
    out.missing_groups = groups
        .iter()
        .filter(|g| g.required && !group_given.iter().any(|(h, _)| *h == g.id))
        .map(|g| g.id)
        .collect();
    out
}

#[cfg(test)]
#[path = "binding_tests.rs"]
mod tests;
