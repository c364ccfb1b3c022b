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

/// Reads `IRB 120-3/0.58`, `IRB120`, `IRB 2400/16`, and MOC.cfg's robot
/// types ([`moc_key`]).
fn key_of(name: &str) -> Option<Key> {
    let t = name.trim();
    let upper = t.to_ascii_uppercase();
    if upper.starts_with("ROB") {
        return moc_key(&upper);
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

/// MOC.cfg's robot type (`-use_robot_type` of the `ROBOT` instance):
/// `ROBn_FAMILY[_VARIANT]_REACH_PAYLOAD` in the spellings controllers
/// write: `ROB1_120_0.58_3`, `ROB2_6700_2.6_200`, `ROB1_2600ID_2.00_8`,
/// `ROB1_6700_LeanID_2.65_220`, `ROB1_1200_0.9_5_TypeB`, and with the
/// robot number apart, the payload before the reach and a revision after
/// (`ROB_1_2600_12_1.85__03`). The reach is the number with a decimal
/// point, the payload the first whole number; a number with a leading
/// zero (`03`) and a `Type` letter (`TypeB`, `Type_B`) are revisions of the
/// same arm; any other word is a variant (`LeanID`) and part of the family.
fn moc_key(upper: &str) -> Option<Key> {
    let rest = upper.strip_prefix("ROB")?.trim_start_matches('_');
    let rest = rest.trim_start_matches(|c: char| c.is_ascii_digit());
    let rest = rest.strip_prefix('_')?;
    let mut family = String::new();
    let mut variant = String::new();
    let mut reach = None;
    let mut payload = None;
    let mut revision_letter = false;
    for part in rest.split('_').filter(|p| !p.is_empty()) {
        if std::mem::take(&mut revision_letter) && part.len() == 1 {
            continue;
        }
        if family.is_empty() {
            if part.starts_with(|c: char| c.is_ascii_digit()) {
                family.push_str(part);
            } else if part != "IRB" {
                variant.push_str(part);
            }
            continue;
        }
        let whole = part.bytes().all(|b| b.is_ascii_digit());
        if part.contains('.') {
            match part.parse::<f64>() {
                Ok(v) if reach.is_none() => reach = Some(v),
                Ok(_) => {}
                Err(_) => variant.push_str(part),
            }
        } else if whole {
            if payload.is_none() && !part.starts_with('0') {
                payload = part.parse::<f64>().ok();
            }
        } else if part == "TYPE" {
            revision_letter = true;
        } else if !(part.starts_with("TYPE") && part.len() == 5) {
            variant.push_str(part);
        }
    }
    family.push_str(&variant);
    (!family.is_empty() && family.starts_with(|c: char| c.is_ascii_digit())).then_some(Key {
        family,
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
            // A family covers its variants (`CRB` covers `CRB15000`, `1660`
            // covers `1660ID`), but a number is not a longer one (`52` is
            // not `5200`).
            key.family.strip_prefix(&f).is_some_and(|tail| {
                let named = f.starts_with(|c: char| c.is_ascii_alphabetic());
                tail.is_empty() || named || tail.starts_with(|c: char| c.is_ascii_alphabetic())
            })
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

/// The model `name` denotes ([`lookup`]), or why there is none, for a
/// message: an arm we do not model (with the reason), or a name that is no
/// modelled arm (with the names of those that are).
pub fn find_model(name: &str) -> Result<&'static Model, String> {
    match lookup(name) {
        Lookup::Found(m) => Ok(m),
        Lookup::Unsupported(why) => Err(format!("not modelled: {why}")),
        Lookup::Unknown => {
            let known: Vec<&str> = models().iter().map(|m| m.name.as_str()).collect();
            Err(format!(
                "`{name}` is not a modelled robot; known: {}",
                known.join(", ")
            ))
        }
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
        assert!(matches!(
            lookup("IRB 1660ID-4/1.55"),
            Lookup::Unsupported(_)
        ));
        assert_eq!(lookup("IRB 5200"), Lookup::Unknown, "52 is not 5200");
        assert_eq!(lookup(""), Lookup::Unknown);
        assert_eq!(lookup("KR 6 R900"), Lookup::Unknown);
    }

    /// The `-use_robot_type` spellings of public controller backups
    /// (SYSPAR/MOC.cfg of ABB-Rapid-Git, abb-rapidserver: IRB 120;
    /// compas_rcf, PaletizadoCajasConFrascos: IRB 4600; Kraker1: IRB 6660;
    /// abb_SAMXL_Grinding_RAPID: IRB 1200 Type B; abb-robot-welder: IRB
    /// 2600ID; Robo_ABB_Injetora: IRB 6700-205/2.80; Tamponadora: IRB 360;
    /// ABB_ROBOT_Socket: IRB 910SC), and the other forms controllers write
    /// (robot number apart, payload before reach, a revision after).
    #[test]
    fn moc_cfg_robot_types_as_controllers_write_them() {
        let found = |t: &str| model_by_name(t).map(|m| m.name.as_str());
        for (t, name) in [
            ("ROB1_120_0.58_3", "IRB 120-3/0.58"),
            ("ROB1_4600_2.55_40", "IRB 4600-40/2.55"),
            ("ROB1_6660_1.90_205", "IRB 6660-205/1.9"),
            ("ROB1_1200_0.9_5_TypeB", "IRB 1200-5/0.9"),
            ("ROB1_1200_0.9_5_Type_B", "IRB 1200-5/0.9"),
            ("ROB_1_2600_12_1.85__03", "IRB 2600-12/1.85"),
            ("ROB_2_2600_12_1.85", "IRB 2600-12/1.85"),
            ("ROB2_2600_1.85_12_03", "IRB 2600-12/1.85"),
            ("rob1_2400_1.55_16", "IRB 2400-10/1.55"),
            ("ROB1_6650S_3.5_125", "IRB 6650S-125/3.5"),
        ] {
            assert_eq!(found(t), Some(name), "{t}");
        }
        for t in ["ROB1_2600ID_2.00_8", "ROB1_360_1.6_6", "ROB1_910SC_0.55_3"] {
            assert!(matches!(lookup(t), Lookup::Unsupported(_)), "{t}");
        }
        // An arm of a modelled family whose size is not modelled, and a
        // variant with another arm, are not guessed.
        for t in [
            "ROB1_6700_2.80_205",
            "ROB1_6700_LeanID_2.65_220",
            "ROB1_2600_1.85_99",
            "ROB1_",
            "ROB_",
            "ROBOT",
        ] {
            assert_eq!(lookup(t), Lookup::Unknown, "{t}");
        }
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
