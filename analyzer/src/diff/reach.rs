//! Whether a moved `robtarget` is still reachable, and in which arm
//! configuration: asked of the new side's task robot (its `MOC.cfg` or
//! `rapid.toml`) at the moves that use the target, with their tools and
//! work objects, through the very check that reports `target-out-of-reach`,
//! `joint-out-of-range` and `configuration-mismatch`
//! ([`crate::check::move_reaches`]). A target no move of the task uses by
//! name (with a known tool and work object) gets no answer: its reach
//! depends on a tool nobody wrote down.

use super::{Reach, Report};
use crate::check::{MoveReach, move_reaches};
use crate::task::Task;

/// A target's text compared with a datum's name: blanks left out, any
/// letter case (`pPath{ 3 }` is `ppath{3}`).
fn key(text: &str) -> String {
    text.chars()
        .filter(|c| !c.is_whitespace())
        .flat_map(char::to_lowercase)
        .collect()
}

impl Report {
    /// Fills in [`super::Motion::reach`] of the moved data of task
    /// `task_name` that `task` (the new side's) moves to by name. Nothing
    /// without a robot, or when no datum moved.
    pub fn annotate_reach(&mut self, task_name: &str, task: &Task) {
        let Some(robot) = task.robot.as_ref() else {
            return;
        };
        let Some(diff) = self.tasks.iter_mut().find(|t| t.name == task_name) else {
            return;
        };
        // The names of the moved data (an element's array): only the
        // files that mention one are checked.
        let moved: Vec<String> = diff
            .modules
            .iter()
            .flat_map(|m| &m.data)
            .filter(|d| d.motion.as_ref().is_some_and(|m| m.is_move()))
            .map(|d| {
                d.name
                    .split('{')
                    .next()
                    .unwrap_or_default()
                    .to_ascii_lowercase()
            })
            .collect();
        if moved.is_empty() {
            return;
        }
        let reaches = move_reaches(task, &|unit| {
            let text = unit.text.to_ascii_lowercase();
            moved.iter().any(|name| text.contains(name.as_str()))
        });
        let model = &robot.robot.model.name;
        for d in diff.modules.iter_mut().flat_map(|m| &mut m.data) {
            let Some(motion) = d.motion.as_mut() else {
                continue;
            };
            let name = key(&d.name);
            let at: Vec<&MoveReach> = reaches.iter().filter(|r| key(&r.target) == name).collect();
            motion.reach = judge(task, model, &at);
        }
    }
}

/// The answer for one target from its moves: not reachable when any move
/// cannot reach it (that move said), else the configuration of the first.
fn judge(task: &Task, model: &str, moves: &[&MoveReach]) -> Option<Reach> {
    let first = moves.first()?;
    let failed = moves.iter().find(|m| m.result.is_err()).unwrap_or(first);
    let line = task.units.get(failed.unit).map(|u| {
        u.text[..failed.offset.min(u.text.len())]
            .matches('\n')
            .count()
            + 1
    });
    let place = match (task.units.get(failed.unit), line) {
        (Some(u), Some(line)) => {
            let file = u.path.rsplit(['/', '\\']).next().unwrap_or(&u.path);
            format!("{} at {file}:{line}", failed.instruction)
        }
        _ => failed.instruction.clone(),
    };
    Some(match &failed.result {
        Ok(solution) => Reach {
            reachable: true,
            detail: format!("conf {} on the {model}", solution.conf),
        },
        Err(e) => Reach {
            reachable: false,
            detail: format!("{e} ({place}, {model})"),
        },
    })
}
