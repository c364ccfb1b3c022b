//! Editor features through the protocol: the `ide` answers, converted.
//! The answers' content is the `ide` module's business (tested there);
//! these tests check that each request reaches it with the right offset and
//! that ranges, locations and kinds come back right.

use serde_json::{Value, json};

use super::{TestClient, doc_pos, pos, temp_dir, write_files};

const LIB: &str = "MODULE Lib\n    RECORD part\n        num weight;\n    ENDRECORD\n\n    ! Moves to the safe position.\n    PROC helper(num speed)\n    ENDPROC\nENDMODULE\n";
const MAIN: &str = "MODULE Main\n    VAR part box;\n    VAR num count := 0;\n\n    PROC main()\n        helper 100;\n        count := count + 1;\n        box.weight := 2.5;\n        MoveL p10, v100, fine, tool0;\n    ENDPROC\nENDMODULE\n";

async fn setup(name: &str) -> (TestClient, String, String) {
    let dir = temp_dir(name);
    write_files(
        &dir,
        &[
            ("Lib.mod", LIB),
            ("rapid.toml", "[format]\nindent-width = 2\n"),
        ],
    );
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    let lib = super::uri(&dir.join("Lib.mod"));
    client.keep(dir);
    (client, main, lib)
}

fn line_of(location: &Value) -> i64 {
    location["range"]["start"]["line"].as_i64().unwrap_or(-1)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn hover_completion_and_signature_help() {
    let (mut client, main, _) = setup("feat-hover").await;
    let at = pos(MAIN, "helper 100", 2);
    let hover = client.call("textDocument/hover", doc_pos(&main, at)).await;
    let text = hover["contents"]["value"].as_str().unwrap_or_default();
    assert!(text.contains("helper"), "{hover}");
    assert_eq!(hover["contents"]["kind"], "markdown");
    assert_eq!(
        hover["range"],
        json!({"start": {"line": 5, "character": 8}, "end": {"line": 5, "character": 14}})
    );

    // Completion at the start of a statement offers the task's routines.
    let at = pos(MAIN, "count := count", 0);
    let list = client
        .call("textDocument/completion", doc_pos(&main, at))
        .await;
    let items = list["items"].as_array().cloned().unwrap_or_default();
    // The whole list would be every built-in and datum: cut to the best,
    // and said to be incomplete so that the editor asks again as the user
    // types.
    assert_eq!(list["isIncomplete"], true, "{}", items.len());
    assert_eq!(items.len(), super::super::requests::MOST_COMPLETIONS);
    let helper = items
        .iter()
        .find(|i| i["label"] == "helper")
        .unwrap_or_else(|| panic!("helper offered: {items:?}"));
    assert_eq!(helper["kind"], 2, "a procedure is a method: {helper}");
    // Documentation comes on resolve.
    if let Some(movel) = items.iter().find(|i| i["label"] == "MoveL") {
        assert!(movel.get("documentation").is_none());
        let resolved = client.call("completionItem/resolve", movel.clone()).await;
        assert!(resolved["documentation"]["value"].is_string(), "{resolved}");
    }
    // Resolving an item the server never made leaves it as it was.
    let foreign = json!({"label": "x"});
    assert_eq!(
        client.call("completionItem/resolve", foreign.clone()).await,
        foreign
    );

    // Signature help inside the arguments of a built-in instruction.
    let at = pos(MAIN, "v100, fine", 0);
    let help = client
        .call("textDocument/signatureHelp", doc_pos(&main, at))
        .await;
    if !help.is_null() {
        let signature = &help["signatures"][0];
        let label = signature["label"].as_str().unwrap_or_default();
        assert!(label.contains("MoveL"), "{help}");
        // Parameter offsets lie within the label.
        let len = label.encode_utf16().count() as i64;
        for p in signature["parameters"].as_array().into_iter().flatten() {
            let [a, b] = [&p["label"][0], &p["label"][1]].map(|v| v.as_i64().unwrap_or(-1));
            assert!(0 <= a && a <= b && b <= len, "{p}");
        }
    }
    client.shutdown().await;
}

/// A client that resolves `detail` (as VS Code does) gets lists without it,
/// and each item's detail on resolve: the same one the list would carry.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn completion_detail_on_resolve() {
    let dir = temp_dir("feat-lazy-detail");
    write_files(&dir, &[("Lib.mod", LIB)]);
    let lazy = json!({"textDocument": {"completion": {"completionItem": {
        "resolveSupport": {"properties": ["documentation", "detail"]}}}}});
    let mut client =
        TestClient::with_capabilities(dir.to_path_buf(), lazy, json!({"diagnosticsDelay": 0}))
            .await;
    let main = client.open(&dir.join("Main.mod"), MAIN);
    let mut eager = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let main2 = eager.open(&dir.join("Main.mod"), MAIN);
    // Each label where the first two letters of it are typed.
    for (label, at) in [
        ("helper", pos(MAIN, "helper 100", 2)),
        ("MoveL", pos(MAIN, "MoveL p10", 2)),
        ("count", pos(MAIN, "count := count", 2)),
        ("v100", pos(MAIN, "v100, fine", 2)),
    ] {
        let list = client
            .call("textDocument/completion", doc_pos(&main, at.clone()))
            .await;
        let items = list["items"].as_array().cloned().unwrap_or_default();
        assert!(items.iter().all(|i| i.get("detail").is_none()), "{items:?}");
        let item = items
            .iter()
            .find(|i| i["label"] == label)
            .unwrap_or_else(|| panic!("{label} offered: {items:?}"));
        let full = eager
            .call("textDocument/completion", doc_pos(&main2, at))
            .await;
        let expected = full["items"]
            .as_array()
            .into_iter()
            .flatten()
            .find(|i| i["label"] == label)
            .map(|i| i["detail"].clone())
            .unwrap_or_default();
        assert!(expected.is_string(), "{label}: {full}");
        let resolved = client.call("completionItem/resolve", item.clone()).await;
        assert_eq!(resolved["detail"], expected, "{label}: {resolved}");
    }
    eager.shutdown().await;
    client.shutdown().await;
}

/// A long list is cut to the items that hold the letters typed; a short
/// one is whole.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn long_completion_lists_are_cut_by_what_is_typed() {
    let (mut client, main, _) = setup("feat-cut").await;
    let list = client
        .call(
            "textDocument/completion",
            doc_pos(&main, pos(MAIN, "MoveL p10", 3)),
        )
        .await;
    let labels: Vec<&str> = list["items"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|i| i["label"].as_str())
        .collect();
    assert_eq!(list["isIncomplete"], true);
    assert!(
        labels.contains(&"MoveL") && labels.contains(&"MoveAbsJ"),
        "{labels:?}"
    );
    assert!(
        labels.iter().all(|l| {
            let l = l.to_ascii_lowercase();
            let (m, o) = (l.find('m'), l.rfind('v'));
            m.is_some() && o.is_some() && m < o
        }),
        "{labels:?}"
    );
    // After `box.`: the record's components, all of them.
    let list = client
        .call(
            "textDocument/completion",
            doc_pos(&main, pos(MAIN, "box.weight", 4)),
        )
        .await;
    assert_eq!(list["isIncomplete"], false, "{list}");
    assert_eq!(list["items"][0]["label"], "weight", "{list}");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn navigation_across_files() {
    let (mut client, main, lib) = setup("feat-nav").await;
    let at = pos(MAIN, "helper 100", 1);
    for method in ["textDocument/definition", "textDocument/declaration"] {
        let found = client.call(method, doc_pos(&main, at.clone())).await;
        assert_eq!(found[0]["uri"], lib, "{method}: {found}");
        assert_eq!(line_of(&found[0]), 6, "{method}: {found}");
    }
    // Type definition of a variable of a record type: the record.
    let at = pos(MAIN, "box.weight", 0);
    let found = client
        .call("textDocument/typeDefinition", doc_pos(&main, at))
        .await;
    assert_eq!(found[0]["uri"], lib, "{found}");
    assert_eq!(line_of(&found[0]), 1, "{found}");
    // References to `count`, with and without the declaration.
    let at = pos(MAIN, "count := count", 0);
    let mut params = doc_pos(&main, at.clone());
    params["context"] = json!({"includeDeclaration": true});
    let with = client.call("textDocument/references", params.clone()).await;
    params["context"] = json!({"includeDeclaration": false});
    let without = client.call("textDocument/references", params).await;
    let lines = |v: &Value| -> Vec<i64> {
        let mut l: Vec<i64> = v.as_array().into_iter().flatten().map(line_of).collect();
        l.sort_unstable();
        l
    };
    assert_eq!(lines(&with), [2, 6, 6], "{with}");
    assert_eq!(lines(&without), [6, 6], "{without}");
    // Highlights: the assignment writes, the right-hand side reads.
    let highlights = client
        .call("textDocument/documentHighlight", doc_pos(&main, at))
        .await;
    let kinds: Vec<(i64, i64)> = highlights
        .as_array()
        .into_iter()
        .flatten()
        .filter(|h| line_of(h) == 6)
        .map(|h| {
            (
                h["range"]["start"]["character"].as_i64().unwrap_or(-1),
                h["kind"].as_i64().unwrap_or(0),
            )
        })
        .collect();
    assert_eq!(kinds, [(8, 3), (17, 2)], "{highlights}");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn rename_across_files() {
    let (mut client, main, lib) = setup("feat-rename").await;
    let at = pos(MAIN, "helper 100", 0);
    let range = client
        .call("textDocument/prepareRename", doc_pos(&main, at.clone()))
        .await;
    assert_eq!(
        range,
        json!({"start": {"line": 5, "character": 8}, "end": {"line": 5, "character": 14}})
    );
    let mut params = doc_pos(&main, at);
    params["newName"] = json!("moveSafe");
    let edit = client.call("textDocument/rename", params).await;
    let changes = edit["changes"].as_object().cloned().unwrap_or_default();
    assert_eq!(changes[&main][0]["newText"], "moveSafe", "{edit}");
    assert_eq!(line_of(&changes[&lib][0]), 6, "{edit}");
    // Renaming a keyword is refused with a message.
    let at = pos(MAIN, "ENDPROC", 1);
    let response = client
        .request("textDocument/prepareRename", doc_pos(&main, at))
        .await;
    assert!(
        response["error"]["message"].is_string() || response["result"].is_null(),
        "{response}"
    );
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn symbols_folding_selection_and_hints() {
    let (mut client, main, _) = setup("feat-symbols").await;
    let doc = json!({"textDocument": {"uri": main}});
    let symbols = client
        .call("textDocument/documentSymbol", doc.clone())
        .await;
    let module = &symbols[0];
    assert_eq!(module["name"], "Main", "{symbols}");
    let children: Vec<&str> = module["children"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|c| c["name"].as_str())
        .collect();
    assert_eq!(children, ["box", "count", "main"], "{symbols}");
    let found = client
        .call("workspace/symbol", json!({"query": "helper"}))
        .await;
    assert!(
        found
            .as_array()
            .into_iter()
            .flatten()
            .any(|s| s["name"] == "helper" && line_of(&s["location"]) == 6),
        "{found}"
    );
    let folds = client.call("textDocument/foldingRange", doc.clone()).await;
    assert!(
        folds
            .as_array()
            .into_iter()
            .flatten()
            .any(|f| f["startLine"] == 4 && f["endLine"].as_i64() >= Some(8)),
        "the routine folds: {folds}"
    );
    let mut params = doc.clone();
    params["positions"] = json!([pos(MAIN, "weight", 1)]);
    let selection = client.call("textDocument/selectionRange", params).await;
    let mut depth = 0;
    let mut node = &selection[0];
    let mut previous: Option<(i64, i64)> = None;
    while node.is_object() {
        let start = node["range"]["start"]["line"].as_i64().unwrap_or(0) * 1000
            + node["range"]["start"]["character"].as_i64().unwrap_or(0);
        let end = node["range"]["end"]["line"].as_i64().unwrap_or(0) * 1000
            + node["range"]["end"]["character"].as_i64().unwrap_or(0);
        if let Some((s, e)) = previous {
            assert!(
                start <= s && e <= end,
                "parents contain children: {selection}"
            );
        }
        previous = Some((start, end));
        node = &node["parent"];
        depth += 1;
    }
    assert!(depth >= 3, "{selection}");
    let mut params = doc.clone();
    params["range"] =
        json!({"start": {"line": 0, "character": 0}, "end": {"line": 11, "character": 0}});
    let hints = client.call("textDocument/inlayHint", params).await;
    assert!(hints.is_array(), "{hints}");
    for h in hints.as_array().into_iter().flatten() {
        assert!(h["position"]["line"].as_i64() <= Some(10), "{h}");
    }
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn semantic_tokens_full_delta_and_range() {
    let (mut client, main, _) = setup("feat-tokens").await;
    let doc = json!({"textDocument": {"uri": main}});
    let full = client
        .call("textDocument/semanticTokens/full", doc.clone())
        .await;
    let data = full["data"].as_array().cloned().unwrap_or_default();
    assert_eq!(data.len() % 5, 0);
    assert!(!data.is_empty(), "{full}");
    let first_id = full["resultId"].clone();
    // Nothing changed: an empty delta.
    let mut params = doc.clone();
    params["previousResultId"] = first_id.clone();
    let delta = client
        .call("textDocument/semanticTokens/full/delta", params.clone())
        .await;
    assert_eq!(delta["edits"], json!([]), "{delta}");
    // An edit: the delta applied to the old data gives the new full data.
    client.change(
        &main,
        2,
        json!([{"range": {"start": {"line": 6, "character": 8}, "end": {"line": 6, "character": 8}}, "text": "count := 2;\n        "}]),
    );
    params["previousResultId"] = delta["resultId"].clone();
    let delta = client
        .call("textDocument/semanticTokens/full/delta", params.clone())
        .await;
    let mut applied: Vec<Value> = data.clone();
    for edit in delta["edits"].as_array().into_iter().flatten() {
        let start = edit["start"].as_u64().unwrap_or(0) as usize;
        let count = edit["deleteCount"].as_u64().unwrap_or(0) as usize;
        let insert = edit["data"].as_array().cloned().unwrap_or_default();
        applied.splice(start..start + count, insert);
    }
    let fresh = client
        .call("textDocument/semanticTokens/full", doc.clone())
        .await;
    assert_eq!(Value::Array(applied), fresh["data"], "{delta}");
    // An unknown previous result: the full tokens.
    params["previousResultId"] = json!("stale");
    let full_again = client
        .call("textDocument/semanticTokens/full/delta", params)
        .await;
    assert_eq!(full_again["data"], fresh["data"]);
    // A range gives the tokens of those lines only.
    let mut params = doc.clone();
    params["range"] =
        json!({"start": {"line": 5, "character": 0}, "end": {"line": 6, "character": 0}});
    let range = client
        .call("textDocument/semanticTokens/range", params)
        .await;
    let range_data = range["data"].as_array().cloned().unwrap_or_default();
    assert!(
        !range_data.is_empty() && range_data.len() < data.len(),
        "{range}"
    );
    assert_eq!(range_data[0], 5, "first token on line 5: {range}");
    client.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn formatting_follows_rapid_toml() {
    let (mut client, main, _) = setup("feat-format").await;
    let options = json!({"tabSize": 8, "insertSpaces": true});
    let edits = client
        .call(
            "textDocument/formatting",
            json!({"textDocument": {"uri": main}, "options": options}),
        )
        .await;
    let text = apply(MAIN, &edits);
    assert!(text.contains("\n  VAR part box;\n"), "{text}");
    assert!(text.contains("\n    helper 100;\n"), "{text}");
    // Range formatting touches only the lines asked for.
    let range = json!({"start": {"line": 5, "character": 0}, "end": {"line": 5, "character": 3}});
    let edits = client
        .call(
            "textDocument/rangeFormatting",
            json!({"textDocument": {"uri": main}, "range": range, "options": options}),
        )
        .await;
    let text = apply(MAIN, &edits);
    assert!(text.contains("\n    VAR part box;\n"), "{text}");
    assert!(text.contains("\n    helper 100;\n"), "{text}");
    assert!(text.contains("\n        count := count + 1;\n"), "{text}");
    client.shutdown().await;
}

/// Formatting answers with whole changed lines, one edit per run of them,
/// not one edit per blank; and with one edit of the whole text when most
/// of its lines change.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn formatting_sends_line_edits() {
    let (mut client, _, _) = setup("feat-format-lines").await;
    let dir = temp_dir("feat-format-lines-doc");
    let mut body: Vec<String> = (0..300).map(|i| format!("    x{i} := {i};")).collect();
    body[40] = "x40 := 40;".to_owned();
    body[41] = "      x41 := 41;".to_owned();
    body[200] = "   x200 := 200;".to_owned();
    let text = format!(
        "MODULE Big\n  PROC p()\n{}\n  ENDPROC\nENDMODULE\n",
        body.join("\n")
    );
    let uri = client.open(&dir.join("Big.mod"), &text);
    let edits = format_document(&mut client, &uri).await;
    let list = edits.as_array().cloned().unwrap_or_default();
    assert_eq!(list.len(), 2, "{edits}");
    for e in &list {
        assert_eq!(e["range"]["start"]["character"], 0, "{e}");
        assert_eq!(e["range"]["end"]["character"], 0, "{e}");
    }
    assert_eq!(list[0]["range"]["start"]["line"], 42);
    assert_eq!(list[0]["range"]["end"]["line"], 44);
    assert_eq!(list[0]["newText"], "    x40 := 40;\n    x41 := 41;\n");
    let formatted = apply(&text, &edits);
    assert!(formatted.contains("\n    x200 := 200;\n"), "{formatted}");

    // a text written flat changes on most lines: one edit
    let flat = format!(
        "MODULE Flat\nPROC p()\n{}\nENDPROC\nENDMODULE\n",
        (0..300)
            .map(|i| format!("y{i} := {i};"))
            .collect::<Vec<_>>()
            .join("\n")
    );
    let uri = client.open(&dir.join("Flat.mod"), &flat);
    let edits = format_document(&mut client, &uri).await;
    let list = edits.as_array().cloned().unwrap_or_default();
    assert_eq!(list.len(), 1, "{edits}");
    assert_eq!(
        list[0]["range"]["start"],
        json!({"line": 0, "character": 0})
    );
    let formatted = apply(&flat, &edits);
    assert!(formatted.contains("\n    y7 := 7;\n"), "{formatted}");
    client.keep(dir);
    client.shutdown().await;
}

/// The edits of a whole-document formatting request.
async fn format_document(client: &mut TestClient, uri: &str) -> Value {
    let options = json!({"tabSize": 4, "insertSpaces": true});
    client
        .call(
            "textDocument/formatting",
            json!({"textDocument": {"uri": uri}, "options": options}),
        )
        .await
}

/// Applies LSP text edits to an ASCII text.
fn apply(text: &str, edits: &Value) -> String {
    let lines: Vec<usize> = std::iter::once(0)
        .chain(text.match_indices('\n').map(|(i, _)| i + 1))
        .collect();
    let offset = |p: &Value| -> usize {
        let line = p["line"].as_u64().unwrap_or(0) as usize;
        lines.get(line).copied().unwrap_or(text.len())
            + p["character"].as_u64().unwrap_or(0) as usize
    };
    let mut edits: Vec<(usize, usize, String)> = edits
        .as_array()
        .into_iter()
        .flatten()
        .map(|e| {
            (
                offset(&e["range"]["start"]),
                offset(&e["range"]["end"]),
                e["newText"].as_str().unwrap_or_default().to_owned(),
            )
        })
        .collect();
    edits.sort_by_key(|e| std::cmp::Reverse(e.0));
    let mut out = text.to_owned();
    for (a, b, new) in edits {
        out.replace_range(a..b, &new);
    }
    out
}

const TASK1: &str = "MODULE Main\n  PERS bool bWaitForJob := FALSE;\n  PROC main()\n    bWaitForJob := TRUE;\n  ENDPROC\nENDMODULE\n";
const TASK2: &str = "MODULE Main\n  PERS bool bWaitForJob;\n  PROC main()\n    WaitUntil bWaitForJob;\n    bWaitForJob := FALSE;\n  ENDPROC\nENDMODULE\n";

/// A persistent shared by the tasks of a backup: references and rename
/// reach the tasks whose files are not open; a task that declares it with
/// another type makes rename refuse, with the reason.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn shared_persistents_link_the_tasks_of_a_backup() {
    let dir = temp_dir("feat-shared-pers");
    let t1 = "RAPID/TASK1/PROGMOD/Main.mod";
    let t3 = "RAPID/TASK3/PROGMOD/Main.mod";
    write_files(
        &dir,
        &[(t1, TASK1), (t3, TASK1), ("BACKINFO/backinfo.txt", "")],
    );
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let task2 = client.open(&dir.join("RAPID/TASK2/PROGMOD/Main.mod"), TASK2);
    let (uri1, uri3) = (super::uri(&dir.join(t1)), super::uri(&dir.join(t3)));
    let at = pos(TASK2, "WaitUntil bWaitForJob", 10);
    let mut params = doc_pos(&task2, at.clone());
    params["context"] = json!({"includeDeclaration": true});
    let found = client.call("textDocument/references", params).await;
    let mut files: Vec<(String, i64)> = found
        .as_array()
        .into_iter()
        .flatten()
        .map(|l| (l["uri"].as_str().unwrap_or_default().to_owned(), line_of(l)))
        .collect();
    files.sort();
    let mut want = vec![
        (uri1.clone(), 1),
        (uri1.clone(), 3),
        (task2.clone(), 1),
        (task2.clone(), 3),
        (task2.clone(), 4),
        (uri3.clone(), 1),
        (uri3.clone(), 3),
    ];
    want.sort();
    assert_eq!(files, want, "{found}");
    let mut params = doc_pos(&task2, at.clone());
    params["newName"] = json!("bJobReady");
    let edit = client.call("textDocument/rename", params.clone()).await;
    let changes = edit["changes"].as_object().cloned().unwrap_or_default();
    let count = |uri: &str| {
        changes
            .get(uri)
            .and_then(Value::as_array)
            .map_or(0, Vec::len)
    };
    assert_eq!(
        (count(&uri1), count(&task2), count(&uri3)),
        (2, 3, 2),
        "{edit}"
    );
    // TASK3 declares it as a num: the same name, another datum
    let other = TASK1
        .replace(
            "PERS bool bWaitForJob := FALSE",
            "PERS num bWaitForJob := 0",
        )
        .replace("TRUE", "1");
    client.open(&dir.join(t3), &other);
    let response = client.request("textDocument/rename", params).await;
    let message = response["error"]["message"].as_str().unwrap_or_default();
    assert!(
        message.contains("TASK3") && message.contains("`num`"),
        "{response}"
    );
    client.keep(dir);
    client.shutdown().await;
}

/// Typing a blank or the `=` of `:=` asks for the values of the argument
/// that starts there (the data of its type, the most used first), and for
/// nothing elsewhere.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn completion_triggered_by_a_blank_or_an_equals_sign() {
    let text = "MODULE Main\n    PERS wobjdata wTable := [FALSE, TRUE, \"\", [[0,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];\n    VAR num count := 0;\n\n    PROC main()\n        MoveL p10, v100, fine, tool0\\WObj:=\n        IF count \n    ENDPROC\nENDMODULE\n";
    let dir = temp_dir("feat-trigger");
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let main = client.open(&dir.join("Main.mod"), text);
    let ask = |at: Value, trigger: &str| {
        let mut params = doc_pos(&main, at);
        params["context"] = json!({"triggerKind": 2, "triggerCharacter": trigger});
        params
    };
    let labels = |list: &Value| -> Vec<String> {
        let mut items: Vec<(String, String)> = list["items"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|i| {
                (
                    i["sortText"].as_str().unwrap_or_default().to_owned(),
                    i["label"].as_str().unwrap_or_default().to_owned(),
                )
            })
            .collect();
        items.sort();
        items.into_iter().map(|(_, l)| l).collect()
    };
    let list = client
        .call(
            "textDocument/completion",
            ask(pos(text, "MoveL p10", 6), " "),
        )
        .await;
    let items = labels(&list);
    assert!(items.iter().any(|l| l == "Offs"), "{items:?}");
    assert!(
        !items.iter().any(|l| l == "count"),
        "only robtargets: {items:?}"
    );
    let list = client
        .call(
            "textDocument/completion",
            ask(pos(text, "\\WObj:=", 7), "="),
        )
        .await;
    assert_eq!(
        labels(&list).first().map(String::as_str),
        Some("wTable"),
        "{list}"
    );
    let list = client
        .call(
            "textDocument/completion",
            ask(pos(text, "IF count ", 9), " "),
        )
        .await;
    assert_eq!(labels(&list), Vec::<String>::new(), "{list}");
    client.keep(dir);
    client.shutdown().await;
}

/// `rapid/indentation` says how the formatter indents a document: the
/// majority's tabs or spaces (a file of spaces with one line led by a tab
/// is a file of spaces), or the configured width.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn indentation_is_the_formatters() {
    let dir = temp_dir("feat-indentation");
    let spaces = "MODULE A\n    PROC p()\n        x := 1;\n\ty := 2;\n        z := 3;\n    ENDPROC\nENDMODULE\n";
    let tabs =
        "MODULE B\n\tPROC p()\n\t\tx := 1;\n        y := 2;\n\t\tz := 3;\n\tENDPROC\nENDMODULE\n";
    let mut client = TestClient::new(dir.to_path_buf(), json!({"diagnosticsDelay": 0})).await;
    let a = client.open(&dir.join("A.mod"), spaces);
    let b = client.open(&dir.join("B.mod"), tabs);
    let ask = |uri: &str| json!({"textDocument": {"uri": uri}});
    assert_eq!(
        client.call("rapid/indentation", ask(&a)).await,
        json!({"width": 4, "tabs": false})
    );
    assert_eq!(
        client.call("rapid/indentation", ask(&b)).await,
        json!({"width": 4, "tabs": true})
    );
    client.keep(dir);
    client.shutdown().await;
}
