//! The shape of the TOML files, converted into the public types after parsing.

use serde::Deserialize;

use crate::{
    AltGroup, Catalogue, Component, DataType, Datum, DatumKind, Mode, Origin, Package, Param,
    Routine, Source, TypeKind, ValueClass, Version,
};

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct File {
    /// A package file's option.
    package: Option<RawPackage>,
    #[serde(default)]
    function: Vec<RawRoutine>,
    #[serde(default)]
    instruction: Vec<RawRoutine>,
    #[serde(default)]
    datatype: Vec<RawDataType>,
    #[serde(default)]
    datum: Vec<RawDatum>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPackage {
    id: String,
    name: String,
    #[serde(default)]
    matches: Vec<String>,
    summary: String,
    note: Option<String>,
    #[serde(default)]
    includes: Vec<String>,
}

/// Fields every entry has: versions, package, source (read from each
/// entry's own fields: `deny_unknown_fields` does not work with flattening).
struct RawOrigin {
    since: String,
    until: Option<String>,
    package: Option<String>,
    source: Source,
    section: Option<String>,
    note: Option<String>,
}

macro_rules! origin_of {
    ($e:expr) => {
        RawOrigin {
            since: std::mem::take(&mut $e.since),
            until: $e.until.take(),
            package: $e.package.take(),
            source: $e.source,
            section: $e.section.take(),
            note: $e.note.take(),
        }
    };
}

/// Parses one file into `cat`. Entries of a package file belong to its
/// package; a `package` field on an entry must agree with it.
pub(crate) fn load_file(cat: &mut Catalogue, file: &str, text: &str) -> Result<(), String> {
    let data: File = toml::from_str(text).map_err(|e| format!("{file}: {e}"))?;
    let package = data.package.as_ref().map(|p| p.id.clone());
    let origin = |name: &str, o: RawOrigin| -> Result<Origin, String> {
        let at = |e: String| format!("{file}: {name}: {e}");
        let since = Version::parse(&o.since).map_err(at)?;
        let until = o
            .until
            .as_deref()
            .map(Version::parse)
            .transpose()
            .map_err(at)?;
        let pkg = match (&package, o.package) {
            (Some(file_pkg), Some(own)) if !own.eq_ignore_ascii_case(file_pkg) => {
                return Err(at(format!(
                    "package `{own}` in the file of package `{file_pkg}`"
                )));
            }
            (Some(file_pkg), _) => Some(file_pkg.clone()),
            (None, own) => own,
        };
        Ok(Origin {
            since,
            until,
            package: pkg,
            source: o.source,
            section: o.section,
            note: o.note,
        })
    };
    if let Some(p) = data.package {
        cat.packages.push(Package {
            id: p.id,
            name: p.name,
            matches: p.matches,
            summary: p.summary,
            note: p.note,
            includes: p.includes,
        });
    }
    for mut f in data.function {
        let name = f.name.clone();
        let o = origin(&name, origin_of!(f))?;
        cat.functions.push(f.into_routine(true, o, file)?);
    }
    for mut i in data.instruction {
        let name = i.name.clone();
        let o = origin(&name, origin_of!(i))?;
        cat.instructions.push(i.into_routine(false, o, file)?);
    }
    for mut t in data.datatype {
        let name = t.name.clone();
        let o = origin(&name, origin_of!(t))?;
        cat.datatypes.push(t.into_datatype(o, file)?);
    }
    for mut d in data.datum {
        let name = d.name.clone();
        let o = origin(&name, origin_of!(d))?;
        cat.data.push(Datum {
            name,
            ty: d.ty,
            kind: d.kind,
            value: d.value,
            read_only: d.read_only,
            origin: o,
            summary: d.summary,
        });
    }
    Ok(())
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRoutine {
    name: String,
    returns: Option<String>,
    #[serde(default)]
    pure: bool,
    #[serde(default)]
    real_valued: bool,
    #[serde(default)]
    terminates: bool,
    since: String,
    until: Option<String>,
    package: Option<String>,
    source: Source,
    section: Option<String>,
    note: Option<String>,
    summary: String,
    #[serde(default)]
    doc: String,
    #[serde(default)]
    required_alts: Vec<u32>,
    /// The parameters are not documented publicly: only the name and kind.
    #[serde(default)]
    params_unknown: bool,
    /// The parameters are the ones loaded code calls it with, not a
    /// reference's: the simulation binds calls by them, the checker does
    /// not check calls against them (a call may use one not listed).
    #[serde(default)]
    params_unchecked: bool,
    #[serde(default)]
    params: Vec<RawParam>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawParam {
    name: String,
    #[serde(rename = "type")]
    ty: String,
    mode: Option<Mode>,
    #[serde(default)]
    optional: bool,
    #[serde(default)]
    switch: bool,
    #[serde(default)]
    array: u8,
    alt: Option<u32>,
    since: Option<String>,
    #[serde(default)]
    any_rank: bool,
}

impl RawRoutine {
    fn into_routine(
        self,
        is_function: bool,
        origin: Origin,
        file: &str,
    ) -> Result<Routine, String> {
        let name = self.name;
        let at = |e: String| format!("{file}: {name}: {e}");
        if is_function != self.returns.is_some() {
            return Err(at(
                "functions need `returns`, instructions must not have it".into(),
            ));
        }
        if self.params_unknown && !self.params.is_empty() {
            return Err(at("`params_unknown` with parameters".into()));
        }
        if self.params_unchecked && (self.params.is_empty() || self.params_unknown) {
            return Err(at(
                "`params_unchecked` needs parameters (and not `params_unknown`)".into(),
            ));
        }
        let mut alt_groups: Vec<AltGroup> = Vec::new();
        for p in &self.params {
            if let Some(id) = p.alt
                && !alt_groups.iter().any(|g| g.id == id)
            {
                alt_groups.push(AltGroup {
                    id,
                    required: self.required_alts.contains(&id),
                });
            }
        }
        if let Some(id) = self
            .required_alts
            .iter()
            .find(|id| !alt_groups.iter().any(|g| g.id == **id))
        {
            return Err(at(format!("required_alts names unknown group {id}")));
        }
        let mut params = Vec::with_capacity(self.params.len());
        for p in self.params {
            let since = p
                .since
                .as_deref()
                .map(Version::parse)
                .transpose()
                .map_err(|e| at(format!("parameter {}: {e}", p.name)))?;
            params.push(Param {
                mode: if p.switch {
                    p.mode
                } else {
                    Some(p.mode.unwrap_or(Mode::In))
                },
                name: p.name,
                ty: p.ty,
                optional: p.optional,
                switch: p.switch,
                array: p.array,
                alt_group: p.alt,
                since,
                any_rank: p.any_rank,
            });
        }
        Ok(Routine {
            name,
            returns: self.returns,
            params,
            alt_groups,
            signature_known: !self.params_unknown && !self.params_unchecked,
            pure: self.pure,
            real_valued: self.real_valued,
            terminates: self.terminates,
            origin,
            summary: self.summary,
            doc: self.doc,
        })
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDataType {
    name: String,
    kind: TypeKind,
    alias_of: Option<String>,
    /// Each component written "name type", or "name type VERSION" for a
    /// component that RobotWare VERSION added.
    #[serde(default)]
    components: Vec<String>,
    /// A record whose components are not documented publicly.
    #[serde(default)]
    layout_unknown: bool,
    value_class: Option<ValueClass>,
    since: String,
    until: Option<String>,
    package: Option<String>,
    source: Source,
    section: Option<String>,
    note: Option<String>,
    summary: String,
    #[serde(default)]
    doc: String,
}

impl RawDataType {
    fn into_datatype(self, origin: Origin, file: &str) -> Result<DataType, String> {
        let mut components = Vec::with_capacity(self.components.len());
        for c in &self.components {
            let mut parts = c.split_whitespace();
            let bad = || {
                format!(
                    "{file}: type {}: component `{c}` is not `name type` or `name type VERSION`",
                    self.name
                )
            };
            match (parts.next(), parts.next(), parts.next(), parts.next()) {
                (Some(name), Some(ty), since, None) => {
                    let since = since.map(Version::parse).transpose().map_err(|_| bad())?;
                    components.push(Component {
                        name: name.to_string(),
                        ty: ty.to_string(),
                        since,
                    });
                }
                _ => return Err(bad()),
            }
        }
        if self.layout_unknown && !components.is_empty() {
            return Err(format!(
                "{file}: type {}: `layout_unknown` with components",
                self.name
            ));
        }
        Ok(DataType {
            name: self.name,
            kind: self.kind,
            alias_of: self.alias_of,
            components,
            layout_known: !self.layout_unknown,
            value_class: self.value_class,
            origin,
            summary: self.summary,
            doc: self.doc,
        })
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDatum {
    name: String,
    #[serde(rename = "type")]
    ty: String,
    kind: DatumKind,
    value: Option<String>,
    #[serde(default)]
    read_only: bool,
    since: String,
    until: Option<String>,
    package: Option<String>,
    source: Source,
    section: Option<String>,
    note: Option<String>,
    summary: String,
}
