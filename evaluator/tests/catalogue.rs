//! What the evaluator takes from the catalogue: predefined constants,
//! record layouts and alias types.

use rapid_evaluator::{
    EmptyEnv, Type, Value, builtin_record_layout, is_builtin_num_alias, is_builtin_string_alias,
    predefined,
};

#[test]
fn predefined_constants_come_from_the_catalogue_values() {
    #[allow(clippy::approx_constant)]
    let pi = Value::Num(3.141_592_6);
    assert_eq!(predefined("PI"), Some(pi));
    assert_eq!(predefined("eof_num"), Some(Value::Num(9.998e36)));
    assert_eq!(
        predefined("STR_WHITE"),
        Some(Value::Str(" \t\n\u{b}\u{c}\r".into()))
    );
    assert_eq!(
        predefined("STR_DIGIT"),
        Some(Value::Str("0123456789".into()))
    );
    assert_eq!(
        predefined("STR_UPPER").and_then(|v| v.as_str().map(|s| s.chars().count())),
        Some(56)
    );
    assert_eq!(predefined("GTEQ"), Some(Value::Num(5.0)));
    assert_eq!(predefined("OpMod"), Some(Value::Num(5.0)));
    assert_eq!(predefined("diskhome"), Some(Value::Str("HOME:".into())));
    assert_eq!(predefined("stEmpty"), Some(Value::Str(String::new())));
    assert!(matches!(predefined("v100"), Some(Value::Record { ty, .. }) if ty == "speeddata"));
    assert_eq!(predefined("no_such_constant"), None);
}

#[test]
fn layouts_and_aliases_come_from_the_catalogue() {
    let names: Vec<&str> = builtin_record_layout("RobTarget")
        .unwrap_or_default()
        .iter()
        .map(|c| c.name.as_str())
        .collect();
    assert_eq!(names, ["trans", "rot", "robconf", "extax"]);
    assert!(builtin_record_layout("num").is_none());
    assert!(is_builtin_num_alias("byte") && is_builtin_num_alias("ERRNUM"));
    assert!(!is_builtin_num_alias("num") && !is_builtin_num_alias("stringdig"));
    assert!(is_builtin_string_alias("stringdig") && !is_builtin_string_alias("byte"));
}

/// Data without an initial value start at zero in the catalogue's record
/// layouts (and the environment's); a type the evaluator does not know is
/// the caller's.
#[test]
fn zero_values_follow_the_layouts() {
    let opaque = |name: &str| Value::Str(format!("<{name}>"));
    let zero = |ty: Type, env: &dyn rapid_evaluator::Env| {
        rapid_evaluator::zero_value(&ty, env, &opaque).to_string()
    };
    assert_eq!(zero(Type::named("pos"), &EmptyEnv), "[0,0,0]");
    assert_eq!(
        zero(Type::array("num", vec![2, 3]), &EmptyEnv),
        "[[0,0,0],[0,0,0]]"
    );
    assert_eq!(zero(Type::named("errnum"), &EmptyEnv), "0");
    assert_eq!(zero(Type::named("bool"), &EmptyEnv), "FALSE");
    assert_eq!(zero(Type::named("signaldo"), &EmptyEnv), "\"<signaldo>\"");
    let mut env = rapid_evaluator::MapEnv::new();
    env.record(
        "part",
        vec![
            ("name".into(), Type::named("string")),
            ("at".into(), Type::named("pos")),
        ],
    );
    assert_eq!(zero(Type::named("Part"), &env), "[\"\",[0,0,0]]");
}
