//! The RAPID Message Queue between the controller's tasks: each task has a
//! queue (its slot is named `RMQ_` and the task's name), a message carries
//! a value with its data type's name and dimensions, its sender and a user
//! number. A task receives in interrupt mode (`IRMQMessage`: the message
//! of a subscribed type leaves the queue and runs the trap routine, which
//! takes it with `RMQGetMessage`) or in synchronous mode (`RMQReadWait`,
//! `RMQSendWait`: the task waits for the next message).
//!
//! Not simulated: clients outside the controller (PC and FlexPendant
//! applications: their slot names are unknown), the queue's size and a
//! message's size (`SYS.cfg`'s `RmqMaxNoOfMsg`, `RmqMaxMsgSize`: no
//! `ERR_RMQ_FULL`, `ERR_RMQ_MSGSIZE`), and `RmqType` (every task has a
//! queue).

use std::collections::VecDeque;

use rapid_evaluator::Value;

/// A message: what was sent, by whom.
#[derive(Clone, Debug)]
pub(crate) struct Message {
    /// The sending task's index.
    pub sender: usize,
    /// The data type's name as the sender declared it (`num`, `robjoint`),
    /// and folded, as a receiver asks for it.
    pub datatype: String,
    pub key: String,
    /// Each dimension's size (none for a single value).
    pub dims: Vec<usize>,
    pub value: Value,
    pub user_def: f64,
}

/// Every task's queue, and the messages sent (by handle).
#[derive(Default)]
pub(crate) struct Queues {
    /// Each task's queue: handles of messages not yet received.
    queues: Vec<VecDeque<u32>>,
    messages: Vec<Message>,
}

impl Queues {
    /// A queue for one more task.
    pub(crate) fn add_task(&mut self) {
        self.queues.push(VecDeque::new());
    }

    /// `message` into the queue of task `to`; its handle (`None`: no such
    /// task).
    pub(crate) fn send(&mut self, to: usize, message: Message) -> Option<u32> {
        let queue = self.queues.get_mut(to)?;
        let handle = u32::try_from(self.messages.len()).ok()?;
        self.messages.push(message);
        queue.push_back(handle);
        Some(handle)
    }

    /// The message of a handle.
    pub(crate) fn get(&self, handle: u32) -> Option<&Message> {
        self.messages.get(handle as usize)
    }

    /// Takes the first message of task `task`'s queue whose type `wanted`
    /// accepts.
    pub(crate) fn take(&mut self, task: usize, wanted: impl Fn(&Message) -> bool) -> Option<u32> {
        let queue = self.queues.get_mut(task)?;
        let messages = &self.messages;
        let at = queue
            .iter()
            .position(|h| messages.get(*h as usize).is_some_and(&wanted))?;
        queue.remove(at)
    }

    /// Does task `task`'s queue hold a message `wanted` accepts?
    pub(crate) fn has(&self, task: usize, wanted: impl Fn(&Message) -> bool) -> bool {
        self.queues.get(task).is_some_and(|q| {
            q.iter()
                .any(|h| self.messages.get(*h as usize).is_some_and(&wanted))
        })
    }

    /// `RMQEmptyQueue`: task `task`'s queue is emptied.
    pub(crate) fn clear(&mut self, task: usize) {
        if let Some(q) = self.queues.get_mut(task) {
            q.clear();
        }
    }
}

/// The data type's name and dimensions of a value as the controller's
/// messages carry them (a record's type; `num` for a number of any alias).
pub(crate) fn type_of(v: &Value) -> (String, Vec<usize>) {
    let mut dims = Vec::new();
    let mut at = v;
    while let Value::Array(items) = at {
        dims.push(items.len());
        match items.first() {
            Some(first) => at = first,
            None => break,
        }
    }
    let name = match at {
        Value::Num(_) => "num".to_owned(),
        Value::Dnum(_) => "dnum".to_owned(),
        Value::Bool(_) => "bool".to_owned(),
        Value::Str(_) => "string".to_owned(),
        Value::Record { ty, .. } => ty.clone(),
        Value::Array(_) => String::new(),
    };
    (name, dims)
}

/// A slot's value: the task's number (index + 1).
pub(crate) fn slot_value(task: usize) -> Value {
    crate::builtins::handle_value("rmqslot", (task + 1) as f64)
}

/// The task index of a slot's value (`None`: a slot never found).
pub(crate) fn slot_task(v: &Value) -> Option<usize> {
    let n = crate::builtins::handle_in(v)?;
    (n >= 1.0).then(|| n as usize - 1)
}

/// A received message's value (its handle).
pub(crate) fn message_value(handle: u32) -> Value {
    crate::builtins::handle_value("rmqmessage", f64::from(handle) + 1.0)
}

/// The handle of a received message's value (`None`: none received).
pub(crate) fn message_handle(v: &Value) -> Option<u32> {
    let n = crate::builtins::handle_in(v)?;
    (n >= 1.0).then(|| n as u32 - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_s_type_carries_its_dimensions() {
        let row = Value::Array(vec![Value::Num(1.0), Value::Num(2.0)]);
        let grid = Value::Array(vec![row.clone(), row.clone(), row]);
        assert_eq!(type_of(&grid), ("num".to_owned(), vec![3, 2]));
        assert_eq!(type_of(&Value::pos(0.0, 0.0, 0.0)).0, "pos");
    }

    #[test]
    fn messages_are_taken_by_type_in_order() {
        let mut q = Queues::default();
        q.add_task();
        let message = |v: Value| {
            let (datatype, dims) = type_of(&v);
            Message {
                sender: 0,
                key: datatype.clone(),
                datatype,
                dims,
                value: v,
                user_def: 0.0,
            }
        };
        let a = q.send(0, message(Value::Num(1.0)));
        let b = q.send(0, message(Value::Str("x".into())));
        let c = q.send(0, message(Value::Num(2.0)));
        assert_eq!(q.send(1, message(Value::Num(3.0))), None, "no task 2");
        let strings = |m: &Message| m.datatype == "string";
        assert!(q.has(0, strings));
        assert_eq!(q.take(0, strings), b);
        assert_eq!(q.take(0, |_| true), a);
        assert_eq!(q.take(0, |_| true), c);
        assert_eq!(q.take(0, |_| true), None);
    }
}
