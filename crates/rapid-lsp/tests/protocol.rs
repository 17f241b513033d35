//! The server driven through a real protocol client path: `lsp_server`'s in-memory
//! connection, JSON-RPC messages in and out, as an editor would send them. Every
//! expected position is counted by hand from the fixture texts below.

mod client;

use client::{Client, Folder};
use serde_json::{json, Value};

const MAIN: &str = "MODULE Main
  PROC main()
    VAR num n;
    n := Helper(2);
    cnt := StrLen(\"ä\");
  ENDPROC
ENDMODULE
";

const TOOLS: &str = "MODULE Tools
  FUNC num Helper(num x)
    RETURN x * 2;
  ENDFUNC
ENDMODULE
";

fn two_modules() -> (Folder, Client) {
    let folder = Folder::new("two_modules", &[("Main.mod", MAIN), ("Tools.mod", TOOLS)]);
    let client = Client::start(&folder, json!({}));
    (folder, client)
}

fn range(l1: u32, c1: u32, l2: u32, c2: u32) -> Value {
    json!({"start": {"line": l1, "character": c1}, "end": {"line": l2, "character": c2}})
}

#[test]
fn pushes_the_checkers_findings_for_the_whole_folder() {
    let (folder, mut client) = two_modules();
    let main = folder.uri("Main.mod");
    let diags = client.diagnostics_for(&main);
    // `cnt` is undeclared: line 4, UTF-16 columns 4..7.
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0]["code"], "E0201");
    assert_eq!(diags[0]["severity"], 1);
    assert_eq!(diags[0]["range"], range(4, 4, 4, 7));
    // The message is the checker's, word for word.
    let inputs = folder.inputs();
    let found = rapid_sema::check(&inputs, &rapid_sema::Options::default());
    assert_eq!(found.len(), 1);
    assert_eq!(diags[0]["message"], found[0].message.as_str());
    client.shutdown();
}

#[test]
fn an_edit_is_checked_again_and_positions_count_utf16_units() {
    let (folder, mut client) = two_modules();
    let main = folder.uri("Main.mod");
    client.open(&main, MAIN);
    client.diagnostics_for(&main);
    // Declare cnt (line 3, after `VAR num n;` at column 14) and add an error after a
    // Latin-1 letter on line 4: `"ä"` is 3 UTF-16 units; `x` is then at column 26.
    client.change(&main, 2, range(2, 14, 2, 14), "\n    VAR num cnt;");
    client.change(&main, 3, range(5, 22, 5, 22), " + x");
    let diags = client.diagnostics_for_version(&main, 3);
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0]["code"], "E0201");
    assert_eq!(diags[0]["range"], range(5, 25, 5, 26));
    client.shutdown();
}

#[test]
fn goes_to_a_definition_in_another_module_and_finds_references() {
    let (folder, mut client) = two_modules();
    let main = folder.uri("Main.mod");
    let tools = folder.uri("Tools.mod");
    client.open(&main, MAIN);
    // `Helper` in `    n := Helper(2);` starts at column 9.
    let def = client.request("textDocument/definition", client::at(&main, 3, 11));
    assert_eq!(def["uri"], tools.as_str());
    assert_eq!(def["range"], range(1, 11, 1, 17));
    let refs = client.request(
        "textDocument/references",
        json!({"textDocument": {"uri": main}, "position": {"line": 3, "character": 9}, "context": {"includeDeclaration": true}}),
    );
    let mut places: Vec<(String, Value)> =
        refs.as_array().unwrap().iter().map(|r| (r["uri"].as_str().unwrap().to_owned(), r["range"].clone())).collect();
    places.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(places, [(main.clone(), range(3, 9, 3, 15)), (tools.clone(), range(1, 11, 1, 17))]);
    // A parameter resolves to its routine's declaration, not to anything global.
    let def = client.request("textDocument/definition", client::at(&tools, 2, 11));
    assert_eq!(def["range"], range(1, 22, 1, 23));
    client.shutdown();
}

#[test]
fn hovers_builtins_from_the_catalogue_and_user_declarations() {
    let (folder, mut client) = two_modules();
    let main = folder.uri("Main.mod");
    client.open(&main, MAIN);
    let hover = client.request("textDocument/hover", client::at(&main, 4, 12));
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(text.contains("FUNC num StrLen(string Str)"), "{text}");
    assert!(text.contains("Returns the number of characters in a string."), "{text}");
    assert_eq!(hover["range"], range(4, 11, 4, 17));
    let hover = client.request("textDocument/hover", client::at(&main, 3, 4));
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(text.contains("VAR num n;"), "{text}");
    assert!(text.contains("in main of module Main"), "{text}");
    client.shutdown();
}

#[test]
fn outlines_a_module() {
    let (folder, mut client) = two_modules();
    let tools = folder.uri("Tools.mod");
    client.open(&tools, TOOLS);
    let symbols = client.request("textDocument/documentSymbol", json!({"textDocument": {"uri": tools}}));
    assert_eq!(symbols[0]["name"], "Tools");
    assert_eq!(symbols[0]["kind"], 2); // Module
    let helper = &symbols[0]["children"][0];
    assert_eq!(helper["name"], "Helper");
    assert_eq!(helper["kind"], 12); // Function
    assert_eq!(helper["detail"], "FUNC num");
    assert_eq!(helper["range"], range(1, 2, 3, 9));
    assert_eq!(helper["children"][0]["name"], "x");
    let found = client.request("workspace/symbol", json!({"query": "help"}));
    assert_eq!(found.as_array().unwrap().len(), 1);
    assert_eq!(found[0]["containerName"], "Tools");
    client.shutdown();
}

#[test]
fn serves_pull_diagnostics_to_a_client_that_asks() {
    let folder = Folder::new("pull", &[("Main.mod", MAIN), ("Tools.mod", TOOLS)]);
    let mut client = Client::start(&folder, json!({"textDocument": {"diagnostic": {"dynamicRegistration": false}}}));
    assert_eq!(client.capabilities["diagnosticProvider"]["identifier"], "rapid");
    let main = folder.uri("Main.mod");
    client.open(&main, MAIN);
    let report = client.request("textDocument/diagnostic", json!({"textDocument": {"uri": main}}));
    assert_eq!(report["kind"], "full");
    assert_eq!(report["items"][0]["code"], "E0201");
    assert_eq!(report["items"][0]["range"], range(4, 4, 4, 7));
    client.shutdown();
}

#[test]
fn renames_across_modules_and_refuses_reserved_words() {
    let (folder, mut client) = two_modules();
    let main = folder.uri("Main.mod");
    let tools = folder.uri("Tools.mod");
    client.open(&main, MAIN);
    let edit = client.request(
        "textDocument/rename",
        json!({"textDocument": {"uri": main}, "position": {"line": 3, "character": 10}, "newName": "Twice"}),
    );
    assert_eq!(edit["changes"][main.as_str()][0]["range"], range(3, 9, 3, 15));
    assert_eq!(edit["changes"][tools.as_str()][0]["range"], range(1, 11, 1, 17));
    assert_eq!(edit["changes"][tools.as_str()][0]["newText"], "Twice");
    let refused = client.request_error(
        "textDocument/rename",
        json!({"textDocument": {"uri": main}, "position": {"line": 3, "character": 10}, "newName": "ENDIF"}),
    );
    assert!(refused.contains("reserved word"), "{refused}");
    client.shutdown();
}

const CELL: &str = "MODULE Cell
  RECORD part
    num weight;
    pos place;
  ENDRECORD
  VAR part p;
  PROC main()
    p.place.x := 1;
    p.
    n := StrFind(\"abc\", 1, \"b\" \\
  ENDPROC
ENDMODULE
";

fn labels(items: &Value) -> Vec<String> {
    let list = items.as_array().or_else(|| items["items"].as_array()).expect("a completion list");
    list.iter().map(|i| i["label"].as_str().unwrap().to_owned()).collect()
}

#[test]
fn completes_components_optional_arguments_and_names_in_scope() {
    let folder = Folder::new("complete", &[("Cell.mod", CELL)]);
    let snippets = json!({"textDocument": {"completion": {"completionItem": {"snippetSupport": true}}}});
    let signals = vec![("diPartReady".to_owned(), "signaldi".to_owned())];
    let mut client = Client::start_with(&folder, snippets, signals);
    let cell = folder.uri("Cell.mod");
    client.open(&cell, CELL);
    // After `p.place.` (line 7, column 12): the components of the built-in pos.
    assert_eq!(labels(&client.request("textDocument/completion", client::at(&cell, 7, 12))), ["x", "y", "z"]);
    // After `p.` (line 8, column 6): the user record's components.
    assert_eq!(labels(&client.request("textDocument/completion", client::at(&cell, 8, 6))), ["weight", "place"]);
    // After the `\` of StrFind's call: its one optional parameter, a switch.
    let line = "    n := StrFind(\"abc\", 1, \"b\" \\";
    let after = line.len() as u32;
    let optional = client.request("textDocument/completion", client::at(&cell, 9, after));
    assert_eq!(labels(&optional), ["NotInSet"]);
    // At the start of line 8: data, routines, signals and built-ins in scope.
    let all = client.request("textDocument/completion", client::at(&cell, 8, 4));
    let names = labels(&all);
    for wanted in ["p", "main", "part", "diPartReady", "StrLen", "MoveL"] {
        assert!(names.iter().any(|n| n == wanted), "{wanted} missing");
    }
    let strlen = all.as_array().unwrap().iter().find(|i| i["label"] == "StrLen").unwrap();
    assert_eq!(strlen["insertText"], "StrLen(${1:Str})");
    assert_eq!(strlen["insertTextFormat"], 2);
    client.shutdown();
}

#[test]
fn helps_with_the_signature_of_the_call_at_the_cursor() {
    let folder = Folder::new("signature", &[("Cell.mod", CELL)]);
    let mut client = Client::start(&folder, json!({}));
    let cell = folder.uri("Cell.mod");
    client.open(&cell, CELL);
    // `StrFind("abc", 1, ` + cursor: the third parameter, Set (index 2).
    let help = client.request("textDocument/signatureHelp", client::at(&cell, 9, 28));
    assert_eq!(help["signatures"][0]["label"], "FUNC StrFind(string Str, num ChPos, string Set, \\switch NotInSet)");
    assert_eq!(help["activeParameter"], 2);
    // After `\`: the optional parameter NotInSet (index 3) once its name is typed.
    let mut client2 = client;
    client2.change(&cell, 2, range(9, 33, 9, 33), "Not");
    let help = client2.request("textDocument/signatureHelp", client::at(&cell, 9, 36));
    assert_eq!(help["activeParameter"], 3);
    client2.shutdown();
}

const FIX: &str = "MODULE Fix
  VAR num counter;
  PROC main2()
    countr := 1;
    total := counter;
  ENDPROC
ENDMODULE
";

const OPEN: &str = "MODULE Open
  PROC main()
    IF TRUE THEN
      TPWrite \"a\";
  ENDPROC
ENDMODULE
";

/// The code actions offered for the diagnostics published for `uri`: (title, the
/// edit's range and text).
fn quick_fixes(client: &mut Client, uri: &str) -> Vec<(String, Value, String)> {
    let diags = client.diagnostics_for(uri);
    let params = json!({"textDocument": {"uri": uri}, "range": range(0, 0, 0, 0), "context": {"diagnostics": diags}});
    let actions = client.request("textDocument/codeAction", params);
    actions
        .as_array()
        .unwrap()
        .iter()
        .map(|a| {
            let edit = &a["edit"]["changes"][uri][0];
            (
                a["title"].as_str().unwrap().to_owned(),
                edit["range"].clone(),
                edit["newText"].as_str().unwrap().to_owned(),
            )
        })
        .collect()
}

#[test]
fn offers_fixes_for_undefined_names_and_an_unclosed_if() {
    let folder = Folder::new("actions", &[("Fix.mod", FIX), ("Open.mod", OPEN)]);
    let mut client = Client::start(&folder, json!({}));
    let fix = folder.uri("Fix.mod");
    let fixes = quick_fixes(&mut client, &fix);
    // `countr := 1`: declared as a num under the header (line 3), or corrected.
    assert!(
        fixes.contains(&("Declare `VAR num countr`".into(), range(3, 0, 3, 0), "    VAR num countr;\n".into())),
        "{fixes:?}"
    );
    assert!(fixes.contains(&("Change to `counter`".into(), range(3, 4, 3, 10), "counter".into())), "{fixes:?}");
    // `total := counter`: counter is a num, so total is declared one.
    assert!(
        fixes.contains(&("Declare `VAR num total`".into(), range(3, 0, 3, 0), "    VAR num total;\n".into())),
        "{fixes:?}"
    );
    let open = folder.uri("Open.mod");
    let fixes = quick_fixes(&mut client, &open);
    // ENDIF before ENDPROC (line 4), indented as the IF.
    assert_eq!(fixes, [("Add the missing ENDIF".to_owned(), range(4, 0, 4, 0), "    ENDIF\n".to_owned())]);
    client.shutdown();
}

#[test]
fn classifies_tokens_and_folds_blocks() {
    let text = "MODULE M\n  PROC p()\n    TPWrite \"x\";\n  ENDPROC\nENDMODULE\n";
    let folder = Folder::new("semantic", &[("M.mod", text)]);
    let mut client = Client::start(&folder, json!({}));
    let m = folder.uri("M.mod");
    client.open(&m, text);
    let legend = &client.capabilities["semanticTokensProvider"]["legend"];
    assert_eq!(legend["tokenTypes"][7], "method");
    assert_eq!(legend["tokenModifiers"], json!(["declaration", "readonly", "defaultLibrary"]));
    let tokens = client.request("textDocument/semanticTokens/full", json!({"textDocument": {"uri": m}}));
    // (Δline, Δstart, length, type, modifiers): MODULE, M (namespace, declaration),
    // PROC, p (method, declaration), TPWrite (method, defaultLibrary), "x", ENDPROC,
    // ENDMODULE.
    let expected = [
        [0, 0, 6, 8, 0],
        [0, 7, 1, 0, 1],
        [1, 2, 4, 8, 0],
        [0, 5, 1, 7, 1],
        [1, 4, 7, 7, 4],
        [0, 8, 3, 10, 0],
        [1, 2, 7, 8, 0],
        [1, 0, 9, 8, 0],
    ];
    assert_eq!(tokens["data"], json!(expected.concat()));
    let folds = client.request("textDocument/foldingRange", json!({"textDocument": {"uri": m}}));
    let lines: Vec<(u64, u64)> = folds
        .as_array()
        .unwrap()
        .iter()
        .map(|f| (f["startLine"].as_u64().unwrap(), f["endLine"].as_u64().unwrap()))
        .collect();
    assert_eq!(lines, [(0, 4), (1, 3)]);
    client.shutdown();
}

#[test]
fn hovers_an_optional_argument_with_its_parameter() {
    let text = "MODULE M\n  PROC p()\n    TPWrite \"n = \" \\Num:=3;\n  ENDPROC\nENDMODULE\n";
    let folder = Folder::new("hover_optional", &[("M.mod", text)]);
    let mut client = Client::start(&folder, json!({}));
    let m = folder.uri("M.mod");
    client.open(&m, text);
    // `\Num` starts at column 19 of line 2 (the name at 20..23).
    let hover = client.request("textDocument/hover", client::at(&m, 2, 21));
    let value = hover["contents"]["value"].as_str().unwrap();
    assert!(value.contains("\\num Num"), "{value}");
    assert!(value.contains("Optional parameter of TPWrite"), "{value}");
    assert_eq!(hover["range"], range(2, 20, 2, 23));
    client.shutdown();
}

#[test]
fn completes_routine_names_in_a_late_binding_string() {
    let text = "MODULE M\n  PROC station1()\n  ENDPROC\n  PROC p()\n    % \"st\" %;\n  ENDPROC\nENDMODULE\n";
    let folder = Folder::new("late_binding", &[("M.mod", text)]);
    let mut client = Client::start(&folder, json!({}));
    let m = folder.uri("M.mod");
    client.open(&m, text);
    // Inside `"st"` (line 4, after `st` at column 9): the task's routines and modules.
    let names = labels(&client.request("textDocument/completion", client::at(&m, 4, 9)));
    assert_eq!(names, ["M", "station1", "p"]);
    client.shutdown();
}

/// Broken and unusual text: Latin-1 letters, an unterminated string, a statement cut
/// short, an unclosed aggregate, a stray `\`, a comment, a record chain.
const ROUGH: &str = "MODULE Rough
  ! Größe: größer
  RECORD r
    pos p;
  ENDRECORD
  VAR r rr;
  PERS num größe := 1;
  PROC p(\\num opt, INOUT num x)
    VAR num a{3};
    a{1} := rr.p.x + größe;
    TPWrite \"unterminated
    MoveL [[1,2,3],
    IF a{1} > 0 THEN x := 1; ENDIF
    \\ ;
    %\"p\"% ;
  ENDPROC
ENDMODULE
";

#[test]
fn every_position_of_rough_text_gets_an_answer() {
    let folder = Folder::new("rough", &[("Rough.mod", ROUGH)]);
    let mut client = Client::start(&folder, json!({}));
    let uri = folder.uri("Rough.mod");
    client.open(&uri, ROUGH);
    let methods =
        ["textDocument/hover", "textDocument/definition", "textDocument/completion", "textDocument/signatureHelp"];
    for (line, text) in ROUGH.lines().enumerate() {
        // Every UTF-16 column of the line, and one past its end.
        for character in 0..=text.encode_utf16().count() as u32 + 1 {
            for method in methods {
                client.request(method, client::at(&uri, line as u32, character));
            }
        }
    }
    for method in ["textDocument/semanticTokens/full", "textDocument/foldingRange", "textDocument/documentSymbol"] {
        client.request(method, json!({"textDocument": {"uri": uri}}));
    }
    // The Latin-1 name resolves across its uses: declaration and one use.
    let refs = client.request(
        "textDocument/references",
        json!({"textDocument": {"uri": uri}, "position": {"line": 9, "character": 22}, "context": {"includeDeclaration": true}}),
    );
    let ranges: Vec<Value> = refs.as_array().unwrap().iter().map(|r| r["range"].clone()).collect();
    assert_eq!(ranges, [range(6, 11, 6, 16), range(9, 21, 9, 26)]);
    client.shutdown();
}

#[test]
fn formats_as_rapid_fmt_does_and_refuses_broken_text() {
    let text = "module M\nproc p()\ntpwrite \"x\";\nendproc\nendmodule\n";
    let folder = Folder::new("format", &[("M.mod", text)]);
    let mut client = Client::start(&folder, json!({}));
    let m = folder.uri("M.mod");
    client.open(&m, text);
    let params = json!({"textDocument": {"uri": m}, "options": {"tabSize": 4, "insertSpaces": true}});
    let edits = client.request("textDocument/formatting", params.clone());
    // Reserved words upper case, TPWrite as the catalogue spells it, four spaces a level
    // (module items one level, statements two); the edit spans the whole text.
    let formatted = "MODULE M\n    PROC p()\n        TPWrite \"x\";\n    ENDPROC\nENDMODULE\n";
    assert_eq!(edits, json!([{"range": range(0, 0, 5, 0), "newText": formatted}]));
    // Formatted already: no edit.
    client.change(&m, 2, range(0, 0, 5, 0), formatted);
    assert_eq!(client.request("textDocument/formatting", params.clone()), json!([]));
    // A syntax error: refused, as rapid fmt refuses it.
    client.change(&m, 3, range(2, 0, 2, 0), "IF\n");
    let refused = client.request_error("textDocument/formatting", params);
    assert!(refused.contains("syntax error"), "{refused}");
    client.shutdown();
}
