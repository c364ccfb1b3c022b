//! The instructions and functions of the simulated controller. Each
//! receives its arguments bound to the catalogue's parameters (by name)
//! and evaluates the ones it needs.
//!
//! Anything the catalogue knows and this module does not implement stops
//! a run with "not supported in simulation: NAME".

pub(crate) mod data;
pub(crate) mod files;
pub(crate) mod io;
pub(crate) mod motion;
pub(crate) mod output;

use rapid_analyzer::catalogue::{self, base as catalogue};
use rapid_evaluator::Value;

use crate::code::{ArgValue, Expr};
use crate::machine::{Machine, Place, R, Slot, invalid};

/// An instruction of the simulated controller.
pub(crate) type InsFn = fn(&mut Machine, &Args<'_>) -> R<()>;
/// A function of the simulated controller.
pub(crate) type FuncFn = fn(&mut Machine, &Args<'_>) -> R<Value>;

/// The implemented instructions, by their catalogue names.
const INSTRUCTIONS: &[(&str, InsFn)] = &[
    ("TPWrite", output::tp_write),
    ("ErrWrite", output::err_write),
    ("TPErase", output::nothing),
    ("TPShow", output::nothing),
    ("Incr", data::incr),
    ("Decr", data::decr),
    ("Add", data::add),
    ("Clear", data::clear),
    ("BookErrNo", data::book_err_no),
    ("GetDataVal", data::get_data_val),
    ("SetDataVal", data::set_data_val),
    ("CallByVar", data::call_by_var),
    ("WaitTime", data::wait_time),
    ("ClkReset", data::clk_reset),
    ("ClkStart", data::clk_start),
    ("ClkStop", data::clk_stop),
    ("Stop", data::stop),
    ("Break", data::stop),
    ("ExitCycle", data::exit_cycle),
    ("WaitUntil", io::wait_until),
    ("WaitDI", io::wait_di),
    ("WaitDO", io::wait_di),
    ("WaitGI", io::wait_di),
    ("WaitGO", io::wait_di),
    ("WaitAI", io::wait_ai),
    ("WaitAO", io::wait_ai),
    ("SetDO", io::set_do),
    ("Set", io::set),
    ("Reset", io::reset),
    ("PulseDO", io::pulse_do),
    ("InvertDO", io::invert_do),
    ("SetAO", io::set_ao),
    ("SetGO", io::set_do),
    ("AliasIO", io::alias_io),
    ("ISignalDI", io::i_signal),
    ("ISignalDO", io::i_signal),
    ("ISignalGI", io::i_signal_any),
    ("ISignalGO", io::i_signal_any),
    ("ITimer", io::i_timer),
    ("IDelete", io::i_delete),
    ("IDisable", io::i_disable),
    ("IEnable", io::i_enable),
    ("ISleep", io::i_sleep),
    ("IWatch", io::i_watch),
    ("MoveL", motion::move_to_point),
    ("MoveJ", motion::move_to_point),
    ("MoveC", motion::move_to_point),
    ("MoveAbsJ", motion::move_abs_j),
    ("MoveLDO", motion::move_do),
    ("MoveJDO", motion::move_do),
    ("MoveCDO", motion::move_do),
    ("SearchL", motion::search),
    ("SearchJ", motion::search),
    ("SearchC", motion::search),
    ("TriggL", motion::move_to_point),
    ("TriggJ", motion::move_to_point),
    ("TriggC", motion::move_to_point),
    ("ConfL", motion::setting),
    ("ConfJ", motion::setting),
    ("SingArea", motion::setting),
    ("AccSet", motion::setting),
    ("VelSet", motion::setting),
    ("WaitRob", motion::setting),
    ("StopMove", motion::setting),
    ("StartMove", motion::setting),
    ("StorePath", motion::setting),
    ("RestoPath", motion::setting),
    ("ClearPath", motion::setting),
    ("PathResolution", motion::setting),
    ("CirPathMode", motion::setting),
    ("WorldAccLim", motion::setting),
    ("PathAccLim", motion::setting),
    ("GripLoad", motion::setting),
    ("PDispOff", motion::setting),
    ("EOffsOff", motion::setting),
    ("EOffsSet", motion::setting),
    ("EOffsOn", motion::setting),
    ("AliasIOReset", io::alias_io_reset),
    ("Open", files::open),
    ("Close", files::close),
    ("Write", files::write),
    ("WriteStrBin", files::write_str_bin),
    ("WriteBin", files::write_bin),
    ("Rewind", files::rewind),
    ("RemoveFile", files::remove_file),
    ("MakeDir", files::make_dir),
    ("RemoveDir", files::remove_dir),
];

/// The implemented functions that are not pure (the pure ones are the
/// evaluator's).
const FUNCTIONS: &[(&str, FuncFn)] = &[
    ("Dim", data::dim),
    ("StrToVal", data::str_to_val),
    ("ClkRead", data::clk_read),
    ("CTime", data::c_time),
    ("CDate", data::c_date),
    ("GetTime", data::get_time),
    ("GetTaskName", data::get_task_name),
    ("RobOS", data::rob_os),
    ("OpMode", data::op_mode),
    ("RunMode", data::run_mode),
    ("IsStopMoveAct", data::is_stop_move_act),
    ("DInput", io::input),
    ("DOutput", io::input),
    ("AInput", io::input),
    ("AOutput", io::input),
    ("GInput", io::input),
    ("GOutput", io::input),
    ("TestDI", io::test_di),
    ("CRobT", motion::c_rob_t),
    ("CPos", motion::c_pos),
    ("CJointT", motion::c_joint_t),
    ("ReadStr", files::read_str),
    ("ReadNum", files::read_num),
    ("ReadBin", files::read_bin),
    ("IsFile", files::is_file),
];

/// The implemented instruction `key` (folded): its name and code.
pub(crate) fn instruction(key: &str) -> Option<(&'static str, InsFn)> {
    INSTRUCTIONS
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(key))
        .copied()
}

/// The implemented controller function `key` (folded).
pub(crate) fn function(key: &str) -> Option<(&'static str, FuncFn)> {
    FUNCTIONS
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(key))
        .copied()
}

/// The arguments of a built-in, by the catalogue's parameter names.
pub(crate) struct Args<'a> {
    pub name: &'static str,
    sig: Option<&'static catalogue::Routine>,
    values: &'a [Option<ArgValue>],
}

impl<'a> Args<'a> {
    pub(crate) fn new(name: &'static str, values: &'a [Option<ArgValue>]) -> Args<'a> {
        let c = catalogue();
        Args {
            name,
            sig: c.instruction(name).or_else(|| c.function(name)),
            values,
        }
    }

    fn slot(&self, param: &str) -> Option<&'a ArgValue> {
        let i = self
            .sig?
            .params
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(param))?;
        self.values.get(i)?.as_ref()
    }

    /// Is `param` given as `*`?
    pub(crate) fn is_star(&self, param: &str) -> bool {
        matches!(self.slot(param), Some(ArgValue::Star))
    }

    /// The expression given for `param`, if it is an expression.
    pub(crate) fn expr(&self, param: &str) -> Option<&'a Expr> {
        match self.slot(param)? {
            ArgValue::Expr(e) => Some(e),
            _ => None,
        }
    }
}

/// A required argument's value, or the fault that says it is missing.
fn required<T>(a: &Args<'_>, param: &str, v: Option<T>) -> R<T> {
    match v {
        Some(v) => Ok(v),
        None => invalid(format!("{}: the argument {param} is missing", a.name)),
    }
}

impl Machine {
    /// Was `param` given (a switch set, an optional argument present)?
    pub(crate) fn given(&self, a: &Args<'_>, param: &str) -> bool {
        match a.slot(param) {
            None => false,
            Some(ArgValue::Conditional(s)) => !matches!(
                self.stack.get(self.base + *s as usize),
                None | Some(Slot::Absent)
            ),
            Some(_) => true,
        }
    }

    /// The value of `param`, if given.
    pub(crate) fn opt(&mut self, a: &Args<'_>, param: &str) -> R<Option<Value>> {
        match a.slot(param) {
            None => Ok(None),
            Some(ArgValue::Expr(e)) => self.eval(e).map(Some),
            Some(ArgValue::Switch) => Ok(Some(Value::Bool(true))),
            Some(ArgValue::Star) => invalid(format!("{}: * stands for {param}", a.name)),
            Some(ArgValue::Conditional(s)) => {
                let s = *s;
                match self.stack.get(self.base + s as usize) {
                    None | Some(Slot::Absent) => Ok(None),
                    _ => self.eval(&Expr::Local(s)).map(Some),
                }
            }
        }
    }

    /// The value of a required `param`.
    pub(crate) fn req(&mut self, a: &Args<'_>, param: &str) -> R<Value> {
        let v = self.opt(a, param)?;
        required(a, param, v)
    }

    /// A numeric argument (a signal gives its value).
    pub(crate) fn opt_num(&mut self, a: &Args<'_>, param: &str) -> R<Option<f64>> {
        match self.opt(a, param)? {
            None => Ok(None),
            Some(v) => match self.scalar(v)? {
                Value::Num(x) => Ok(Some(f64::from(x))),
                Value::Dnum(x) => Ok(Some(x)),
                other => invalid(format!(
                    "{}: {param} must be a number, not {}",
                    a.name,
                    crate::machine::describe(&other)
                )),
            },
        }
    }

    pub(crate) fn num(&mut self, a: &Args<'_>, param: &str) -> R<f64> {
        let v = self.opt_num(a, param)?;
        required(a, param, v)
    }

    pub(crate) fn opt_string(&mut self, a: &Args<'_>, param: &str) -> R<Option<String>> {
        match self.opt(a, param)? {
            None => Ok(None),
            Some(Value::Str(s)) => Ok(Some(s)),
            Some(other) => invalid(format!(
                "{}: {param} must be a string, not {}",
                a.name,
                crate::machine::describe(&other)
            )),
        }
    }

    pub(crate) fn string(&mut self, a: &Args<'_>, param: &str) -> R<String> {
        let v = self.opt_string(a, param)?;
        required(a, param, v)
    }

    /// The data `param` refers to (a `VAR`, `INOUT` or `PERS` argument).
    pub(crate) fn opt_place(&mut self, a: &Args<'_>, param: &str) -> R<Option<Place>> {
        match a.slot(param) {
            None => Ok(None),
            Some(ArgValue::Expr(e)) if e.is_place() => self.place(e).map(Some),
            Some(ArgValue::Conditional(s)) => {
                let s = *s;
                match self.stack.get(self.base + s as usize) {
                    None | Some(Slot::Absent) => Ok(None),
                    _ => self.place(&Expr::Local(s)).map(Some),
                }
            }
            Some(ArgValue::Expr(e)) if let Some(f) = e.failure() => self.failure(&f),
            Some(_) => invalid(format!(
                "{}: {param} must be a variable or a persistent",
                a.name
            )),
        }
    }

    pub(crate) fn place_arg(&mut self, a: &Args<'_>, param: &str) -> R<Place> {
        let v = self.opt_place(a, param)?;
        required(a, param, v)
    }

    /// The name of the data an argument names directly (`p10`), for
    /// traces and booked error names.
    pub(crate) fn arg_name(&self, a: &Args<'_>, param: &str) -> Option<String> {
        match a.expr(param)? {
            Expr::Global(g) => self.prog.globals.get(*g as usize).map(|g| g.name.clone()),
            Expr::Local(s) => self
                .frames
                .last()
                .and_then(|f| f.routine.slots.get(*s as usize))
                .map(|s| s.name.clone()),
            _ => None,
        }
    }
}
