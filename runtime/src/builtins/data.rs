//! Data, time and program flow: `Incr`, `BookErrNo`, `GetDataVal`,
//! `CallByVar`, `WaitTime`, clocks, `Stop`, `Dim`, `StrToVal`.

use rapid_evaluator::{BinOp, Type, Value};

use super::Args;
use crate::machine::{FaultKind, Machine, R, Status, fault, invalid, named_error};
use crate::types::TypesEnv;

fn step(m: &mut Machine, a: &Args<'_>, op: BinOp, by: Value) -> R<()> {
    let p = m.place_arg(a, "Name")?;
    let v = m.get(&p).cloned().unwrap_or(Value::Num(0.0));
    let r = rapid_evaluator::apply_binary(op, v, by, &TypesEnv(&m.prog.types))
        .or_else(|e| m.eval_error(e))?;
    m.store(&p, r)
}

/// `Incr Name`.
pub(crate) fn incr(m: &mut Machine, a: &Args<'_>) -> R<()> {
    step(m, a, BinOp::Add, Value::Num(1.0))
}

/// `Decr Name`.
pub(crate) fn decr(m: &mut Machine, a: &Args<'_>) -> R<()> {
    step(m, a, BinOp::Sub, Value::Num(1.0))
}

/// `Add Name, AddValue`.
pub(crate) fn add(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let by = m.req(a, "AddValue")?;
    let by = m.scalar(by)?;
    step(m, a, BinOp::Add, by)
}

/// `Clear Name`.
pub(crate) fn clear(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let p = m.place_arg(a, "Name")?;
    let zero = match m.get(&p) {
        Some(Value::Dnum(_)) => Value::Dnum(0.0),
        _ => Value::Num(0.0),
    };
    m.store(&p, zero)
}

/// `BookErrNo ErrorName`: books a new error number for `RAISE`, known by
/// the variable's name in messages.
pub(crate) fn book_err_no(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let p = m.place_arg(a, "ErrorName")?;
    let name = m
        .arg_name(a, "ErrorName")
        .unwrap_or_else(|| "booked error".to_owned());
    let n = FIRST_BOOKED + m.booked.len() as f32;
    m.booked.push((n, name));
    m.store(&p, Value::Num(n))
}

/// The first number `BookErrNo` gives (numbers 1 to 90 are the
/// program's own).
const FIRST_BOOKED: f32 = 500.0;

/// The global data object (or data of the running routine's module) named
/// by a string at run time.
fn data_named(m: &Machine, name: &str) -> Option<u32> {
    let key = name.to_ascii_lowercase();
    let module = m
        .frames
        .last()
        .and_then(|f| m.prog.routines.get(f.routine.id as usize))
        .map(|r| r.module);
    module
        .and_then(|i| m.prog.modules.get(i))
        .and_then(|md| md.data.get(&key))
        .or_else(|| m.prog.global_data.get(&key))
        .copied()
}

fn no_symbol<T>(m: &Machine, name: &str) -> R<T> {
    fault(named_error(
        &m.prog,
        "ERR_SYM_ACCESS",
        format!("there is no data object {name}"),
    ))
}

/// `GetDataVal Object, Value`: copies the data object named `Object`.
pub(crate) fn get_data_val(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let name = m.string(a, "Object")?;
    let Some(g) = data_named(m, &name) else {
        return no_symbol(m, &name);
    };
    m.ensure_global(g)?;
    let v = m
        .globals
        .get(g as usize)
        .cloned()
        .unwrap_or(Value::Num(0.0));
    let p = m.place_arg(a, "Value")?;
    m.store(&p, v)
}

/// `SetDataVal Object, Value`: sets the data object named `Object`.
pub(crate) fn set_data_val(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let name = m.string(a, "Object")?;
    let Some(g) = data_named(m, &name) else {
        return no_symbol(m, &name);
    };
    m.ensure_global(g)?;
    let v = m.req(a, "Value")?;
    let p = crate::machine::Place {
        root: crate::machine::Root::Global(g),
        path: Vec::new(),
    };
    m.store(&p, v)
}

/// `CallByVar Name, Number`: calls the procedure `Name` followed by the
/// number.
pub(crate) fn call_by_var(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let name = m.string(a, "Name")?;
    let n = m.num(a, "Number")?;
    if n.fract() != 0.0 || n < 0.0 {
        return fault(named_error(
            &m.prog,
            "ERR_REFUNKPRC",
            format!("CallByVar: {n} is not a whole number"),
        ));
    }
    m.call_by_name(&format!("{name}{n}"), &[])
}

/// `WaitTime Time`.
pub(crate) fn wait_time(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let t = m.num(a, "Time")?;
    if t < 0.0 {
        return fault(named_error(
            &m.prog,
            "ERR_ARGVALERR",
            format!("WaitTime: {t} is a negative time"),
        ));
    }
    m.wait(t)
}

fn clock_fields(v: &Value) -> (bool, f64, f64) {
    let get = |n: &str| v.field(n).and_then(Value::as_f64).unwrap_or(0.0);
    (
        matches!(v.field("running"), Some(Value::Bool(true))),
        get("start"),
        get("elapsed"),
    )
}

fn clock_value(running: bool, start: f64, elapsed: f64) -> Value {
    Value::Record {
        ty: "clock".to_owned(),
        fields: vec![
            ("running".to_owned(), Value::Bool(running)),
            ("start".to_owned(), Value::Dnum(start)),
            ("elapsed".to_owned(), Value::Dnum(elapsed)),
        ],
    }
}

fn update_clock(m: &mut Machine, a: &Args<'_>, f: impl Fn(bool, f64, f64, f64) -> Value) -> R<()> {
    let p = m.place_arg(a, "Clock")?;
    let (running, start, elapsed) = clock_fields(m.get(&p).unwrap_or(&Value::Num(0.0)));
    let now = m.ctl.clock;
    m.store(&p, f(running, start, elapsed, now))
}

/// `ClkReset Clock`.
pub(crate) fn clk_reset(m: &mut Machine, a: &Args<'_>) -> R<()> {
    update_clock(m, a, |running, _, _, now| clock_value(running, now, 0.0))
}

/// `ClkStart Clock`.
pub(crate) fn clk_start(m: &mut Machine, a: &Args<'_>) -> R<()> {
    update_clock(m, a, |running, start, elapsed, now| {
        if running {
            clock_value(true, start, elapsed)
        } else {
            clock_value(true, now, elapsed)
        }
    })
}

/// `ClkStop Clock`.
pub(crate) fn clk_stop(m: &mut Machine, a: &Args<'_>) -> R<()> {
    update_clock(m, a, |running, start, elapsed, now| {
        if running {
            clock_value(false, now, elapsed + (now - start))
        } else {
            clock_value(false, start, elapsed)
        }
    })
}

/// `ClkRead(Clock [\HighRes])`: seconds, to 0.01 s (0.001 s with
/// `\HighRes`).
pub(crate) fn clk_read(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let v = m.req(a, "Clock")?;
    let (running, start, elapsed) = clock_fields(&v);
    let t = elapsed + if running { m.ctl.clock - start } else { 0.0 };
    let unit = if m.given(a, "HighRes") { 1000.0 } else { 100.0 };
    Ok(Value::Num(((t * unit + 1e-9).floor() / unit) as f32))
}

/// `Stop` and `Break`: the program stops.
pub(crate) fn stop(_: &mut Machine, _: &Args<'_>) -> R<()> {
    fault(FaultKind::Halt(Status::Stopped))
}

/// `ExitCycle`: the cycle ends; a single run ends with it.
pub(crate) fn exit_cycle(_: &mut Machine, _: &Args<'_>) -> R<()> {
    fault(FaultKind::Halt(Status::Exited))
}

/// `Dim(ArrPar, DimNo)`: the size of a dimension of an array, read in
/// place.
pub(crate) fn dim(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let d = m.num(a, "DimNo")?;
    let owned;
    let v = match m.opt_place(a, "ArrPar") {
        Ok(Some(p)) => match m.get(&p) {
            Some(v) => v,
            None => return invalid("Dim: the array no longer exists"),
        },
        _ => {
            owned = m.req(a, "ArrPar")?;
            &owned
        }
    };
    let mut v = v;
    let mut k = 1.0;
    loop {
        let Value::Array(items) = v else {
            return fault(named_error(
                &m.prog,
                "ERR_ILLDIM",
                format!("Dim: the array has no dimension {d}"),
            ));
        };
        if k == d {
            return Ok(Value::Num(items.len() as f32));
        }
        match items.first() {
            Some(first) if k < d => v = first,
            _ => {
                return fault(named_error(
                    &m.prog,
                    "ERR_ILLDIM",
                    format!("Dim: the array has no dimension {d}"),
                ));
            }
        }
        k += 1.0;
    }
}

/// The type of a value, for reading text into data of the same type.
pub(crate) fn type_of_value(v: &Value) -> Option<Type> {
    match v {
        Value::Array(items) => {
            let inner = type_of_value(items.first()?)?;
            let mut dims = vec![items.len()];
            dims.extend(inner.dims);
            Some(Type::array(inner.name, dims))
        }
        other => other.type_name().map(Type::named),
    }
}

/// `StrToVal(Str, Val)`: reads a value written as RAPID writes it into
/// `Val`; `FALSE` (and `Val` unchanged) when the text does not fit.
pub(crate) fn str_to_val(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let text = m.string(a, "Str")?;
    let p = m.place_arg(a, "Val")?;
    let Some(ty) = m.get(&p).and_then(type_of_value) else {
        return invalid("StrToVal: the type of Val is not known");
    };
    let Some(expr) = rapid_evaluator::parse_data_literal(&text) else {
        return Ok(Value::Bool(false));
    };
    match rapid_evaluator::eval_as(&expr, Some(&ty), &TypesEnv(&m.prog.types)) {
        Ok(v) => {
            m.store(&p, v)?;
            Ok(Value::Bool(true))
        }
        Err(_) => Ok(Value::Bool(false)),
    }
}

/// Seconds since midnight of the simulated date, and the day.
fn time_of_day(m: &Machine) -> (u64, u64) {
    let t = m.ctl.clock.max(0.0) as u64;
    (t % 86_400, t / 86_400)
}

/// `CTime()`: the simulated time of day, `hh:mm:ss` (runs start at
/// midnight).
pub(crate) fn c_time(m: &mut Machine, _: &Args<'_>) -> R<Value> {
    let (s, _) = time_of_day(m);
    Ok(Value::Str(format!(
        "{:02}:{:02}:{:02}",
        s / 3600,
        s / 60 % 60,
        s % 60
    )))
}

/// `CDate()`: the simulated date, `yyyy-mm-dd` (runs start on Monday
/// 2024-01-01).
pub(crate) fn c_date(m: &mut Machine, _: &Args<'_>) -> R<Value> {
    let (_, day) = time_of_day(m);
    let (y, mo, d) = civil_from_days(19_723 + day as i64);
    Ok(Value::Str(format!("{y:04}-{mo:02}-{d:02}")))
}

/// The date of a day number (days since 1970-01-01).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let y = yoe + era * 400;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (if m <= 2 { y + 1 } else { y }, m, d)
}

/// `GetTime(\WDay | \Hour | \Min | \Sec)` of the simulated clock.
pub(crate) fn get_time(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let (s, day) = time_of_day(m);
    let v = if m.given(a, "WDay") {
        (day % 7) + 1
    } else if m.given(a, "Hour") {
        s / 3600
    } else if m.given(a, "Min") {
        s / 60 % 60
    } else if m.given(a, "Sec") {
        s % 60
    } else {
        return invalid("GetTime needs one of \\WDay, \\Hour, \\Min or \\Sec");
    };
    Ok(Value::Num(v as f32))
}

/// `GetTaskName()`: the simulated task is `T_ROB1`.
pub(crate) fn get_task_name(_: &mut Machine, _: &Args<'_>) -> R<Value> {
    Ok(Value::Str("T_ROB1".to_owned()))
}

/// `RobOS()`: `FALSE`, as on a virtual controller.
pub(crate) fn rob_os(_: &mut Machine, _: &Args<'_>) -> R<Value> {
    Ok(Value::Bool(false))
}

/// `OpMode()`: automatic mode (`OP_AUTO`).
pub(crate) fn op_mode(m: &mut Machine, _: &Args<'_>) -> R<Value> {
    system_constant(m, "OP_AUTO")
}

/// `RunMode()`: continuous (`RUN_CONT_CYCLE`).
pub(crate) fn run_mode(m: &mut Machine, _: &Args<'_>) -> R<Value> {
    system_constant(m, "RUN_CONT_CYCLE")
}

/// `IsStopMoveAct()`: `FALSE`: nothing stops the simulated motion.
pub(crate) fn is_stop_move_act(_: &mut Machine, _: &Args<'_>) -> R<Value> {
    Ok(Value::Bool(false))
}

/// The value of a predefined constant of the catalogue.
fn system_constant(m: &mut Machine, name: &str) -> R<Value> {
    let Some(&g) = m.prog.global_data.get(&name.to_ascii_lowercase()) else {
        return invalid(format!("the constant {name} is not in the catalogue"));
    };
    m.ensure_global(g)?;
    Ok(m.globals
        .get(g as usize)
        .cloned()
        .unwrap_or(Value::Num(0.0)))
}
