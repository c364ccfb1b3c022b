//! Robot models as data (`data/models.toml`), looked up by the name a
//! controller or a person gives.

use std::sync::OnceLock;

use serde::Deserialize;

/// The seven lengths of an ortho-parallel arm with a spherical wrist, in mm.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Opw {
    pub a1: f64,
    pub a2: f64,
    pub b: f64,
    pub c1: f64,
    pub c2: f64,
    pub c3: f64,
    pub c4: f64,
}

/// What confdata's `cfx` means for a model.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum Cfx {
    /// The arm configuration, 0 to 7 (the manual's table: wrist centre in
    /// front of or behind axis 1, in front of or behind the lower arm, axis
    /// 5 positive or negative).
    #[default]
    Arm,
    /// Not used: the controller checks cf1, cf4 and cf6 only.
    Unused,
}

/// One robot model.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Model {
    /// ABB's name, `IRB 120-3/0.58`.
    pub name: String,
    /// Other names of the same arm (payload variants).
    #[serde(default)]
    pub aliases: Vec<String>,
    pub opw: Opw,
    /// Axis 3 is measured from the horizontal (parallel-arm robots).
    #[serde(default)]
    pub coupled: bool,
    #[serde(default)]
    pub cfx: Cfx,
    /// Working range of each axis, degrees.
    pub limits: [[f64; 2]; 6],
    /// Maximum speed of each axis, degrees per second.
    pub speeds: [f64; 6],
    /// tool0's position at all axes zero, mm.
    pub home: [f64; 3],
    pub kinematics_source: String,
    pub limits_source: String,
    pub home_source: String,
}

/// A family of arms we do not model, and why.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Unsupported {
    pub family: Vec<String>,
    pub reason: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Data {
    model: Vec<Model>,
    unsupported: Vec<Unsupported>,
}

fn data() -> &'static Data {
    static DATA: OnceLock<Data> = OnceLock::new();
    DATA.get_or_init(|| {
        // The file is part of the crate and a test parses it: a failure
        // here is a build defect, not input.
        #[allow(clippy::expect_used)]
        toml::from_str(include_str!("../data/models.toml")).expect("data/models.toml parses")
    })
}

/// Every supported model, in the order of the data file.
pub fn models() -> &'static [Model] {
    &data().model
}

/// What a name says about a robot: family (`120`, `6700LEANID`), reach in
/// metres and payload in kg, when it has them.
#[derive(Clone, Debug, PartialEq)]
struct Key {
    family: String,
    reach: Option<f64>,
    payload: Option<f64>,
}

/// Reads `IRB 120-3/0.58`, `IRB120`, `IRB 2400/16`, `ROB1_120_0.58_3`,
/// `ROB1_6700_LeanID_2.65_220`.
fn key_of(name: &str) -> Option<Key> {
    let t = name.trim();
    let upper = t.to_ascii_uppercase();
    // MOC.cfg's robot type: ROBn_FAMILY[_VARIANT]_REACH_PAYLOAD.
    if let Some(rest) = upper.strip_prefix("ROB") {
        let rest = rest.trim_start_matches(|c: char| c.is_ascii_digit());
        let rest = rest.strip_prefix('_')?;
        let mut family = String::new();
        let mut reach = None;
        let mut payload = None;
        for part in rest.split('_').filter(|p| !p.is_empty()) {
            let number = part.parse::<f64>().ok();
            match number {
                Some(v) if part.contains('.') && reach.is_none() => reach = Some(v),
                Some(v) if !family.is_empty() && reach.is_some() => payload = Some(v),
                Some(_) if family.is_empty() => family.push_str(part),
                _ => family.push_str(part),
            }
        }
        return (!family.is_empty()).then_some(Key {
            family,
            reach,
            payload,
        });
    }
    let rest = upper.strip_prefix("IRB").unwrap_or(&upper).trim();
    let compact: String = rest.chars().filter(|c| !c.is_whitespace()).collect();
    // FAMILY[-PAYLOAD][/REACH], or the older FAMILY/PAYLOAD.
    let (family, tail) = match compact.find(['-', '/']) {
        Some(i) => (&compact[..i], &compact[i..]),
        None => (compact.as_str(), ""),
    };
    let mut payload = None;
    let mut reach = None;
    if let Some(t) = tail.strip_prefix('-') {
        let (p, r) = t.split_once('/').unwrap_or((t, ""));
        payload = p.parse().ok();
        reach = r.parse().ok();
    } else if let Some(t) = tail.strip_prefix('/') {
        let v: Option<f64> = t.parse().ok();
        // `IRB 2400/16`: a payload; `/1.55`: a reach.
        if t.contains('.') {
            reach = v;
        } else {
            payload = v;
        }
    }
    (!family.is_empty()).then(|| Key {
        family: family.to_owned(),
        reach,
        payload,
    })
}

fn same(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() < 1e-6,
        _ => true,
    }
}

/// The answer of a lookup by name.
#[derive(Clone, Debug, PartialEq)]
pub enum Lookup {
    Found(&'static Model),
    /// A robot we do not model, with the reason.
    Unsupported(String),
    /// A name that names no robot we know.
    Unknown,
}

/// The model a name denotes: ABB's name (`IRB 120-3/0.58`, any case and
/// spacing), one of its aliases, or MOC.cfg's robot type
/// (`ROB1_120_0.58_3`). A family alone (`IRB 120`) names the model when the
/// family has one.
pub fn lookup(name: &str) -> Lookup {
    let Some(key) = key_of(name) else {
        return Lookup::Unknown;
    };
    let matching: Vec<&'static Model> = models()
        .iter()
        .filter(|m| {
            std::iter::once(&m.name)
                .chain(&m.aliases)
                .filter_map(|n| key_of(n))
                .any(|k| {
                    k.family == key.family
                        && same(key.reach, k.reach)
                        && same(key.payload, k.payload)
                })
        })
        .collect();
    if let [one] = matching.as_slice() {
        return Lookup::Found(one);
    }
    if matching.len() > 1 {
        // Several arms of the family fit: an exact name decides, else the
        // name is ambiguous (a family alone), which we do not guess.
        return Lookup::Unknown;
    }
    for u in &data().unsupported {
        if u.family.iter().any(|f| {
            let f = f.to_ascii_uppercase();
            // Named families (`CRB`, `GoFa`) cover their variants; numbered
            // ones are exact (`52` is not `5200`).
            let named = f.starts_with(|c: char| c.is_ascii_alphabetic());
            key.family == f || (named && key.family.starts_with(&f))
        }) {
            return Lookup::Unsupported(format!("{name}: {}", u.reason));
        }
    }
    Lookup::Unknown
}

/// The model a name denotes, if we model it (see [`lookup`]).
pub fn model_by_name(name: &str) -> Option<&'static Model> {
    match lookup(name) {
        Lookup::Found(m) => Some(m),
        _ => None,
    }
}

/// The arms we do not model, for documentation.
pub fn unsupported() -> &'static [Unsupported] {
    &data().unsupported
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_moc_types_find_the_model() {
        for n in [
            "IRB 120-3/0.58",
            "irb120-3/0.58",
            "ROB1_120_0.58_3",
            "IRB 120",
        ] {
            assert_eq!(
                model_by_name(n).map(|m| m.name.as_str()),
                Some("IRB 120-3/0.58"),
                "{n}"
            );
        }
        assert_eq!(
            model_by_name("ROB1_2400_1.55_16").map(|m| m.name.as_str()),
            Some("IRB 2400-10/1.55")
        );
        assert_eq!(
            model_by_name("IRB 2400/16").map(|m| m.name.as_str()),
            Some("IRB 2400-10/1.55")
        );
        assert_eq!(
            model_by_name("ROB2_6700_2.6_200").map(|m| m.name.as_str()),
            Some("IRB 6700-200/2.60")
        );
        // A family with several arms needs the arm.
        assert_eq!(lookup("IRB 4600"), Lookup::Unknown);
        assert!(matches!(lookup("IRB 14000"), Lookup::Unsupported(_)));
        assert!(matches!(lookup("ROB1_460_2.4_110"), Lookup::Unsupported(_)));
        assert!(matches!(lookup("CRB 15000-5/0.95"), Lookup::Unsupported(_)));
        assert_eq!(lookup("ROB1_6700_LeanID_2.65_220"), Lookup::Unknown);
        assert_eq!(lookup(""), Lookup::Unknown);
        assert_eq!(lookup("KR 6 R900"), Lookup::Unknown);
    }

    #[test]
    fn every_model_is_consistent() {
        for m in models() {
            for (i, [lo, hi]) in m.limits.iter().enumerate() {
                assert!(lo < hi, "{} axis {}", m.name, i + 1);
            }
            assert!(m.speeds.iter().all(|s| *s > 0.0), "{}", m.name);
            assert_eq!(model_by_name(&m.name), Some(m), "{}", m.name);
        }
    }
}
