use super::*;

/// The 80 function chapters of the RAPID reference manual part 2, in manual order.
const MANUAL_FUNCTIONS: &[&str] = &[
    "Abs",
    "ACos",
    "AOutput",
    "ASin",
    "ATan",
    "ATan2",
    "ByteToStr",
    "CalcJointT",
    "CalcRobT",
    "CalcRotAxisFrame",
    "CDate",
    "CJointT",
    "ClkRead",
    "Cos",
    "CPos",
    "CRobT",
    "CSpeedOverride",
    "CTime",
    "CTool",
    "CWObj",
    "DefAccFrame",
    "DefDFrame",
    "DefFrame",
    "Dim",
    "Distance",
    "DotProd",
    "DOutput",
    "EulerZYX",
    "Exp",
    "FileTime",
    "GetNextMechUnit",
    "GetNextSym",
    "GetTaskName",
    "GetTime",
    "GOutput",
    "IsMechUnitActive",
    "IsPers",
    "IsSysId",
    "IsVar",
    "MaxRobSpeed",
    "MirPos",
    "ModTime",
    "NOrient",
    "NumToStr",
    "Offs",
    "OpMode",
    "OrientZYX",
    "ORobT",
    "PoseInv",
    "PoseMult",
    "PoseVect",
    "Pow",
    "Present",
    "ReadBin",
    "ReadMotor",
    "ReadNum",
    "ReadStr",
    "ReadStrBin",
    "RelTool",
    "RobOS",
    "Round",
    "RunMode",
    "Sin",
    "Sqrt",
    "StrFind",
    "StrLen",
    "StrMap",
    "StrMatch",
    "StrMemb",
    "StrOrder",
    "StrPart",
    "StrToByte",
    "StrToVal",
    "Tan",
    "TestAndSet",
    "TestDI",
    "TestSignRead",
    "Trunc",
    "ValToStr",
    "VectMagn",
];

/// The data type chapters of the manual (signalxx split into its six types).
const MANUAL_DATATYPES: &[&str] = &[
    "aiotrigg",
    "bool",
    "byte",
    "clock",
    "confdata",
    "dionum",
    "errdomain",
    "errnum",
    "errtype",
    "extjoint",
    "intnum",
    "iodev",
    "jointtarget",
    "loaddata",
    "loadsession",
    "mecunit",
    "motsetdata",
    "num",
    "o_jointtarget",
    "o_robtarget",
    "opnum",
    "orient",
    "pos",
    "pose",
    "progdisp",
    "robjoint",
    "robtarget",
    "shapedata",
    "signalai",
    "signalao",
    "signaldi",
    "signaldo",
    "signalgi",
    "signalgo",
    "speeddata",
    "stoppointdata",
    "string",
    "symnum",
    "taskid",
    "testsignal",
    "tooldata",
    "tpnum",
    "triggdata",
    "trapdata",
    "tunetype",
    "wobjdata",
    "wzstationary",
    "wztemporary",
    "zonedata",
];

#[test]
fn sources_parse() {
    let cat = Catalogue::load();
    assert!(cat.is_ok(), "{:?}", cat.err());
    assert!(!base().functions.is_empty());
}

#[test]
fn catalogue_is_consistent() {
    assert_eq!(base().check(), Vec::<String>::new());
}

#[test]
fn check_reports_broken_entries() {
    // A catalogue with deliberate mistakes: the checker must find each one.
    let mut cat = Catalogue::load().unwrap_or_default();
    let mut bad = cat.functions[0].clone();
    bad.name = "ABS".into(); // duplicate name, other case
    bad.params.push(Param {
        name: "X".into(),
        ty: "nosuchtype".into(),
        mode: Some(Mode::In),
        optional: true,
        switch: false,
        array: 0,
        alt_group: Some(9),
        since: None,
        any_rank: false,
    });
    bad.alt_groups.push(AltGroup {
        id: 9,
        required: false,
    });
    cat.functions.push(bad);
    cat.data.push(Datum {
        name: "zz".into(),
        ty: "nosuchtype".into(),
        kind: DatumKind::Const,
        value: None,
        read_only: false,
        origin: Origin {
            since: Version::FIRST,
            until: None,
            package: Some("nosuchpackage".into()),
            source: Source::Reference,
            section: None,
            note: None,
        },
        summary: String::new(),
    });
    let problems = cat.check().join("\n");
    assert!(problems.contains("`ABS`: name already used"), "{problems}");
    assert!(problems.contains("unknown type `nosuchtype`"), "{problems}");
    assert!(
        problems.contains("group 9 has fewer than 2 members"),
        "{problems}"
    );
    assert!(problems.contains("datum zz: unknown type"), "{problems}");
    assert!(
        problems.contains("zz: unknown package `nosuchpackage`"),
        "{problems}"
    );
}

#[test]
fn manual_functions_are_exactly_the_manuals() {
    let cat = base();
    let manual: Vec<&str> = cat
        .functions
        .iter()
        .filter(|f| f.origin.source == Source::Manual)
        .map(|f| f.name.as_str())
        .collect();
    assert_eq!(manual, MANUAL_FUNCTIONS);
    assert_eq!(manual.len(), 80);
    for f in cat
        .functions
        .iter()
        .filter(|f| f.origin.source == Source::Manual)
    {
        assert!(f.origin.section.is_some(), "{} lacks a section", f.name);
    }
}

#[test]
fn manual_datatypes_are_present() {
    let cat = base();
    for name in MANUAL_DATATYPES {
        let t = cat.datatype(name);
        assert!(
            t.is_some_and(|t| t.origin.source == Source::Manual),
            "{name}"
        );
    }
}

#[test]
fn lookups_ignore_case() {
    let cat = base();
    assert_eq!(
        cat.function("strpart").map(|f| f.name.as_str()),
        Some("StrPart")
    );
    assert_eq!(cat.routine("ROUND").map(|f| f.name.as_str()), Some("Round"));
    assert_eq!(
        cat.datatype("ROBTARGET").map(|t| t.name.as_str()),
        Some("robtarget")
    );
    assert_eq!(
        cat.datum("V100").and_then(|d| d.value.as_deref()),
        Some("[100,500,5000,1000]")
    );
    assert_eq!(cat.resolve_alias("errnum"), "num");
    assert_eq!(cat.resolve_alias("wzstationary"), "wztemporary");
    assert!(cat.function("NoSuchFunction").is_none());
}

#[test]
fn manual_function_signatures() {
    let text: String = base()
        .functions
        .iter()
        .filter(|f| f.origin.source == Source::Manual)
        .map(|f| {
            // Parameters later RobotWare added are not the manual's: marked.
            let later: Vec<String> = f
                .params
                .iter()
                .filter_map(|p| p.since.map(|v| format!("{} {v}", p.name)))
                .collect();
            format!(
                "{}{}{}\n",
                f.signature(),
                if f.pure { "  [pure]" } else { "" },
                if later.is_empty() {
                    String::new()
                } else {
                    format!("  [later: {}]", later.join(", "))
                }
            )
        })
        .collect();
    insta::assert_snapshot!(text);
}

#[test]
fn manual_datatype_shapes() {
    let text: String = base()
        .datatypes
        .iter()
        .filter(|t| t.origin.source == Source::Manual)
        .map(|t| format!("{}\n", t.signature()))
        .collect();
    insta::assert_snapshot!(text);
}

/// Splits a RAPID aggregate `[a, [b, c], "d"]` into its top-level elements; `None` when
/// `text` is not an aggregate.
fn aggregate_elements(text: &str) -> Option<Vec<&str>> {
    let inner = text.trim().strip_prefix('[')?.strip_suffix(']')?;
    let (mut depth, mut in_string, mut start) = (0i32, false, 0usize);
    let mut out = Vec::new();
    for (i, c) in inner.char_indices() {
        match c {
            '"' => in_string = !in_string,
            '[' if !in_string => depth += 1,
            ']' if !in_string => depth -= 1,
            ',' if !in_string && depth == 0 => {
                out.push(inner[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(inner[start..].trim());
    Some(out)
}

/// Whether `value` (RAPID literal text) fits data type `ty` of the catalogue.
fn value_fits(cat: &Catalogue, ty: &str, value: &str) -> Result<(), String> {
    let ty = cat.resolve_alias(ty);
    let Some(t) = cat.datatype(ty) else {
        return Err(format!("unknown type {ty}"));
    };
    match t.kind {
        TypeKind::Record => {
            let elems =
                aggregate_elements(value).ok_or(format!("{value} is not an aggregate for {ty}"))?;
            if elems.len() != t.components.len() {
                return Err(format!(
                    "{value}: {} elements for {ty} with {} components",
                    elems.len(),
                    t.components.len()
                ));
            }
            for (e, c) in elems.iter().zip(&t.components) {
                value_fits(cat, &c.ty, e).map_err(|m| format!("{ty}.{}: {m}", c.name))?;
            }
            Ok(())
        }
        _ => {
            let ok = match ty {
                "num" | "dnum" => {
                    value.parse::<f64>().is_ok()
                        || cat
                            .datum(value)
                            .is_some_and(|d| cat.resolve_alias(&d.ty) == "num")
                }
                "bool" => value == "TRUE" || value == "FALSE",
                "string" => value.starts_with('"') && value.ends_with('"') && value.len() >= 2,
                _ => false,
            };
            if ok {
                Ok(())
            } else {
                Err(format!("`{value}` is not a {ty} literal"))
            }
        }
    }
}

#[test]
fn predefined_values_match_their_types() {
    let cat = base();
    let mut problems = Vec::new();
    for d in &cat.data {
        if let Some(v) = &d.value
            && let Err(m) = value_fits(cat, &d.ty, v)
        {
            problems.push(format!("{}: {m}", d.name));
        }
    }
    assert_eq!(problems, Vec::<String>::new());
    // The checker itself must reject a wrong value.
    assert!(value_fits(cat, "speeddata", "[100,500,5000]").is_err());
    assert!(value_fits(cat, "zonedata", "[FALSE,1,1,1,0.1,1,TRUE]").is_err());
}

#[test]
fn every_entry_is_documented() {
    let cat = base();
    let mut missing = Vec::new();
    for r in cat.functions.iter().chain(&cat.instructions) {
        if r.summary.trim().is_empty() || r.summary.contains('\n') || r.doc.trim().is_empty() {
            missing.push(r.name.as_str());
        }
        if r.origin.source == Source::Manual && r.origin.section.is_none() {
            missing.push(r.name.as_str());
        }
    }
    for t in &cat.datatypes {
        if t.summary.trim().is_empty() || t.summary.contains('\n') || t.doc.trim().is_empty() {
            missing.push(t.name.as_str());
        }
    }
    for d in &cat.data {
        if d.summary.trim().is_empty() {
            missing.push(d.name.as_str());
        }
    }
    assert_eq!(missing, Vec::<&str>::new());
}

#[test]
fn reference_page_is_current() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/catalogue.md");
    let page = base().reference_page();
    if std::env::var_os("RAPID_BLESS").is_some() {
        std::fs::write(path, &page).expect("write docs/catalogue.md");
        return;
    }
    let current = std::fs::read_to_string(path).unwrap_or_default();
    assert!(
        current == page,
        "docs/catalogue.md is stale: run `RAPID_BLESS=1 cargo test -p rapid-catalogue reference_page`"
    );
}

#[test]
fn views_keep_every_name_and_drop_later_parameters() {
    let old = view(&Selection::new(Some(Version::new(5, 15)), []));
    // EGM came with RobotWare 6: still known, but newer than 5.15.
    let egm = old
        .instruction("EGMReset")
        .map(|r| old.availability(&r.origin));
    assert!(matches!(egm, Some(Availability::Newer { .. })), "{egm:?}");
    // A parameter added in 6.07 is not in 6.05's EGMSetupUC.
    let v605 = view(&Selection::new(
        Some(Version::new(6, 5)),
        ["egm".to_string()],
    ));
    let uc = v605.instruction("EGMSetupUC").map(|r| r.params.len());
    let full = base().instruction("EGMSetupUC").map(|r| r.params.len());
    assert_eq!(uc.zip(full).map(|(a, b)| b - a), Some(2));
    assert_eq!(
        v605.instruction("EGMReset")
            .map(|r| v605.availability(&r.origin)),
        Some(Availability::Yes)
    );
    // Without the option, an option routine is known and needs its package.
    let arc = base()
        .instruction("ArcLStart")
        .map(|r| base().availability(&r.origin));
    assert!(matches!(arc, Some(Availability::NeedsOption(p)) if p.id == "arc"));
    assert_eq!(
        base().packages_named_in("689-1 Externally Guided Motion"),
        vec!["egm"]
    );
    assert!(base().packages_named_in("ArcCell 7").is_empty());
}
