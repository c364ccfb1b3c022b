//! Expressions: reading data, operators (the evaluator's), aggregates and
//! function calls.

use rapid_evaluator::{Expr as E, Options, Value};

use crate::code::{Arg, ArgValue, Expr, Failure};
use crate::machine::{
    FaultKind, Machine, Place, R, Root, Slot, Step, fault, invalid, named_error, rapid_error,
};
use crate::types::TypesEnv;

impl Machine {
    /// The value of an expression.
    pub(crate) fn eval(&mut self, e: &Expr) -> R<Value> {
        match e {
            Expr::Const(v) => Ok(v.clone()),
            Expr::Local(i) => match self.stack.get(self.base + *i as usize) {
                Some(Slot::Val(v)) => Ok(v.clone()),
                Some(Slot::Ref(p)) => match self.get(p) {
                    Some(v) => Ok(v.clone()),
                    None => invalid("a reference to data that no longer exists"),
                },
                Some(Slot::Absent) => self.not_present(*i),
                None => invalid("a local slot out of range"),
            },
            Expr::Global(g) => {
                self.ensure_global(*g)?;
                match self.globals.get(*g as usize) {
                    Some(v) => Ok(v.clone()),
                    None => invalid("a global out of range"),
                }
            }
            Expr::Field(..) | Expr::Index(..) if e.is_place() => {
                let p = self.place(e)?;
                match self.get(&p) {
                    Some(v) => Ok(v.clone()),
                    None => invalid("a reference to data that no longer exists"),
                }
            }
            Expr::Field(base, name) => {
                let v = self.eval(base)?;
                match v {
                    Value::Record { ty, mut fields } => {
                        match fields
                            .iter()
                            .position(|(n, _)| n.eq_ignore_ascii_case(name))
                        {
                            Some(i) => Ok(fields.swap_remove(i).1),
                            None => invalid(format!("{ty} has no component {name}")),
                        }
                    }
                    other => no_components(&other, name),
                }
            }
            Expr::Index(base, ix) => {
                let mut v = self.eval(base)?;
                for i in ix {
                    let k = self.index(i)?;
                    v = match v {
                        Value::Array(mut items) => {
                            if k == 0 || k > items.len() {
                                return self.out_of_bounds(k, items.len());
                            }
                            items.swap_remove(k - 1)
                        }
                        other => {
                            return invalid(format!(
                                "{} is not an array",
                                crate::machine::describe(&other)
                            ));
                        }
                    };
                }
                Ok(v)
            }
            Expr::Aggregate(ty, items) => {
                let mut values = Vec::with_capacity(items.len());
                for i in items {
                    values.push(self.eval(i)?);
                }
                let v = Value::Array(values);
                match ty {
                    Some(t) => rapid_evaluator::coerce(v, t, &TypesEnv(&self.prog.types))
                        .or_else(|e| self.eval_error(e)),
                    None => Ok(v),
                }
            }
            Expr::Unary(op, x) => {
                let v = self.eval(x)?;
                let v = self.scalar(v)?;
                rapid_evaluator::apply_unary(*op, v).or_else(|e| self.eval_error(e))
            }
            Expr::Binary(op, a, b) => {
                let a = self.eval(a)?;
                let b = self.eval(b)?;
                let (a, b) = match (a, b) {
                    (a @ Value::Num(_), b @ Value::Num(_)) => (a, b),
                    (a, b) => (self.scalar(a)?, self.scalar(b)?),
                };
                match rapid_evaluator::apply_binary(*op, a, b, &TypesEnv(&self.prog.types)) {
                    Ok(v) => Ok(v),
                    Err(e) => self.eval_error(e),
                }
            }
            Expr::Call { routine, args } => match self.invoke(*routine, args)? {
                Some(v) => Ok(v),
                None => invalid("the function returned no value"),
            },
            Expr::Pure { name, args } => self.pure(name, args),
            Expr::Func { name, f, args } => {
                let a = crate::builtins::Args::new(name, args);
                f(self, &a)
            }
            Expr::Present(slot) => Ok(Value::Bool(!matches!(
                self.stack.get(self.base + *slot as usize),
                Some(Slot::Absent) | None
            ))),
            Expr::Fail(f) => self.failure(f),
        }
    }

    /// A condition's value.
    pub(crate) fn truth(&mut self, e: &Expr) -> R<bool> {
        match self.eval(e)? {
            Value::Bool(b) => Ok(b),
            other => invalid(format!(
                "a condition must be a bool, not {}",
                crate::machine::describe(&other)
            )),
        }
    }

    /// A signal read as its value; any other value as it is.
    #[inline(always)]
    pub(crate) fn scalar(&mut self, v: Value) -> R<Value> {
        if let Value::Record { .. } = v {
            return self.signal_or_record(v);
        }
        Ok(v)
    }

    fn signal_or_record(&mut self, v: Value) -> R<Value> {
        if self.is_signal(&v) {
            return self.signal_value(&v).map(Value::Num);
        }
        Ok(v)
    }

    /// A 1-based index's value.
    fn index(&mut self, e: &Expr) -> R<usize> {
        let v = self.eval(e)?;
        let x = self.scalar(v)?.as_f64().unwrap_or(f64::NAN);
        if x.fract() != 0.0 || x.is_nan() {
            return fault(rapid_error(
                &self.prog,
                rapid_evaluator::ErrorCode::NotIntVal,
                "an array index must be an integer".into(),
            ));
        }
        Ok(if x < 1.0 { 0 } else { x as usize })
    }

    fn out_of_bounds<T>(&self, k: usize, n: usize) -> R<T> {
        fault(rapid_error(
            &self.prog,
            rapid_evaluator::ErrorCode::OutOfBnd,
            format!("the index {k} is outside the array bounds 1 to {n}"),
        ))
    }

    fn not_present<T>(&self, slot: u32) -> R<T> {
        let name = self
            .frames
            .last()
            .and_then(|f| f.routine.slots.get(slot as usize))
            .map_or("", |s| s.name.as_str())
            .to_owned();
        fault(named_error(
            &self.prog,
            "ERR_NOTPRES",
            format!("the optional parameter {name} is not present"),
        ))
    }

    /// Where a data reference points.
    pub(crate) fn place(&mut self, e: &Expr) -> R<Place> {
        match e {
            Expr::Local(i) => match self.stack.get(self.base + *i as usize) {
                Some(Slot::Val(_)) => Ok(Place {
                    root: Root::Stack((self.base + *i as usize) as u32),
                    path: Vec::new(),
                }),
                Some(Slot::Ref(p)) => Ok(p.clone()),
                Some(Slot::Absent) => self.not_present(*i),
                None => invalid("a local slot out of range"),
            },
            Expr::Global(g) => {
                self.ensure_global(*g)?;
                Ok(Place {
                    root: Root::Global(*g),
                    path: Vec::new(),
                })
            }
            Expr::Field(base, name) => {
                let mut p = self.place(base)?;
                let i = match self.get(&p) {
                    Some(Value::Record { ty, fields }) => {
                        match fields
                            .iter()
                            .position(|(n, _)| n.eq_ignore_ascii_case(name))
                        {
                            Some(i) => i,
                            None => return invalid(format!("{ty} has no component {name}")),
                        }
                    }
                    Some(other) => return no_components(other, name),
                    None => return invalid("a reference to data that no longer exists"),
                };
                p.path.push(Step::Field(i as u16));
                Ok(p)
            }
            Expr::Index(base, ix) => {
                let mut p = self.place(base)?;
                for i in ix {
                    let k = self.index(i)?;
                    let n = match self.get(&p) {
                        Some(Value::Array(items)) => items.len(),
                        Some(other) => {
                            return invalid(format!(
                                "{} is not an array",
                                crate::machine::describe(other)
                            ));
                        }
                        None => return invalid("a reference to data that no longer exists"),
                    };
                    if k == 0 || k > n {
                        return self.out_of_bounds(k, n);
                    }
                    p.path.push(Step::Index((k - 1) as u32));
                }
                Ok(p)
            }
            _ => invalid("not a data reference"),
        }
    }

    /// A pure function, computed by the evaluator on the argument values.
    fn pure(&mut self, name: &str, args: &[Arg]) -> R<Value> {
        let mut out = Vec::with_capacity(args.len());
        for a in args {
            let name = a.name.as_deref().map(str::to_owned);
            match &a.value {
                ArgValue::Expr(e) => {
                    let v = self.eval(e)?;
                    let v = self.scalar(v)?;
                    out.push(rapid_evaluator::Arg {
                        name,
                        value: Some(E::Value(v)),
                    });
                }
                ArgValue::Switch => out.push(rapid_evaluator::Arg { name, value: None }),
                ArgValue::Conditional(slot) => {
                    let switch = self
                        .frames
                        .last()
                        .and_then(|f| f.routine.params.get(*slot as usize))
                        .is_some_and(|p| p.switch);
                    match self.stack.get(self.base + *slot as usize) {
                        None | Some(Slot::Absent) => {}
                        Some(_) if switch => out.push(rapid_evaluator::Arg { name, value: None }),
                        Some(_) => {
                            let v = self.eval(&Expr::Local(*slot))?;
                            out.push(rapid_evaluator::Arg {
                                name,
                                value: Some(E::Value(v)),
                            });
                        }
                    }
                }
                ArgValue::Star => return invalid(format!("* is no argument of {name:?}")),
            }
        }
        let call = E::Call {
            name: name.to_owned(),
            args: out,
        };
        let options = Options {
            max_steps: u64::MAX,
            ..Options::default()
        };
        match rapid_evaluator::eval_with(&call, None, &TypesEnv(&self.prog.types), &options) {
            Ok(e) => Ok(e.value),
            Err(e) => self.eval_error(e),
        }
    }

    /// The fault of a statement or expression that cannot run.
    pub(crate) fn failure<T>(&self, f: &Failure) -> R<T> {
        match f {
            Failure::Unknown(name) => invalid(format!(
                "`{name}` is not declared in the task (nor a built-in the catalogue knows)"
            )),
            Failure::Unsupported(name) => fault(FaultKind::Unsupported(name.clone())),
            Failure::Invalid(why) => invalid(why.clone()),
        }
    }
}

/// The fault of `.name` on a value that is not a record.
fn no_components<T>(v: &Value, name: &str) -> R<T> {
    match v {
        Value::Array(_) => invalid(format!(
            ".{name}: the data is an array, or an aggregate of a type the task does not declare (is its RECORD in another task?)"
        )),
        other => invalid(format!(
            ".{name}: {} has no components",
            crate::machine::describe(other)
        )),
    }
}
