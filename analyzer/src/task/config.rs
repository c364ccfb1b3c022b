//! What a task's checks read from the controller's configuration files
//! (`EIO.cfg`, `MOC.cfg`, `SYS.cfg`), through the one reader [`crate::cfg`].

use std::collections::HashMap;

use crate::names::fold;

/// Configured I/O signals: folded name to RAPID data type.
pub type Signals = HashMap<String, &'static str>;

/// What a controller configuration file declares for RAPID programs.
#[derive(Clone, Debug, Default)]
pub struct Config {
    /// I/O signals (`EIO.cfg`); `None` when the file has no signal section.
    pub signals: Option<Signals>,
    /// Mechanical units (`MOC.cfg`, section `MECHANICAL_UNIT`), folded.
    pub mecunits: Vec<String>,
    /// The controller's tasks in order (`SYS.cfg`, section `CAB_TASKS`):
    /// their names as written. A backup keeps task *n* in `RAPID/TASKn`.
    pub tasks: Vec<String>,
    /// Modules the controller loads into tasks when it starts (`SYS.cfg`,
    /// section `CAB_TASK_MODULES`).
    pub task_modules: Vec<TaskModule>,
    /// The robots (`MOC.cfg`, sections `ROBOT` and `ARM`).
    pub robots: Vec<crate::robot::MocRobot>,
    /// How the controller runs each task of `tasks`, in the same order.
    pub task_settings: Vec<TaskSettings>,
}

/// How `SYS.cfg` (section `CAB_TASKS`) has the controller run a task.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TaskSettings {
    /// `-Name`, as written.
    pub name: String,
    /// `-Type`.
    pub kind: TaskKind,
    /// `-Entry`: the routine the task starts in; `None` for `main`.
    pub entry: Option<String>,
    /// `-MotionTask`: the task moves a robot.
    pub motion: bool,
    /// `-UseMechanicalUnitGroup`: the `MOC.cfg` group (and so the robot)
    /// a MultiMove task moves, as written.
    pub unit_group: Option<String>,
}

/// The `-Type` of a task: when the controller starts it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TaskKind {
    /// Started and stopped with the program (`NORMAL`; also when `-Type` is
    /// not given, as the configurations RobotStudio writes give it for
    /// every motion task).
    Normal,
    /// Started when the controller starts, from the beginning each time
    /// (`SEMISTATIC`).
    SemiStatic,
    /// Started when the controller starts, where it last was (`STATIC`).
    Static,
}

/// A module that `SYS.cfg` has the controller load into a task.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TaskModule {
    /// The file as written: `HOME:/user.sys`, `RELEASE:/options/...`.
    pub file: String,
    /// The task's name; `None` for every task (`-AllTask`).
    pub task: Option<String>,
}

impl TaskModule {
    /// The file's path below the controller's `HOME:` folder, if it is there.
    pub fn home_path(&self) -> Option<&str> {
        let head = self.file.get(..5)?;
        head.eq_ignore_ascii_case("home:").then(|| {
            self.file
                .get(5..)
                .unwrap_or_default()
                .trim_start_matches(['/', '\\'])
        })
    }

    /// The file's name, without folders, lowercase.
    pub fn file_name(&self) -> String {
        self.file
            .rsplit(['/', '\\', ':'])
            .next()
            .unwrap_or_default()
            .to_ascii_lowercase()
    }
}

/// Reads a configuration file ([`crate::cfg`]): the signals of `EIO.cfg`,
/// the mechanical units of `MOC.cfg`, the tasks and task modules of
/// `SYS.cfg` (whatever the file is called).
pub fn parse_config(cfg: &str) -> Config {
    config_of(&crate::cfg::parse(cfg))
}

/// What a task's checks need of a configuration file already read.
pub fn config_of(file: &crate::cfg::CfgFile) -> Config {
    let has_signals = file.types.iter().any(is_signal_type);
    let task_settings: Vec<TaskSettings> = file
        .instances("CAB_TASKS")
        .filter_map(|e| {
            let kind = match e.get("Type").map(|t| t.to_ascii_uppercase()) {
                Some(t) if t == "SEMISTATIC" => TaskKind::SemiStatic,
                Some(t) if t == "STATIC" => TaskKind::Static,
                _ => TaskKind::Normal,
            };
            Some(TaskSettings {
                name: e.get("Name")?.to_owned(),
                kind,
                entry: e.get("Entry").map(str::to_owned),
                motion: e.has("MotionTask"),
                unit_group: e.get("UseMechanicalUnitGroup").map(str::to_owned),
            })
        })
        .collect();
    let tasks = task_settings.iter().map(|t| t.name.clone()).collect();
    let task_modules = file
        .instances("CAB_TASK_MODULES")
        .filter_map(|e| {
            let file = e.get("File")?.to_owned();
            let task = e
                .get("Task")
                .filter(|_| !e.has("AllTask"))
                .map(str::to_owned);
            Some(TaskModule { file, task })
        })
        .collect();
    let mecunits = file
        .instances("MECHANICAL_UNIT")
        .filter_map(|e| e.get("name").map(fold))
        .collect();
    Config {
        signals: has_signals.then(|| signals_of(file)),
        mecunits,
        tasks,
        task_modules,
        robots: crate::robot::moc_robots(file),
        task_settings,
    }
}

/// Is this a type of I/O signals (its name holds `SIGNAL`: `EIO_SIGNAL`,
/// `EIO_USER_SIGNAL`)?
pub fn is_signal_type(t: &crate::cfg::CfgType) -> bool {
    t.name.to_ascii_uppercase().contains("SIGNAL")
}

/// The signals declared in an I/O configuration file (`EIO.cfg`): every
/// instance of a type whose name holds `SIGNAL`, with its `-Name` and
/// `-SignalType` (DI, DO, AI, AO, GI, GO).
pub fn parse_eio_signals(cfg: &str) -> Signals {
    signals_of(&crate::cfg::parse(cfg))
}

fn signals_of(file: &crate::cfg::CfgFile) -> Signals {
    let mut out = HashMap::new();
    for e in file
        .types
        .iter()
        .filter(|t| is_signal_type(t))
        .flat_map(|t| &t.instances)
    {
        let Some(name) = e.get("Name") else {
            continue;
        };
        let kind = SignalKind::from_cfg(e.get("SignalType").unwrap_or_default());
        out.insert(fold(name), kind.type_name());
    }
    out
}

/// The kind of an I/O signal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SignalKind {
    DigitalIn,
    DigitalOut,
    AnalogIn,
    AnalogOut,
    GroupIn,
    GroupOut,
}

impl SignalKind {
    /// The RAPID type of the signal (`signaldi` ...).
    pub fn type_name(self) -> &'static str {
        match self {
            SignalKind::DigitalIn => "signaldi",
            SignalKind::DigitalOut => "signaldo",
            SignalKind::AnalogIn => "signalai",
            SignalKind::AnalogOut => "signalao",
            SignalKind::GroupIn => "signalgi",
            SignalKind::GroupOut => "signalgo",
        }
    }

    /// The kind a signal's name suggests, for signals no configuration
    /// declares: `di...`, `do...`, `ai...`, `ao...`, `gi...`, `go...`; a
    /// digital input otherwise.
    pub fn guess(name: &str) -> SignalKind {
        match name.get(..2).map(str::to_ascii_lowercase).as_deref() {
            Some("do") => SignalKind::DigitalOut,
            Some("ai") => SignalKind::AnalogIn,
            Some("ao") => SignalKind::AnalogOut,
            Some("gi") => SignalKind::GroupIn,
            Some("go") => SignalKind::GroupOut,
            _ => SignalKind::DigitalIn,
        }
    }

    /// The kind of an `EIO.cfg` `-SignalType` (`DI`, `DO`, `AI`, `AO`,
    /// `GI`, `GO`); a digital input otherwise.
    pub fn from_cfg(signal_type: &str) -> SignalKind {
        match signal_type.to_ascii_uppercase().as_str() {
            "DO" => SignalKind::DigitalOut,
            "AI" => SignalKind::AnalogIn,
            "AO" => SignalKind::AnalogOut,
            "GI" => SignalKind::GroupIn,
            "GO" => SignalKind::GroupOut,
            _ => SignalKind::DigitalIn,
        }
    }

    /// How much a use that takes a signal of this kind says of it: an
    /// input can be read, an output set and read, so of two uses of one
    /// name the stronger's kind is the one the signal can be (a group or
    /// analog value over a digital one).
    pub fn strength(self) -> u8 {
        match self {
            SignalKind::DigitalIn => 1,
            SignalKind::AnalogIn | SignalKind::GroupIn => 2,
            SignalKind::DigitalOut => 3,
            SignalKind::AnalogOut | SignalKind::GroupOut => 4,
        }
    }

    /// The kind of a RAPID signal type name.
    pub fn from_type(name: &str) -> Option<SignalKind> {
        [
            SignalKind::DigitalIn,
            SignalKind::DigitalOut,
            SignalKind::AnalogIn,
            SignalKind::AnalogOut,
            SignalKind::GroupIn,
            SignalKind::GroupOut,
        ]
        .into_iter()
        .find(|k| k.type_name().eq_ignore_ascii_case(name))
    }

    /// Can the program set it?
    pub fn is_output(self) -> bool {
        matches!(
            self,
            SignalKind::DigitalOut | SignalKind::AnalogOut | SignalKind::GroupOut
        )
    }
}
