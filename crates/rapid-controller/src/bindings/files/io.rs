//! Reading and writing through an open iodev: Write, ReadNum, ReadStr (character
//! based) and ReadBin, ReadStrBin, WriteBin, WriteStrBin, WriteAnyBin, ReadAnyBin,
//! WriteRawBytes, ReadRawBytes (binary).
//!
//! A file never makes a read wait, so `\Time` is checked but never expires
//! (ERR_DEV_MAXTIME belongs to serial channels, which we do not have). Text and binary
//! instructions may be mixed on one file: the controller's manual restricts each to
//! its kind of device, but names no error for files.
// uncertain: whether the controller refuses Write on a file opened with \Bin (the
// motion program of abb-motion-program-exec writes text with Write \NoNewLine).

use super::iodev::{check_time, with_file, Need};
use super::text::{bytes_of, delimiters, latin1, parse_num, push_latin1, read_field, skip_lines};
use super::{anybin, fault, io_fault, opt_string, Fault, Res};
use rapid_vm::ext::{present, Ctx, Err, Opaque, OpaqueState, RapidError, Value, MAX_STRING_CHARS};

/// What ReadNum returns at end of file: EOF_NUM (manual ReadNum; the catalogue's
/// constant).
const EOF_NUM: f32 = 9.998e36;
/// What ReadBin returns at end of file: EOF_BIN.
const EOF_BIN: f32 = -1.0;
/// What ReadStr and ReadStrBin return at end of file: the predefined string EOF.
const EOF_STR: &str = "EOF";
/// A rawbytes holds at most this many bytes (ReadRawBytes reads at most that).
const RAWBYTES_CAPACITY: usize = 1024;

rapid_vm::ext::layout! {
    static WRITE: WriteArgs = "Write" { num: "Num", dnum: "Dnum", no_new_line: "NoNewLine" }
    static READ_NUM: ReadNumArgs = "ReadNum" { delim: "Delim", time: "Time" }
    static READ_STR: ReadStrArgs = "ReadStr" {
        delim: "Delim", remove_cr: "RemoveCR", discard_headers: "DiscardHeaders", time: "Time", line: "Line",
    }
    /// The binary reads after IODevice and one more argument: only `\Time` is looked up.
    static READ_TIMED: ReadTimedArgs = "ReadStrBin" | "ReadAnyBin" | "ReadRawBytes" { time: "Time" }
    static WRITE_RAW: WriteRawArgs = "WriteRawBytes" { no_of_bytes: "NoOfBytes" }
}

/// `Write IODevice String [\Num] | [\Bool] | [\Pos] | [\Orient] | [\Dnum] [\NoNewLine]`:
/// the text, the value in the format TPWrite uses, and a line feed unless `\NoNewLine`.
pub(super) fn write(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let text = ctx.str_arg(&args[1])?;
    let mut bytes = Vec::with_capacity(text.len() + 24);
    push_latin1(&mut bytes, &text);
    let at = *WRITE;
    // \Num | \Bool | \Pos | \Orient | \Dnum: the alternatives are declared side by side.
    let values = args.get(at.num..=at.dnum).unwrap_or_default();
    if let Some(value) = values.iter().find(|a| present(Some(a))) {
        push_latin1(&mut bytes, &rapid_vm::ext::value_text(ctx, &ctx.value(value)?));
    }
    if !present(args.get(at.no_new_line)) {
        bytes.push(b'\n');
    }
    with_file(ctx, &args[0], Need::Write, |file| file.write_bytes(&bytes).map_err(|e| io_fault("Write failed", &e)))?;
    Ok(None)
}

/// `ReadNum(IODevice [\Delim] [\Time])`: the next number; EOF_NUM at end of file;
/// ERR_RCVDATA when the field is not a number.
pub(super) fn read_num(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let delims = delimiters(opt_string(ctx, args.get(READ_NUM.delim))?.as_deref());
    check_time(ctx, args.get(READ_NUM.time))?;
    let field = with_file(ctx, &args[0], Need::Read, |file| {
        read_field(file, &delims, true).map_err(|e| io_fault("ReadNum failed", &e))
    })?;
    let Some(field) = field else { return Ok(Some(Value::Num(EOF_NUM))) };
    match parse_num(&field) {
        Some(n) => Ok(Some(Value::Num(n))),
        None => Err(ctx.error(Err::ReceiveData, format!("`{}` is not a number", latin1(&field)))),
    }
}

/// `ReadStr(IODevice [\Delim] [\RemoveCR] [\DiscardHeaders] [\Time] [\Line])`: the text up
/// to the next delimiter (at most 80 characters); "EOF" at end of file. `\Line:=n` reads
/// from the start of line n of the file.
pub(super) fn read_str(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *READ_STR;
    let delims = delimiters(opt_string(ctx, args.get(at.delim))?.as_deref());
    let remove_cr = present(args.get(at.remove_cr));
    let discard = present(args.get(at.discard_headers));
    check_time(ctx, args.get(at.time))?;
    // uncertain: \Line counts lines from the start of the file, 1 being the first.
    let line = match ctx.opt_num(args.get(at.line))? {
        Some(n) if n.fract() == 0.0 && n >= 1.0 => Some(n as u64),
        Some(n) => return Err(ctx.error(Err::ArgValue, format!("\\Line:={n} is not a line number"))),
        None => None,
    };
    let field = with_file(ctx, &args[0], Need::Read, |file| {
        let failed = |e: std::io::Error| io_fault("ReadStr failed", &e);
        if let Some(n) = line {
            file.rewind().map_err(failed)?;
            if !skip_lines(file, n - 1).map_err(failed)? {
                return Ok(None);
            }
        }
        read_field(file, &delims, discard).map_err(failed)
    })?;
    let text = match field {
        None => EOF_STR.to_string(),
        Some(mut bytes) => {
            if remove_cr && bytes.last() == Some(&b'\r') {
                bytes.pop();
            }
            latin1(&bytes)
        }
    };
    Ok(Some(Value::Str(text.into())))
}

/// `ReadBin(IODevice [\Time])`: the next byte (0..255); EOF_BIN at end of file.
pub(super) fn read_bin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    check_time(ctx, args.get(1))?;
    let bytes =
        with_file(ctx, &args[0], Need::Read, |file| file.read_bytes(1).map_err(|e| io_fault("ReadBin failed", &e)))?;
    Ok(Some(Value::Num(bytes.first().map_or(EOF_BIN, |&b| f32::from(b)))))
}

/// `ReadStrBin(IODevice NoOfChars [\Time])`: the next NoOfChars bytes as characters;
/// "EOF" when the file has no byte left.
// uncertain: near the end of the file we return the characters that are left.
pub(super) fn read_str_bin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let count = ctx.num(&args[1])?;
    if count.fract() != 0.0 || !(1.0..=MAX_STRING_CHARS as f64).contains(&count) {
        return Err(ctx.error(Err::ArgValue, format!("NoOfChars {count} is not in 1..80")));
    }
    check_time(ctx, args.get(READ_TIMED.time))?;
    let bytes = with_file(ctx, &args[0], Need::Read, |file| {
        file.read_bytes(count as usize).map_err(|e| io_fault("ReadStrBin failed", &e))
    })?;
    let text = if bytes.is_empty() { EOF_STR.to_string() } else { latin1(&bytes) };
    Ok(Some(Value::Str(text.into())))
}

rapid_vm::ext::layout! {
    static WRITE_BIN: WriteBinArgs = "WriteBin" { buffer: "Buffer", n_char: "NChar" }
}

/// `WriteBin IODevice Buffer NChar`: the first NChar numbers of Buffer, each a byte.
pub(super) fn write_bin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let Value::Array(buffer) = ctx.value(&args[WRITE_BIN.buffer])? else {
        return Err(ctx.error(Err::ArgValue, "Buffer must be an array of num"));
    };
    let count = ctx.num(&args[WRITE_BIN.n_char])?;
    if count.fract() != 0.0 || count < 0.0 || count > buffer.elems.len() as f64 {
        // uncertain: the manual names no error for NChar beyond the array.
        return Err(ctx.error(
            Err::OutOfBounds,
            format!("NChar {count} is not within the {} elements of Buffer", buffer.elems.len()),
        ));
    }
    let mut bytes = Vec::with_capacity(count as usize);
    for elem in &buffer.elems[..count as usize] {
        match elem.as_f64() {
            Some(v) if v.fract() == 0.0 && (0.0..=255.0).contains(&v) => bytes.push(v as u8),
            other => {
                return Err(ctx.error(Err::ArgValue, format!("{:?} in Buffer is not a byte (0..255)", other)));
            }
        }
    }
    with_file(ctx, &args[0], Need::Write, |file| {
        file.write_bytes(&bytes).map_err(|e| io_fault("WriteBin failed", &e))
    })?;
    Ok(None)
}

/// `WriteStrBin IODevice Str`: the characters of Str, one byte each, nothing added.
pub(super) fn write_str_bin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let bytes = bytes_of(&ctx.string(&args[1])?);
    with_file(ctx, &args[0], Need::Write, |file| {
        file.write_bytes(&bytes).map_err(|e| io_fault("WriteStrBin failed", &e))
    })?;
    Ok(None)
}

/// `WriteAnyBin IODevice Data`: Data in the binary form of [`anybin`].
pub(super) fn write_any_bin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let frame = anybin::encode(&ctx.value(&args[1])?).map_err(|f| fault(ctx, f))?;
    with_file(ctx, &args[0], Need::Write, |file| {
        file.write_bytes(&frame).map_err(|e| io_fault("WriteAnyBin failed", &e))
    })?;
    Ok(None)
}

/// `ReadAnyBin IODevice Data [\Time]`: the next value WriteAnyBin wrote, into Data.
/// ERR_RANYBIN_EOF when the file ends before the whole value is read; ERR_RANYBIN_CHK
/// on a checksum error (or data of another type than Data).
pub(super) fn read_any_bin(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    check_time(ctx, args.get(READ_TIMED.time))?;
    let like = ctx.value(&args[1])?;
    let value = with_file(ctx, &args[0], Need::Read, |file| {
        let short = || (Err::AnyBinEof, "end of file before the whole value was read".to_string());
        let read = |file: &mut super::iodev::OpenFile, n: usize| -> Result<Vec<u8>, Fault> {
            let bytes = file.read_bytes(n).map_err(|e| io_fault("ReadAnyBin failed", &e))?;
            if bytes.len() < n {
                return Err(short());
            }
            Ok(bytes)
        };
        let header = read(file, anybin::HEADER_LEN)?;
        let len = anybin::body_len(&header)?;
        let body = read(file, len)?;
        let sum = read(file, 1)?[0];
        anybin::decode(&body, sum, &like)
    })?;
    ctx.store(&args[1], value)?;
    Ok(None)
}

/// The valid bytes of a rawbytes argument, with its opaque shell.
fn raw_bytes(ctx: &Ctx<'_>, arg: &Value) -> Result<(Vec<u8>, Opaque), RapidError> {
    match ctx.value(arg)? {
        Value::Opaque(opaque) => match &opaque.state {
            OpaqueState::RawBytes(bytes) => Ok((bytes.clone(), *opaque)),
            OpaqueState::None => Ok((Vec::new(), *opaque)),
            _ => Err(ctx.error(Err::ArgValue, "a rawbytes was expected")),
        },
        _ => Err(ctx.error(Err::ArgValue, "a rawbytes was expected")),
    }
}

/// `WriteRawBytes IODevice RawData [\NoOfBytes]`: the valid bytes of RawData (or the
/// first NoOfBytes of them).
pub(super) fn write_raw_bytes(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let (bytes, _) = raw_bytes(ctx, &args[1])?;
    let count = match ctx.opt_num(args.get(WRITE_RAW.no_of_bytes))? {
        None => bytes.len(),
        Some(n) if n.fract() == 0.0 && n >= 0.0 && n <= bytes.len() as f64 => n as usize,
        // uncertain: the error for more bytes than RawData holds (rawbytes family: ERR_OUTOFBND).
        Some(n) => {
            return Err(ctx.error(
                Err::OutOfBounds,
                format!("NoOfBytes {n} is more than the {} valid bytes of RawData", bytes.len()),
            ))
        }
    };
    with_file(ctx, &args[0], Need::Write, |file| {
        file.write_bytes(&bytes[..count]).map_err(|e| io_fault("WriteRawBytes failed", &e))
    })?;
    Ok(None)
}

/// `ReadRawBytes IODevice RawData [\Time]`: RawData gets the next bytes of the file
/// from index 1, as many as are left up to 1024; its valid length is how many were
/// read. At end of file nothing is left to read: ERR_RANYBIN_EOF.
// Source: abb-motion-program-exec reads a whole file with ReadRawBytes and ends the loop
// on ERR_RANYBIN_EOF (docs/semantics.md). uncertain: whether a last, short chunk already
// raises the error on the controller; we deliver it and raise at the next read.
pub(super) fn read_raw_bytes(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    check_time(ctx, args.get(READ_TIMED.time))?;
    let (_, mut shell) = raw_bytes(ctx, &args[1])?;
    let bytes = with_file(ctx, &args[0], Need::Read, |file| {
        file.read_bytes(RAWBYTES_CAPACITY).map_err(|e| io_fault("ReadRawBytes failed", &e))
    })?;
    let at_end = bytes.is_empty();
    shell.state = OpaqueState::RawBytes(bytes);
    ctx.store(&args[1], Value::Opaque(Box::new(shell)))?;
    if at_end {
        return Err(ctx.error(Err::AnyBinEof, "end of file: no bytes left to read"));
    }
    Ok(None)
}
