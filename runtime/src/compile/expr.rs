//! Expressions and places. A name is what `sema` says it is; the type a
//! value is stored as comes from the context (an assignment's target, a
//! parameter, an aggregate's record type), as the controller types it:
//! it types aggregates and makes literals `dnum` where a `dnum` is
//! wanted.

use rapid_analyzer::resolve::DataRef;
use rapid_analyzer::ty::Ty;
use rapid_evaluator::{BinOp, Expr as E, UnOp, Value};

use super::{Compiler, Shape, named_object};
use crate::code::*;
use crate::program::Home;

/// How deep an expression is compiled before it is refused.
const MAX_DEPTH: u32 = 200;

/// What a data name compiles to.
enum Data {
    Local(u32),
    Global(u32),
    Pers(u32),
    Const(Value),
}

impl Compiler<'_> {
    /// Compiles an expression; `expected` is the type its value is stored
    /// as.
    pub(crate) fn expr(&mut self, e: &E, expected: Option<&Ty>) {
        self.expr_depth(e, expected, 0);
    }

    fn expr_depth(&mut self, e: &E, expected: Option<&Ty>, depth: u32) {
        if depth > MAX_DEPTH {
            return self.fail(Failure::Invalid(
                "the expression is nested too deeply".into(),
            ));
        }
        let d = depth + 1;
        match e {
            E::Num(text) => match rapid_evaluator::parse_num_literal(text) {
                Ok(x) => {
                    let dnum = expected.is_some_and(|t| self.shape(t) == Shape::Dnum);
                    let v = if dnum || x > f64::from(f32::MAX) {
                        Value::Dnum(x)
                    } else {
                        Value::Num(x as f32)
                    };
                    self.push_const(v);
                }
                Err(err) => self.fail(Failure::Invalid(err.message)),
            },
            E::Str(text) => match rapid_evaluator::parse_string_literal(text) {
                Ok(s) => self.push_const(Value::Str(s)),
                Err(err) => self.fail(Failure::Invalid(err.message)),
            },
            E::Bool(b) => self.push_const(Value::Bool(*b)),
            E::Value(v) => self.push_const(v.clone()),
            E::Name(n) => match self.data(n) {
                Some((Data::Local(s), _)) => {
                    self.emit(Op::Local(s));
                }
                Some((Data::Global(g), _)) => {
                    self.emit(Op::Global(g));
                }
                Some((Data::Pers(k), _)) => {
                    self.emit(Op::Pers(k));
                }
                Some((Data::Const(v), _)) => self.push_const(v),
                None => self.fail(Failure::UnknownData(n.clone())),
            },
            E::Aggregate(items) => self.aggregate(items, expected, d),
            E::Unary(op, x) => match (op, x.as_ref()) {
                (UnOp::Neg, E::Num(_)) => {
                    let at = self.code.ops.len();
                    self.expr_depth(x, expected, d);
                    // A negative literal is a constant.
                    let folded = match self.code.ops.get(at) {
                        Some(Op::Const(c)) if self.code.ops.len() == at + 1 => {
                            match self.code.consts.get(*c as usize) {
                                Some(Value::Num(v)) => Some(Value::Num(-v)),
                                Some(Value::Dnum(v)) => Some(Value::Dnum(-v)),
                                _ => None,
                            }
                        }
                        _ => None,
                    };
                    match folded {
                        Some(v) => {
                            self.code.ops.truncate(at);
                            self.push_const(v);
                        }
                        None => {
                            self.emit(Op::Unary(*op));
                        }
                    }
                }
                _ => {
                    self.expr_depth(x, expected, d);
                    self.emit(Op::Unary(*op));
                }
            },
            E::Binary(op, l, r) => {
                let hint = match op {
                    BinOp::Add | BinOp::Sub => expected.filter(|t| {
                        matches!(
                            self.shape(t),
                            Shape::Num | Shape::Dnum | Shape::Str | Shape::Record
                        )
                    }),
                    BinOp::Mul | BinOp::Div | BinOp::IntDiv | BinOp::Mod => {
                        expected.filter(|t| self.shape(t) == Shape::Dnum)
                    }
                    _ => None,
                };
                let hint = hint.cloned();
                self.expr_depth(l, hint.as_ref(), d);
                self.expr_depth(r, hint.as_ref(), d);
                self.emit(Op::Binary(*op));
            }
            E::Call { name, args } => self.function_call(name, args),
            E::Component(b, f) => {
                if self.is_place(e) {
                    self.place(e);
                    self.emit(Op::Load);
                } else {
                    self.expr_depth(b, None, d);
                    let i = self.name_index(f);
                    self.emit(Op::Field(i));
                }
            }
            E::Index(b, ix) => {
                if self.is_place(e) {
                    self.place(e);
                    self.emit(Op::Load);
                } else {
                    self.expr_depth(b, None, d);
                    for i in ix {
                        self.expr_depth(i, Some(&Ty::num()), d);
                    }
                    self.emit(Op::Index(ix.len() as u32));
                }
            }
            E::Conditional(n) => self.fail(Failure::Invalid(format!(
                "?{n} stands outside an argument list"
            ))),
            E::Unknown => self.fail(Failure::Invalid(
                "a placeholder or a broken expression".to_owned(),
            )),
        }
    }

    pub(super) fn push_const(&mut self, v: Value) {
        let c = self.constant(v);
        self.emit(Op::Const(c));
    }

    fn aggregate(&mut self, items: &[E], expected: Option<&Ty>, depth: u32) {
        let n = items.len() as u32;
        let Some(ty) = expected else {
            for i in items {
                self.expr_depth(i, None, depth);
            }
            self.emit(Op::Aggregate { n, ty: None });
            return;
        };
        if ty.dims() > 0 {
            let elem = ty.element().clone().array(ty.dims() - 1);
            for i in items {
                self.expr_depth(i, Some(&elem), depth);
            }
        } else {
            let components = self
                .names
                .types()
                .components(ty)
                .filter(|c| c.len() == items.len());
            match components {
                Some(c) => {
                    for (i, (_, t)) in items.iter().zip(c) {
                        self.expr_depth(i, Some(&t), depth);
                    }
                }
                None => {
                    for i in items {
                        self.expr_depth(i, None, depth);
                    }
                }
            }
        }
        let ty = super::type_of_ty(ty).map(|t| self.type_index(t));
        self.emit(Op::Aggregate { n, ty });
    }

    /// What a data name compiles to, with its declared type.
    fn data(&self, name: &str) -> Option<(Data, Ty)> {
        let d = self.names.data(name)?;
        let data = match &d.what {
            DataRef::Param(i) => Data::Local(*i as u32),
            DataRef::Local { name_range } => Data::Local(Self::slot_at(&self.locals, name_range)?),
            DataRef::ForVar { range } => Data::Local(Self::slot_at(&self.for_slots, range)?),
            DataRef::Item(item) => match self.prog.items.get(item)? {
                Home::Global(g) => Data::Global(*g),
                Home::Pers(k) => Data::Pers(*k),
            },
            DataRef::Builtin(datum) => Data::Global(self.prog.system_global(&datum.name)?),
            DataRef::Signal { name, .. } => Data::Global(self.prog.system_global(name)?),
            // Written as the program spells it (`GetMecUnitName`); the
            // unit instructions fold it.
            DataRef::MecUnit(_) => Data::Const(Value::Record {
                ty: "mecunit".to_owned(),
                fields: vec![("name".to_owned(), Value::Str(name.to_owned()))],
            }),
            DataRef::TaskId(n) => Data::Const(named_object("taskid", n)),
        };
        Some((data, d.ty))
    }

    /// The operation that stores into the data a plain name denotes (a
    /// local slot or the task's data object), when it is one.
    pub(super) fn store_op(&self, e: &E) -> Option<Op> {
        let E::Name(n) = e else {
            return None;
        };
        match self.data(n)?.0 {
            Data::Local(s) => Some(Op::StoreLocal(s)),
            Data::Global(g) => Some(Op::StoreGlobal(g)),
            _ => None,
        }
    }

    /// Is `e` a reference to stored data (which `VAR`/`INOUT` parameters
    /// and assignments need)?
    pub(super) fn is_place(&self, e: &E) -> bool {
        match e {
            E::Name(n) => matches!(
                self.data(n),
                Some((Data::Local(_) | Data::Global(_) | Data::Pers(_), _))
            ),
            E::Component(b, _) | E::Index(b, _) => self.is_place(b),
            _ => false,
        }
    }

    /// The declared type of a data reference (`Some(None)`: a place of a
    /// type not known); `None` when `e` is not one.
    pub(super) fn place_type(&self, e: &E) -> Option<Option<Ty>> {
        if !self.is_place(e) {
            return None;
        }
        Some(self.type_of(e))
    }

    fn type_of(&self, e: &E) -> Option<Ty> {
        let ty = match e {
            E::Name(n) => self.data(n)?.1,
            E::Component(b, f) => {
                let t = self.type_of(b)?;
                if t.dims() > 0 {
                    return None;
                }
                self.names.types().component(&t, f)?
            }
            E::Index(b, ix) => {
                let t = self.type_of(b)?;
                let left = t.dims().checked_sub(u8::try_from(ix.len()).ok()?)?;
                t.element().clone().array(left)
            }
            _ => return None,
        };
        (!ty.is_unknown()).then_some(ty)
    }

    /// Compiles a data reference as a place on the place stack; its type
    /// (`None` and a failure when it is not a data reference).
    pub(super) fn place(&mut self, e: &E) -> Option<Option<Ty>> {
        let ty = self.place_type(e);
        if ty.is_none() {
            self.fail(Failure::Invalid("not a data reference".to_owned()));
            return None;
        }
        self.place_ops(e, 0);
        ty
    }

    fn place_ops(&mut self, e: &E, depth: u32) {
        if depth > MAX_DEPTH {
            return self.fail(Failure::Invalid(
                "the expression is nested too deeply".into(),
            ));
        }
        match e {
            E::Name(n) => match self.data(n) {
                Some((Data::Local(s), _)) => {
                    self.emit(Op::PlaceLocal(s));
                }
                Some((Data::Global(g), _)) => {
                    self.emit(Op::PlaceGlobal(g));
                }
                Some((Data::Pers(k), _)) => {
                    self.emit(Op::PlacePers(k));
                }
                _ => self.fail(Failure::UnknownData(n.clone())),
            },
            E::Component(b, f) => {
                self.place_ops(b, depth + 1);
                let i = self.name_index(f);
                self.emit(Op::PlaceField(i));
            }
            E::Index(b, ix) => {
                self.place_ops(b, depth + 1);
                for i in ix {
                    self.expr_depth(i, Some(&Ty::num()), depth + 1);
                }
                self.emit(Op::PlaceIndex(ix.len() as u32));
            }
            _ => self.fail(Failure::Invalid("not a data reference".to_owned())),
        }
    }

    /// An error number of an `ERROR (...)` list.
    pub(super) fn simple(&self, e: &E) -> Simple {
        match e {
            E::Num(t) => match rapid_evaluator::parse_num_literal(t) {
                Ok(x) => Simple::Const(Value::Num(x as f32)),
                Err(_) => Simple::Other,
            },
            E::Unary(UnOp::Neg, x) => Simple::Neg(Box::new(self.simple(x))),
            E::Name(n) => match self.data(n) {
                Some((Data::Local(s), _)) => Simple::Local(s),
                Some((Data::Global(g), _)) => Simple::Global(g),
                Some((Data::Pers(k), _)) => Simple::Pers(k),
                Some((Data::Const(v), _)) => Simple::Const(v),
                None => Simple::Other,
            },
            _ => Simple::Other,
        }
    }
}
