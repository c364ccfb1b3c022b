//! The instructions and functions of the simulated controller. Each gets
//! its arguments bound to the catalogue's parameters of the task's view
//! (the binding the compiler made, [`crate::code::BuiltinSite`]) and reads
//! them by parameter name; waits come back as data ([`Done::Wait`]).
//!
//! Anything the catalogue knows and this module does not implement stops
//! a run with "not supported in simulation: NAME".

pub(crate) mod anybin;
pub(crate) mod arc;
pub(crate) mod calibration;
pub(crate) mod config;
pub(crate) mod data;
pub(crate) mod displacement;
pub(crate) mod dnum;
pub(crate) mod files;
pub(crate) mod gripper;
pub(crate) mod io;
pub(crate) mod modules;
pub(crate) mod motion;
pub(crate) mod output;
pub(crate) mod paths;
pub(crate) mod pendant;
pub(crate) mod rawbytes;
pub(crate) mod rmq;
pub(crate) mod save;
pub(crate) mod search;
pub(crate) mod settings;
pub(crate) mod sockets;
pub(crate) mod symbols;
pub(crate) mod tasks;
pub(crate) mod texts;
pub(crate) mod triggs;
pub(crate) mod units;
pub(crate) mod zones;

use rapid_analyzer::catalogue::Routine as CatalogueRoutine;
use rapid_evaluator::Value;

use crate::controller::Shared;
use crate::machine::{ArgVal, Machine, Place, R, Root, Wait, invalid};

/// What an instruction leaves the task to do.
pub(crate) enum Done {
    /// Go on with the next operation.
    Next,
    /// Wait (the instruction is done when the wait ends).
    Wait(Box<Wait>),
    /// Call the procedure of the program without arguments (`CallByVar`).
    Call(u32),
    /// Run the statement that raised the error again, as `RETRY` does
    /// (`StartMoveRetry`).
    Retry,
}

/// A non-value object of the controller (an open file or folder, a
/// socket, a message queue's slot, a received message): a record of its
/// type holding the number the controller knows it by.
pub(crate) fn handle_value(ty: &str, n: f64) -> Value {
    Value::Record {
        ty: ty.to_owned(),
        fields: vec![("handle".to_owned(), Value::Num(n as f32))],
    }
}

/// The number a [`handle_value`] holds (`None`: not one, as before the
/// object is made).
pub(crate) fn handle_in(v: &Value) -> Option<f64> {
    v.field("handle").and_then(Value::as_f64)
}

/// A built-in's view of the machine and the controller.
pub(crate) struct Cx<'a> {
    pub m: &'a mut Machine,
    pub sh: &'a mut Shared,
}

/// An instruction of the simulated controller.
pub(crate) type InsFn = fn(&mut Cx<'_>, &mut Args) -> R<Done>;
/// A function of the simulated controller.
pub(crate) type FuncFn = fn(&mut Cx<'_>, &mut Args) -> R<Value>;

/// The implemented instructions, by their catalogue names.
const INSTRUCTIONS: &[(&str, InsFn)] = &[
    ("TPWrite", output::tp_write),
    ("ErrWrite", output::err_write),
    ("ErrLog", output::err_log),
    ("ErrRaise", output::err_raise),
    ("SkipWarn", output::skip_warn),
    ("EventLog", output::event_log),
    ("TPErase", output::tp_erase),
    ("TPShow", output::tp_show),
    ("UIMsgWrite", output::ui_msg_write),
    ("UIMsgWriteAbort", output::ui_msg_write_abort),
    ("TPReadFK", pendant::tp_read_fk),
    ("TPReadNum", pendant::tp_read_num),
    ("TPReadDnum", pendant::tp_read_num),
    ("UIMsgBox", pendant::ui_msg_box),
    ("UIShow", output::ui_show),
    ("ExecEngine", pendant::exec_engine),
    ("g_Init", gripper::g_init),
    ("g_Calibrate", gripper::g_calibrate),
    ("g_GripIn", gripper::g_grip_in),
    ("g_JogIn", gripper::g_grip_in),
    ("g_GripOut", gripper::g_grip_out),
    ("g_JogOut", gripper::g_grip_out),
    ("g_MoveTo", gripper::g_move_to),
    ("g_Stop", gripper::g_accept),
    ("g_BlowOn1", gripper::g_accept),
    ("g_BlowOff1", gripper::g_accept),
    ("g_BlowOn2", gripper::g_accept),
    ("g_BlowOff2", gripper::g_accept),
    ("g_VacuumOn1", gripper::g_accept),
    ("g_VacuumOff1", gripper::g_accept),
    ("g_VacuumOn2", gripper::g_accept),
    ("g_VacuumOff2", gripper::g_accept),
    ("Incr", data::incr),
    ("Decr", data::decr),
    ("Add", data::add),
    ("Clear", data::clear),
    ("BitSet", data::bit_set),
    ("BitClear", data::bit_set),
    ("BookErrNo", data::book_err_no),
    ("GetDataVal", data::get_data_val),
    ("SetDataVal", data::set_data_val),
    ("SetDataSearch", symbols::set_data_search),
    ("Load", modules::load_module),
    ("UnLoad", modules::unload_module),
    ("StartLoad", modules::start_load),
    ("WaitLoad", modules::wait_load),
    ("CancelLoad", modules::cancel_load),
    ("EraseModule", modules::erase_module),
    ("SetAllDataVal", symbols::set_all_data_val),
    ("CallByVar", data::call_by_var),
    ("WaitTime", data::wait_time),
    ("ClkReset", data::clk_reset),
    ("ClkStart", data::clk_start),
    ("ClkStop", data::clk_stop),
    ("Stop", data::stop),
    ("SystemStopAction", data::system_stop_action),
    ("TextTabInstall", texts::text_tab_install),
    ("WriteAnyBin", anybin::write_any_bin),
    ("ReadAnyBin", anybin::read_any_bin),
    ("Break", data::stop),
    ("WarmStart", data::warm_start),
    ("ExitCycle", data::exit_cycle),
    ("ResetRetryCount", data::reset_retry_count),
    ("ClearIOBuff", files::clear_io_buff),
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
    ("IOEnable", io::io_enable),
    ("IODisable", io::io_disable),
    ("IOActivate", io::io_enable),
    ("IODeactivate", io::io_disable),
    ("AliasIOReset", io::alias_io_reset),
    ("ISignalDI", io::i_signal),
    ("ISignalDO", io::i_signal),
    ("ISignalGI", io::i_signal_any),
    ("ISignalGO", io::i_signal_any),
    ("ISignalAI", io::i_signal_analog),
    ("ISignalAO", io::i_signal_analog),
    ("ITimer", io::i_timer),
    ("IPers", io::i_pers),
    ("IError", io::i_error),
    ("GetTrapData", io::get_trap_data),
    ("ReadErrData", io::read_err_data),
    ("IDelete", io::i_delete),
    ("IDisable", io::i_disable),
    ("IEnable", io::i_enable),
    ("ISleep", io::i_sleep),
    ("IWatch", io::i_watch),
    ("MoveL", motion::move_to_point),
    ("MoveJ", motion::move_to_point),
    ("MoveC", motion::move_to_point),
    ("MoveAbsJ", motion::move_abs_j),
    ("MoveExtJ", motion::move_abs_j),
    ("MoveLDO", motion::move_do),
    ("MoveLSync", motion::move_sync),
    ("MoveJSync", motion::move_sync),
    ("MoveCSync", motion::move_sync),
    ("MoveJDO", motion::move_do),
    ("MoveCDO", motion::move_do),
    ("MoveLAO", motion::move_do),
    ("MoveJAO", motion::move_do),
    ("MoveCAO", motion::move_do),
    ("MoveLGO", motion::move_do),
    ("MoveJGO", motion::move_do),
    ("MoveCGO", motion::move_do),
    ("SearchL", search::search),
    ("SearchJ", search::search),
    ("SearchC", search::search),
    ("TriggL", triggs::trigg_move),
    ("TriggJ", triggs::trigg_move),
    ("TriggC", triggs::trigg_move),
    ("TriggIO", triggs::trigg_io),
    ("TriggEquip", triggs::trigg_equip),
    ("TriggInt", triggs::trigg_int),
    ("WaitRob", motion::wait_rob),
    ("SetSysData", motion::set_sys_data),
    ("GetSysData", motion::get_sys_data),
    ("MToolTCPCalib", calibration::m_tool_tcp_calib),
    ("ArcLStart", arc::arc_move),
    ("ArcL", arc::arc_move),
    ("ArcLEnd", arc::arc_move),
    ("ArcCStart", arc::arc_move),
    ("ArcC", arc::arc_move),
    ("ArcCEnd", arc::arc_move),
    ("ConfL", motion::conf),
    ("ConfJ", motion::conf),
    ("SingArea", motion::setting),
    ("AccSet", settings::acc_set),
    ("VelSet", settings::vel_set),
    ("SpeedLimAxis", settings::speed_limit),
    ("SpeedLimCheckPoint", settings::speed_limit),
    ("SpeedRefresh", settings::speed_refresh),
    ("StopMove", paths::stop_move),
    ("StartMove", paths::start_move),
    ("StopMoveReset", motion::setting),
    ("RMQFindSlot", rmq::find_slot),
    ("RMQSendMessage", rmq::send_message),
    ("RMQSendWait", rmq::send_wait),
    ("RMQReadWait", rmq::read_wait),
    ("IRMQMessage", rmq::irmq_message),
    ("RMQGetMessage", rmq::get_message),
    ("RMQGetMsgHeader", rmq::get_msg_header),
    ("RMQGetMsgData", rmq::get_msg_data),
    ("RMQEmptyQueue", rmq::empty_queue),
    ("StartMoveRetry", paths::start_move_retry),
    ("StorePath", paths::store_path),
    ("RestoPath", paths::resto_path),
    ("ClearPath", paths::clear_path),
    ("PathResol", motion::setting),
    ("MechUnitLoad", motion::setting),
    ("ActEventBuffer", motion::setting),
    ("DeactEventBuffer", motion::setting),
    ("SpyStart", motion::setting),
    ("SpyStop", motion::setting),
    ("CirPathMode", motion::setting),
    ("WorldAccLim", motion::setting),
    ("PathAccLim", motion::setting),
    ("GripLoad", motion::setting),
    ("PDispOff", displacement::p_disp_off),
    ("PDispSet", displacement::p_disp_set),
    ("PDispOn", displacement::p_disp_on),
    ("EOffsOff", motion::setting),
    ("EOffsSet", motion::setting),
    ("EOffsOn", motion::setting),
    ("Open", files::open),
    ("Close", files::close),
    ("Write", files::write),
    ("WriteStrBin", files::write_str_bin),
    ("WriteBin", files::write_bin),
    ("WriteRawBytes", files::write_raw_bytes),
    ("ReadRawBytes", files::read_raw_bytes),
    ("Rewind", files::rewind),
    ("RemoveFile", files::remove_file),
    ("MakeDir", files::make_dir),
    ("RenameFile", files::rename_file),
    ("CopyFile", files::copy_file),
    ("Save", save::save),
    ("RemoveDir", files::remove_dir),
    ("OpenDir", files::open_dir),
    ("CloseDir", files::close_dir),
    ("SocketCreate", sockets::socket_create),
    ("SocketConnect", sockets::socket_connect),
    ("SocketSend", sockets::socket_send),
    ("SocketReceive", sockets::socket_receive),
    ("SocketSendTo", sockets::socket_send_to),
    ("SocketReceiveFrom", sockets::socket_receive_from),
    ("SocketClose", sockets::socket_close),
    ("SocketBind", sockets::socket_bind),
    ("SocketListen", sockets::socket_listen),
    ("SocketAccept", sockets::socket_accept),
    ("ReadCfgData", config::read_cfg_data),
    ("WriteCfgData", config::write_cfg_data),
    ("ActUnit", units::act_unit),
    ("DeactUnit", units::deact_unit),
    ("MotionSup", motion::setting),
    ("SoftAct", motion::setting),
    ("SoftDeact", motion::setting),
    ("TuneServo", motion::setting),
    ("TuneReset", motion::setting),
    ("ClearRawBytes", rawbytes::clear_raw_bytes),
    ("CopyRawBytes", rawbytes::copy_raw_bytes),
    ("PackRawBytes", rawbytes::pack_raw_bytes),
    ("UnpackRawBytes", rawbytes::unpack_raw_bytes),
    ("WaitSyncTask", tasks::wait_sync_task),
    ("WZBoxDef", zones::wz_box_def),
    ("WZCylDef", zones::wz_cyl_def),
    ("WZSphDef", zones::wz_sph_def),
    ("WZHomeJointDef", zones::wz_home_joint_def),
    ("WZLimJointDef", zones::wz_lim_joint_def),
    ("WZDOSet", zones::wz_do_set),
    ("WZLimSup", zones::wz_lim_sup),
    ("WZEnable", zones::wz_enable),
    ("WZDisable", zones::wz_disable),
    ("WZFree", zones::wz_free),
    ("SyncMoveOn", tasks::sync_move_on),
    ("SyncMoveOff", tasks::sync_move_off),
    ("SyncMoveUndo", tasks::sync_move_undo),
    ("WaitTestAndSet", tasks::wait_test_and_set),
];

/// The implemented functions that are not pure (the pure ones are the
/// evaluator's).
const FUNCTIONS: &[(&str, FuncFn)] = &[
    ("Dim", data::dim),
    ("StrToVal", data::str_to_val),
    ("StrFormat", output::str_format),
    ("PowDnum", dnum::pow),
    ("CrossProd", dnum::cross_prod),
    ("SinDnum", dnum::trig),
    ("CosDnum", dnum::trig),
    ("TanDnum", dnum::trig),
    ("ASinDnum", dnum::inverse_trig),
    ("ACosDnum", dnum::inverse_trig),
    ("ATanDnum", dnum::inverse_trig),
    ("ATan2Dnum", dnum::atan2),
    ("BitAndDnum", dnum::two),
    ("BitOrDnum", dnum::two),
    ("BitXOrDnum", dnum::two),
    ("BitNegDnum", dnum::neg),
    ("BitLShDnum", dnum::shift),
    ("BitRShDnum", dnum::shift),
    ("BitCheckDnum", dnum::check),
    ("Max", dnum::max_min),
    ("Min", dnum::max_min),
    ("ClkRead", data::clk_read),
    ("CTime", data::c_time),
    ("CDate", data::c_date),
    ("FileTime", files::file_time),
    ("TextTabGet", texts::text_tab_get),
    ("TextGet", texts::text_get),
    ("TextTabFreeToUse", texts::text_tab_free_to_use),
    ("ModTime", modules::mod_time),
    ("GetTime", data::get_time),
    ("RobOS", data::rob_os),
    ("OpMode", data::op_mode),
    ("RunMode", data::run_mode),
    ("IsStopMoveAct", paths::is_stop_move_act),
    ("UIMessageBox", pendant::ui_message_box),
    ("UINumEntry", pendant::ui_num_entry),
    ("UIDnumEntry", pendant::ui_num_entry),
    ("UINumTune", pendant::ui_num_tune),
    ("UIDnumTune", pendant::ui_num_tune),
    ("UIAlphaEntry", pendant::ui_alpha_entry),
    ("UIListView", pendant::ui_list_view),
    ("UIClientExist", pendant::ui_client_exist),
    ("SocketGetStatus", sockets::socket_get_status),
    ("RMQGetSlotName", rmq::get_slot_name),
    ("SocketPeek", sockets::socket_peek),
    ("GetNextSym", symbols::get_next_sym),
    ("ModExist", modules::mod_exist),
    ("RawBytesLen", rawbytes::raw_bytes_len),
    ("IsMechUnitActive", units::is_mech_unit_active),
    ("GetMecUnitName", units::get_mec_unit_name),
    ("GetNextMechUnit", units::get_next_mech_unit),
    ("GetMotorTorque", units::get_motor_torque),
    ("g_GetPos", gripper::g_get_pos),
    ("g_IsCalibrated", gripper::g_is_calibrated),
    ("GetSysInfo", config::get_sys_info),
    ("IsSysId", config::is_sys_id),
    ("PPMovedInManMode", config::pp_moved_in_man_mode),
    ("GetModalPayloadMode", config::get_modal_payload_mode),
    ("CSpeedOverride", settings::c_speed_override),
    ("DInput", io::input),
    ("DOutput", io::input),
    ("AInput", io::input),
    ("AOutput", io::input),
    ("GInput", io::input),
    ("GOutput", io::input),
    ("GInputDnum", io::input_dnum),
    ("GOutputDnum", io::input_dnum),
    ("TestDI", io::test_di),
    ("GetSignalOrigin", io::get_signal_origin),
    ("ValidIO", io::valid_io),
    ("IOUnitState", io::io_unit_state),
    ("RemainingRetries", data::remaining_retries),
    ("IsPers", data::is_pers),
    ("IsVar", data::is_var),
    ("RobName", units::rob_name),
    ("FileSize", files::file_size),
    ("ArgName", data::arg_name),
    ("CRobT", motion::c_rob_t),
    ("CPos", motion::c_pos),
    ("CJointT", motion::c_joint_t),
    ("CTool", motion::c_tool),
    ("ORobT", displacement::o_rob_t),
    ("CWObj", motion::c_wobj),
    ("CalcJointT", motion::calc_joint_t),
    ("CalcRobT", motion::calc_rob_t),
    ("ReadStr", files::read_str),
    ("ReadNum", files::read_num),
    ("ReadBin", files::read_bin),
    ("ReadStrBin", files::read_str_bin),
    ("IsFile", files::is_file),
    ("ReadDir", files::read_dir),
    ("GetTaskName", tasks::get_task_name),
    ("TestAndSet", tasks::test_and_set),
    ("IsSyncMoveOn", tasks::is_sync_move_on),
    ("TaskRunMec", tasks::task_run_mec),
    ("TaskRunRob", tasks::task_run_rob),
];

/// The implemented instruction `name`: its catalogue name and code.
pub(crate) fn instruction(name: &str) -> Option<(&'static str, InsFn)> {
    INSTRUCTIONS
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .copied()
}

/// The implemented controller function `name`.
pub(crate) fn function(name: &str) -> Option<(&'static str, FuncFn)> {
    FUNCTIONS
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .copied()
}

/// The arguments of a built-in, by the catalogue's parameters (of the
/// task's view, the signature the call was bound with).
pub(crate) struct Args {
    pub name: &'static str,
    sig: &'static CatalogueRoutine,
    /// By parameter index.
    values: Vec<Option<ArgVal>>,
    /// The data each parameter's argument names, by parameter index.
    names: Vec<Option<Box<str>>>,
}

impl Args {
    pub(crate) fn new(
        name: &'static str,
        sig: &'static CatalogueRoutine,
        params: &[u32],
        names: &[Option<Box<str>>],
        given: Vec<ArgVal>,
    ) -> Args {
        let mut values: Vec<Option<ArgVal>> = vec![None; sig.params.len()];
        let mut named: Vec<Option<Box<str>>> = vec![None; sig.params.len()];
        for ((a, &i), n) in given.into_iter().zip(params).zip(names) {
            if let Some(slot) = values.get_mut(i as usize) {
                *slot = Some(a);
            }
            if let Some(slot) = named.get_mut(i as usize) {
                slot.clone_from(n);
            }
        }
        Args {
            name,
            sig,
            values,
            names: named,
        }
    }

    fn index(&self, param: &str) -> Option<usize> {
        self.sig
            .params
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(param))
    }

    fn slot(&self, param: &str) -> Option<&ArgVal> {
        self.values.get(self.index(param)?)?.as_ref()
    }

    /// Is `param` given as `*`?
    pub(crate) fn is_star(&self, param: &str) -> bool {
        matches!(self.slot(param), Some(ArgVal::Star))
    }

    /// Was `param` given (a switch set, an optional argument present)?
    pub(crate) fn given(&self, param: &str) -> bool {
        !matches!(self.slot(param), None | Some(ArgVal::Absent))
    }

    /// The place given for `param`, when a data reference was given.
    pub(crate) fn place_of(&self, param: &str) -> Option<&Place> {
        match self.slot(param)? {
            ArgVal::Place(p) => Some(p),
            _ => None,
        }
    }
}

/// A required argument's value, or the fault that says it is missing.
fn required<T>(a: &Args, param: &str, v: Option<T>) -> R<T> {
    match v {
        Some(v) => Ok(v),
        None => invalid(format!("{}: the argument {param} is missing", a.name)),
    }
}

impl Cx<'_> {
    /// The value of `param`, if given.
    pub(crate) fn opt(&mut self, a: &Args, param: &str) -> R<Option<Value>> {
        match a.slot(param) {
            None | Some(ArgVal::Absent) => Ok(None),
            Some(ArgVal::Value(v)) => Ok(Some(v.clone())),
            Some(ArgVal::Place(p)) => self.m.load(self.sh, p).map(Some),
            Some(ArgVal::Switch) => Ok(Some(Value::Bool(true))),
            Some(ArgVal::Star) => invalid(format!("{}: * stands for {param}", a.name)),
        }
    }

    /// The value of a required `param`.
    pub(crate) fn req(&mut self, a: &Args, param: &str) -> R<Value> {
        let v = self.opt(a, param)?;
        required(a, param, v)
    }

    /// A numeric argument (a signal gives its value).
    pub(crate) fn opt_num(&mut self, a: &Args, param: &str) -> R<Option<f64>> {
        match self.opt(a, param)? {
            None => Ok(None),
            Some(v) => match self.m.scalar(self.sh, v)? {
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

    pub(crate) fn num(&mut self, a: &Args, param: &str) -> R<f64> {
        let v = self.opt_num(a, param)?;
        required(a, param, v)
    }

    pub(crate) fn opt_string(&mut self, a: &Args, param: &str) -> R<Option<String>> {
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

    pub(crate) fn string(&mut self, a: &Args, param: &str) -> R<String> {
        let v = self.opt_string(a, param)?;
        required(a, param, v)
    }

    /// The data `param` refers to (a `VAR`, `INOUT` or `PERS` argument).
    pub(crate) fn opt_place(&mut self, a: &Args, param: &str) -> R<Option<Place>> {
        match a.slot(param) {
            None | Some(ArgVal::Absent) => Ok(None),
            Some(ArgVal::Place(p)) => Ok(Some(p.clone())),
            Some(_) => invalid(format!(
                "{}: {param} must be a variable or a persistent",
                a.name
            )),
        }
    }

    pub(crate) fn place_arg(&mut self, a: &Args, param: &str) -> R<Place> {
        let v = self.opt_place(a, param)?;
        required(a, param, v)
    }

    /// Stores a value at a place.
    pub(crate) fn store(&mut self, p: &Place, v: Value) -> R<()> {
        self.m.store(self.sh, p, v)
    }

    /// The name of the data an argument names directly (`p10`), for traces,
    /// booked error names and synchronization points.
    pub(crate) fn arg_name(&self, a: &Args, param: &str) -> Option<String> {
        if let Some(Some(n)) = a.index(param).and_then(|i| a.names.get(i)) {
            return Some(n.to_string());
        }
        let p = a.place_of(param)?;
        if !p.path.is_empty() {
            return None;
        }
        self.m.data_name(p.root)
    }

    /// The place of the catalogue's predefined data `name` (`tool0`,
    /// `C_PROGDISP`), the task's own, whatever the program declares.
    pub(crate) fn system_place(&self, name: &str) -> R<Place> {
        match self.m.prog.system_global(name) {
            Some(g) => Ok(Place::root(Root::Global(g))),
            None => invalid(format!("the catalogue has no {name}")),
        }
    }

    /// The simulated time now.
    pub(crate) fn now(&self) -> f64 {
        self.sh.clock
    }

    /// A line on the pendant or in the event log.
    pub(crate) fn print(&mut self, stream: crate::Stream, text: &str) {
        self.sh.print(&self.m.name, stream, text);
    }

    /// A trace of what the pendant shows, with where the program asked
    /// (`[TPErase at m.mod:4] ...`).
    pub(crate) fn trace(&mut self, text: &str) {
        let at = self
            .m
            .location()
            .map_or_else(String::new, |l| format!(" at {}:{}", l.path, l.line));
        let (what, rest) = text.split_once(": ").unwrap_or((text, ""));
        let line = format!("[{what}{at}] {rest}");
        self.sh.print(&self.m.name, crate::Stream::Trace, &line);
    }
}

impl Machine {
    /// The declared name of the data at a place's root.
    pub(crate) fn data_name(&self, root: Root) -> Option<String> {
        match root {
            Root::Global(g) => self.prog.globals.get(g as usize).map(|g| g.name.clone()),
            Root::Pers(i) => {
                let k = self.pers_map.iter().position(|&x| x == i)?;
                self.prog.pers.get(k).map(|p| p.name.clone())
            }
            Root::Stack(s) => {
                let f = self
                    .frames
                    .iter()
                    .rev()
                    .find(|f| (f.base as usize) <= s as usize)?;
                f.code
                    .slots
                    .get(s as usize - f.base as usize)
                    .map(|s| s.name.clone())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use rapid_analyzer::catalogue::base;

    /// A built-in registered under a name the catalogue does not know is
    /// never called (a program's call binds to the catalogue's name).
    #[test]
    fn every_builtin_is_a_catalogue_routine() {
        let cat = base();
        let unknown: Vec<&str> = super::INSTRUCTIONS
            .iter()
            .map(|(n, _)| *n)
            .filter(|n| cat.instruction(n).is_none())
            .chain(
                super::FUNCTIONS
                    .iter()
                    .map(|(n, _)| *n)
                    .filter(|n| cat.function(n).is_none()),
            )
            .collect();
        assert!(unknown.is_empty(), "{unknown:?}");
    }
}
