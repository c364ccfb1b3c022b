//! The built-in catalogue, from the `rapid-catalogue` crate: every RobotWare
//! built-in and option, as data. A task holds the view of it that its
//! controller has ([`crate::task::Task::catalogue`]).

pub use rapid_catalogue::*;
