//! The controller's world: what a program touches outside its own data.
//! Each part is a trait, so a test (or a richer simulation) substitutes
//! it; the defaults are the simulated controller's behaviour.
//!
//! | part | trait | default |
//! |---|---|---|
//! | the robot arm of a motion task | [`Robot`] | [`InstantRobot`]: moves arrive at once, no kinematics; [`ArmRobot`]: a modelled arm (kinematics, limits, move times) |
//! | files (`Open`, `Write`, `ReadStr`...) | [`FileSystem`] | [`SandboxFs`]: a folder, no path leaves it |
//! | I/O signals | [`Io`] | [`ScriptedIo`]: zero at the start, a script of timed changes |
//! | the operator at the FlexPendant | [`Pendant`] | [`ScriptedOperator`]: [`crate::Config::answers`] |
//! | sockets | [`Sockets`] | [`EmptyNetwork`]: nobody answers (`rapid run`: the host's) |
//! | printed lines (`TPWrite`, `ErrWrite`) | [`crate::Output`] | the caller's sink |
//! | the configuration and identity (`ReadCfgData`, `GetSysInfo`) | [`System`] | [`crate::Config::system`]: the backup's `SYSPAR` files and `BACKINFO` |

mod arm;
mod files;
mod io;
mod pendant;
mod robot;
mod sockets;
mod system;

pub use arm::ArmRobot;
pub(crate) use files::path_key;
pub use files::{FileError, FileKind, FileSystem, MemoryFs, SandboxFs};
pub use io::{Io, ScriptedIo};
pub use pendant::{Expect, NoOperator, Pendant, Question, Reply, ScriptedOperator, parse_answer};
pub use robot::{
    InstantRobot, JointTarget, Known, Motion, MoveKind, MoveRequest, MoveTarget, NO_KINEMATICS,
    Pose, RobTarget, Robot, RobotError, Speed, Tool, WObj, Zone,
};
pub use sockets::{EmptyNetwork, NoSockets, SocketError, SocketState, Sockets, WAIT_MAX};
pub use system::{CfgError, CfgValue, MechUnit, SYS_INFO_DEFAULTS, SysInfo, System};

use crate::{Config, Output};

/// The world a controller runs in (its robots are given per task, see
/// [`crate::TaskSpec`]).
pub struct World {
    pub io: Box<dyn Io>,
    pub files: Box<dyn FileSystem>,
    pub pendant: Box<dyn Pendant>,
    pub sockets: Box<dyn Sockets>,
    pub output: Box<dyn Output>,
}

impl World {
    /// The simulated controller's world: the signals scripted in `config`,
    /// files in its sandbox folder (none: file instructions are not
    /// supported), an operator who gives the answers of `config` (lines
    /// that do not parse are left out: [`ScriptedOperator::new`] says
    /// why), a network where nobody answers, lines to `output`.
    pub fn simulated(config: &Config, output: Box<dyn Output>) -> World {
        World {
            io: Box::new(ScriptedIo::new(config.signals.clone())),
            files: Box::new(SandboxFs::new(config.sandbox.clone())),
            pendant: Box::new(ScriptedOperator::new(&config.answers).unwrap_or_default()),
            sockets: Box::new(EmptyNetwork::default()),
            output,
        }
    }
}

/// A number an argument gave, in a message: as the controller prints a
/// `num` (`0.05`, not the `f64` of its `f32`), else as a `dnum`.
pub(crate) fn num_text(x: f64) -> String {
    let single = x as f32;
    if f64::from(single) == x {
        rapid_evaluator::format_num(single)
    } else {
        rapid_evaluator::format_dnum(x)
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_num_argument_is_shown_as_the_controller_prints_it() {
        assert_eq!(super::num_text(f64::from(0.05_f32)), "0.05");
        assert_eq!(super::num_text(f64::from(1.5_f32)), "1.5");
        // A dnum's value, which no f32 holds.
        assert_eq!(super::num_text(0.1), "0.1");
        assert_eq!(super::num_text(4_294_967_295.0), "4294967295");
    }
}
