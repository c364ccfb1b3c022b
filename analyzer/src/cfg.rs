//! The controller's configuration files (`SYSPAR/*.cfg`: `EIO.cfg`,
//! `MOC.cfg`, `SYS.cfg`, `SIO.cfg`, `PROC.cfg`...) as data: the one reader
//! of the format, used for what a task's checks need
//! ([`crate::task::parse_config`]) and by `rapid diff`.
//!
//! A file starts with a header line (`EIO:CFG_1.0:6:1::`); `#` lines
//! separate its parts. A line `NAME:` (one word) starts a type; each of its
//! instances is a line of attributes `-Name "diGrip" -SignalType "DI"`,
//! continued over the next line when it ends in `\`. An attribute has a
//! value (quoted, which may hold blanks, or a single word; a negative
//! number is a value, not an attribute) or none (a flag: `-AllTask`).
//! Attribute names are compared case-insensitively (`MOC.cfg` writes them
//! in lower case, the others in mixed case). Nothing here fails: a line
//! that is none of these is skipped.

/// One configuration file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CfgFile {
    /// The header line (`EIO:CFG_1.0:6:1::`), if the file has one.
    pub header: Option<String>,
    /// The types in the order of the file.
    pub types: Vec<CfgType>,
}

/// A type (`EIO_SIGNAL:`) and its instances.
#[derive(Clone, Debug, PartialEq)]
pub struct CfgType {
    pub name: String,
    /// 1-based line of `NAME:`.
    pub line: usize,
    pub instances: Vec<Instance>,
}

/// One instance: its attributes in the order written.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    /// 1-based line of its first attribute.
    pub line: usize,
    pub attrs: Vec<Attr>,
}

/// `-Name "value"`, `-Name value` or the flag `-Name`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Attr {
    /// Without the leading `-`.
    pub name: String,
    /// Without quotes; `None` for a flag.
    pub value: Option<String>,
}

impl CfgFile {
    /// The types called `name` (any letter case), in order; a file may
    /// repeat a type.
    pub fn types_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a CfgType> + 'a {
        self.types
            .iter()
            .filter(move |t| t.name.eq_ignore_ascii_case(name))
    }

    /// Every instance of the types called `name`.
    pub fn instances<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Instance> + 'a {
        self.types_named(name).flat_map(|t| &t.instances)
    }
}

impl Instance {
    /// The attribute `name` (any letter case).
    pub fn attr(&self, name: &str) -> Option<&Attr> {
        self.attrs
            .iter()
            .find(|a| a.name.eq_ignore_ascii_case(name))
    }

    /// The value of attribute `name`; `None` for a flag or when absent.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.attr(name).and_then(|a| a.value.as_deref())
    }

    /// Is the attribute (or flag) `name` there?
    pub fn has(&self, name: &str) -> bool {
        self.attr(name).is_some()
    }
}

/// Reads a configuration file.
pub fn parse(text: &str) -> CfgFile {
    let mut file = CfgFile::default();
    // The instance being read: (its first line, its text so far).
    let mut pending: Option<(usize, String)> = None;
    let mut continued = false;
    let flush = |file: &mut CfgFile, pending: &mut Option<(usize, String)>| {
        if let Some((line, text)) = pending.take()
            && let Some(t) = file.types.last_mut()
        {
            let attrs = attributes(&text);
            if !attrs.is_empty() {
                t.instances.push(Instance { line, attrs });
            }
        }
    };
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let t = raw.trim();
        if continued {
            continued = t.ends_with('\\');
            if let Some((_, text)) = pending.as_mut() {
                text.push(' ');
                text.push_str(t.trim_end_matches('\\'));
            }
            continue;
        }
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        if file.header.is_none() && file.types.is_empty() && t.contains("CFG_") {
            file.header = Some(t.to_owned());
            continue;
        }
        if t.ends_with(':') && !t.starts_with('-') && !t.contains(char::is_whitespace) {
            flush(&mut file, &mut pending);
            file.types.push(CfgType {
                name: t[..t.len() - 1].to_owned(),
                line,
                instances: Vec::new(),
            });
            continue;
        }
        if t.starts_with('-') && !file.types.is_empty() {
            flush(&mut file, &mut pending);
            continued = t.ends_with('\\');
            pending = Some((line, t.trim_end_matches('\\').to_owned()));
        }
    }
    flush(&mut file, &mut pending);
    file
}

/// The attributes of an instance's text (its lines joined).
fn attributes(text: &str) -> Vec<Attr> {
    let mut out: Vec<Attr> = Vec::new();
    let mut rest = text.trim_start();
    while !rest.is_empty() {
        let (token, quoted, after) = next_token(rest);
        rest = after.trim_start();
        let is_name = !quoted
            && token.len() > 1
            && token.starts_with('-')
            && token[1..].starts_with(|c: char| c.is_ascii_alphabetic() || c == '_');
        if is_name {
            out.push(Attr {
                name: token[1..].to_owned(),
                value: None,
            });
        } else if let Some(last) = out.last_mut().filter(|a| a.value.is_none()) {
            last.value = Some(token.to_owned());
        }
        // A value without an attribute before it is not part of the format.
    }
    out
}

/// The first token of `s` (which starts with no blank): a quoted string
/// (without its quotes; a doubled quote is not special in this format) or
/// a run of non-blank characters. Returns the token, whether it was
/// quoted, and the rest.
fn next_token(s: &str) -> (&str, bool, &str) {
    if let Some(body) = s.strip_prefix('"') {
        return match body.find('"') {
            Some(end) => (&body[..end], true, &body[end + 1..]),
            None => (body, true, ""),
        };
    }
    let end = s.find(char::is_whitespace).unwrap_or(s.len());
    (&s[..end], false, &s[end..])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn types_instances_attributes_flags_and_continuations() {
        let text = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n  -Name \"diA\" -SignalType \"DI\"\\\n  -Device \"d1\"\n  -Name doB -SignalType \"DO\" -Label \"two words\"\n#\nCAB_TASKS:\n  -Name \"T_ROB1\" -Type \"NORMAL\" \\\n   -MotionTask\n#\nARM:\n  -name \"rob1_1\" -upper_joint_bound 2.96706 -lower_joint_bound -2.96706\n";
        let f = parse(text);
        assert_eq!(f.header.as_deref(), Some("EIO:CFG_1.0:6:1::"));
        let names: Vec<&str> = f.types.iter().map(|t| t.name.as_str()).collect();
        assert_eq!(names, ["EIO_SIGNAL", "CAB_TASKS", "ARM"]);
        let signals: Vec<&Instance> = f.instances("eio_signal").collect();
        assert_eq!(signals.len(), 2);
        assert_eq!(signals[0].get("device"), Some("d1"));
        assert_eq!(signals[0].line, 5);
        assert_eq!(signals[1].get("Name"), Some("doB"));
        assert_eq!(signals[1].get("Label"), Some("two words"));
        let task = f.instances("CAB_TASKS").next().expect("a task");
        assert!(task.has("MotionTask"));
        assert_eq!(task.get("MotionTask"), None);
        let arm = f.instances("ARM").next().expect("an arm");
        assert_eq!(arm.get("lower_joint_bound"), Some("-2.96706"));
        assert_eq!(arm.get("NAME"), Some("rob1_1"));
    }

    #[test]
    fn anything_else_is_skipped() {
        let f = parse("garbage\n-Orphan 1\nT:\nnot an instance\n  -A \"unterminated\n");
        assert_eq!(f.types.len(), 1);
        assert_eq!(f.types[0].instances[0].get("A"), Some("unterminated"));
        assert_eq!(parse(""), CfgFile::default());
    }
}
