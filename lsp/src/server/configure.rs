//! Resolving the settings: `rapid.toml` with the client's settings over it.

use rapid_analyzer::format::FormatOptions;
use serde_json::Value;

use super::settings::Settings;

use super::backend::*;

impl Backend {
    /// Resolves the settings again: `rapid.toml` from the first workspace
    /// folder, the client's settings over it (`client`, or the last ones).
    pub(super) fn reload_settings(&self, client: Option<&Value>) -> Vec<String> {
        let (roots, client) = {
            let mut s = self.shared.lock();
            if let Some(c) = client {
                s.client_settings = c.clone();
            }
            (s.roots.clone(), s.client_settings.clone())
        };
        let root = roots.first().cloned().unwrap_or_default();
        let mut problems = Vec::new();
        let file =
            crate::config::find(&root).and_then(|path| match crate::config::read_text(&path) {
                Ok(text) => Some((path, text)),
                Err(e) => {
                    problems.push(format!("{}: {e}", path.display()));
                    None
                }
            });
        let (settings, more) = Settings::resolve(
            &client,
            file.as_ref().map(|(p, t)| (p.as_path(), t.as_str())),
            &root,
        );
        problems.extend(more);
        self.mutate("applying settings", |s| {
            s.ws.set_controller(settings.config.controller.resolve().unwrap_or_default());
            s.settings = settings;
            s.config_generation += 1;
        });
        problems
    }

    pub(super) fn format_options(&self) -> FormatOptions {
        self.shared.lock().settings.config.format.options()
    }
}
