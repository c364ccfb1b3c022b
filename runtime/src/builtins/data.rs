//! Data, time and program flow: `Incr`, `BookErrNo`, `GetDataVal`,
//! `CallByVar`, `WaitTime`, clocks, `Stop`, `Dim`, `StrToVal`.

use rapid_evaluator::{BinOp, Type, Value};

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, Place, R, Root, Status, Wait, fault, invalid, named_error};
use crate::program::Home;

fn step(cx: &mut Cx<'_>, a: &Args, op: BinOp, by: Value) -> R<Done> {
    let p = cx.place_arg(a, "Name")?;
    let v = cx.m.load(cx.sh, &p)?;
    let r = rapid_evaluator::apply_binary(op, v, by, &cx.m.prog.types)
        .or_else(|e| cx.m.eval_error(e))?;
    cx.store(&p, r)?;
    Ok(Done::Next)
}

/// `Incr Name`.
pub(crate) fn incr(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    step(cx, a, BinOp::Add, Value::Num(1.0))
}

/// `Decr Name`.
pub(crate) fn decr(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    step(cx, a, BinOp::Sub, Value::Num(1.0))
}

/// `Add Name, AddValue`.
pub(crate) fn add(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let by = cx.req(a, "AddValue")?;
    let by = cx.m.scalar(cx.sh, by)?;
    step(cx, a, BinOp::Add, by)
}

/// `BitSet BitData, BitPos` and `BitClear`: bit `BitPos` (1, the lowest,
/// to 8) of a byte set to 1 or 0; `ERR_ARGVALERR` for another position or
/// a value that is not a byte, as `BitCheck` has it.
pub(crate) fn bit_set(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let p = cx.place_arg(a, "BitData")?;
    let data = cx.m.get(cx.sh, &p).and_then(Value::as_f64).unwrap_or(0.0);
    let pos = cx.num(a, "BitPos")?;
    let bad = |what: String| fault(named_error(&cx.m.prog, "ERR_ARGVALERR", what));
    if data.fract() != 0.0 || !(0.0..=255.0).contains(&data) {
        return bad(format!("{}: {data} is not a byte (0 to 255)", a.name));
    }
    if pos.fract() != 0.0 || !(1.0..=8.0).contains(&pos) {
        return bad(format!(
            "{}: BitPos must be a whole number from 1 to 8",
            a.name
        ));
    }
    let bit = 1u8 << (pos as u32 - 1);
    let byte = data as u8;
    let new = if a.name.eq_ignore_ascii_case("BitSet") {
        byte | bit
    } else {
        byte & !bit
    };
    cx.store(&p, Value::Num(f32::from(new)))?;
    Ok(Done::Next)
}

/// `Clear Name`.
pub(crate) fn clear(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let p = cx.place_arg(a, "Name")?;
    let zero = match cx.m.get(cx.sh, &p) {
        Some(Value::Dnum(_)) => Value::Dnum(0.0),
        _ => Value::Num(0.0),
    };
    cx.store(&p, zero)?;
    Ok(Done::Next)
}

/// `BookErrNo ErrorName`: books a new error number for `RAISE`, known by
/// the variable's name in messages.
pub(crate) fn book_err_no(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let p = cx.place_arg(a, "ErrorName")?;
    let name = cx
        .arg_name(a, "ErrorName")
        .unwrap_or_else(|| "booked error".to_owned());
    let n = FIRST_BOOKED + cx.m.booked.len() as f32;
    cx.m.booked.push((n, name));
    cx.store(&p, Value::Num(n))?;
    Ok(Done::Next)
}

/// The first number `BookErrNo` gives (numbers 1 to 90 are the
/// program's own).
const FIRST_BOOKED: f32 = 500.0;

/// The data object named by a string at run time, as the running
/// routine's module sees the name.
pub(crate) fn data_named(cx: &Cx<'_>, name: &str) -> R<Place> {
    let module = cx.m.frames.last().map_or(usize::MAX, |f| f.code.module);
    data_in(cx, module, name)
}

/// The data object `name`, as module `module` sees the name.
fn data_in(cx: &Cx<'_>, module: usize, name: &str) -> R<Place> {
    let root = match cx.m.prog.data_named(module, name) {
        Some(Home::Global(g)) => Root::Global(g),
        Some(Home::Pers(k)) => match cx.m.pers_map.get(k as usize) {
            Some(&i) => Root::Pers(i),
            None => return no_symbol(cx, name),
        },
        None => return no_symbol(cx, name),
    };
    Ok(Place::root(root))
}

fn no_symbol<T>(cx: &Cx<'_>, name: &str) -> R<T> {
    fault(named_error(
        &cx.m.prog,
        "ERR_SYM_ACCESS",
        format!("there is no data object {name}"),
    ))
}

/// The data object named `name`, as the running routine's module sees
/// it, or as the module of `\Block` (a `GetNextSym` match) does.
fn data_in_block(cx: &mut Cx<'_>, a: &Args, name: &str) -> R<Place> {
    let Some(block) = cx.opt(a, "Block")? else {
        return data_named(cx, name);
    };
    match super::symbols::block_module(&block) {
        Some(module) => data_in(cx, module, name),
        None => no_symbol(cx, name),
    }
}

/// `GetDataVal Object [\Block], Value`: copies the data object named
/// `Object`.
pub(crate) fn get_data_val(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let name = cx.string(a, "Object")?;
    let from = data_in_block(cx, a, &name)?;
    let v = cx.m.load(cx.sh, &from)?;
    let p = cx.place_arg(a, "Value")?;
    cx.store(&p, v)?;
    Ok(Done::Next)
}

/// `SetDataVal Object [\Block], Value`: sets the data object named
/// `Object`.
pub(crate) fn set_data_val(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let name = cx.string(a, "Object")?;
    let to = data_in_block(cx, a, &name)?;
    let v = cx.req(a, "Value")?;
    cx.store(&to, v)?;
    Ok(Done::Next)
}

/// `CallByVar Name, Number`: calls the procedure `Name` followed by the
/// number.
pub(crate) fn call_by_var(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let name = cx.string(a, "Name")?;
    let n = cx.num(a, "Number")?;
    if n.fract() != 0.0 || n < 0.0 {
        return fault(named_error(
            &cx.m.prog,
            "ERR_REFUNKPRC",
            format!("CallByVar: {n} is not a whole number"),
        ));
    }
    procedure_named(cx, &format!("{name}{n}")).map(Done::Call)
}

/// The procedure of the program a name given at run time names, seen from
/// the running routine's module (`ERR_REFUNKPRC` when there is none,
/// `ERR_CALLPROC` when it is a function or a trap).
pub(crate) fn procedure_named(cx: &Cx<'_>, name: &str) -> R<u32> {
    let module = cx.m.frames.last().map_or(usize::MAX, |f| f.code.module);
    let Some(id) = cx.m.prog.routine_named(module, name) else {
        return fault(named_error(
            &cx.m.prog,
            "ERR_REFUNKPRC",
            format!("there is no procedure {name}"),
        ));
    };
    let is_proc =
        cx.m.prog
            .routines
            .get(id as usize)
            .is_some_and(|r| r.decl.kind == rapid_analyzer::items::RoutineKind::Proc);
    if !is_proc {
        return fault(named_error(
            &cx.m.prog,
            "ERR_CALLPROC",
            format!("{name} is not a procedure"),
        ));
    }
    Ok(id)
}

/// `WaitTime [\InPos] Time`.
pub(crate) fn wait_time(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let t = cx.num(a, "Time")?;
    if t < 0.0 {
        return fault(named_error(
            &cx.m.prog,
            "ERR_ARGVALERR",
            format!("WaitTime: {} is a negative time", crate::world::num_text(t)),
        ));
    }
    let mut until = cx.now() + t;
    if a.given("InPos") {
        until = until.max(super::motion::motion_end(cx));
    }
    Ok(Done::Wait(Box::new(Wait::until(
        until,
        format!("WaitTime {}", crate::world::num_text(t)),
    ))))
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

fn update_clock(cx: &mut Cx<'_>, a: &Args, f: impl Fn(bool, f64, f64, f64) -> Value) -> R<Done> {
    let p = cx.place_arg(a, "Clock")?;
    let (running, start, elapsed) = clock_fields(&cx.m.load(cx.sh, &p)?);
    let now = cx.now();
    cx.store(&p, f(running, start, elapsed, now))?;
    Ok(Done::Next)
}

/// `ClkReset Clock`.
pub(crate) fn clk_reset(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    update_clock(cx, a, |running, _, _, now| clock_value(running, now, 0.0))
}

/// `ClkStart Clock`.
pub(crate) fn clk_start(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    update_clock(cx, a, |running, start, elapsed, now| {
        if running {
            clock_value(true, start, elapsed)
        } else {
            clock_value(true, now, elapsed)
        }
    })
}

/// `ClkStop Clock`.
pub(crate) fn clk_stop(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    update_clock(cx, a, |running, start, elapsed, now| {
        if running {
            clock_value(false, now, elapsed + (now - start))
        } else {
            clock_value(false, start, elapsed)
        }
    })
}

/// `ClkRead(Clock [\HighRes])`: seconds, to 0.01 s (0.001 s with
/// `\HighRes`).
pub(crate) fn clk_read(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    cx.m.read_clock = true;
    let v = cx.req(a, "Clock")?;
    let (running, start, elapsed) = clock_fields(&v);
    let t = elapsed + if running { cx.now() - start } else { 0.0 };
    let unit = if a.given("HighRes") { 1000.0 } else { 100.0 };
    Ok(Value::Num(((t * unit + 1e-9).floor() / unit) as f32))
}

/// `Stop` and `Break`: the task stops.
pub(crate) fn stop(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    if a.given("AllMoveTasks") {
        cx.sh.stop_normal = Some(format!("Stop \\AllMoveTasks in {}", cx.m.name));
    }
    fault(FaultKind::Halt(Status::Stopped))
}

/// `SystemStopAction \Stop | \StopBlock | \Halt`: the program stops in
/// every normal task (with `\Halt` the motors go off: the simulation
/// stops the same way; with `\StopBlock` the cycle could not be restarted
/// from there, which a run never does). A static or semistatic task (a
/// supervisor) goes on.
pub(crate) fn system_stop_action(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let how = ["Stop", "StopBlock", "Halt"]
        .into_iter()
        .find(|s| a.given(s))
        .unwrap_or("Stop");
    let why = format!("SystemStopAction \\{how} in {}", cx.m.name);
    cx.sh.stop_normal = Some(why.clone());
    let index = cx.m.number.saturating_sub(1);
    let normal = cx
        .sh
        .kinds
        .get(index)
        .is_none_or(|k| *k == crate::controller::TaskKind::Normal);
    if normal {
        fault(FaultKind::Stopped(why))
    } else {
        Ok(Done::Next)
    }
}

/// `WarmStart`: the controller restarts, and its program stops there (it
/// does not start again by itself).
pub(crate) fn warm_start(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    cx.trace("WarmStart: the controller restarts; the program stops");
    fault(FaultKind::Halt(Status::Stopped))
}

/// `ExitCycle`: the cycle ends; a single run ends with it.
pub(crate) fn exit_cycle(_: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    fault(FaultKind::Halt(Status::Exited))
}

/// `Dim(ArrPar, DimNo)`: the size of a dimension of an array, read in
/// place.
pub(crate) fn dim(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let d = cx.num(a, "DimNo")?;
    let owned;
    let v = match a.place_of("ArrPar") {
        Some(p) => match cx.m.get(cx.sh, p) {
            Some(v) => v,
            None => return invalid("Dim: the array no longer exists"),
        },
        None => {
            owned = cx.req(a, "ArrPar")?;
            &owned
        }
    };
    let no_dim = || {
        fault(named_error(
            &cx.m.prog,
            "ERR_ILLDIM",
            format!("Dim: the array has no dimension {d}"),
        ))
    };
    let mut v = v;
    let mut k = 1.0;
    loop {
        let Value::Array(items) = v else {
            return no_dim();
        };
        if k == d {
            return Ok(Value::Num(items.len() as f32));
        }
        match items.first() {
            Some(first) if k < d => v = first,
            _ => return no_dim(),
        }
        k += 1.0;
    }
}

/// The type of a value, for reading text into data of the same type.
fn type_of_value(v: &Value) -> Option<Type> {
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
pub(crate) fn str_to_val(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let text = cx.string(a, "Str")?;
    let p = cx.place_arg(a, "Val")?;
    let Some(ty) = cx.m.get(cx.sh, &p).and_then(type_of_value) else {
        return invalid("StrToVal: the type of Val is not known");
    };
    let Some(expr) = rapid_evaluator::parse_data_literal(&text) else {
        return Ok(Value::Bool(false));
    };
    match rapid_evaluator::eval_as(&expr, Some(&ty), &cx.m.prog.types) {
        Ok(v) => {
            cx.store(&p, v)?;
            Ok(Value::Bool(true))
        }
        Err(_) => Ok(Value::Bool(false)),
    }
}

/// The day the simulated clock starts (days since 1970-01-01): Monday
/// 2024-01-01.
const START_DAY: u64 = 19_723;

/// The controller's time for simulated second `t`: seconds since
/// 1970-01-01 00:00:00 GMT (`FileTime`, `ModTime`), as a `num` holds it
/// (to 128 s at this size, as on the controller).
pub(crate) fn epoch_value(t: f64) -> Value {
    Value::Num(((START_DAY * 86_400) as f64 + t.max(0.0)) as f32)
}

/// Seconds since midnight of the simulated date, and the day.
fn time_of_day(cx: &mut Cx<'_>) -> (u64, u64) {
    cx.m.read_clock = true;
    let t = cx.now().max(0.0) as u64;
    (t % 86_400, t / 86_400)
}

/// `CTime()`: the simulated time of day, `hh:mm:ss` (runs start at
/// midnight).
pub(crate) fn c_time(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    let (s, _) = time_of_day(cx);
    Ok(Value::Str(format!(
        "{:02}:{:02}:{:02}",
        s / 3600,
        s / 60 % 60,
        s % 60
    )))
}

/// `CDate()`: the simulated date, `yyyy-mm-dd` (runs start on Monday
/// 2024-01-01).
pub(crate) fn c_date(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    let (_, day) = time_of_day(cx);
    let (y, mo, d) = civil_from_days((START_DAY + day) as i64);
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
pub(crate) fn get_time(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let (s, day) = time_of_day(cx);
    let v = if a.given("WDay") {
        (day % 7) + 1
    } else if a.given("Hour") {
        s / 3600
    } else if a.given("Min") {
        s / 60 % 60
    } else if a.given("Sec") {
        s % 60
    } else {
        return invalid("GetTime needs one of \\WDay, \\Hour, \\Min or \\Sec");
    };
    Ok(Value::Num(v as f32))
}

/// `RobOS()`: `FALSE`, as on a virtual controller.
pub(crate) fn rob_os(_: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Bool(false))
}

/// `OpMode()`: automatic mode (`OP_AUTO`).
pub(crate) fn op_mode(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    system_constant(cx, "OP_AUTO")
}

/// `RunMode()`: continuous (`RUN_CONT_CYCLE`).
pub(crate) fn run_mode(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    system_constant(cx, "RUN_CONT_CYCLE")
}

/// The value of a predefined constant of the catalogue.
fn system_constant(cx: &mut Cx<'_>, name: &str) -> R<Value> {
    match cx.m.prog.system_global(name) {
        Some(g) => Ok(cx
            .m
            .globals
            .get(g as usize)
            .cloned()
            .unwrap_or(Value::Num(0.0))),
        None => invalid(format!("the constant {name} is not in the catalogue")),
    }
}

/// `RemainingRetries()`: how many more `RETRY`s the error handler running
/// may make before the error goes to the caller (the controller's limit,
/// 4 by default, less those made for this error).
pub(crate) fn remaining_retries(cx: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    let made =
        cx.m.frames
            .iter()
            .rev()
            .find(|f| f.in_handler)
            .or(cx.m.frames.last())
            .map_or(0, |f| f.retries);
    let left = cx.sh.limits.max_retries.saturating_sub(made);
    Ok(Value::Num(left as f32))
}

/// `ResetRetryCount`: the `RETRY`s the running handler has made are
/// forgotten, so `RemainingRetries` counts from the full number again.
pub(crate) fn reset_retry_count(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    let at = cx.m.frames.iter().rposition(|f| f.in_handler);
    if let Some(f) = at
        .or(cx.m.frames.len().checked_sub(1))
        .and_then(|i| cx.m.frames.get_mut(i))
    {
        f.retries = 0;
    }
    Ok(Done::Next)
}

/// What the data object `DatObj` (an `INOUT` parameter, followed back to
/// the caller's object) is: a persistent, a variable, or neither.
fn storage_of(cx: &Cx<'_>, a: &Args) -> Option<rapid_analyzer::items::Storage> {
    use rapid_analyzer::items::Storage;
    match a.place_of("DatObj")?.root {
        Root::Pers(_) => Some(Storage::Pers),
        Root::Global(g) => cx.m.prog.globals.get(g as usize).map(|g| g.storage),
        // A routine's own data.
        Root::Stack(_) => Some(Storage::Var),
    }
}

/// `IsPers(DatObj)`: is the actual `INOUT` parameter a persistent?
pub(crate) fn is_pers(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let s = storage_of(cx, a);
    Ok(Value::Bool(s == Some(rapid_analyzer::items::Storage::Pers)))
}

/// `IsVar(DatObj)`: is the actual `INOUT` parameter a variable?
pub(crate) fn is_var(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let s = storage_of(cx, a);
    Ok(Value::Bool(s == Some(rapid_analyzer::items::Storage::Var)))
}

/// `ArgName(Parameter [\ErrorNumber])`: the name of the data object the
/// argument is: a whole object (a component or an element gives its
/// object's name), followed back through the parameters it was passed
/// by, value parameters included. A value (an expression, a literal) is
/// no data object: `ERR_ARGNAME`, or with `\ErrorNumber` that error in the
/// variable and an empty name.
pub(crate) fn arg_name(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = a
        .place_of("Parameter")
        .and_then(|p| cx.m.origin_name(p.root));
    if let Some(name) = name {
        return Ok(Value::Str(name));
    }
    if let Some(p) = cx.opt_place(a, "ErrorNumber")? {
        let errno = cx.m.prog.errnum("ERR_ARGNAME");
        cx.store(&p, Value::Num(errno))?;
        return Ok(Value::Str(String::new()));
    }
    fault(named_error(
        &cx.m.prog,
        "ERR_ARGNAME",
        "ArgName: the argument is a value, not a data object".to_owned(),
    ))
}
