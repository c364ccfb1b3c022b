//! The RAPID Message Queue's instructions between the controller's tasks
//! ([`crate::rmq`]): `RMQFindSlot`, `RMQSendMessage`, `IRMQMessage` and
//! `RMQGetMessage` (interrupt mode), `RMQReadWait` and `RMQSendWait`
//! (synchronous mode), `RMQGetMsgHeader`, `RMQGetMsgData`,
//! `RMQEmptyQueue`, `RMQGetSlotName`.

use rapid_analyzer::names::fold;
use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, Timeout, Wait, WaitKind, fault, named_error};
use crate::rmq::{self, Message};
use crate::world::WAIT_MAX;

/// `RMQReadWait`'s and `RMQSendWait`'s time-out when none is given.
const DEFAULT_TIMEOUT: f64 = 60.0;

fn error<T>(cx: &Cx<'_>, name: &str, message: String) -> R<T> {
    fault(named_error(&cx.m.prog, name, message))
}

fn own(cx: &Cx<'_>) -> usize {
    cx.m.number.saturating_sub(1)
}

/// The slot's name of task `task`: `RMQ_` and its name.
fn slot_name(cx: &Cx<'_>, task: usize) -> String {
    format!("RMQ_{}", cx.sh.names.get(task).map_or("", String::as_str))
}

/// The task a slot argument names, or `ERR_RMQ_INVALID`.
fn slot_arg(cx: &mut Cx<'_>, a: &Args) -> R<usize> {
    let v = cx.req(a, "Slot")?;
    match rmq::slot_task(&v).filter(|t| *t < cx.sh.names.len()) {
        Some(t) => Ok(t),
        None => error(
            cx,
            "ERR_RMQ_INVALID",
            format!("{}: the slot is not one RMQFindSlot found", a.name),
        ),
    }
}

/// The received message an argument holds, or `ERR_RMQ_INVMSG`.
fn message_arg(cx: &mut Cx<'_>, a: &Args) -> R<Message> {
    let v = cx.req(a, "Message")?;
    match rmq::message_handle(&v).and_then(|h| cx.sh.rmq.get(h)) {
        Some(m) => Ok(m.clone()),
        None => error(
            cx,
            "ERR_RMQ_INVMSG",
            format!("{}: the message was never received", a.name),
        ),
    }
}

/// `RMQFindSlot Slot, Name`: a task's queue by its name (`RMQ_T_ROB1`).
pub(crate) fn find_slot(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let name = cx.string(a, "Name")?;
    let task = (0..cx.sh.names.len()).find(|&t| slot_name(cx, t).eq_ignore_ascii_case(&name));
    let Some(task) = task else {
        return error(
            cx,
            "ERR_RMQ_NAME",
            format!(
                "RMQFindSlot: no queue is named {name} (a task's is RMQ_ and its name; clients outside the controller are not simulated)"
            ),
        );
    };
    let p = cx.place_arg(a, "Slot")?;
    cx.store(&p, rmq::slot_value(task))?;
    Ok(Done::Next)
}

/// Sends `SendData` (with `\UserDef`) to the slot's task.
fn send(cx: &mut Cx<'_>, a: &Args) -> R<()> {
    let to = slot_arg(cx, a)?;
    let value = cx.req(a, "SendData")?;
    let (datatype, dims) = rmq::type_of(&value);
    let message = Message {
        sender: own(cx),
        key: fold(&datatype),
        datatype,
        dims,
        value,
        user_def: cx.opt_num(a, "UserDef")?.unwrap_or(0.0),
    };
    cx.sh.rmq.send(to, message);
    Ok(())
}

/// `RMQSendMessage Slot, SendData [\UserDef]`.
pub(crate) fn send_message(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    send(cx, a)?;
    Ok(Done::Next)
}

/// A wait for the next message (of type `wanted`) into `Message`.
fn wait_message(cx: &mut Cx<'_>, a: &Args, wanted: Option<String>) -> R<Done> {
    let to = cx.place_arg(a, "Message")?;
    let limit = cx.opt_num(a, "TimeOut")?.unwrap_or(DEFAULT_TIMEOUT);
    let deadline = (limit < WAIT_MAX).then(|| cx.now() + limit.max(0.0));
    let what = match &wanted {
        Some(t) => format!("{} (a message of type {t})", a.name),
        None => format!("{} (a message)", a.name),
    };
    Ok(Done::Wait(Box::new(Wait {
        kind: WaitKind::Message { to, wanted },
        deadline,
        on_timeout: Timeout::Error(
            "ERR_RMQ_TIMEOUT",
            format!("{}: no message came within {} s", a.name, limit),
        ),
        what,
    })))
}

/// `RMQReadWait Message [\TimeOut]`.
pub(crate) fn read_wait(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    wait_message(cx, a, None)
}

/// `RMQSendWait Slot, SendData [\UserDef], Message, ReceiveDataType
/// [\TimeOut]`: sends, then waits for a message of `ReceiveDataType`'s type.
pub(crate) fn send_wait(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    send(cx, a)?;
    let wanted = cx.req(a, "ReceiveDataType")?;
    let (ty, _) = rmq::type_of(&wanted);
    wait_message(cx, a, Some(fold(&ty)))
}

/// `IRMQMessage InterruptDataType, Interrupt`.
pub(crate) fn irmq_message(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let data = cx.req(a, "InterruptDataType")?;
    let id = cx.num(a, "Interrupt")? as i32;
    if !cx.m.interrupts.is_connected(id) {
        return error(
            cx,
            "ERR_UNKINO",
            "IRMQMessage: the interrupt is not connected to a trap routine".to_owned(),
        );
    }
    let (ty, _) = rmq::type_of(&data);
    let ty = fold(&ty);
    cx.m.interrupts.rmq.retain(|(t, i)| *i != id && *t != ty);
    cx.m.interrupts.rmq.push((ty, id));
    Ok(Done::Next)
}

/// `RMQGetMessage Message`: the message whose arrival ran the trap.
pub(crate) fn get_message(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let Some(h) = cx.m.rmq_received.pop_front() else {
        return error(
            cx,
            "ERR_RMQ_NOMSG",
            "RMQGetMessage: no message came (it is taken in the trap routine of IRMQMessage)"
                .to_owned(),
        );
    };
    let p = cx.place_arg(a, "Message")?;
    cx.store(&p, rmq::message_value(h))?;
    Ok(Done::Next)
}

/// `RMQGetMsgHeader Message [\Header] [\SenderId] [\UserDef]`.
pub(crate) fn get_msg_header(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let m = message_arg(cx, a)?;
    if let Some(p) = cx.opt_place(a, "Header")? {
        let dim = |i: usize| Value::Num(m.dims.get(i).copied().unwrap_or(0) as f32);
        let header = Value::Record {
            ty: "rmqheader".to_owned(),
            fields: vec![
                ("datatype".to_owned(), Value::Str(m.datatype.clone())),
                ("ndim".to_owned(), Value::Num(m.dims.len() as f32)),
                ("dim1".to_owned(), dim(0)),
                ("dim2".to_owned(), dim(1)),
                ("dim3".to_owned(), dim(2)),
            ],
        };
        cx.store(&p, header)?;
    }
    if let Some(p) = cx.opt_place(a, "SenderId")? {
        cx.store(&p, rmq::slot_value(m.sender))?;
    }
    if let Some(p) = cx.opt_place(a, "UserDef")? {
        cx.store(&p, Value::Num(m.user_def as f32))?;
    }
    Ok(Done::Next)
}

/// `RMQGetMsgData Message, Data`: `ERR_RMQ_VALUE` when `Data`'s type is
/// not the message's, `ERR_RMQ_DIM` when its dimensions are not.
pub(crate) fn get_msg_data(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let m = message_arg(cx, a)?;
    let p = cx.place_arg(a, "Data")?;
    let now = cx.m.load(cx.sh, &p)?;
    let (ty, dims) = rmq::type_of(&now);
    if !ty.eq_ignore_ascii_case(&m.datatype) {
        return error(
            cx,
            "ERR_RMQ_VALUE",
            format!(
                "RMQGetMsgData: the message holds a {}, the data is a {ty}",
                m.datatype
            ),
        );
    }
    if dims != m.dims {
        return error(
            cx,
            "ERR_RMQ_DIM",
            format!(
                "RMQGetMsgData: the message's dimensions are {:?}, the data's {dims:?}",
                m.dims
            ),
        );
    }
    cx.store(&p, m.value)?;
    Ok(Done::Next)
}

/// `RMQEmptyQueue`: the task's queue, and the messages taken and not yet
/// read, are dropped.
pub(crate) fn empty_queue(cx: &mut Cx<'_>, _: &mut Args) -> R<Done> {
    let own = own(cx);
    cx.sh.rmq.clear(own);
    cx.m.rmq_received.clear();
    Ok(Done::Next)
}

/// `RMQGetSlotName(Slot)`.
pub(crate) fn get_slot_name(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let task = slot_arg(cx, a)?;
    Ok(Value::Str(slot_name(cx, task)))
}
