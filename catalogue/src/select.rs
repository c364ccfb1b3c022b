//! Views of the catalogue: what one controller (a RobotWare version and its
//! options) has.

use crate::{AltGroup, Catalogue, Param, Version};

/// A controller's RobotWare version and enabled options.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub struct Selection {
    /// The RobotWare version; `None` accepts every version (the union of
    /// their signatures).
    pub robotware: Option<Version>,
    /// Enabled option packages, by [`crate::Package::id`] (lowercase, sorted,
    /// without duplicates).
    options: Vec<String>,
}

impl Selection {
    /// A selection of a version and options (package ids, any case; unknown
    /// ids are kept and simply enable nothing).
    pub fn new(robotware: Option<Version>, options: impl IntoIterator<Item = String>) -> Selection {
        let mut options: Vec<String> = options
            .into_iter()
            .map(|o| o.trim().to_ascii_lowercase())
            .filter(|o| !o.is_empty())
            .collect();
        options.sort();
        options.dedup();
        Selection { robotware, options }
    }

    /// The enabled packages' ids.
    pub fn options(&self) -> &[String] {
        &self.options
    }

    /// Is the package `id` enabled?
    pub fn enabled(&self, id: &str) -> bool {
        self.options.iter().any(|o| o.eq_ignore_ascii_case(id))
    }
}

impl Catalogue {
    /// The package ids whose [`crate::Package::matches`] occur in `text` (an
    /// installed option's line of a backup: `689-1 Externally Guided
    /// Motion`), in catalogue order.
    pub fn packages_named_in(&self, text: &str) -> Vec<&str> {
        let lower = text.to_ascii_lowercase();
        let named = self.packages.iter().filter(|p| {
            p.matches
                .iter()
                .any(|m| contains_word(&lower, &m.to_ascii_lowercase()))
        });
        let mut out: Vec<&str> = Vec::new();
        for p in named {
            for id in std::iter::once(&p.id).chain(&p.includes) {
                if !out.contains(&id.as_str()) {
                    out.push(id);
                }
            }
        }
        out
    }

    /// The package ids `ids` with those they include ([`crate::Package::includes`]).
    pub fn with_included(&self, ids: &[String]) -> Vec<String> {
        let mut out: Vec<String> = ids.to_vec();
        for id in ids {
            if let Some(p) = self.package(id) {
                for inc in &p.includes {
                    if !out.iter().any(|o| o.eq_ignore_ascii_case(inc)) {
                        out.push(inc.clone());
                    }
                }
            }
        }
        out
    }

    /// This catalogue as the controller of `selection` has it: every entry
    /// stays (a name RobotWare knows is never unknown), but parameters and
    /// components added after the selected version are left out, and the
    /// view remembers the selection for [`Catalogue::availability`].
    pub fn select(&self, selection: &Selection) -> Catalogue {
        let mut out = Catalogue {
            functions: self.functions.clone(),
            instructions: self.instructions.clone(),
            datatypes: self.datatypes.clone(),
            data: self.data.clone(),
            packages: self.packages.clone(),
            selection: selection.clone(),
            index: Default::default(),
        };
        if let Some(v) = selection.robotware {
            for r in out.functions.iter_mut().chain(&mut out.instructions) {
                // An entry newer than the version keeps its own signature:
                // its calls are reported once as needing a newer RobotWare.
                if r.origin.since <= v {
                    let (params, groups) = params_in(&r.params, &r.alt_groups, v);
                    r.params = params;
                    r.alt_groups = groups;
                }
            }
            for t in &mut out.datatypes {
                if t.origin.since <= v {
                    t.components.retain(|c| c.since.is_none_or(|s| s <= v));
                }
            }
        }
        out.reindex();
        out
    }
}

impl Catalogue {
    /// [`Catalogue::select`], keeping only the entries the controller has
    /// (its RobotWare version, the base language and its enabled options):
    /// the catalogue of one version, for listing.
    pub fn only_available(&self, selection: &Selection) -> Catalogue {
        let mut out = self.select(selection);
        let keep = |o: &crate::Origin| out.availability(o) == crate::Availability::Yes;
        let functions: Vec<_> = out
            .functions
            .iter()
            .filter(|r| keep(&r.origin))
            .cloned()
            .collect();
        let instructions: Vec<_> = out
            .instructions
            .iter()
            .filter(|r| keep(&r.origin))
            .cloned()
            .collect();
        let datatypes: Vec<_> = out
            .datatypes
            .iter()
            .filter(|t| keep(&t.origin))
            .cloned()
            .collect();
        let data: Vec<_> = out
            .data
            .iter()
            .filter(|d| keep(&d.origin))
            .cloned()
            .collect();
        out.functions = functions;
        out.instructions = instructions;
        out.datatypes = datatypes;
        out.data = data;
        out.reindex();
        out
    }
}

/// The parameters a routine has in version `v`, with its `|` groups: a
/// group left with one member becomes a plain parameter (required when the
/// group was).
fn params_in(params: &[Param], groups: &[AltGroup], v: Version) -> (Vec<Param>, Vec<AltGroup>) {
    let mut kept: Vec<Param> = params
        .iter()
        .filter(|p| p.since.is_none_or(|s| s <= v))
        .cloned()
        .collect();
    let mut out_groups = Vec::new();
    for g in groups {
        let members: Vec<usize> = kept
            .iter()
            .enumerate()
            .filter(|(_, p)| p.alt_group == Some(g.id))
            .map(|(i, _)| i)
            .collect();
        if members.len() >= 2 {
            out_groups.push(*g);
        } else {
            for i in members {
                kept[i].alt_group = None;
                if g.required {
                    kept[i].optional = false;
                }
            }
        }
    }
    (kept, out_groups)
}

/// Whether `needle` occurs in `hay` not inside a longer word.
fn contains_word(hay: &str, needle: &str) -> bool {
    if needle.is_empty() {
        return false;
    }
    let word = |c: Option<char>| c.is_some_and(|c| c.is_ascii_alphanumeric());
    let mut from = 0;
    while let Some(i) = hay[from..].find(needle) {
        let start = from + i;
        let end = start + needle.len();
        if !word(hay[..start].chars().next_back()) && !word(hay[end..].chars().next()) {
            return true;
        }
        from = start + needle.len().max(1);
        if from >= hay.len() {
            break;
        }
    }
    false
}
