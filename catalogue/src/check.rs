//! The catalogue's self-checks: names unique, types known, modes and
//! alternatives well formed, versions and packages consistent.

use std::collections::HashMap;

use crate::{ANYTYPE, Catalogue, Origin, Source, TypeKind};

/// Checks the catalogue against itself; returns one message per problem.
pub(crate) fn check(cat: &Catalogue) -> Vec<String> {
    let mut problems = Vec::new();
    let type_known = |ty: &str| ty == ANYTYPE || cat.datatype(ty).is_some();

    let mut seen: HashMap<String, &str> = HashMap::new();
    let mut unique = |name: &str, what: &'static str, problems: &mut Vec<String>| {
        if let Some(prev) = seen.insert(name.to_lowercase(), what) {
            problems.push(format!("{what} `{name}`: name already used by a {prev}"));
        }
    };
    for r in &cat.functions {
        unique(&r.name, "function", &mut problems);
    }
    for r in &cat.instructions {
        unique(&r.name, "instruction", &mut problems);
    }
    for t in &cat.datatypes {
        unique(&t.name, "data type", &mut problems);
    }
    for d in &cat.data {
        unique(&d.name, "datum", &mut problems);
    }

    for r in cat.functions.iter().chain(&cat.instructions) {
        if let Some(ret) = &r.returns
            && !type_known(ret)
        {
            problems.push(format!("{}: unknown return type `{ret}`", r.name));
        }
        let mut names: HashMap<String, ()> = HashMap::new();
        for p in &r.params {
            if !type_known(&p.ty) {
                problems.push(format!(
                    "{}: parameter {}: unknown type `{}`",
                    r.name, p.name, p.ty
                ));
            }
            if names.insert(p.name.to_lowercase(), ()).is_some() {
                problems.push(format!("{}: duplicate parameter {}", r.name, p.name));
            }
            if p.switch && (p.ty != "switch" || p.mode.is_some() || !p.optional) {
                problems.push(format!(
                    "{}: switch {} must be optional, of type switch, without mode",
                    r.name, p.name
                ));
            }
            if !p.switch && (p.mode.is_none() || p.ty == "switch") {
                problems.push(format!(
                    "{}: parameter {} needs a mode and a non-switch type",
                    r.name, p.name
                ));
            }
            if p.array > 3 {
                problems.push(format!(
                    "{}: parameter {} has {} dimensions",
                    r.name, p.name, p.array
                ));
            }
        }
        for g in &r.alt_groups {
            let members: Vec<usize> = r
                .params
                .iter()
                .enumerate()
                .filter(|(_, p)| p.alt_group == Some(g.id))
                .map(|(i, _)| i)
                .collect();
            if members.len() < 2 {
                problems.push(format!(
                    "{}: alternative group {} has fewer than 2 members",
                    r.name, g.id
                ));
            }
            if members.windows(2).any(|w| w[1] != w[0] + 1) {
                problems.push(format!(
                    "{}: members of alternative group {} are not adjacent",
                    r.name, g.id
                ));
            }
            let optional: Vec<bool> = members.iter().map(|&i| r.params[i].optional).collect();
            if optional.iter().any(|&o| o != optional[0]) {
                problems.push(format!(
                    "{}: alternative group {} mixes optional and required",
                    r.name, g.id
                ));
            }
            if !optional.first().copied().unwrap_or(true) {
                problems.push(format!(
                    "{}: alternatives of group {} must be written optional (`\\`); use required_alts",
                    r.name, g.id
                ));
            }
        }
    }

    for t in &cat.datatypes {
        match t.kind {
            TypeKind::Alias => match &t.alias_of {
                Some(target) if cat.datatype(target).is_some() => {
                    if cat.resolve_alias(&t.name).eq_ignore_ascii_case(&t.name) {
                        problems.push(format!("type {}: alias cycle", t.name));
                    }
                }
                Some(target) => {
                    problems.push(format!("type {}: alias of unknown `{target}`", t.name))
                }
                None => problems.push(format!("type {}: alias without alias_of", t.name)),
            },
            TypeKind::Record => {
                if t.components.is_empty() && t.layout_known {
                    problems.push(format!("type {}: record without components", t.name));
                }
                if t.alias_of.is_some() {
                    problems.push(format!("type {}: record with alias_of", t.name));
                }
            }
            TypeKind::Atomic => {
                if !t.components.is_empty() || t.alias_of.is_some() {
                    problems.push(format!(
                        "type {}: atomic with components or alias_of",
                        t.name
                    ));
                }
            }
        }
        let mut names: HashMap<String, ()> = HashMap::new();
        for c in &t.components {
            if cat.datatype(&c.ty).is_none() {
                problems.push(format!(
                    "type {}: component {}: unknown type `{}`",
                    t.name, c.name, c.ty
                ));
            }
            if names.insert(c.name.to_lowercase(), ()).is_some() {
                problems.push(format!("type {}: duplicate component {}", t.name, c.name));
            }
        }
    }

    for d in &cat.data {
        if cat.datatype(&d.ty).is_none() {
            problems.push(format!("datum {}: unknown type `{}`", d.name, d.ty));
        }
    }
    check_origins(cat, &mut problems);
    problems
}

/// Versions, packages and sources of every entry.
fn check_origins(cat: &Catalogue, problems: &mut Vec<String>) {
    let mut origin = |name: &str, o: &Origin| {
        if let Some(u) = o.until
            && u <= o.since
        {
            problems.push(format!("{name}: until {u} is not after since {}", o.since));
        }
        if let Some(p) = &o.package
            && cat.package(p).is_none()
        {
            problems.push(format!("{name}: unknown package `{p}`"));
        }
        if o.package.is_some() && o.source == Source::Manual {
            problems.push(format!(
                "{name}: an option entry cannot come from the base manual"
            ));
        }
        if o.source == Source::Manual && o.section.is_none() {
            problems.push(format!("{name}: a manual entry needs its section"));
        }
    };
    for r in cat.functions.iter().chain(&cat.instructions) {
        origin(&r.name, &r.origin);
    }
    for t in &cat.datatypes {
        origin(&t.name, &t.origin);
    }
    for d in &cat.data {
        origin(&d.name, &d.origin);
    }
    for r in cat.functions.iter().chain(&cat.instructions) {
        for p in &r.params {
            if let Some(s) = p.since
                && s <= r.origin.since
            {
                problems.push(format!(
                    "{}: parameter {} since {s} is not after its routine's {}",
                    r.name, p.name, r.origin.since
                ));
            }
        }
        if !r.signature_known && r.pure {
            problems.push(format!("{}: a pure function needs its signature", r.name));
        }
    }
    for t in &cat.datatypes {
        for c in &t.components {
            if let Some(s) = c.since
                && s <= t.origin.since
            {
                problems.push(format!(
                    "type {}: component {} since {s} is not after its type's {}",
                    t.name, c.name, t.origin.since
                ));
            }
        }
        if !t.layout_known && t.kind != TypeKind::Record {
            problems.push(format!(
                "type {}: only a record's layout can be unknown",
                t.name
            ));
        }
    }
    let mut ids = HashMap::new();
    for p in &cat.packages {
        if ids.insert(p.id.to_lowercase(), ()).is_some() {
            problems.push(format!("package {}: listed twice", p.id));
        }
        if p.matches.is_empty() {
            problems.push(format!("package {}: no texts to find it by", p.id));
        }
        for inc in &p.includes {
            if cat.package(inc).is_none() || inc.eq_ignore_ascii_case(&p.id) {
                problems.push(format!(
                    "package {}: includes unknown package `{inc}`",
                    p.id
                ));
            }
        }
    }
}
