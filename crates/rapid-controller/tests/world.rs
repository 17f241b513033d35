//! A task in a world of the embedder's making (`rapid_vm::world`): its files on a disk
//! in memory, its calendar on a clock that stands still, its sockets on a network where
//! no peer answers. Nothing here touches the host's disk, network or clock; what the
//! program sees must come from the world it was given.

use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::time::Duration;

use rapid_sema::SourceInput;
use rapid_vm::world::memory::{MemoryFs, SilentNetwork};
use rapid_vm::world::{Clock, StoppedClock, World};
use rapid_vm::{Exit, RecordingHost, Vm};

/// Loads with the controller's standard set of built-ins (the file and socket
/// built-ins are the controller's bindings).
fn load(files: &[SourceInput], entry: &str) -> Result<rapid_vm::Loaded, rapid_vm::LoadError> {
    rapid_controller::builtin_set::load_with(files, entry, &rapid_sema::Options::default())
}

/// The controller root of the file devices: a path on the disk in memory only.
const ROOT: &str = "/virtual-controller";

fn vm(program: &str) -> Vm {
    match load(&[SourceInput::from_text("t.mod", program)], "main") {
        Ok(loaded) => loaded.vm,
        Err(err) => panic!("load failed: {err:?}"),
    }
}

/// Runs `vm` to its end; the pendant's lines.
fn run(mut vm: Vm) -> Vec<String> {
    let mut host = RecordingHost::default();
    let exit = vm.run(&mut host, 1_000_000);
    assert_eq!(exit, Exit::Done, "pendant so far: {:?}", host.lines);
    host.lines
}

/// A disk in memory shared with the test, so it can look at what the program did.
struct SharedFs(Rc<MemoryFs>);

impl rapid_vm::world::FileSystem for SharedFs {
    fn open(
        &self,
        path: &Path,
        mode: rapid_vm::world::OpenMode,
    ) -> std::io::Result<Box<dyn rapid_vm::world::HostFile>> {
        self.0.open(path, mode)
    }
    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        self.0.read(path)
    }
    fn write_atomic(&self, path: &Path, bytes: &[u8]) -> std::io::Result<()> {
        self.0.write_atomic(path, bytes)
    }
    fn metadata(&self, path: &Path) -> std::io::Result<rapid_vm::world::FileMeta> {
        self.0.metadata(path)
    }
    fn symlink_metadata(&self, path: &Path) -> std::io::Result<rapid_vm::world::FileMeta> {
        self.0.symlink_metadata(path)
    }
    fn canonicalize(&self, path: &Path) -> std::io::Result<PathBuf> {
        self.0.canonicalize(path)
    }
    fn read_dir(&self, path: &Path) -> std::io::Result<Vec<String>> {
        self.0.read_dir(path)
    }
    fn create_dir(&self, path: &Path) -> std::io::Result<()> {
        self.0.create_dir(path)
    }
    fn create_dir_all(&self, path: &Path) -> std::io::Result<()> {
        self.0.create_dir_all(path)
    }
    fn remove_dir(&self, path: &Path) -> std::io::Result<()> {
        self.0.remove_dir(path)
    }
    fn remove_file(&self, path: &Path) -> std::io::Result<()> {
        self.0.remove_file(path)
    }
    fn rename(&self, from: &Path, to: &Path) -> std::io::Result<()> {
        self.0.rename(from, to)
    }
    fn copy(&self, from: &Path, to: &Path) -> std::io::Result<()> {
        self.0.copy(from, to)
    }
    fn space(&self, path: &Path) -> std::io::Result<(u64, u64)> {
        self.0.space(path)
    }
}

const FILES: &str = r#"MODULE t
PROC main()
  VAR iodev f;
  VAR dir d;
  VAR string name;
  Open "HOME:" \File:="log.txt", f \Write;
  Write f, "hello world";
  Close f;
  Open "home:/LOG.TXT", f \Read;
  TPWrite "read " + ReadStr(f);
  Close f;
  OpenDir d, "HOME:";
  WHILE ReadDir(d, name) DO
    TPWrite "entry " + name;
  ENDWHILE
  CloseDir d;
  Open "HOME:/missing.txt", f \Read;
  TPWrite "not reached";
ERROR
  IF ERRNO = ERR_FILEOPEN THEN
    TPWrite "missing: ERR_FILEOPEN";
    RETURN;
  ENDIF
ENDPROC
ENDMODULE
"#;

#[test]
fn files_are_written_read_and_listed_on_the_worlds_disk() {
    let fs = Rc::new(MemoryFs::new());
    let mut vm = vm(FILES);
    vm.resources_mut().devices.set_root(ROOT);
    vm.set_world(World { files: Box::new(SharedFs(fs.clone())), ..World::closed() });
    let lines = run(vm);
    // What the program read back is what it wrote; the listing has the controller's
    // "." and ".." first; a missing file keeps its RAPID error number.
    let expected = ["read hello world", "entry .", "entry ..", "entry log.txt", "missing: ERR_FILEOPEN"];
    assert_eq!(lines, expected);
    let file = Path::new(ROOT).join("HOME").join("log.txt");
    assert_eq!(fs.get(&file).as_deref(), Some(&b"hello world\n"[..]));
    let calls = fs.calls();
    let opened = format!("open {}", file.display());
    assert_eq!(calls.iter().filter(|c| **c == opened).count(), 2, "{calls:?}");
    assert!(calls.contains(&format!("read_dir {}", Path::new(ROOT).join("HOME").display())), "{calls:?}");
    assert!(!Path::new(ROOT).exists(), "the host's disk was not touched");
}

#[test]
fn without_a_world_a_file_cannot_be_opened() {
    // The closed world has no disk: Open fails with Open's error, not a panic.
    let program = "MODULE t\nPROC main()\n  VAR iodev f;\n  Open \"HOME:/a.txt\", f \\Write;\nERROR\n  \
                   IF ERRNO = ERR_FILEOPEN TPWrite \"no disk\";\n  RETURN;\nENDPROC\nENDMODULE\n";
    let mut vm = vm(program);
    vm.resources_mut().devices.set_root(ROOT);
    assert_eq!(run(vm), ["no disk"]);
}

const TEXT_TABLE_STILL_OPEN: &str = r#"MODULE t
PROC main()
  VAR iodev f;
  Open "HOME:/texts.eng", f \Write;
  Write f, "greetings::";
  Write f, "1:";
  Write f, "Hello operator";
  TextTabInstall "HOME:/texts.eng";
  TPWrite TextGet(TextTabGet("greetings"), 1);
  Close f;
ENDPROC
ENDMODULE
"#;

#[test]
fn a_file_still_open_for_writing_is_read_as_written_by_the_languages_own_built_ins() {
    // The three lines are still in the open file's write buffer when TextTabInstall
    // (a built-in of the language, not of the files extension) reads the file: the
    // files extension writes them out first (TaskHooks::flush_files), so the table
    // is there; without that the file would still be empty.
    let fs = Rc::new(MemoryFs::new());
    let mut vm = vm(TEXT_TABLE_STILL_OPEN);
    vm.resources_mut().devices.set_root(ROOT);
    vm.set_world(World { files: Box::new(SharedFs(fs.clone())), ..World::closed() });
    assert_eq!(run(vm), ["Hello operator"]);
    let file = Path::new(ROOT).join("HOME").join("texts.eng");
    assert_eq!(fs.get(&file).as_deref(), Some(&b"greetings::\n1:\nHello operator\n"[..]));
}

/// 2024-02-29 13:45:30 UTC in seconds since 1970: 54 years with 13 leap days to
/// 2024-01-01 (19 723 days), 59 days more to 29 February.
const LEAP_DAY: f64 = (19_723.0 + 59.0) * 86_400.0 + 13.0 * 3600.0 + 45.0 * 60.0 + 30.0;

#[test]
fn the_calendar_reads_the_worlds_clock() {
    let program = "MODULE t\nPROC main()\n  TPWrite CDate() + \" \" + CTime();\n  \
                   TPWrite \"day \" \\Num:=GetTime(\\WDay);\nENDPROC\nENDMODULE\n";
    let mut vm = vm(program);
    vm.set_world(World { clock: Rc::new(StoppedClock::at(LEAP_DAY)), ..World::closed() });
    // 29 February 2024 was a Thursday: GetTime \WDay counts Monday as 1.
    assert_eq!(run(vm), ["2024-02-29 13:45:30", "day 4"]);
}

const SOCKET: &str = r#"MODULE t
PROC main()
  VAR socketdev s;
  VAR string answer;
  SocketCreate s;
  SocketConnect s, "10.0.0.7", 1025;
  SocketSend s \Str:="ping";
  SocketReceive s \Str:=answer \Time:=3;
  TPWrite "not reached";
ERROR
  IF ERRNO = ERR_SOCK_TIMEOUT THEN
    TPWrite "timeout at " + CTime();
    SocketClose s;
    RETURN;
  ENDIF
ENDPROC
ENDMODULE
"#;

#[test]
fn a_receive_nobody_answers_times_out_on_the_worlds_clock() {
    let clock = Rc::new(StoppedClock::at(LEAP_DAY));
    let net = SilentNetwork::new(clock.clone());
    let sent = net.sent();
    let mut vm = vm(SOCKET);
    vm.set_world(World { net: Box::new(net), clock: clock.clone(), ..World::closed() });
    // The 3 s of \Time pass on the world's clock at once, and the controller's clock
    // moves on by them: CTime shows 13:45:33.
    assert_eq!(run(vm), ["timeout at 13:45:33"]);
    assert_eq!(*sent.borrow(), [b"ping".to_vec()]);
    assert_eq!(clock.elapsed(), Duration::from_secs(3));
}

#[test]
fn without_a_world_there_is_no_network() {
    let program = "MODULE t\nPROC main()\n  VAR socketdev s;\n  SocketCreate s;\nERROR\n  \
                   IF ERRNO = ERR_SOCK_UNSPEC TPWrite \"no network\";\n  RETURN;\nENDPROC\nENDMODULE\n";
    assert_eq!(run(vm(program)), ["no network"]);
}
