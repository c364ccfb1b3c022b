//! Data: places (a root slot and a path of components and elements),
//! reading and storing through them, making values fit their type, and the
//! starting values of data objects.

use std::sync::Arc;

use rapid_analyzer::items::Storage;
use rapid_evaluator::{ErrorCode, Type, Value};

use super::{FrameKind, Init, Machine, R, Slot, fault, invalid, named_error, rapid_error};
use crate::code::{Code, Conv, DataInit, SlotKind, Target};
use crate::controller::Shared;
use crate::program::{MAX_ELEMENTS, Start};

/// Where a reference points: a task's data object, a shared persistent or
/// a slot of the stack, then components and elements.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Place {
    pub root: Root,
    pub path: Vec<Step>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Root {
    Global(u32),
    /// A persistent of the controller ([`Shared::pers`]).
    Pers(u32),
    Stack(u32),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Step {
    Field(u16),
    Index(u32),
}

impl Place {
    pub(crate) fn root(root: Root) -> Place {
        Place {
            root,
            path: Vec::new(),
        }
    }
}

/// A value's type, for messages.
pub(crate) fn describe(v: &Value) -> String {
    match v.type_name() {
        Some(t) => t.to_owned(),
        None => "an aggregate".to_owned(),
    }
}

impl Machine {
    /// The value at a place.
    pub(crate) fn get<'a>(&'a self, sh: &'a Shared, p: &Place) -> Option<&'a Value> {
        let mut v = match p.root {
            Root::Global(g) => self.globals.get(g as usize)?,
            Root::Pers(i) => sh.pers.get(i as usize)?,
            Root::Stack(s) => match self.slots.get(s as usize)? {
                Slot::Val(v) => v,
                _ => return None,
            },
        };
        for step in &p.path {
            v = match (step, v) {
                (Step::Field(i), Value::Record { fields, .. }) => &fields.get(usize::from(*i))?.1,
                (Step::Index(i), Value::Array(items)) => items.get(*i as usize)?,
                _ => return None,
            };
        }
        Some(v)
    }

    fn get_mut<'a>(&'a mut self, sh: &'a mut Shared, p: &Place) -> Option<&'a mut Value> {
        let mut v = match p.root {
            Root::Global(g) => self.globals.get_mut(g as usize)?,
            Root::Pers(i) => sh.pers.get_mut(i as usize)?,
            Root::Stack(s) => match self.slots.get_mut(s as usize)? {
                Slot::Val(v) => v,
                _ => return None,
            },
        };
        for step in &p.path {
            v = match (step, v) {
                (Step::Field(i), Value::Record { fields, .. }) => {
                    &mut fields.get_mut(usize::from(*i))?.1
                }
                (Step::Index(i), Value::Array(items)) => items.get_mut(*i as usize)?,
                _ => return None,
            };
        }
        Some(v)
    }

    /// The value at a place, or the fault of a reference that no longer
    /// holds.
    pub(crate) fn load(&self, sh: &Shared, p: &Place) -> R<Value> {
        match self.get(sh, p) {
            Some(v) => Ok(v.clone()),
            None => invalid("a reference to data that no longer exists"),
        }
    }

    /// Stores `v` at a place (not a constant's), keeping array sizes.
    pub(crate) fn store(&mut self, sh: &mut Shared, p: &Place, v: Value) -> R<()> {
        if self.is_constant(p) {
            return invalid("a constant cannot be changed");
        }
        if let (Some(Value::Array(old)), Value::Array(new)) = (self.get(sh, p), &v)
            && old.len() != new.len()
        {
            return fault(rapid_error(
                &self.prog,
                ErrorCode::OutOfBnd,
                format!(
                    "an array of {} cannot hold {} elements",
                    old.len(),
                    new.len()
                ),
            ));
        }
        match self.get_mut(sh, p) {
            Some(slot) => {
                *slot = v;
                Ok(())
            }
            None => invalid("the data referred to no longer exists"),
        }
    }

    fn is_constant(&self, p: &Place) -> bool {
        match p.root {
            Root::Global(g) => self
                .prog
                .globals
                .get(g as usize)
                .is_some_and(|d| d.storage == Storage::Const),
            Root::Pers(_) => false,
            Root::Stack(s) => {
                let Some(f) = self
                    .frames
                    .iter()
                    .rev()
                    .find(|f| (f.base as usize) <= s as usize)
                else {
                    return false;
                };
                f.code
                    .slots
                    .get(s as usize - f.base as usize)
                    .is_some_and(|info| info.kind == SlotKind::Const)
            }
        }
    }

    /// The place of local slot `i` of the frame at `base`.
    pub(crate) fn place_local(&self, base: usize, i: u32) -> R<Place> {
        match self.slots.get(base + i as usize) {
            Some(Slot::Val(_)) => Ok(Place::root(Root::Stack((base + i as usize) as u32))),
            Some(Slot::Ref(p)) => Ok(p.clone()),
            Some(Slot::Absent) => self.not_present(base, i),
            None => invalid("a local slot out of range"),
        }
    }

    /// The value of local slot `i` of the frame at `base`.
    pub(crate) fn local(&self, sh: &Shared, base: usize, i: u32) -> R<Value> {
        match self.slots.get(base + i as usize) {
            Some(Slot::Val(v)) => Ok(v.clone()),
            Some(Slot::Ref(p)) => self.load(sh, p),
            Some(Slot::Absent) => self.not_present(base, i),
            None => invalid("a local slot out of range"),
        }
    }

    /// A local slot as a debugger shows it (`None`: not given).
    pub(crate) fn slot_value(&self, sh: &Shared, base: usize, slot: usize) -> Option<Value> {
        match self.slots.get(base + slot)? {
            Slot::Val(v) => Some(v.clone()),
            Slot::Ref(p) => self.get(sh, p).cloned(),
            Slot::Absent => None,
        }
    }

    fn not_present<T>(&self, base: usize, slot: u32) -> R<T> {
        let name = self
            .frames
            .iter()
            .rev()
            .find(|f| f.base as usize == base)
            .and_then(|f| f.code.slots.get(slot as usize))
            .map_or("", |s| s.name.as_str())
            .to_owned();
        fault(named_error(
            &self.prog,
            "ERR_NOTPRES",
            format!("the optional parameter {name} is not present"),
        ))
    }

    /// The place one component further.
    pub(crate) fn field_place(&self, sh: &Shared, mut p: Place, name: &str) -> R<Place> {
        let i = match self.get(sh, &p) {
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

    /// The place of an element (1-based indexes).
    pub(crate) fn index_place(&self, sh: &Shared, mut p: Place, ix: &[Value]) -> R<Place> {
        for i in ix {
            let k = self.index_of(sh, i)?;
            let n = match self.get(sh, &p) {
                Some(Value::Array(items)) => items.len(),
                Some(other) => return invalid(format!("{} is not an array", describe(other))),
                None => return invalid("a reference to data that no longer exists"),
            };
            if k == 0 || k > n {
                return self.out_of_bounds(k, n);
            }
            p.path.push(Step::Index((k - 1) as u32));
        }
        Ok(p)
    }

    /// A component of a value that is not stored.
    pub(crate) fn field_of(&self, v: Value, name: &str) -> R<Value> {
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

    /// An element of a value that is not stored.
    pub(crate) fn element_of(&self, sh: &Shared, mut v: Value, ix: &[Value]) -> R<Value> {
        for i in ix {
            let k = self.index_of(sh, i)?;
            v = match v {
                Value::Array(mut items) => {
                    if k == 0 || k > items.len() {
                        return self.out_of_bounds(k, items.len());
                    }
                    items.swap_remove(k - 1)
                }
                other => return invalid(format!("{} is not an array", describe(&other))),
            };
        }
        Ok(v)
    }

    /// A 1-based index's value (0 for anything below 1).
    fn index_of(&self, sh: &Shared, v: &Value) -> R<usize> {
        let x = self.scalar(sh, v.clone())?.as_f64().unwrap_or(f64::NAN);
        if x.fract() != 0.0 || x.is_nan() {
            return fault(rapid_error(
                &self.prog,
                ErrorCode::NotIntVal,
                "an array index must be an integer".into(),
            ));
        }
        Ok(if x < 1.0 { 0 } else { x as usize })
    }

    fn out_of_bounds<T>(&self, k: usize, n: usize) -> R<T> {
        fault(rapid_error(
            &self.prog,
            ErrorCode::OutOfBnd,
            format!("the index {k} is outside the array bounds 1 to {n}"),
        ))
    }

    /// A signal read as its value; any other value as it is.
    #[inline(always)]
    pub(crate) fn scalar(&self, sh: &Shared, v: Value) -> R<Value> {
        if let Value::Record { .. } = v {
            return self.signal_or_record(sh, v);
        }
        Ok(v)
    }

    fn signal_or_record(&self, sh: &Shared, v: Value) -> R<Value> {
        if is_signal(&v) {
            return self.signal_value(sh, &v).map(Value::Num);
        }
        Ok(v)
    }

    /// The configured signal a signal value stands for: its name as
    /// declared and its kind.
    pub(crate) fn signal_of(&self, sh: &Shared, v: &Value) -> R<(String, crate::SignalKind)> {
        let name = match v.field("name") {
            Some(Value::Str(n)) => n,
            _ => return invalid("not a signal"),
        };
        if name.is_empty() {
            return fault(named_error(
                &self.prog,
                "ERR_NO_ALIASIO_DEF",
                "the signal variable is not connected to a signal (AliasIO)".to_owned(),
            ));
        }
        match sh.io.signal(name) {
            Some(s) => Ok(s),
            None => fault(named_error(
                &self.prog,
                "ERR_NAME_INVALID",
                format!("there is no signal {name}"),
            )),
        }
    }

    /// The current value of a signal.
    pub(crate) fn signal_value(&self, sh: &Shared, v: &Value) -> R<f32> {
        let (name, _) = self.signal_of(sh, v)?;
        Ok(sh.io.read(&name).unwrap_or(0.0) as f32)
    }

    /// Makes a value fit its destination.
    #[inline]
    pub(crate) fn convert(&self, sh: &Shared, v: Value, conv: &Conv) -> R<Value> {
        match (conv, &v) {
            (Conv::Num, Value::Num(_)) | (Conv::Dnum, Value::Dnum(_)) => Ok(v),
            _ => self.convert_slow(sh, v, conv),
        }
    }

    fn convert_slow(&self, sh: &Shared, v: Value, conv: &Conv) -> R<Value> {
        match conv {
            Conv::Num => match v {
                Value::Num(_) => Ok(v),
                Value::Dnum(x) => {
                    if x.abs() > f64::from(f32::MAX) {
                        fault(rapid_error(
                            &self.prog,
                            ErrorCode::NumLimit,
                            "the value is outside the range of num".into(),
                        ))
                    } else {
                        Ok(Value::Num(x as f32))
                    }
                }
                Value::Record { .. } if is_signal(&v) => self.signal_value(sh, &v).map(Value::Num),
                other => invalid(format!("expected a num, found {}", describe(&other))),
            },
            Conv::Dnum => match v {
                Value::Dnum(_) => Ok(v),
                Value::Num(x) => Ok(Value::Dnum(f64::from(x))),
                Value::Record { .. } if is_signal(&v) => {
                    self.signal_value(sh, &v).map(|x| Value::Dnum(f64::from(x)))
                }
                other => invalid(format!("expected a dnum, found {}", describe(&other))),
            },
            Conv::Full(ty) => {
                if let Value::Record { ty: t, .. } = &v
                    && ty.dims.is_empty()
                    && t.eq_ignore_ascii_case(&ty.name)
                {
                    return Ok(v);
                }
                rapid_evaluator::coerce(v, ty, &self.prog.types).or_else(|e| self.eval_error(e))
            }
        }
    }

    /// Runs the starting value of every data object of the task (and the
    /// shared persistents no task has set yet), in the task's order. As
    /// the program starts (`at_start`), a persistent that an earlier
    /// task declared without a value takes the value this task's
    /// declaration gives.
    pub(crate) fn initialise(&mut self, sh: &mut Shared, at_start: bool) {
        for g in 0..self.prog.globals.len() {
            if !matches!(self.init.get(g), Some(Init::Pending)) {
                continue;
            }
            match &self.prog.globals[g].start {
                Start::Value(v) => {
                    self.globals[g] = v.clone();
                    self.init[g] = Init::Ready;
                }
                Start::Code(code) => {
                    let code = code.clone();
                    self.run_init(sh, code, Target::Global(g as u32));
                }
            }
        }
        for k in 0..self.pers_map.len() {
            let i = self.pers_map[k] as usize;
            let valued = self.prog.pers.get(k).is_some_and(|p| p.valued);
            let replaces = at_start && sh.takes_value(i, valued);
            if !matches!(sh.pers_init.get(i), Some(Init::Pending)) && !replaces {
                continue;
            }
            if let Some(code) = self.prog.pers.get(k).and_then(|p| p.start.clone()) {
                self.run_init(sh, code, Target::Pers(k as u32));
            }
        }
    }

    /// The task runs `prog` from now on: a program with modules loaded
    /// after its own, or the one it had before them (`Load`, `UnLoad`).
    /// What both lay out is kept; the data of a loaded module start as
    /// the controller sets them, the persistents it shares too.
    pub(crate) fn adopt(&mut self, sh: &mut Shared, prog: Arc<crate::program::Program>) {
        let n = prog.globals.len();
        self.globals.resize(n, Value::Num(0.0));
        self.init.resize(n, Init::Pending);
        for p in prog.pers.iter().skip(self.pers_map.len()) {
            self.pers_map.push(sh.persistent(&p.name));
        }
        for i in self
            .pers_map
            .split_off(prog.pers.len().min(self.pers_map.len()))
        {
            sh.release_persistent(i);
        }
        self.prog = prog;
        // The starting values are computed on a stack of their own: the
        // running routines (the one that loads) wait below, untouched.
        let running = std::mem::take(&mut self.frames);
        self.initialise(sh, false);
        self.frames = running;
    }

    /// Runs an initialisation frame to its end.
    fn run_init(&mut self, sh: &mut Shared, code: Arc<Code>, target: Target) {
        self.begin_init(sh, code, target);
        let depth = self.frames.len() - 1;
        let mut guard = 0u32;
        while self.frames.len() > depth && guard < 1_000_000 {
            guard += 1;
            let _ = self.run_slice(sh, u32::MAX);
        }
    }

    /// Pushes the frame that computes a data object's starting value.
    pub(crate) fn begin_init(&mut self, sh: &mut Shared, code: Arc<Code>, target: Target) {
        self.set_init(sh, target, Init::Busy);
        self.push_frame(code, FrameKind::Init, Vec::new());
    }

    /// Sets the initialisation state of a global or persistent (a slot of a
    /// routine has none).
    fn set_init(&mut self, sh: &mut Shared, target: Target, state: Init) {
        let place = match target {
            Target::Global(g) => self.init.get_mut(g as usize),
            Target::Pers(k) => match self.pers_map.get(k as usize) {
                Some(&i) => sh.pers_init.get_mut(i as usize),
                None => None,
            },
            Target::Slot => None,
        };
        if let Some(place) = place {
            *place = state;
        }
    }

    /// The data object the innermost (initialisation) frame computes cannot
    /// start: why.
    pub(crate) fn init_failed(&mut self, sh: &mut Shared, why: String) {
        let Some(top) = self.frames.last() else {
            return;
        };
        let code = top.code.clone();
        let Some(decl) = code.decls.first() else {
            return;
        };
        let at = self.prog.location(code.unit, code.range.start);
        let why = format!("{at}: the data {} cannot be initialised: {why}", code.name);
        self.set_init(sh, decl.target, Init::Failed(why));
    }

    /// The starting value of a data declaration: array sizes and the
    /// initial value (when given) are on the value stack.
    pub(crate) fn start_value(&mut self, sh: &Shared, d: &DataInit, convs: &[Conv]) -> R<Value> {
        let init = if d.init { self.vals.pop() } else { None };
        let at = self.vals.len().saturating_sub(d.dims as usize);
        let dims: Vec<Value> = self.vals.split_off(at);
        let mut sizes = Vec::with_capacity(dims.len());
        for v in dims {
            let v = self.scalar(sh, v)?;
            let n = v.as_f64().unwrap_or(-1.0);
            if n.fract() != 0.0 || !(1.0..=MAX_ELEMENTS as f64).contains(&n) {
                return invalid(format!(
                    "an array dimension of {v} is not a positive integer"
                ));
            }
            sizes.push(n as usize);
        }
        let total = sizes.iter().try_fold(1usize, |t, &n| t.checked_mul(n));
        if total.is_none_or(|t| t > MAX_ELEMENTS) {
            return invalid(format!(
                "an array of {} elements is larger than the simulation holds ({MAX_ELEMENTS})",
                sizes
                    .iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(" x "),
            ));
        }
        let ty = Type::array(d.ty.name.clone(), sizes);
        match init {
            Some(v) => match d.conv.and_then(|c| convs.get(c as usize)) {
                Some(Conv::Full(_)) => self.convert(sh, v, &Conv::Full(ty)),
                Some(c) => self.convert(sh, v, c),
                None => Ok(v),
            },
            None => Ok(self.prog.zero(&ty)),
        }
    }
}

/// Is `v` a signal (of the configuration, or a signal variable)?
pub(crate) fn is_signal(v: &Value) -> bool {
    matches!(v, Value::Record { ty, .. } if ty.len() == 8 && ty.get(..6).is_some_and(|h| h.eq_ignore_ascii_case("signal")))
}

/// The fault of `.name` on a value that is not a record.
fn no_components<T>(v: &Value, name: &str) -> R<T> {
    match v {
        Value::Array(_) => invalid(format!(
            ".{name}: the data is an array, or an aggregate of a type the task does not declare (is its RECORD in another task?)"
        )),
        other => invalid(format!(".{name}: {} has no components", describe(other))),
    }
}
