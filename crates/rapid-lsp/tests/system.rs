//! A workspace that is a system of two tasks, through the in-memory protocol client:
//! the findings `rapid check` makes about the system as a whole are published on the
//! configuration and the modules they point at, and follow the editor's text.

mod client;

use std::path::Path;

use client::{read_folder, Client, Folder};
use rapid_lsp::{System, Task, Workspace, WorkspaceLoader};
use rapid_sema::{Options, SourceInput};
use serde_json::{json, Value};

const SYS_CFG: &str = "SYS:CFG_1.0:6:0::
#
CAB_TASKS:

      -Name \"T_ROB1\" -Entry \"main\"

      -Name \"T_BG\" -Entry \"bg_main\"
#
";

const MAIN: &str = "MODULE Main
  PERS num count := 0;
  PROC main()
    count := count + 1;
  ENDPROC
ENDMODULE
";

/// T_BG declares `count` a string, and has no `bg_main`.
const BG: &str = "MODULE Bg
  PERS string count := \"\";
  PROC bg_start()
  ENDPROC
ENDMODULE
";

/// Reads `A/` as task T_ROB1 and `B/` as T_BG, with `SYS.cfg` as their system.
struct TwoTasks;

impl WorkspaceLoader for TwoTasks {
    fn load(&self, root: &Path) -> Result<Workspace, String> {
        let task = |name: &str, folder: &str| Task {
            name: Some(name.to_owned()),
            modules: read_folder(&root.join(folder)),
            options: Options::default(),
        };
        let path = root.join("SYS.cfg");
        let config = SourceInput::from_bytes(path.display().to_string(), std::fs::read(&path).unwrap());
        let sys = rapid_config::sys::read(&rapid_config::parse(&config.text));
        Ok(Workspace {
            tasks: vec![task("T_ROB1", "A"), task("T_BG", "B")],
            other_files: vec![config],
            other_findings: Vec::new(),
            system: Some(System { sys, file: Some(0) }),
        })
    }
}

fn range(l1: u32, c1: u32, l2: u32, c2: u32) -> Value {
    json!({"start": {"line": l1, "character": c1}, "end": {"line": l2, "character": c2}})
}

#[test]
fn the_systems_findings_are_published_where_they_point_and_follow_edits() {
    let folder = Folder::new("system", &[("SYS.cfg", SYS_CFG), ("A/Main.mod", MAIN), ("B/Bg.mod", BG)]);
    let mut client = Client::start_loader(&folder, json!({}), TwoTasks);
    // The entry routine T_BG lacks: at `"bg_main"` of line 6 (columns 26..35).
    let cfg = client.diagnostics_for(&folder.uri("SYS.cfg"));
    assert_eq!(cfg.len(), 1, "{cfg:?}");
    assert_eq!(cfg[0]["code"], "E0705");
    assert_eq!(cfg[0]["range"], range(6, 26, 6, 35));
    assert_eq!(
        cfg[0]["message"],
        "task T_BG has no procedure `bg_main` to start: its entry routine must be a global procedure of the task"
    );
    // `count` declared otherwise in the later task: at its name in Bg.mod (line 1, 14..19).
    let bg = folder.uri("B/Bg.mod");
    let found = client.diagnostics_for(&bg);
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0]["code"], "E0703");
    assert_eq!(found[0]["range"], range(1, 14, 1, 19));
    // Declared a num in the editor (`string count := ""` is 7..25): the finding goes.
    client.open(&bg, BG);
    client.change(&bg, 2, range(1, 7, 1, 25), "num count := 0");
    assert_eq!(client.diagnostics_for_version(&bg, 2), Vec::<Value>::new());
    client.shutdown();
}

#[test]
fn a_pulled_modules_diagnostics_compare_it_with_the_other_task() {
    let folder = Folder::new("system_pull", &[("SYS.cfg", SYS_CFG), ("A/Main.mod", MAIN), ("B/Bg.mod", BG)]);
    let pull = json!({"textDocument": {"diagnostic": {"dynamicRegistration": false}}});
    let mut client = Client::start_loader(&folder, pull, TwoTasks);
    let bg = folder.uri("B/Bg.mod");
    client.open(&bg, BG);
    // Bg.mod alone cannot tell its `count` disagrees with T_ROB1's: the pull checks both.
    let report = client.request("textDocument/diagnostic", json!({"textDocument": {"uri": bg}}));
    let items = report["items"].as_array().expect("items");
    assert_eq!(items.len(), 1, "{items:?}");
    assert_eq!(items[0]["code"], "E0703");
    assert_eq!(items[0]["range"], range(1, 14, 1, 19));
    let main = folder.uri("A/Main.mod");
    client.open(&main, MAIN);
    let report = client.request("textDocument/diagnostic", json!({"textDocument": {"uri": main}}));
    assert_eq!(report["items"], json!([]));
    client.shutdown();
}
