//! Names resolved by their scope and type, through the in-memory protocol client: a
//! record component by the type of the expression before its `.` (a user RECORD, a
//! built-in one, an array element, a function's result), and a FOR loop variable
//! only inside its loop. Every expected position is counted by hand from `PARTS`.

mod client;

use client::{Client, Folder};
use serde_json::{json, Value};

/// Two records with a component `name` each, and two loops with a variable `i` each.
const PARTS: &str = "MODULE Shop
  RECORD part
    string name;
    num count;
  ENDRECORD
  RECORD tool
    string name;
    pos tip;
  ENDRECORD
  VAR part parts{3};
  VAR tool tl;
  FUNC tool Current()
    RETURN tl;
  ENDFUNC
  PROC main()
    VAR robtarget p1;
    p1.trans.x := 1;
    parts{2}.name := \"a\";
    tl.name := Current().name;
    FOR i FROM 1 TO 3 DO
      parts{i}.count := i;
    ENDFOR
    FOR i FROM 1 TO 2 DO
      p1.trans.z := i + parts{i}.count;
    ENDFOR
    p1.trans.y := 0;
  ENDPROC
ENDMODULE
";

fn parts() -> (Folder, Client, String) {
    let folder = Folder::new("scopes", &[("Parts.mod", PARTS)]);
    let client = Client::start(&folder, json!({}));
    let uri = folder.uri("Parts.mod");
    client.open(&uri, PARTS);
    (folder, client, uri)
}

fn range(l1: u32, c1: u32, l2: u32, c2: u32) -> Value {
    json!({"start": {"line": l1, "character": c1}, "end": {"line": l2, "character": c2}})
}

fn labels(items: &Value) -> Vec<String> {
    let list = items.as_array().or_else(|| items["items"].as_array()).expect("a completion list");
    list.iter().map(|i| i["label"].as_str().unwrap().to_owned()).collect()
}

/// The (line, start, end) of each location, sorted.
fn places(locations: &Value) -> Vec<(u64, u64, u64)> {
    let mut out: Vec<(u64, u64, u64)> = locations
        .as_array()
        .expect("a list of locations")
        .iter()
        .map(|l| {
            let r = &l["range"];
            assert_eq!(r["start"]["line"], r["end"]["line"]);
            (
                r["start"]["line"].as_u64().unwrap(),
                r["start"]["character"].as_u64().unwrap(),
                r["end"]["character"].as_u64().unwrap(),
            )
        })
        .collect();
    out.sort_unstable();
    out
}

fn hover_text(client: &mut Client, uri: &str, line: u32, character: u32) -> String {
    let hover = client.request("textDocument/hover", client::at(uri, line, character));
    hover["contents"]["value"].as_str().expect("a hover").to_owned()
}

fn references(client: &mut Client, uri: &str, line: u32, character: u32) -> Vec<(u64, u64, u64)> {
    let refs = client.request(
        "textDocument/references",
        json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character},
               "context": {"includeDeclaration": true}}),
    );
    places(&refs)
}

#[test]
fn a_component_is_the_one_of_the_expressions_record_type() {
    let (_folder, mut client, uri) = parts();
    // `tl.name` (line 18, `name` at 7..11) is tool's `name` (line 6, 11..15), not
    // part's, though part declares a `name` first.
    let def = client.request("textDocument/definition", client::at(&uri, 18, 8));
    assert_eq!(def["range"], range(6, 11, 6, 15));
    // `Current().name` (25..29): the function returns a tool.
    let def = client.request("textDocument/definition", client::at(&uri, 18, 26));
    assert_eq!(def["range"], range(6, 11, 6, 15));
    // `parts{2}.name` (line 17, 13..17): an element of an array of part.
    let def = client.request("textDocument/definition", client::at(&uri, 17, 14));
    assert_eq!(def["range"], range(2, 11, 2, 15));
    // Every place tool's `name` is named: its declaration and the two on line 18.
    assert_eq!(references(&mut client, &uri, 6, 12), [(6, 11, 15), (18, 7, 11), (18, 25, 29)]);
    // And part's: its declaration and `parts{2}.name`.
    assert_eq!(references(&mut client, &uri, 2, 12), [(2, 11, 15), (17, 13, 17)]);
    client.shutdown();
}

#[test]
fn a_builtin_records_component_is_hovered_by_its_type() {
    let (_folder, mut client, uri) = parts();
    // `p1.trans.x` (line 16): trans (7..12) is robtarget's pos, x (13..14) pos's num.
    let text = hover_text(&mut client, &uri, 16, 8);
    assert!(text.contains("pos trans"), "{text}");
    assert!(text.contains("Component of robtarget"), "{text}");
    let text = hover_text(&mut client, &uri, 16, 13);
    assert!(text.contains("num x"), "{text}");
    assert!(text.contains("Component of pos"), "{text}");
    // A built-in component has no place in the workspace.
    let def = client.request("textDocument/definition", client::at(&uri, 16, 8));
    assert_eq!(def, Value::Null);
    client.shutdown();
}

#[test]
fn completes_the_components_of_an_element_and_of_a_functions_result() {
    let (_folder, mut client, uri) = parts();
    // After `parts{2}.` (line 17, column 13): part's components.
    let items = client.request("textDocument/completion", client::at(&uri, 17, 13));
    assert_eq!(labels(&items), ["name", "count"]);
    // After `Current().` (line 18, column 25): tool's.
    let items = client.request("textDocument/completion", client::at(&uri, 18, 25));
    assert_eq!(labels(&items), ["name", "tip"]);
    // After `p1.trans.` (line 16, column 13): pos's.
    let items = client.request("textDocument/completion", client::at(&uri, 16, 13));
    assert_eq!(labels(&items), ["x", "y", "z"]);
    client.shutdown();
}

#[test]
fn two_for_loops_of_one_routine_have_two_variables() {
    let (_folder, mut client, uri) = parts();
    // The first loop's `i` (declared line 19, 8..9): used twice on line 20.
    assert_eq!(references(&mut client, &uri, 20, 24), [(19, 8, 9), (20, 12, 13), (20, 24, 25)]);
    // The second loop's (line 22): used twice on line 23.
    assert_eq!(references(&mut client, &uri, 23, 20), [(22, 8, 9), (23, 20, 21), (23, 30, 31)]);
    let def = client.request("textDocument/definition", client::at(&uri, 23, 30));
    assert_eq!(def["range"], range(22, 8, 22, 9));
    let text = hover_text(&mut client, &uri, 20, 12);
    assert!(text.contains("FOR i FROM 1 TO 3 DO"), "{text}");
    // Renaming the first loop's variable leaves the second loop alone.
    let edit = client.request(
        "textDocument/rename",
        json!({"textDocument": {"uri": uri}, "position": {"line": 19, "character": 8}, "newName": "k"}),
    );
    let edits = edit["changes"][uri.as_str()].as_array().expect("edits in Parts.mod").clone();
    let renamed: Vec<Value> = edits.iter().map(|e| e["range"].clone()).collect();
    assert_eq!(renamed, [range(19, 8, 19, 9), range(20, 12, 20, 13), range(20, 24, 20, 25)]);
    client.shutdown();
}

#[test]
fn a_loop_variable_is_offered_inside_its_loop_only() {
    let (_folder, mut client, uri) = parts();
    // Inside the first loop (line 20, column 6): `i` once, with the routine's data.
    let names = labels(&client.request("textDocument/completion", client::at(&uri, 20, 6)));
    assert_eq!(names.iter().filter(|n| *n == "i").count(), 1);
    assert!(names.iter().any(|n| n == "p1"));
    // After both loops (line 25, column 4): no `i`.
    let names = labels(&client.request("textDocument/completion", client::at(&uri, 25, 4)));
    assert!(!names.iter().any(|n| n == "i"), "{names:?}");
    assert!(names.iter().any(|n| n == "p1"));
    client.shutdown();
}
