//! The path page of a debug session (`plot`): the page `rapid run --plot`
//! writes, kept at the debugger's stop. At each stop and at the end the
//! adapter rewrites the page (its data at that stop: the moves so far, the
//! arm at the stop's simulated time, the move that brought the robot there)
//! and the script beside it that an open page reads to follow, and sends
//! the same state as a `rapidPath` event (`{"page", "state"}`) for an
//! editor's webview.

use std::path::PathBuf;

use rapid_runtime::Controller;
use serde_json::{Value, json};

use crate::run::trace;

pub struct PathPage {
    file: PathBuf,
    title: String,
    arm: Option<rapid_robot::Robot>,
    /// States written so far.
    seq: u64,
}

impl PathPage {
    pub fn new(file: PathBuf, title: String, arm: Option<rapid_robot::Robot>) -> PathPage {
        PathPage {
            file,
            title,
            arm,
            seq: 0,
        }
    }

    /// The script beside the page: `NAME.live.js` for `NAME.html`.
    fn live_file(&self) -> PathBuf {
        let stem = self
            .file
            .file_stem()
            .map_or_else(|| "path".into(), |s| s.to_string_lossy().into_owned());
        self.file.with_file_name(format!("{stem}.live.js"))
    }

    /// Writes the page and its script for the controller stopped in task
    /// `task` (`None`: the program ended) and gives the `rapidPath` event's
    /// body; `Err` names the file that could not be written.
    pub fn write(&mut self, c: &Controller, task: Option<usize>) -> Result<Value, String> {
        self.seq += 1;
        let at = task.and_then(|t| c.stack(t).first().map(|f| f.at.clone()));
        let several = c.tasks().len() > 1;
        let name = task
            .filter(|_| several)
            .and_then(|t| c.tasks().get(t))
            .map(|m| m.name().to_owned());
        let state = trace::followed(
            c.moves(),
            self.arm.as_ref(),
            &trace::Stopped {
                now: c.clock(),
                at: at.as_ref().map(|l| (l.path.as_str(), l.line)),
                task: name.as_deref(),
                seq: self.seq,
                ended: task.is_none(),
            },
        );
        let live = self.live_file();
        let live_name = live
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let page = trace::page(&state, &self.title, Some(&live_name));
        let written = |file: &PathBuf, text: String| {
            std::fs::write(file, text).map_err(|e| format!("{}: {e}", file.display()))
        };
        written(&self.file, page)?;
        written(&live, trace::live_script(&state))?;
        Ok(json!({ "page": self.file.to_string_lossy(), "state": state }))
    }
}
