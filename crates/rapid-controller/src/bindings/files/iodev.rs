//! The `iodev` table: Open, Close, Rewind, ClearIOBuff, and the open file each handle
//! names (a host file with a small read-ahead buffer).
//!
//! Open's modes (manual, Open): `\Read` reads from the start of the file; `\Write`
//! empties the file (or creates it) and writes from the start; `\Append` writes at the
//! end. Without `\Read`, `\Write` or `\Append`, a character-based Open acts like
//! `\Write`, and a binary one (`\Bin`) opens for both reading and writing with the
//! position at the end of the file.
// uncertain: the no-switch rules are from our reading of the manual's Open page.

use std::io::{self, SeekFrom};

use super::text::ByteSource;
use super::{fault, handle_of, io_fault, opt_string, resolve, set_handle, table, Fault, Res};
use rapid_vm::ext::{present, Ctx, Err, FileKind, HostFile, OpaqueState, OpenMode, RapidError, Value};

/// Bytes read ahead from the host file at a time.
const READ_AHEAD: usize = 4096;

/// Bytes written are held until this many are pending (one system call per Write
/// made file-heavy programs five times slower than Lua; bench/interp/fileio). They
/// reach the file at Close, Rewind, the next read, when any built-in names a path
/// (`files::resolve`), at PP to Main and when the program ends.
const WRITE_BUFFER: usize = 8192;

/// An open file.
pub(super) struct OpenFile {
    file: Box<dyn HostFile>,
    readable: bool,
    writable: bool,
    /// Read ahead but not yet consumed: `buf[pos..]`.
    buf: Vec<u8>,
    pos: usize,
    /// Written but not yet handed to the host file.
    pending: Vec<u8>,
}

impl Drop for OpenFile {
    /// Closing without Close (end of program, PP to Main) still keeps what was written.
    fn drop(&mut self) {
        let _ = self.flush();
    }
}

/// What an instruction needs of the file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Need {
    /// It reads: the file must have been opened for reading.
    Read,
    /// It writes: the file must have been opened for writing.
    Write,
    /// The file only has to be open (Rewind, ClearIOBuff).
    Open,
}

impl OpenFile {
    /// The bytes at the position, up to `n` of them (fewer only at end of file).
    pub(super) fn read_bytes(&mut self, n: usize) -> io::Result<Vec<u8>> {
        let mut out = Vec::with_capacity(n.min(READ_AHEAD));
        while out.len() < n {
            if !self.fill()? {
                break;
            }
            let take = (n - out.len()).min(self.buf.len() - self.pos);
            out.extend_from_slice(&self.buf[self.pos..self.pos + take]);
            self.pos += take;
        }
        Ok(out)
    }

    pub(super) fn write_bytes(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.drop_read_ahead()?;
        self.pending.extend_from_slice(bytes);
        if self.pending.len() >= WRITE_BUFFER {
            self.flush()?;
        }
        Ok(())
    }

    /// Hands the pending writes to the host file.
    pub(super) fn flush(&mut self) -> io::Result<()> {
        if !self.pending.is_empty() {
            self.file.write_all(&self.pending)?;
            self.pending.clear();
        }
        Ok(())
    }

    pub(super) fn rewind(&mut self) -> io::Result<()> {
        self.flush()?;
        self.buf.clear();
        self.pos = 0;
        self.file.seek(SeekFrom::Start(0)).map(|_| ())
    }

    /// Makes sure unread bytes are buffered; `false` at end of file.
    fn fill(&mut self) -> io::Result<bool> {
        if self.pos < self.buf.len() {
            return Ok(true);
        }
        self.flush()?;
        self.buf.resize(READ_AHEAD, 0);
        self.pos = 0;
        let n = self.file.read(&mut self.buf)?;
        self.buf.truncate(n);
        Ok(n > 0)
    }

    /// Gives back the bytes read ahead, so the host position is the program's position
    /// again (before a write).
    fn drop_read_ahead(&mut self) -> io::Result<()> {
        let unread = self.buf.len() - self.pos;
        if unread > 0 {
            self.file.seek(SeekFrom::Current(-(unread as i64)))?;
        }
        self.buf.clear();
        self.pos = 0;
        Ok(())
    }
}

impl ByteSource for OpenFile {
    fn peek_byte(&mut self) -> io::Result<Option<u8>> {
        Ok(if self.fill()? { Some(self.buf[self.pos]) } else { None })
    }

    fn next_byte(&mut self) -> io::Result<Option<u8>> {
        let b = self.peek_byte()?;
        self.pos += usize::from(b.is_some());
        Ok(b)
    }
}

/// Runs `work` on the file the iodev `arg` names, after checking it is open and opened
/// for what `need` says. A closed or never opened iodev, and reading a file opened for
/// writing (or the reverse), raise ERR_FILEACC.
// uncertain: the manual says these instructions can only be used on a device opened
// for reading (writing); the error name for breaking that rule is our choice.
pub(super) fn with_file<T>(
    ctx: &mut Ctx<'_>,
    arg: &Value,
    need: Need,
    work: impl FnOnce(&mut OpenFile) -> Result<T, Fault>,
) -> Result<T, RapidError> {
    let handle = ctx.handle_only(arg, "an iodev or dir")?;
    let result = match handle.and_then(|h| table(ctx).files.get_mut(&h)) {
        None => Err((Err::FileAccess, "the I/O device is not open".to_string())),
        Some(file) if need == Need::Read && !file.readable => {
            Err((Err::FileAccess, "the file was not opened for reading".to_string()))
        }
        Some(file) if need == Need::Write && !file.writable => {
            Err((Err::FileAccess, "the file was not opened for writing".to_string()))
        }
        Some(file) => work(file),
    };
    result.map_err(|f| fault(ctx, f))
}

rapid_vm::ext::layout! {
    static OPEN: OpenArgs = "Open" {
        file: "File", io_device: "IODevice", read: "Read", write: "Write", append: "Append", bin: "Bin",
    }
}

/// `Open Object [\File] IODevice [\Read] | [\Write] | [\Append] [\Bin]`.
pub(super) fn open(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *OPEN;
    let object = ctx.string(&args[0])?;
    let file_name = opt_string(ctx, args.get(at.file))?;
    let (shell, handle) = handle_of(ctx, &args[at.io_device])?;
    // uncertain: opening an iodev that is already open; we raise ERR_FILEOPEN.
    if handle.is_some_and(|h| table(ctx).files.contains_key(&h)) {
        return Err(ctx.error(Err::FileOpen, "the I/O device is already open; Close it first"));
    }
    // Ours (the controller's figure is not public): a program opening in a loop must
    // not exhaust the host's file handles.
    if table(ctx).files.len() >= rapid_limits::OPEN_FILES {
        let limit = rapid_limits::OPEN_FILES;
        return Err(ctx.error(Err::FileOpen, format!("at most {limit} files may be open at once; Close one first")));
    }
    let (read, write, append, bin) = (
        present(args.get(at.read)),
        present(args.get(at.write)),
        present(args.get(at.append)),
        present(args.get(at.bin)),
    );
    let path_text = rapid_vm::ext::devices::join_object(&object, file_name.as_deref());
    let resolved = resolve(ctx, &path_text, Err::FileOpen)?;
    // Only regular files: a directory cannot be read as a file, and opening a FIFO or a
    // device placed in the root would block the controller or reach hardware.
    if let Ok(meta) = ctx.resources.devices.file_system().metadata(&resolved.path) {
        if meta.kind != FileKind::File {
            return Err(ctx.error(Err::FileOpen, format!("`{path_text}` is not a file")));
        }
    }
    let mut options = OpenMode::default();
    let (readable, writable, at_end) = match (read, write, append, bin) {
        (true, _, _, _) => (true, false, false),
        (_, true, _, _) => (false, true, false),
        (_, _, true, _) => (false, true, true),
        (_, _, _, false) => (false, true, false),
        (_, _, _, true) => (true, true, true),
    };
    options.read = readable;
    if writable {
        (options.write, options.create) = (true, true);
        if append {
            options.append = true;
        } else if !at_end {
            options.truncate = true;
        }
    }
    let opened = ctx.resources.devices.file_system().open(&resolved.path, options).and_then(|mut file| {
        if at_end {
            file.seek(SeekFrom::End(0))?;
        }
        Ok(file)
    });
    let file = match opened {
        Ok(file) => file,
        Err(e) => return Err(ctx.error(Err::FileOpen, format!("`{path_text}` cannot be opened: {e}"))),
    };
    let handle = table(ctx).new_handle();
    table(ctx)
        .files
        .insert(handle, OpenFile { file, readable, writable, buf: Vec::new(), pos: 0, pending: Vec::new() });
    set_handle(ctx, &args[at.io_device], shell, OpaqueState::Handle(handle))
        .inspect_err(|_| {
            table(ctx).files.remove(&handle);
        })
        .map(|_| None)
}

/// `Close IODevice`: closing an iodev that is not open does nothing.
// uncertain: the manual names no error for Close.
pub(super) fn close(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (shell, handle) = handle_of(ctx, &args[0])?;
    let closed = handle.and_then(|h| table(ctx).files.remove(&h));
    set_handle(ctx, &args[0], shell, OpaqueState::None)?;
    if let Some(mut file) = closed {
        // uncertain: the manual names no error for Close; a write that fails here is
        // the host's failure to store the data, reported like other write failures.
        file.flush().map_err(|e| fault(ctx, io_fault("writing the file failed", &e)))?;
    }
    Ok(None)
}

/// `Rewind IODevice`: the position goes back to the start of the file.
pub(super) fn rewind(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    with_file(ctx, &args[0], Need::Open, |file| file.rewind().map_err(|e| io_fault("Rewind failed", &e)))?;
    Ok(None)
}

/// `ClearIOBuff IODevice`: discards input waiting on a serial channel. A file has no
/// such input (what is not read yet stays in the file), so on a file it only checks the
/// iodev is open.
// uncertain: the manual describes ClearIOBuff for serial channels only.
pub(super) fn clear_io_buff(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    with_file(ctx, &args[0], Need::Open, |_| Ok(()))?;
    Ok(None)
}

/// Checks a `\Time` argument: a file never makes a read wait, so the timeout cannot
/// expire, but it must be a sensible number.
pub(super) fn check_time(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<(), RapidError> {
    match ctx.opt_num(arg)? {
        Some(t) if t.is_nan() || t <= 0.0 => Err(ctx.error(Err::ArgValue, format!("\\Time:={t} must be positive"))),
        _ => Ok(()),
    }
}
