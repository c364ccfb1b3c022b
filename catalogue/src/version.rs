//! RobotWare versions: `5.15`, `6.08`, `7.10`.

use std::fmt;

/// A RobotWare version, major and minor (a patch level such as the `.01` of
/// `6.08.01` is read and ignored: the catalogue does not change within one).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Version {
    pub major: u16,
    pub minor: u16,
}

impl Version {
    /// The first version the catalogue describes: an entry with this `since`
    /// exists in every RobotWare the catalogue knows.
    pub const FIRST: Version = Version { major: 4, minor: 0 };

    pub const fn new(major: u16, minor: u16) -> Version {
        Version { major, minor }
    }

    /// Parses `6.15`, `6.08.01`, `7.1`, `RobotWare 6.15`, `RW6.15` or
    /// `6.15.0123`. The minor number is read as a number: `6.1` is `6.01`.
    pub fn parse(text: &str) -> Result<Version, String> {
        let t = text.trim();
        let lower = t.to_ascii_lowercase();
        let t = lower
            .strip_prefix("robotware")
            .or_else(|| lower.strip_prefix("rw"))
            .unwrap_or(&lower)
            .trim_start_matches(['_', ' ', '-']);
        let mut parts = t.split(['.', '_', '-']);
        let number = |p: Option<&str>| -> Option<u16> {
            let p = p?;
            if p.is_empty() || p.len() > 4 || !p.bytes().all(|b| b.is_ascii_digit()) {
                return None;
            }
            p.parse().ok()
        };
        match (number(parts.next()), number(parts.next())) {
            (Some(major), Some(minor)) if (4..=9).contains(&major) => Ok(Version { major, minor }),
            (Some(major), None) if (4..=9).contains(&major) && !t.contains('.') => {
                Ok(Version { major, minor: 0 })
            }
            _ => Err(format!(
                "`{text}` is not a RobotWare version (expected MAJOR.MINOR, e.g. 6.15 or 7.10)"
            )),
        }
    }
}

impl fmt::Display for Version {
    /// RobotWare 5 and 6 write two-digit minors (`6.08`), RobotWare 7 does
    /// not (`7.1`, `7.10`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.major <= 6 {
            write!(f, "{}.{:02}", self.major, self.minor)
        } else {
            write!(f, "{}.{}", self.major, self.minor)
        }
    }
}

impl serde::Serialize for Version {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

#[cfg(test)]
mod tests {
    use super::Version;

    #[test]
    fn versions_parse_and_print() {
        let v = |s: &str| Version::parse(s).map(|v| v.to_string());
        assert_eq!(v("6.15").as_deref(), Ok("6.15"));
        assert_eq!(v("6.08.01").as_deref(), Ok("6.08"));
        assert_eq!(v("6.8").as_deref(), Ok("6.08"));
        assert_eq!(v("RobotWare 7.1").as_deref(), Ok("7.1"));
        assert_eq!(v("RW6.10").as_deref(), Ok("6.10"));
        assert_eq!(v("RobotWare_6.13.0135").as_deref(), Ok("6.13"));
        assert_eq!(v("7").as_deref(), Ok("7.0"));
        assert!(v("six").is_err());
        assert!(v("12.1").is_err());
        assert!(v("3.2").is_err());
        assert!(v("6.x").is_err());
        assert!(Version::parse("6.08").unwrap_or(Version::FIRST) < Version::new(6, 10));
    }
}
