//! The shape of the TOML files, converted into the public types after parsing.

use serde::Deserialize;

use super::{
    AltGroup, Component, DataType, Datum, DatumKind, Mode, Param, Routine, Source, TypeKind,
    ValueClass,
};

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct File {
    #[serde(default)]
    pub function: Vec<RawRoutine>,
    #[serde(default)]
    pub instruction: Vec<RawRoutine>,
    #[serde(default)]
    pub datatype: Vec<RawDataType>,
    #[serde(default)]
    pub datum: Vec<RawDatum>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRoutine {
    name: String,
    returns: Option<String>,
    #[serde(default)]
    pure: bool,
    source: Source,
    section: Option<String>,
    summary: String,
    #[serde(default)]
    doc: String,
    note: Option<String>,
    #[serde(default)]
    required_alts: Vec<u32>,
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
    #[serde(default)]
    later: bool,
}

impl RawRoutine {
    pub(super) fn into_routine(self, is_function: bool) -> Result<Routine, String> {
        if is_function != self.returns.is_some() {
            return Err(format!(
                "{}: functions need `returns`, instructions must not have it",
                self.name
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
            return Err(format!(
                "{}: required_alts names unknown group {id}",
                self.name
            ));
        }
        let params = self
            .params
            .into_iter()
            .map(|p| Param {
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
                later: p.later,
            })
            .collect();
        Ok(Routine {
            name: self.name,
            returns: self.returns,
            params,
            alt_groups,
            pure: self.pure,
            source: self.source,
            section: self.section,
            summary: self.summary,
            doc: self.doc,
            note: self.note,
        })
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawDataType {
    name: String,
    kind: TypeKind,
    alias_of: Option<String>,
    /// Each component written "name type", or "name type later" for a component that
    /// later RobotWare versions added.
    #[serde(default)]
    components: Vec<String>,
    value_class: Option<ValueClass>,
    source: Source,
    section: Option<String>,
    summary: String,
    #[serde(default)]
    doc: String,
    note: Option<String>,
}

impl RawDataType {
    pub(super) fn into_datatype(self) -> Result<DataType, String> {
        let mut components = Vec::with_capacity(self.components.len());
        for c in &self.components {
            let mut parts = c.split_whitespace();
            match (parts.next(), parts.next(), parts.next(), parts.next()) {
                (Some(name), Some(ty), later @ (None | Some("later")), None) => {
                    components.push(Component {
                        name: name.to_string(),
                        ty: ty.to_string(),
                        later: later.is_some(),
                    });
                }
                _ => {
                    return Err(format!(
                        "type {}: component `{c}` is not `name type` or `name type later`",
                        self.name
                    ));
                }
            }
        }
        Ok(DataType {
            name: self.name,
            kind: self.kind,
            alias_of: self.alias_of,
            components,
            value_class: self.value_class,
            source: self.source,
            section: self.section,
            summary: self.summary,
            doc: self.doc,
            note: self.note,
        })
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawDatum {
    name: String,
    #[serde(rename = "type")]
    ty: String,
    kind: DatumKind,
    value: Option<String>,
    source: Source,
    section: Option<String>,
    summary: String,
    note: Option<String>,
}

impl RawDatum {
    pub(super) fn into_datum(self) -> Datum {
        Datum {
            name: self.name,
            ty: self.ty,
            kind: self.kind,
            value: self.value,
            source: self.source,
            section: self.section,
            summary: self.summary,
            note: self.note,
        }
    }
}
