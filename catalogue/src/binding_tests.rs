//! `bind_args` as a table: signature × call → binding, each written in a
//! small notation.
//!
//! A signature is its parameters separated by commas: `A` positional,
//! `\A` optional, `\A|\B` an optional group, `!\A|\B` a required group.
//! A call is its arguments separated by spaces: `_` positional, a name for
//! a named one. A binding shows each argument's target (a parameter's
//! name, `?` for an unknown name, `+` for one positional too many), with
//! `=k` when it repeats argument k and `/N` when it excludes the given
//! alternative N; then the missing parameters and the missing groups.

use super::*;

/// A signature: its parameters and `|` groups.
struct Signature {
    params: Vec<Param>,
    groups: Vec<AltGroup>,
}

fn signature(spec: &str) -> Signature {
    let mut params = Vec::new();
    let mut groups = Vec::new();
    for part in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let (required, part) = match part.strip_prefix('!') {
            Some(rest) => (true, rest),
            None => (false, part),
        };
        let members: Vec<&str> = part.split('|').collect();
        let group = (members.len() > 1).then(|| {
            let id = u32::try_from(groups.len() + 1).unwrap_or(u32::MAX);
            groups.push(AltGroup { id, required });
            id
        });
        for m in members {
            let (optional, name) = match m.strip_prefix('\\') {
                Some(n) => (true, n),
                None => (false, m),
            };
            params.push(Param {
                name: name.to_owned(),
                ty: "num".to_owned(),
                mode: Some(crate::Mode::In),
                optional,
                switch: false,
                array: 0,
                alt_group: group,
                since: None,
                any_rank: false,
            });
        }
    }
    Signature { params, groups }
}

fn bind(s: &Signature, args: &[Arg<'_>]) -> Binding {
    bind_args(&s.params, &s.groups, args)
}

fn call(spec: &str) -> Vec<Arg<'_>> {
    spec.split_whitespace()
        .map(|a| {
            if a == "_" {
                Arg::Positional
            } else {
                Arg::Named(a)
            }
        })
        .collect()
}

fn show(sig: &Signature, b: &Binding) -> String {
    let name = |i: usize| sig.params.get(i).map_or("!", |p| p.name.as_str());
    let mut out: Vec<String> = b
        .args
        .iter()
        .map(|a| {
            let mut s = match a.target {
                Target::Param(i) => name(i).to_owned(),
                Target::UnknownName => "?".to_owned(),
                Target::TooMany => "+".to_owned(),
            };
            if let Some(k) = a.repeats {
                s.push_str(&format!("={k}"));
            }
            if let Some(o) = a.excludes {
                s.push_str(&format!("/{}", name(o)));
            }
            s
        })
        .collect();
    if !b.missing.is_empty() {
        let m: Vec<&str> = b.missing.iter().map(|&i| name(i)).collect();
        out.push(format!("missing {}", m.join(" ")));
    }
    if !b.missing_groups.is_empty() {
        let g: Vec<String> = b.missing_groups.iter().map(u32::to_string).collect();
        out.push(format!("groups {}", g.join(" ")));
    }
    out.join(", ")
}

#[test]
fn binds_arguments_as_the_table_says() {
    let table: &[(&str, &str, &str)] = &[
        // Positional arguments fill the positional parameters in order.
        ("A, B", "_ _", "A, B"),
        ("A, B", "_", "A, missing B"),
        ("A, B", "", "missing A B"),
        ("A, B", "_ _ _", "A, B, +"),
        ("", "_", "+"),
        // Optional parameters and alternatives are never positional.
        ("\\C, A, \\V|\\T, B", "_ _", "A, B"),
        ("\\C, A, \\V|\\T, B", "C _ V _", "C, A, V, B"),
        ("\\C, A, \\V|\\T, B", "_ V T _", "A, V, T/V, B"),
        ("\\C, A, \\V|\\T, B", "_ T V T _", "A, T, V/T, T=1, B"),
        // Names compare without case; unknown ones bind to nothing.
        ("A, \\Dec", "_ dec", "A, Dec"),
        ("A, \\Dec", "_ Nope", "A, ?"),
        // A named positional parameter moves the position past it; the
        // ones skipped are missing after those not yet reached.
        ("A, B, C", "B _", "B, C, missing A"),
        ("A, B, C, D", "C", "C, missing D A B"),
        ("A, B", "A _ _", "A, B, +"),
        // Duplicates name the previous argument given for the parameter.
        ("A, \\O", "_ O O O", "A, O, O=1, O=2"),
        ("A", "_ A", "A, A=0"),
        // A required group needs one member.
        ("A, !\\On|\\Off", "_", "A, groups 1"),
        ("A, !\\On|\\Off", "_ Off", "A, Off"),
        ("!\\X|\\Y, !\\P|\\Q", "Q", "Q, groups 1"),
    ];
    let mut failures = Vec::new();
    for (sig, args, want) in table {
        let s = signature(sig);
        let got = show(&s, &bind(&s, &call(args)));
        if got != *want {
            failures.push(format!("{sig} / {args}: got `{got}`, want `{want}`"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn next_param_is_after_the_last_bound_one() {
    let s = signature("\\C, A, \\V|\\T, B, \\W");
    assert_eq!(bind(&s, &call("")).next_param(), 0);
    assert_eq!(bind(&s, &call("C")).next_param(), 1);
    assert_eq!(bind(&s, &call("_ V")).next_param(), 3);
    assert_eq!(bind(&s, &call("_ _ Nope")).next_param(), 5);
}
