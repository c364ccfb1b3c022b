//! The questions to the operator: `TPReadFK`, `TPReadNum`, `TPReadDnum`,
//! `UIMsgBox`, and the functions `UIMessageBox`, `UINumEntry`,
//! `UIDnumEntry`, `UINumTune`, `UIDnumTune`, `UIAlphaEntry`,
//! `UIListView`. The world's [`crate::world::Pendant`] answers with text,
//! read here for the question (a key's number or label, a number, a
//! button, a list item, text). An answer that comes after a delay keeps
//! the task waiting that long (simulated); `\MaxTime` ends the dialog with
//! `ERR_TP_MAXTIME`, a `\DIBreak` or `\DOBreak` signal with
//! `ERR_TP_DIBREAK` or `ERR_TP_DOBREAK` (set to 1, or to 0 with
//! `\DIPassive`/`\DOPassive`), and `\BreakFlag` takes the error instead of
//! a raise. Without an answer and without a way out, the task stops
//! waiting for the operator ([`crate::Status::Operator`]).

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, OperatorWait, Place, R, SignalTest, Timeout, Wait, WaitKind};
use crate::machine::{fault, invalid};
use crate::world::{Expect, Question, Reply};

/// The buttons of each `buttondata` value (`btnNone` is -1, `btnOK` 0
/// ...), as the `btnres` constants they answer.
const BUTTONS: &[&[&str]] = &[
    &["resOK"],
    &["resAbort", "resRetry", "resIgnore"],
    &["resOK", "resCancel"],
    &["resRetry", "resCancel"],
    &["resYes", "resNo"],
    &["resYes", "resNo", "resCancel"],
];

/// How a dialog may end other than by an answer.
struct Exits {
    max_time: Option<f64>,
    breaks: Vec<(String, SignalTest, &'static str)>,
    flag: Option<Place>,
}

fn exits(cx: &mut Cx<'_>, a: &Args) -> R<Exits> {
    let max_time = cx.opt_num(a, "MaxTime")?;
    let mut breaks = Vec::new();
    for (param, passive, error) in [
        ("DIBreak", "DIPassive", "ERR_TP_DIBREAK"),
        ("DOBreak", "DOPassive", "ERR_TP_DOBREAK"),
    ] {
        if let Some(v) = cx.opt(a, param)? {
            let (name, _) = cx.m.signal_of(cx.sh, &v)?;
            let value = if a.given(passive) { 0.0 } else { 1.0 };
            breaks.push((name, SignalTest::Equal(value), error));
        }
    }
    let flag = cx.opt_place(a, "BreakFlag")?;
    if let Some(p) = &flag {
        cx.store(p, Value::Num(0.0))?;
    }
    Ok(Exits {
        max_time,
        breaks,
        flag,
    })
}

/// A question being asked: what the operator sees, and how an answer
/// becomes a value.
struct Ask {
    question: Question,
    /// An answer's value, from its text.
    read: fn(&Ask, &str) -> Result<Value, String>,
    /// The choices' values (for [`Expect::Choice`]), by choice.
    values: Vec<Value>,
    /// `\MinValue`, `\MaxValue`, `\AsInteger` of a number.
    range: (Option<f64>, Option<f64>, bool),
    /// A `dnum` answer.
    dnum: bool,
    /// `UIListView` with buttons: how many of the choices are items (the
    /// rest are buttons), and the item chosen when a button is answered
    /// alone ([`read_item_and_button`]).
    list: Option<(usize, Value)>,
}

impl Ask {
    fn new(cx: &Cx<'_>, a: &Args, expect: Expect) -> Ask {
        let at =
            cx.m.location()
                .map_or_else(String::new, |l| format!("{}:{}", l.path, l.line));
        Ask {
            question: Question {
                instruction: a.name,
                at,
                header: String::new(),
                lines: Vec::new(),
                choices: Vec::new(),
                expect,
                initial: None,
            },
            read: match expect {
                Expect::Choice => read_choice,
                Expect::Number => read_number,
                Expect::Text => |_, t| Ok(Value::Str(t.to_owned())),
            },
            values: Vec::new(),
            range: (None, None, false),
            dnum: false,
            list: None,
        }
    }

    /// What the operator sees, in one line (for messages).
    fn summary(&self) -> String {
        let text = if self.question.header.is_empty() {
            self.question.lines.join(" ")
        } else {
            format!("{} {}", self.question.header, self.question.lines.join(" "))
        };
        format!("{} {:?}", self.question.instruction, text.trim())
    }
}

/// A `UIListView` answer with buttons: `[item, button]`. The choices are
/// the items, then the buttons (numbered on, as the keyboard's question
/// lists them): an item (its number or text) is confirmed with the first
/// button (`OK`, `Yes`, the first of `\BtnArray`); a button alone is
/// pressed with the default item chosen; `ITEM, BUTTON` chooses the item
/// and presses the button.
fn read_item_and_button(ask: &Ask, text: &str) -> Result<Value, String> {
    let Some((items, default)) = &ask.list else {
        return read_choice(ask, text);
    };
    let pair = |item: &Value, button: Option<&Value>| {
        Value::Array(vec![
            item.clone(),
            button.cloned().unwrap_or(Value::Num(0.0)),
        ])
    };
    let first_button = ask.values.get(*items);
    match choice_index(&ask.question.choices, text) {
        Some(i) if i < *items => return Ok(pair(&ask.values[i], first_button)),
        Some(i) => return Ok(pair(default, ask.values.get(i))),
        None => {}
    }
    if let Some((item, button)) = text.rsplit_once(',')
        && let Some(i) = choice_index(&ask.question.choices[..*items], item)
        && let Some(b) = choice_index(&ask.question.choices[*items..], button)
    {
        return Ok(pair(&ask.values[i], ask.values.get(items + b)));
    }
    read_choice(ask, text)
}

/// The choice `text` names: its number (from 1) or its text.
fn choice_index(choices: &[String], text: &str) -> Option<usize> {
    let t = text.trim();
    t.parse::<usize>()
        .ok()
        .filter(|&n| n >= 1 && choices.get(n - 1).is_some_and(|c| !c.is_empty()))
        .map(|n| n - 1)
        .or_else(|| {
            choices
                .iter()
                .position(|c| !c.is_empty() && c.trim().eq_ignore_ascii_case(t))
        })
}

fn read_choice(ask: &Ask, text: &str) -> Result<Value, String> {
    let choices = &ask.question.choices;
    match choice_index(choices, text).and_then(|i| ask.values.get(i)) {
        Some(v) => Ok(v.clone()),
        None => {
            let shown: Vec<String> = choices
                .iter()
                .enumerate()
                .filter(|(_, c)| !c.is_empty())
                .map(|(i, c)| format!("{}) {c}", i + 1))
                .collect();
            Err(if shown.is_empty() {
                "there is nothing to choose".to_owned()
            } else {
                format!("expected one of {}", shown.join(", "))
            })
        }
    }
}

fn read_number(ask: &Ask, text: &str) -> Result<Value, String> {
    let x: f64 = text
        .trim()
        .parse()
        .ok()
        .filter(|x: &f64| x.is_finite())
        .ok_or_else(|| "expected a number".to_owned())?;
    let (min, max, integer) = ask.range;
    if integer && x.fract() != 0.0 {
        return Err("expected an integer".to_owned());
    }
    if min.is_some_and(|m| x < m) || max.is_some_and(|m| x > m) {
        let show = |v: Option<f64>| v.map_or_else(String::new, |v| v.to_string());
        return Err(format!("expected a number in {}..{}", show(min), show(max)));
    }
    Ok(if ask.dnum {
        Value::Dnum(x)
    } else {
        Value::Num(x as f32)
    })
}

/// Asks; the answer goes to `to` (an instruction's argument), or is the
/// result of the function that asked (`to` is `None`; `fallback` is its
/// result after a break with `\BreakFlag`).
fn ask(
    cx: &mut Cx<'_>,
    a: &Args,
    ask: Ask,
    to: Option<Place>,
    fallback: Value,
) -> R<Option<Value>> {
    ask_then(cx, a, ask, None, to, fallback)
}

/// The operator's answer to `ask`, read for the question: its value and
/// when it comes; `None`: nobody answers.
fn answer_of(cx: &mut Cx<'_>, ask: &Ask) -> R<Option<(Value, f64)>> {
    let Some(mut reply) = cx.sh.pendant.ask(&cx.m.name, &ask.question) else {
        return Ok(None);
    };
    // A person at the keyboard answers again until the answer fits.
    while let Err(why) = (ask.read)(ask, &reply.text)
        && cx.sh.pendant.ask_again(&reply, &why)
    {
        match cx.sh.pendant.ask(&cx.m.name, &ask.question) {
            Some(r) => reply = r,
            None => return Ok(None),
        }
    }
    let Reply { text, after, from } = reply;
    match (ask.read)(ask, &text) {
        Ok(v) => Ok(Some((v, after))),
        Err(why) => {
            let from = if from.is_empty() {
                from
            } else {
                format!(" ({from})")
            };
            fault(FaultKind::Operator(format!(
                "the answer {text:?}{from} to {} at {}: {why}",
                ask.summary(),
                ask.question.at
            )))
        }
    }
}

/// [`ask`]; with `confirm`, the answer is an item and a button
/// ([`read_item_and_button`]): the item is the result, the button goes to
/// `confirm`'s place when the dialog ends.
fn ask_then(
    cx: &mut Cx<'_>,
    a: &Args,
    ask: Ask,
    confirm: Option<Place>,
    to: Option<Place>,
    fallback: Value,
) -> R<Option<Value>> {
    let ex = exits(cx, a)?;
    let mut reply = answer_of(cx, &ask)?;
    let mut also = None;
    let waiting_for = ask.summary();
    if let (Some((Value::Array(pair), after)), Some(place)) = (&reply, confirm)
        && let [item, button] = pair.as_slice()
    {
        also = Some((place, button.clone()));
        reply = Some((item.clone(), *after));
    }
    let answer = reply.as_ref().map(|(v, _)| v.clone());
    let now = cx.now();
    let after = reply.as_ref().map(|(_, d)| *d);
    if answer.is_none() && ex.max_time.is_none() && ex.breaks.is_empty() {
        return fault(FaultKind::Operator(format!(
            "waiting for the operator at {}: {waiting_for}",
            ask.question.at,
        )));
    }
    let wait = OperatorWait {
        at: after.map(|d| now + d),
        answer: answer.clone().unwrap_or(Value::Num(0.0)),
        to: to.clone(),
        also: also.clone(),
        breaks: ex.breaks,
        flag: ex.flag,
        fallback,
    };
    let breaks_now = wait
        .breaks
        .iter()
        .any(|(s, test, _)| cx.sh.io.read(s).is_some_and(|v| test.holds(v)));
    let late = ex.max_time.is_some_and(|m| after.is_none_or(|d| d > m));
    if let Some(v) = &answer
        && after == Some(0.0)
        && !breaks_now
        && !late
    {
        if let Some((p, v)) = &also {
            cx.store(p, v.clone())?;
        }
        if let Some(p) = &to {
            cx.store(p, v.clone())?;
        }
        return Ok(Some(v.clone()));
    }
    let w = Wait {
        kind: WaitKind::Operator(Box::new(wait)),
        deadline: ex.max_time.map(|m| now + m.max(0.0)),
        on_timeout: Timeout::Error("ERR_TP_MAXTIME", String::new()),
        what: ask.summary(),
    };
    cx.m.function_wait = Some(Box::new(w));
    Ok(None)
}

/// An instruction's question: it waits when the answer is not there at
/// once.
fn ask_instruction(cx: &mut Cx<'_>, a: &Args, q: Ask, to: Option<Place>) -> R<Done> {
    ask(cx, a, q, to, Value::Num(0.0))?;
    Ok(match cx.m.function_wait.take() {
        Some(w) => Done::Wait(w),
        None => Done::Next,
    })
}

/// A function's question: its result, or a placeholder while the task
/// waits (the machine takes the result from the wait's end).
fn ask_function(cx: &mut Cx<'_>, a: &Args, q: Ask, fallback: Value) -> R<Value> {
    Ok(ask(cx, a, q, None, fallback.clone())?.unwrap_or(fallback))
}

/// The `\Message` line or the `\MsgArray` lines.
fn message_lines(cx: &mut Cx<'_>, a: &Args) -> R<Vec<String>> {
    if let Some(m) = cx.opt_string(a, "Message")? {
        return Ok(vec![m]);
    }
    strings(cx, a, "MsgArray")
}

/// The strings of an array argument.
fn strings(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<Vec<String>> {
    match cx.opt(a, param)? {
        None => Ok(Vec::new()),
        Some(Value::Array(items)) => Ok(items
            .into_iter()
            .map(|v| match v {
                Value::Str(s) => s,
                other => other.to_string(),
            })
            .collect()),
        Some(other) => invalid(format!(
            "{}: {param} must be an array of strings, not {}",
            a.name,
            crate::machine::describe(&other)
        )),
    }
}

/// The header and message of a `UI` dialog.
fn dialog(cx: &mut Cx<'_>, a: &Args, expect: Expect) -> R<Ask> {
    let mut q = Ask::new(cx, a, expect);
    q.question.header = cx.opt_string(a, "Header")?.unwrap_or_default();
    q.question.lines = message_lines(cx, a)?;
    Ok(q)
}

/// The buttons of a dialog, after `q`'s choices: `\BtnArray` (answered
/// by their number), `\Buttons` (answered by `btnres` constants), else
/// `default`.
fn buttons(cx: &mut Cx<'_>, a: &Args, q: &mut Ask, default: i64) -> R<()> {
    if a.given("BtnArray") {
        let labels = strings(cx, a, "BtnArray")?;
        q.values
            .extend((1..=labels.len()).map(|i| Value::Num(i as f32)));
        q.question.choices.extend(labels);
        return Ok(());
    }
    let set = cx.opt_num(a, "Buttons")?.map_or(default, |b| b as i64);
    let names: &[&str] = usize::try_from(set)
        .ok()
        .and_then(|i| BUTTONS.get(i))
        .copied()
        .unwrap_or(&[]);
    for n in names {
        q.question
            .choices
            .push(n.trim_start_matches("res").to_owned());
        q.values.push(cx.predefined(n)?);
    }
    Ok(())
}

/// `TPReadFK Answer, Text, FK1, FK2, FK3, FK4, FK5 [\MaxTime] [\DIBreak]
/// [\DOBreak] [\BreakFlag]`: the operator presses a function key; its
/// number (1 to 5) goes to `Answer`.
pub(crate) fn tp_read_fk(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let mut q = Ask::new(cx, a, Expect::Choice);
    q.question.lines = vec![cx.string(a, "TPText")?];
    for (i, k) in ["TPFK1", "TPFK2", "TPFK3", "TPFK4", "TPFK5"]
        .iter()
        .enumerate()
    {
        let label = match cx.opt_string(a, k)? {
            Some(s) if !a.is_star(k) => s,
            _ => String::new(),
        };
        q.question.choices.push(label);
        q.values.push(Value::Num((i + 1) as f32));
    }
    let to = cx.place_arg(a, "TPAnswer")?;
    ask_instruction(cx, a, q, Some(to))
}

/// `TPReadNum Answer, Text ...` and `TPReadDnum`: the operator enters a
/// number.
pub(crate) fn tp_read_num(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let mut q = Ask::new(cx, a, Expect::Number);
    q.question.lines = vec![cx.string(a, "TPText")?];
    q.dnum = a.name.eq_ignore_ascii_case("TPReadDnum");
    let to = cx.place_arg(a, "TPAnswer")?;
    ask_instruction(cx, a, q, Some(to))
}

/// `UIMsgBox [\Header] MsgLine1 [\MsgLine2] ... [\Buttons] | [\BtnArray]
/// [\Result] ...`: a message box; the button pressed goes to `\Result`.
pub(crate) fn ui_msg_box(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let mut q = Ask::new(cx, a, Expect::Choice);
    q.question.header = cx.opt_string(a, "Header")?.unwrap_or_default();
    for p in ["MsgLine1", "MsgLine2", "MsgLine3", "MsgLine4", "MsgLine5"] {
        if let Some(l) = cx.opt_string(a, p)? {
            q.question.lines.push(l);
        }
    }
    buttons(cx, a, &mut q, 0)?;
    let to = cx.opt_place(a, "Result")?;
    ask_instruction(cx, a, q, to)
}

/// `UIMessageBox(...)`: a message box; the button pressed (a `btnres`
/// constant, or the number of a `\BtnArray` button).
pub(crate) fn ui_message_box(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let mut q = dialog(cx, a, Expect::Choice)?;
    buttons(cx, a, &mut q, 0)?;
    let unknown = cx.predefined("resUnkwn")?;
    ask_function(cx, a, q, unknown)
}

/// `UINumEntry(...)` and `UIDnumEntry`: a number on a keypad, within
/// `\MinValue`..`\MaxValue` (an integer with `\AsInteger`).
pub(crate) fn ui_num_entry(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let mut q = dialog(cx, a, Expect::Number)?;
    q.dnum = a.name.to_ascii_lowercase().starts_with("uidnum");
    q.range = (
        cx.opt_num(a, "MinValue")?,
        cx.opt_num(a, "MaxValue")?,
        a.given("AsInteger"),
    );
    let init = cx.opt_num(a, "InitValue")?;
    q.question.initial = init.map(|x| x.to_string());
    let fallback = number(q.dnum, init.unwrap_or(0.0));
    ask_function(cx, a, q, fallback)
}

/// `UINumTune(...)` and `UIDnumTune`: the operator tunes `InitValue` by
/// `Increment`; the answer is the tuned value.
pub(crate) fn ui_num_tune(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let mut q = dialog(cx, a, Expect::Number)?;
    q.dnum = a.name.to_ascii_lowercase().starts_with("uidnum");
    q.range = (
        cx.opt_num(a, "MinValue")?,
        cx.opt_num(a, "MaxValue")?,
        false,
    );
    let init = cx.opt_num(a, "InitValue")?.unwrap_or(0.0);
    let step = cx.opt_num(a, "Increment")?;
    q.question.initial = Some(match step {
        Some(s) => format!("{init}, step {s}"),
        None => init.to_string(),
    });
    let fallback = number(q.dnum, init);
    ask_function(cx, a, q, fallback)
}

fn number(dnum: bool, x: f64) -> Value {
    if dnum {
        Value::Dnum(x)
    } else {
        Value::Num(x as f32)
    }
}

/// `UIAlphaEntry(...)`: text on a keyboard.
pub(crate) fn ui_alpha_entry(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let mut q = dialog(cx, a, Expect::Text)?;
    let init = cx.opt_string(a, "InitString")?;
    q.question.initial.clone_from(&init);
    ask_function(cx, a, q, Value::Str(init.unwrap_or_default()))
}

/// `UIListView([\Result] [\Header] ListItems ...)`: the operator chooses an
/// item (its number, 1 for the first, is the result) and, when the dialog
/// has buttons and `\Result` asks which, presses one, in one answer
/// ([`read_item_and_button`]): a `btnres` button of `\Buttons` (`OK`,
/// `Cancel`...) or a `\BtnArray` button (its number or label). Without
/// buttons, choosing the item ends the dialog.
pub(crate) fn ui_list_view(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let mut q = Ask::new(cx, a, Expect::Choice);
    q.question.header = cx.opt_string(a, "Header")?.unwrap_or_default();
    let items = match cx.req(a, "ListItems")? {
        Value::Array(items) => items,
        other => vec![other],
    };
    for (i, item) in items.iter().enumerate() {
        let text = match item.field("text") {
            Some(Value::Str(s)) => s.clone(),
            _ => item.to_string(),
        };
        q.question.choices.push(text);
        q.values.push(Value::Num((i + 1) as f32));
    }
    let default = cx.opt_num(a, "DefaultIndex")?;
    q.question.initial = default.map(|d| d.to_string());
    let mut confirm = None;
    if let Some(p) = cx.opt_place(a, "Result")? {
        let items = q.values.len();
        buttons(cx, a, &mut q, -1)?;
        // Without buttons the choice itself ends the dialog.
        if q.values.len() > items {
            q.list = Some((items, Value::Num(default.unwrap_or(1.0) as f32)));
            q.read = read_item_and_button;
            confirm = Some(p);
        }
    }
    Ok(ask_then(cx, a, q, confirm, None, Value::Num(0.0))?.unwrap_or(Value::Num(0.0)))
}

/// `ExecEngine` (Production Manager): the execution engine shows the
/// operator its menu of parts, runs the part chosen, and shows the menu
/// again, for ever. The operator answers with the part's procedure (the
/// routine a `partdata` names, a procedure without parameters). An answer
/// after a delay keeps the task waiting that long; without an answer the
/// task waits for the operator. The engine's events (`ee_event` routines)
/// and its station handling are not simulated.
pub(crate) fn exec_engine(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    // The engine's loop: after the part (or the delay), ask again.
    cx.m.again();
    if let Some(part) = cx.m.engine_part.take() {
        return run_part(cx, &part);
    }
    let mut q = Ask::new(cx, a, Expect::Text);
    q.question.header = "Production Manager:".to_owned();
    q.question.lines = vec!["the part to run (its procedure's name)".to_owned()];
    let Some((answer, after)) = answer_of(cx, &q)? else {
        return fault(FaultKind::Operator(format!(
            "waiting for the operator at {}: {}",
            q.question.at,
            q.summary()
        )));
    };
    let part = match answer {
        Value::Str(s) => s.trim().to_owned(),
        other => other.to_string(),
    };
    if after > 0.0 {
        cx.m.engine_part = Some(part);
        let until = cx.now() + after;
        return Ok(Done::Wait(Box::new(Wait::until(until, q.summary()))));
    }
    run_part(cx, &part)
}

/// The part `name` the operator chose: its procedure, called.
fn run_part(cx: &mut Cx<'_>, name: &str) -> R<Done> {
    let module = cx.m.frames.last().map_or(usize::MAX, |f| f.code.module);
    let routine = cx.m.prog.routine_named(module, name);
    let decl = routine.and_then(|id| cx.m.prog.routines.get(id as usize).map(|r| &r.decl));
    match (routine, decl) {
        (Some(id), Some(d))
            if d.kind == rapid_analyzer::items::RoutineKind::Proc
                && d.params.iter().all(|p| p.optional) =>
        {
            Ok(Done::Call(id))
        }
        _ => {
            let at =
                cx.m.location()
                    .map_or_else(String::new, |l| format!(" at {}:{}", l.path, l.line));
            fault(FaultKind::Operator(format!(
                "the answer {name:?} to ExecEngine{at}: expected the name of a procedure without parameters, the part to run"
            )))
        }
    }
}

/// `UIClientExist()`: the simulated controller has its pendant.
pub(crate) fn ui_client_exist(_: &mut Cx<'_>, _: &mut Args) -> R<Value> {
    Ok(Value::Bool(true))
}

impl Cx<'_> {
    /// The value of predefined data (`resOK`).
    pub(crate) fn predefined(&mut self, name: &str) -> R<Value> {
        let Some(g) = self.m.prog.system_global(name) else {
            return invalid(format!(
                "the predefined data {name} is not in the catalogue"
            ));
        };
        let place = Place {
            root: crate::machine::Root::Global(g),
            path: Vec::new(),
        };
        self.m.load(self.sh, &place)
    }
}
