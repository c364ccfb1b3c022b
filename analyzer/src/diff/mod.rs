//! What really changed between two versions of a program: `rapid diff`'s
//! semantic comparison, as plain data.
//!
//! Each side is first reduced to a [`Snapshot`] ([`snapshot::modules_of`]
//! for each module file, in the task that resolves its names; the caller
//! groups modules into tasks and names them, and reads the configuration
//! with [`crate::cfg`]). Two snapshots are then compared by [`compare`]:
//!
//! - tasks by name (when each side has one task, those two), modules by
//!   module name whatever their file, routines, data, records and aliases
//!   by name: moving a declaration, reordering data or renaming a file
//!   changes nothing;
//! - a routine as the list of its statement lines ([`lines`]): tokens with
//!   keywords in upper case and names folded, so that white space,
//!   indentation, line breaks inside a statement, the case of keywords and
//!   names, and the order of the routine's data declarations do not
//!   count; a changed routine comes with hunks of its lines;
//! - data by declaration (storage, scope, type) and by value: the value the
//!   constant evaluator gives (a `PERS` or `VAR` gives the value it
//!   declares), so `[1,2,3]` and `[1.0, 2, 3.00]` are one value, and a
//!   target defined from a moved one has moved too; where no value is
//!   known, the initialiser's tokens are compared. Positions and frames
//!   are measured ([`values`]): distance in mm, rotation in degrees,
//!   joint angles, changed configuration and external axes; other records
//!   (`speeddata`, `zonedata`...) by field;
//! - configuration files by type, instance and attribute ([`config`]);
//! - for two RobotWare versions, the built-ins the program uses whose
//!   signature or availability differs between them ([`builtins`]).
//!
//! Moves smaller than [`Options`]' thresholds are left out and counted.
//! Nothing here reads files or fails.

use std::collections::BTreeSet;

use serde::Serialize;

use crate::catalogue::Version;
use crate::cfg::CfgFile;
use crate::items::{Scope, Storage};

pub mod builtins;
mod compare;
pub mod config;
pub mod lines;
mod reach;
pub mod snapshot;
#[cfg(test)]
mod tests;
pub mod values;

pub use compare::compare;
pub use lines::Line;

// ---------------------------------------------------------------------------
// What each side is made of.

/// One side of a comparison.
#[derive(Clone, Debug, Default)]
pub struct Snapshot {
    pub tasks: Vec<TaskSnapshot>,
    /// Configuration files, each named as the caller matches them (a path
    /// relative to the side's root: `SYSPAR/EIO.cfg`).
    pub configs: Vec<(String, CfgFile)>,
    /// The controller's RobotWare version, when the side says it.
    pub robotware: Option<Version>,
    /// Its enabled option packages (catalogue package ids).
    pub options: Vec<String>,
}

/// The modules of one task.
#[derive(Clone, Debug, Default)]
pub struct TaskSnapshot {
    /// How tasks are matched (`RAPID/TASK1`, or a folder's path).
    pub name: String,
    pub modules: Vec<ModuleSnapshot>,
}

/// A module as compared.
#[derive(Clone, Debug, Default)]
pub struct ModuleSnapshot {
    pub name: String,
    /// Its file, as the caller names it.
    pub file: String,
    /// 1-based line of `MODULE`.
    pub line: usize,
    /// Its attributes in upper case, in order (`SYSMODULE`, `NOSTEPIN`).
    pub attributes: Vec<String>,
    pub routines: Vec<RoutineSnapshot>,
    pub data: Vec<DataSnapshot>,
    /// Records and aliases: name and lines.
    pub types: Vec<TypeSnapshot>,
    /// Every name the module uses or declares, folded (to find the
    /// built-ins it uses).
    pub names: BTreeSet<String>,
    /// The names the module declares (data, routines, types), folded.
    pub declared: BTreeSet<String>,
    /// Reduced as [`snapshot::Depth::SameText`]: its file is the same on
    /// the other side, so its routines and types are not compared (they
    /// have no lines) and only its data's values are.
    pub same_text: bool,
}

/// A routine as the list of its lines.
#[derive(Clone, Debug)]
pub struct RoutineSnapshot {
    pub name: String,
    /// `PROC`, `FUNC` or `TRAP`.
    pub kind: &'static str,
    pub line: usize,
    pub lines: Vec<Line>,
}

/// A record or alias declaration.
#[derive(Clone, Debug)]
pub struct TypeSnapshot {
    pub name: String,
    pub line: usize,
    pub lines: Vec<Line>,
}

/// A module datum.
#[derive(Clone, Debug)]
pub struct DataSnapshot {
    pub name: String,
    pub line: usize,
    pub storage: Storage,
    pub scope: Scope,
    /// The type as written (`robtarget`), and its dimensions.
    pub ty: String,
    pub dims: Vec<Line>,
    /// The initialiser as written (blanks collapsed) and as compared.
    pub init: Option<Line>,
    /// Its value, when the evaluator knows it.
    pub value: Option<rapid_evaluator::Value>,
}

impl DataSnapshot {
    /// `PERS robtarget pPick`, `LOCAL CONST num n{3}`.
    pub fn declaration(&self) -> String {
        let scope = match self.scope {
            Scope::Global => "",
            Scope::Local => "LOCAL ",
            Scope::Task => "TASK ",
        };
        let dims = if self.dims.is_empty() {
            String::new()
        } else {
            let dims: Vec<&str> = self.dims.iter().map(|d| d.text.as_str()).collect();
            format!("{{{}}}", dims.join(","))
        };
        format!(
            "{scope}{} {} {}{dims}",
            self.storage.keyword(),
            self.ty,
            self.name
        )
    }
}

// ---------------------------------------------------------------------------
// What changed.

/// Thresholds below which a move is left out.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Options {
    /// A frame or position that moved less than this many mm ...
    pub moves_below_mm: f64,
    /// ... and turned less than this many degrees (and whose joints moved
    /// less) is left out of the report and counted in
    /// [`Report::ignored_moves`]. A change of configuration, of external
    /// axes or of any other field is always reported.
    pub rotations_below_deg: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    Added,
    Removed,
    Changed,
}

impl Status {
    pub fn word(self) -> &'static str {
        match self {
            Status::Added => "added",
            Status::Removed => "removed",
            Status::Changed => "changed",
        }
    }
}

/// Everything that changed.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Report {
    pub tasks: Vec<TaskDiff>,
    pub config: Vec<config::ConfigDiff>,
    /// Built-ins used whose signature differs between the two RobotWare
    /// versions (`None` when the versions are not both known or are equal).
    pub builtins: Option<builtins::BuiltinChanges>,
    /// Moves left out as smaller than the thresholds.
    pub ignored_moves: usize,
}

impl Report {
    /// Nothing changed (beyond the thresholds).
    pub fn is_empty(&self) -> bool {
        self.tasks.is_empty()
            && self.config.is_empty()
            && self.builtins.as_ref().is_none_or(|b| b.changed.is_empty())
    }

    /// Counts for a summary line: modules by status; routines, data and
    /// types of the changed modules (an added or removed module brings or
    /// takes all of its own).
    pub fn summary(&self) -> Summary {
        let mut s = Summary::default();
        for m in self.tasks.iter().flat_map(|t| &t.modules) {
            match m.status {
                Status::Added => s.modules_added += 1,
                Status::Removed => s.modules_removed += 1,
                Status::Changed => {
                    s.modules_changed += 1;
                    s.routines += m.routines.len();
                    s.types += m.types.len();
                    for d in &m.data {
                        if d.motion.as_ref().is_some_and(Motion::is_move) {
                            s.moves += 1;
                        } else {
                            s.data += 1;
                        }
                    }
                }
            }
        }
        s.config = self.config.iter().map(|c| c.instances.len()).sum();
        s.builtins = self.builtins.as_ref().map_or(0, |b| b.changed.len());
        s
    }
}

/// How many things changed, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Summary {
    pub modules_added: usize,
    pub modules_removed: usize,
    pub modules_changed: usize,
    /// Routines added, removed or changed in the changed modules.
    pub routines: usize,
    /// Data of the changed modules whose value moved a position, frame or
    /// joint.
    pub moves: usize,
    /// Other data of the changed modules added, removed or changed.
    pub data: usize,
    /// Records and aliases of the changed modules.
    pub types: usize,
    /// Configuration instances added, removed or changed.
    pub config: usize,
    pub builtins: usize,
}

/// A task added, removed or with changed modules.
#[derive(Clone, Debug, Serialize)]
pub struct TaskDiff {
    pub name: String,
    /// The old side's name when the two differ (one task on each side).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old_name: Option<String>,
    pub status: Status,
    pub modules: Vec<ModuleDiff>,
}

/// A module added, removed or changed.
#[derive(Clone, Debug, Serialize)]
pub struct ModuleDiff {
    pub name: String,
    pub status: Status,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old_file: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub new_file: Option<String>,
    /// The attributes, when they changed: (old, new).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub attributes: Option<(Vec<String>, Vec<String>)>,
    /// Data, largest moves first, then the other changes by name.
    pub data: Vec<DataDiff>,
    pub routines: Vec<RoutineDiff>,
    pub types: Vec<RoutineDiff>,
}

/// A routine (or a record or alias: `kind` `RECORD`, `ALIAS`) added,
/// removed or changed, with its lines.
#[derive(Clone, Debug, Serialize)]
pub struct RoutineDiff {
    pub name: String,
    pub kind: &'static str,
    pub status: Status,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old_line: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub new_line: Option<usize>,
    /// The changed lines with a few unchanged ones around them; an added
    /// or removed routine is one hunk of all its lines.
    pub hunks: Vec<Hunk>,
}

/// A run of lines with changes.
#[derive(Clone, Debug, Serialize)]
pub struct Hunk {
    pub lines: Vec<HunkLine>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Tag {
    Context,
    Removed,
    Added,
}

/// One line of a hunk: as written (blanks collapsed), its depth of
/// nesting, and its 1-based line on each side where it is there.
#[derive(Clone, Debug, Serialize)]
pub struct HunkLine {
    pub tag: Tag,
    pub depth: u16,
    pub text: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old_line: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub new_line: Option<usize>,
}

/// A datum (or an element of an array: `name{3}`) added, removed or
/// changed.
#[derive(Clone, Debug, Serialize)]
pub struct DataDiff {
    pub name: String,
    pub status: Status,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old: Option<DataSide>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub new: Option<DataSide>,
    /// What changed of a datum on both sides: `storage`, `scope`, `type`,
    /// `value`.
    pub changed: Vec<&'static str>,
    /// The value changed though its initialiser did not: it is computed
    /// from other data that changed.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub derived: bool,
    /// For positions, frames and joints: how far they moved.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub motion: Option<Motion>,
    /// Other components whose value changed (`v_tcp`, `tload.mass`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub fields: Vec<FieldChange>,
}

/// A declaration and value on one side.
#[derive(Clone, Debug, Serialize)]
pub struct DataSide {
    /// `PERS robtarget pPick`.
    pub declaration: String,
    /// The value as RAPID writes it, or the initialiser as written when
    /// its value is not known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<String>,
    pub line: usize,
}

/// How a position, frame or joint value moved.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Motion {
    /// Distance in mm between the positions (the largest, when the value
    /// holds several frames; a work object's is that of its user frame
    /// times its object frame).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub translation_mm: Option<f64>,
    /// Angle in degrees of the rotation between the orientations.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotation_deg: Option<f64>,
    /// The largest change of a robot joint (`jointtarget`), in degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub joints_deg: Option<f64>,
    /// The joints that changed (`robax.rax_1`...).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub joints: Vec<FieldChange>,
    /// The arm configuration (`confdata`), when it changed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conf: Option<(String, String)>,
    /// External axes that changed (`eax_a`...).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub external_axes: Vec<FieldChange>,
    /// Each frame, position or orientation inside the value that changed
    /// (`tframe`, `uframe`, `oframe`, `tload.cog`), when it is not the
    /// value itself.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub frames: Vec<FrameChange>,
    /// The robot's reach of the new position, when a robot model is known
    /// (see [`Reach`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reach: Option<Reach>,
}

impl Motion {
    /// Did anything move (rather than only a field of another kind)?
    pub fn is_move(&self) -> bool {
        self.translation_mm.is_some_and(|d| d > 0.0)
            || self.rotation_deg.is_some_and(|a| a > 0.0)
            || self.joints_deg.is_some_and(|a| a > 0.0)
            || self.conf.is_some()
            || !self.external_axes.is_empty()
    }

    /// The size a list of moves is sorted by: mm, then degrees.
    pub fn size(&self) -> (f64, f64) {
        (
            self.translation_mm.unwrap_or(0.0),
            self.rotation_deg
                .unwrap_or(0.0)
                .max(self.joints_deg.unwrap_or(0.0)),
        )
    }
}

/// Whether the new side's robot reaches a moved target at the moves that
/// use it ([`Report::annotate_reach`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Reach {
    pub reachable: bool,
    /// The configuration the robot reaches it in (`conf [0,-1,0,0] on the
    /// IRB 120`), or why not and at which move.
    pub detail: String,
}

/// A frame inside a value that moved.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FrameChange {
    pub path: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub translation_mm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotation_deg: Option<f64>,
}

/// A component whose value changed.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct FieldChange {
    pub path: String,
    pub old: String,
    pub new: String,
}
