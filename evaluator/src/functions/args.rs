//! Binding a call's arguments to the parameters of the function's catalogue
//! signature, and reading them in an implementation.

use rapid_catalogue::binding::{self, Target};
use rapid_catalogue::{ANYTYPE, Mode, Param, Routine};

use crate::env::Env;
use crate::error::{ErrorCode, EvalError, err};
use crate::eval::Ctx;
use crate::expr::{Arg, Expr, Type};
use crate::value::Value;

/// What [`Args::log`] records: the kind of read in tests, nothing otherwise.
#[cfg(test)]
macro_rules! read {
    ($r:ident) => {
        Read::$r
    };
}
#[cfg(not(test))]
macro_rules! read {
    ($r:ident) => {
        ()
    };
}

/// How a parameter is passed, from its catalogue entry.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Pass {
    /// A value: evaluated (modes IN and REF; REF reads an entire object,
    /// as `Dim` does).
    Value,
    /// A switch `\Name`, given or not.
    Switch,
    /// A data object the function writes (VAR, PERS, INOUT): not
    /// evaluated, kept as the expression.
    Reference,
}

pub(crate) fn pass(p: &Param) -> Pass {
    if p.switch {
        Pass::Switch
    } else if matches!(p.mode, Some(Mode::Var | Mode::Pers | Mode::InOut)) {
        Pass::Reference
    } else {
        Pass::Value
    }
}

/// The type a value argument is evaluated as (`None` for anytype).
fn expected(p: &Param) -> Option<Type> {
    if p.ty.eq_ignore_ascii_case(ANYTYPE) {
        return None;
    }
    Some(if p.array > 0 {
        Type::array(&p.ty, vec![0; usize::from(p.array)])
    } else {
        Type::named(&p.ty)
    })
}

enum Slot<'a> {
    Empty,
    Val(Value),
    Sw,
    Ref(&'a Expr),
}

/// How an implementation read an argument, recorded by the tests that check
/// implementations against their signatures.
#[cfg(test)]
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Read {
    Num,
    Str,
    Value,
    Switch,
    Reference,
}

/// The bound arguments of one call.
pub(crate) struct Args<'a> {
    /// The function's name as the call spells it, for messages.
    pub(crate) func: &'a str,
    params: &'a [Param],
    slots: Vec<Slot<'a>>,
    #[cfg(test)]
    pub(crate) reads: std::cell::RefCell<Vec<(String, Read)>>,
}

impl<'a> Args<'a> {
    #[cfg(test)]
    fn log(&self, name: &str, read: Read) {
        self.reads.borrow_mut().push((name.to_string(), read));
    }
    #[cfg(not(test))]
    fn log(&self, _: &str, _: ()) {}

    fn idx(&self, name: &str) -> usize {
        self.params
            .iter()
            .position(|p| p.name == name)
            .unwrap_or(usize::MAX)
    }
    fn slot(&self, name: &str) -> Option<&Value> {
        match self.slots.get(self.idx(name)) {
            Some(Slot::Val(v)) => Some(v),
            _ => None,
        }
    }
    /// An optional value argument, if given.
    pub(crate) fn get(&self, name: &str) -> Option<&Value> {
        self.log(name, read!(Value));
        self.slot(name)
    }
    /// A value argument.
    pub(crate) fn val(&self, name: &str) -> Result<&Value, EvalError> {
        self.log(name, read!(Value));
        self.present(name)
    }
    fn present(&self, name: &str) -> Result<&Value, EvalError> {
        self.slot(name).ok_or_else(|| {
            EvalError::new(
                ErrorCode::BadArguments,
                format!("{}: argument {name} is missing", self.func),
            )
        })
    }
    /// A num or dnum argument.
    pub(crate) fn num(&self, name: &str) -> Result<f64, EvalError> {
        self.log(name, read!(Num));
        match self.present(name)? {
            v @ (Value::Num(_) | Value::Dnum(_)) => Ok(v.as_f64().unwrap_or(0.0)),
            _ => err(
                ErrorCode::TypeMismatch,
                format!("{}: argument {name} must be a number", self.func),
            ),
        }
    }
    /// An optional num argument, if given.
    pub(crate) fn opt_num(&self, name: &str) -> Result<Option<f64>, EvalError> {
        self.log(name, read!(Num));
        match self.slot(name) {
            Some(_) => self.num(name).map(Some),
            None => Ok(None),
        }
    }
    /// A string argument.
    pub(crate) fn str(&self, name: &str) -> Result<&str, EvalError> {
        self.log(name, read!(Str));
        match self.present(name)? {
            Value::Str(s) => Ok(s),
            _ => err(
                ErrorCode::TypeMismatch,
                format!("{}: argument {name} must be a string", self.func),
            ),
        }
    }
    /// Whether the switch `\name` is given.
    pub(crate) fn sw(&self, name: &str) -> bool {
        self.log(name, read!(Switch));
        matches!(self.slots.get(self.idx(name)), Some(Slot::Sw))
    }
    /// The data object passed to a reference parameter.
    pub(crate) fn reference(&self, name: &str) -> Option<&'a Expr> {
        self.log(name, read!(Reference));
        match self.slots.get(self.idx(name)) {
            Some(Slot::Ref(e)) => Some(e),
            _ => None,
        }
    }
}

pub(crate) fn bad<T>(func: &str, msg: impl std::fmt::Display) -> Result<T, EvalError> {
    err(ErrorCode::BadArguments, format!("{func}: {msg}"))
}

/// Binds `args` to the parameters of `routine` with the one binder
/// ([`rapid_catalogue::binding::bind_args`]: positional arguments fill the
/// positional parameters in order, named ones name theirs; members of one
/// `|` group exclude each other), then checks what the binding says:
/// switches take no value, the others need one. Value arguments are then
/// evaluated as their parameter's type.
pub(crate) fn bind<'a>(
    ctx: &mut Ctx,
    func: &'a str,
    routine: &'a Routine,
    args: &'a [Arg],
    env: &dyn Env,
) -> Result<Args<'a>, EvalError> {
    let params = routine.params.as_slice();
    let shapes: Vec<binding::Arg<'_>> = args
        .iter()
        .map(|a| match &a.name {
            Some(n) => binding::Arg::Named(n),
            None => binding::Arg::Positional,
        })
        .collect();
    let bound = binding::bind_args(params, &routine.alt_groups, &shapes);
    let mut slots: Vec<Slot<'a>> = params.iter().map(|_| Slot::Empty).collect();
    let mut pending: Vec<Option<&'a Expr>> = params.iter().map(|_| None).collect();
    for (arg, b) in args.iter().zip(&bound.args) {
        let i = match b.target {
            Target::Param(i) => i,
            Target::UnknownName => {
                let n = arg.name.as_deref().unwrap_or_default();
                return bad(func, format_args!("there is no parameter {n}"));
            }
            Target::TooMany => return bad(func, "too many arguments"),
        };
        let Some(p) = params.get(i) else {
            return bad(func, "too many arguments");
        };
        if b.repeats.is_some() {
            return bad(func, format_args!("argument {} is given twice", p.name));
        }
        if b.excludes.is_some() {
            return bad(func, "mutually exclusive arguments are given together");
        }
        match (pass(p), &arg.value) {
            (Pass::Switch, None) => slots[i] = Slot::Sw,
            (Pass::Switch, Some(_)) => {
                return bad(
                    func,
                    format_args!("\\{} is a switch and takes no value", p.name),
                );
            }
            (_, None) => return bad(func, format_args!("argument {} needs a value", p.name)),
            (Pass::Reference, Some(e)) => slots[i] = Slot::Ref(e),
            (Pass::Value, Some(e)) => pending[i] = Some(e),
        }
    }
    if let Some(p) = bound.missing.first().and_then(|&i| params.get(i)) {
        return bad(func, format_args!("argument {} is missing", p.name));
    }
    if let Some(&g) = bound.missing_groups.first() {
        let names: Vec<String> = params
            .iter()
            .filter(|p| p.alt_group == Some(g))
            .map(|p| format!("\\{}", p.name))
            .collect();
        return bad(func, format_args!("one of {} is needed", names.join(", ")));
    }
    for (i, p) in params.iter().enumerate() {
        if let Some(e) = pending[i] {
            slots[i] = Slot::Val(ctx.eval(e, expected(p).as_ref(), env)?);
        }
    }
    Ok(Args {
        func,
        params,
        slots,
        #[cfg(test)]
        reads: std::cell::RefCell::new(Vec::new()),
    })
}
