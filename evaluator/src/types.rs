//! Built-in record layouts and alias types the evaluator knows itself.

/// Layout of a built-in record type: `(component, type)` pairs in declaration
/// order, or `None` if `name` is not a built-in record (case-insensitive).
pub fn builtin_record_layout(name: &str) -> Option<&'static [(&'static str, &'static str)]> {
    let lower = name.to_ascii_lowercase();
    Some(match lower.as_str() {
        "pos" => &[("x", "num"), ("y", "num"), ("z", "num")],
        "orient" => &[("q1", "num"), ("q2", "num"), ("q3", "num"), ("q4", "num")],
        "pose" => &[("trans", "pos"), ("rot", "orient")],
        "confdata" => &[
            ("cf1", "num"),
            ("cf4", "num"),
            ("cf6", "num"),
            ("cfx", "num"),
        ],
        "extjoint" => &[
            ("eax_a", "num"),
            ("eax_b", "num"),
            ("eax_c", "num"),
            ("eax_d", "num"),
            ("eax_e", "num"),
            ("eax_f", "num"),
        ],
        "robjoint" => &[
            ("rax_1", "num"),
            ("rax_2", "num"),
            ("rax_3", "num"),
            ("rax_4", "num"),
            ("rax_5", "num"),
            ("rax_6", "num"),
        ],
        "robtarget" | "o_robtarget" => &[
            ("trans", "pos"),
            ("rot", "orient"),
            ("robconf", "confdata"),
            ("extax", "extjoint"),
        ],
        "jointtarget" | "o_jointtarget" => &[("robax", "robjoint"), ("extax", "extjoint")],
        "speeddata" => &[
            ("v_tcp", "num"),
            ("v_ori", "num"),
            ("v_leax", "num"),
            ("v_reax", "num"),
        ],
        "zonedata" => &[
            ("finep", "bool"),
            ("pzone_tcp", "num"),
            ("pzone_ori", "num"),
            ("pzone_eax", "num"),
            ("zone_ori", "num"),
            ("zone_leax", "num"),
            ("zone_reax", "num"),
        ],
        "loaddata" => &[
            ("mass", "num"),
            ("cog", "pos"),
            ("aom", "orient"),
            ("ix", "num"),
            ("iy", "num"),
            ("iz", "num"),
        ],
        "tooldata" => &[
            ("robhold", "bool"),
            ("tframe", "pose"),
            ("tload", "loaddata"),
        ],
        "wobjdata" => &[
            ("robhold", "bool"),
            ("ufprog", "bool"),
            ("ufmec", "string"),
            ("uframe", "pose"),
            ("oframe", "pose"),
        ],
        "progdisp" => &[("pdisp", "pose"), ("eoffs", "extjoint")],
        "inposdata" => &[
            ("position", "num"),
            ("speed", "num"),
            ("mintime", "num"),
            ("maxtime", "num"),
        ],
        "stoppointdata" => &[
            ("type", "stoppoint"),
            ("progsynch", "bool"),
            ("inpos", "inposdata"),
            ("stoptime", "num"),
            ("followtime", "num"),
            ("signal", "string"),
            ("relation", "opnum"),
            ("checkvalue", "num"),
        ],
        _ => return None,
    })
}

/// Built-in alias types of `num` (case-insensitive).
pub fn is_builtin_num_alias(name: &str) -> bool {
    const ALIASES: &[&str] = &[
        "byte",
        "errnum",
        "dionum",
        "intnum",
        "opnum",
        "symnum",
        "errdomain",
        "errtype",
        "tpnum",
        "tunetype",
        "aiotrigg",
        "stoppoint",
        "opcalc",
        "paridnum",
        "paridvalidnum",
        "loadidnum",
        "sensorstate",
        "signalorigin",
        "event_type",
        "handler_type",
        "iounit_state",
        "testsignal",
        "identno",
        "btnres",
        "buttondata",
        "icondata",
        "uishownum",
        "socketstatus",
        "inttypes",
        "egmstate",
        "egmframetype",
        "egmstopmode",
    ];
    ALIASES.iter().any(|a| a.eq_ignore_ascii_case(name))
}

/// Built-in alias types of `string` (case-insensitive).
pub fn is_builtin_string_alias(name: &str) -> bool {
    name.eq_ignore_ascii_case("stringdig") || name.eq_ignore_ascii_case("errstr")
}
