//! What `rapid mcp` gives to read besides its tools: the rules' and the
//! catalogue's documentation and the assertion module as resources, the
//! two prompts, and the instructions sent at the start of a session.

use rapid_analyzer::rules::RULES;
use rmcp::model::{
    ErrorData, GetPromptResult, PromptMessage, ReadResourceResult, Resource, ResourceContents,
    ResourceTemplate, Role,
};
use schemars::JsonSchema;
use serde::Deserialize;

/// Sent to the client when a session starts.
pub const INSTRUCTIONS: &str = "rapid checks, fixes, formats, evaluates, runs and tests ABB RAPID \
robot programs offline, the way the controller loads and runs them. After writing or changing \
RAPID, call `check` (a path, or the unsaved text with the path of its file so the rest of its \
task is known), apply `fix` for the safe repairs, and run `test` on the task's test_ procedures. \
Use `list_symbols` to find the tools (tooldata), work objects (wobjdata), targets (robtarget) \
and signals a program has, `lookup_builtin` for a built-in's signature, `explain_rule` for a \
finding's code. Paths are relative to the first root; nothing outside the roots is read, and \
no tool writes files.";

const RULES_URI: &str = "rapid://rules";
const RULE_PREFIX: &str = "rapid://rules/";
const CATALOGUE_URI: &str = "rapid://builtins";
const BUILTIN_PREFIX: &str = "rapid://builtins/";
const ASSERT_URI: &str = "rapid://test/RapidAssert.sys";

/// The resources: the rule list and each rule, the catalogue's index and
/// the assertion module (each built-in is a template's page).
pub fn resources() -> Vec<Resource> {
    let mut out = vec![
        Resource::new(RULES_URI, "rules")
            .with_title("The checker's rules")
            .with_description("Every rule: code, name, default severity, summary.")
            .with_mime_type("text/plain"),
        Resource::new(CATALOGUE_URI, "builtins")
            .with_title("RAPID built-ins")
            .with_description(
                "Every built-in function, instruction, data type and predefined datum with its \
                 signature (rapid://builtins/NAME documents one).",
            )
            .with_mime_type("text/plain"),
        Resource::new(ASSERT_URI, "RapidAssert.sys")
            .with_title("The assertion module of `test`")
            .with_description(
                "AssertEqual, AssertTrue, AssertNear... as RAPID: loaded with every task `test` \
                 runs; save it beside the tests so `check` knows its routines.",
            )
            .with_mime_type("text/plain"),
    ];
    out.extend(RULES.iter().map(|r| {
        Resource::new(
            format!("{RULE_PREFIX}{}", r.code),
            format!("{} {}", r.code, r.name),
        )
        .with_description(r.summary)
        .with_mime_type("text/markdown")
    }));
    out
}

pub fn templates() -> Vec<ResourceTemplate> {
    vec![
        ResourceTemplate::new(format!("{BUILTIN_PREFIX}{{name}}"), "builtin")
            .with_title("A RAPID built-in")
            .with_description(
                "A built-in's signature, documentation, RobotWare versions and option package.",
            )
            .with_mime_type("text/plain"),
        ResourceTemplate::new(format!("{RULE_PREFIX}{{code}}"), "rule")
            .with_title("A rule of the checker")
            .with_description("A rule's documentation, by code (W201) or name (unused-data).")
            .with_mime_type("text/markdown"),
    ]
}

/// The text of a resource.
pub fn read(uri: &str) -> Result<ReadResourceResult, ErrorData> {
    let text = |t: String, mime: &str| {
        Ok(ReadResourceResult::new(vec![
            ResourceContents::text(t, uri).with_mime_type(mime),
        ]))
    };
    let not_found = |why: String| Err(ErrorData::resource_not_found(why, None));
    if uri == RULES_URI {
        return text(crate::rules_cmd::table(), "text/plain");
    }
    if uri == CATALOGUE_URI {
        let cat = rapid_analyzer::catalogue::base().select(&Default::default());
        return text(crate::builtins::list_human(&cat), "text/plain");
    }
    if uri == ASSERT_URI {
        return text(crate::test_cmd::ASSERT_MODULE.to_owned(), "text/plain");
    }
    if let Some(code) = uri.strip_prefix(RULE_PREFIX) {
        return match rapid_analyzer::rules::find(code) {
            Some(rule) => text(crate::rules_cmd::describe(rule), "text/markdown"),
            None => not_found(format!("no rule has the code or name `{code}`")),
        };
    }
    if let Some(name) = uri.strip_prefix(BUILTIN_PREFIX) {
        let cat = rapid_analyzer::catalogue::base().select(&Default::default());
        return match crate::builtins::describe(&cat, name) {
            Ok(page) => text(page, "text/plain"),
            Err(e) => not_found(e.replace("rapid builtins: ", "")),
        };
    }
    not_found(format!("no resource {uri}"))
}

/// The arguments of the prompt "check-and-fix".
#[derive(Debug, Deserialize, JsonSchema)]
pub struct FixPromptParams {
    /// The module (its path in the project).
    pub path: String,
}

pub fn check_and_fix(p: FixPromptParams) -> GetPromptResult {
    GetPromptResult::new(vec![PromptMessage::new_text(
        Role::User,
        format!(
            "Check the RAPID module `{path}` and make it load cleanly on the controller.\n\n\
             1. Call `check` with path `{path}`.\n\
             2. If findings have safe fixes, call `fix` with path `{path}`, review the repaired \
             text and write it to `{path}`.\n\
             3. Repair what remains by hand: `explain_rule` explains a code, `lookup_builtin` \
             gives a built-in's signature, `list_symbols` the task's routines, data and \
             signals. Keep the module's style and do not change what the program does beyond \
             the repair.\n\
             4. Call `check` again (with the new text and path `{path}` before saving, or after) \
             until it reports no errors, and say what you changed.",
            path = p.path
        ),
    )])
    .with_description("Check a RAPID module, apply the safe fixes, and repair what remains.")
}

/// The arguments of the prompt "write-test".
#[derive(Debug, Deserialize, JsonSchema)]
pub struct TestPromptParams {
    /// The module that declares the routine.
    pub path: String,
    /// The routine to test.
    pub routine: String,
}

pub fn write_test(p: TestPromptParams) -> GetPromptResult {
    GetPromptResult::new(vec![PromptMessage::new_text(
        Role::User,
        format!(
            "Write a unit test for the RAPID routine `{routine}` of `{path}`.\n\n\
             1. Read the routine, and call `list_symbols` on `{path}` for the data and signals \
             it uses.\n\
             2. Write a module named after it with the suffix `_test` (for example \
             `{routine}_test.mod`) in the same folder, so it joins the same task. Each \
             procedure without parameters in it is a test; `setup` and `teardown` run around \
             each. Assert with RapidAssert (the resource rapid://test/RapidAssert.sys): \
             `AssertEqual actual, expected \\Message:=\"...\"`, `AssertTrue`, `AssertNear`, \
             `AssertEqualStr`, `AssertNearPos`, `Fail`. Cover the normal case, the edges \
             and an error the routine handles.\n\
             3. Call `check` on the new module's text (with its path) and fix what it reports.\n\
             4. Call `test` on the folder with `filter` `{routine}_test` and give `signals` \
             the routine waits for; repair the test (not the routine) until it passes, or \
             report what in the routine looks wrong.",
            routine = p.routine,
            path = p.path
        ),
    )])
    .with_description("Write a unit test for a RAPID routine and run it.")
}
