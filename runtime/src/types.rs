//! Data types as the interpreter needs them: what a type name stands for
//! (through aliases), the components of records, and the value a data
//! object of a type starts with.

use std::sync::Arc;

use rapid_analyzer::catalogue::{Catalogue, TypeKind};
use rapid_analyzer::names::{NameMap, fold};
use rapid_analyzer::task::Task;
use rapid_evaluator::{Env, Lookup, Type, Value};

/// A record type: its name and its components (name, type name).
pub(crate) type Layout = Arc<(String, Vec<(String, String)>)>;

/// What a type name stands for.
#[derive(Clone, Debug)]
pub(crate) enum Shape {
    Num,
    Dnum,
    Bool,
    Str,
    Record(Layout),
    /// A type whose values the simulation keeps in its own form (signals,
    /// clocks, files) or knows nothing about: the name, folded.
    Opaque(String),
}

/// The types of a task: user records and aliases, over the catalogue's and
/// the evaluator's.
pub(crate) struct Types {
    records: NameMap<Layout>,
    aliases: NameMap<String>,
    /// The catalogue as the task's controller has it.
    catalogue: &'static Catalogue,
}

impl Types {
    pub(crate) fn new(task: &Task) -> Types {
        let mut records = NameMap::default();
        let mut aliases = NameMap::default();
        for unit in task.units.iter() {
            for m in &unit.items.modules {
                for r in &m.records {
                    let fields = r
                        .components
                        .iter()
                        .map(|(n, t, _)| {
                            (
                                n.clone(),
                                t.as_ref().map(|t| t.name.clone()).unwrap_or_default(),
                            )
                        })
                        .collect();
                    records
                        .entry(fold(&r.name))
                        .or_insert_with(|| Arc::new((r.name.clone(), fields)));
                }
                for a in &m.aliases {
                    if let Some(of) = &a.of {
                        aliases.entry(fold(&a.name)).or_insert(of.name.clone());
                    }
                }
            }
        }
        Types {
            records,
            aliases,
            catalogue: task.catalogue,
        }
    }

    /// What `name` stands for, through user, built-in and catalogue
    /// aliases.
    pub(crate) fn shape(&self, name: &str) -> Shape {
        let mut name = fold(name);
        for _ in 0..16 {
            match name.as_str() {
                "num" => return Shape::Num,
                "dnum" => return Shape::Dnum,
                "bool" => return Shape::Bool,
                "string" => return Shape::Str,
                _ => {}
            }
            if let Some(r) = self.records.get(&name) {
                return Shape::Record(r.clone());
            }
            if let Some(of) = self.aliases.get(&name) {
                name = fold(of);
                continue;
            }
            match self.catalogue.datatype(&name) {
                Some(t) if t.kind == TypeKind::Record && !t.components.is_empty() => {
                    let fields = t
                        .components
                        .iter()
                        .map(|c| (c.name.clone(), c.ty.clone()))
                        .collect();
                    return Shape::Record(Arc::new((name, fields)));
                }
                Some(t) if t.kind == TypeKind::Alias => match &t.alias_of {
                    Some(of) => name = fold(of),
                    None => return Shape::Opaque(name),
                },
                _ => return Shape::Opaque(name),
            }
        }
        Shape::Opaque(name)
    }

    /// The value a data object of type `ty` starts with when it has no
    /// initial value: zero, `FALSE`, an empty string, records and arrays of
    /// those.
    pub(crate) fn zero(&self, ty: &Type) -> Value {
        self.zero_depth(&ty.name, &ty.dims, 0)
    }

    fn zero_depth(&self, name: &str, dims: &[usize], depth: u32) -> Value {
        if let Some((&n, rest)) = dims.split_first() {
            let item = self.zero_depth(name, rest, depth);
            return Value::Array(vec![item; n.min(MAX_ELEMENTS)]);
        }
        if depth > 16 {
            return Value::Num(0.0);
        }
        match self.shape(name) {
            Shape::Num => Value::Num(0.0),
            Shape::Dnum => Value::Dnum(0.0),
            Shape::Bool => Value::Bool(false),
            Shape::Str => Value::Str(String::new()),
            Shape::Record(r) => Value::Record {
                ty: r.0.clone(),
                fields: r
                    .1
                    .iter()
                    .map(|(f, t)| (f.clone(), self.zero_depth(t, &[], depth + 1)))
                    .collect(),
            },
            Shape::Opaque(name) => opaque_zero(&name),
        }
    }

    /// The type of component `field` of record type `record`.
    pub(crate) fn field_type(&self, record: &str, field: &str) -> Option<String> {
        match self.shape(record) {
            Shape::Record(r) => {
                r.1.iter()
                    .find(|(f, _)| f.eq_ignore_ascii_case(field))
                    .map(|(_, t)| t.clone())
            }
            _ => None,
        }
    }
}

/// The largest array the interpreter makes (elements in all).
pub(crate) const MAX_ELEMENTS: usize = 1 << 20;

/// The starting value of a type the simulation keeps in its own form.
pub(crate) fn opaque_zero(folded: &str) -> Value {
    let record = |fields: Vec<(&str, Value)>| Value::Record {
        ty: folded.to_owned(),
        fields: fields.into_iter().map(|(n, v)| (n.to_owned(), v)).collect(),
    };
    match folded {
        s if s.starts_with("signal") => record(vec![("name", Value::Str(String::new()))]),
        "clock" => record(vec![
            ("running", Value::Bool(false)),
            ("start", Value::Dnum(0.0)),
            ("elapsed", Value::Dnum(0.0)),
        ]),
        "iodev" | "dir" => record(vec![("handle", Value::Num(0.0))]),
        _ => record(Vec::new()),
    }
}

/// The types as the evaluator asks for them (for typing aggregates and
/// widening values).
pub(crate) struct TypesEnv<'a>(pub(crate) &'a Types);

impl Env for TypesEnv<'_> {
    fn lookup(&self, _name: &str) -> Lookup<'_> {
        Lookup::Unknown
    }

    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        match self.0.shape(type_name) {
            Shape::Record(r) => Some(
                r.1.iter()
                    .map(|(n, t)| (n.clone(), Type::named(t.clone())))
                    .collect(),
            ),
            _ => None,
        }
    }

    fn alias_of(&self, type_name: &str) -> Option<Type> {
        let key = fold(type_name);
        if let Some(of) = self.0.aliases.get(&key) {
            return Some(Type::named(of.clone()));
        }
        self.0
            .catalogue
            .datatype(&key)
            .and_then(|t| t.alias_of.clone())
            .map(Type::named)
    }

    fn catalogue(&self) -> &Catalogue {
        self.0.catalogue
    }
}
