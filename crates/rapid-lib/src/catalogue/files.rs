//! Catalogue chapter: files, I/O devices and rawbytes (manual §1.10 file/serial/binary part, §1.16).

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // --- Opening and closing files and I/O devices --------------------------------------------
    routine(
        r#"PROC Open(string Object \string File, VAR iodev IODevice \switch Read | switch Write | switch Append \switch Bin)"#,
        "Opens a file or I/O device for reading, writing or appending, as text or binary.",
    ),
    routine(r#"PROC Close(VAR iodev IODevice)"#, "Closes a file or I/O device."),
    routine(r#"PROC Rewind(VAR iodev IODevice)"#, "Moves the position of an open file back to its start."),
    routine(r#"PROC ClearIOBuff(VAR iodev IODevice)"#, "Discards unread input buffered for a serial channel."),
    // --- Character-based reading and writing ------------------------------------------------------
    routine(
        r#"PROC Write(VAR iodev IODevice, string String \num Num | bool Bool | pos Pos | orient Orient | dnum Dnum \switch NoNewLine)"#,
        "Writes a text, optionally followed by a value, to a character-based file or device.",
    ),
    routine(
        r#"FUNC num ReadNum(VAR iodev IODevice \string Delim \num Time)"#,
        "Reads the next number from a character-based file or device (EOF_NUM at end).",
    ),
    routine(
        r#"FUNC string ReadStr(VAR iodev IODevice \string Delim \switch RemoveCR \switch DiscardHeaders \num Time \num Line)"#,
        "Reads text up to the next delimiter from a character-based file or device.",
    ),
    // --- Binary reading and writing -------------------------------------------------------------------
    routine(
        r#"FUNC num ReadBin(VAR iodev IODevice \num Time)"#,
        "Reads one byte (0-255) from a binary file or device (EOF_BIN at end).",
    ),
    routine(
        r#"FUNC string ReadStrBin(VAR iodev IODevice, num NoOfChars \num Time)"#,
        "Reads a given number of characters from a binary file or device.",
    ),
    routine(
        r#"PROC WriteBin(VAR iodev IODevice, num Buffer{*}, num NChar)"#,
        "Writes the first NChar numbers of an array as bytes to a binary device.",
    ),
    routine(
        r#"PROC WriteStrBin(VAR iodev IODevice, string Str)"#,
        "Writes the characters of a string to a binary file or device.",
    ),
    routine(
        r#"PROC WriteAnyBin(VAR iodev IODevice, anytype Data)"#,
        "Writes a value of any type in the controller's own binary format.",
    ),
    routine(
        r#"PROC ReadAnyBin(VAR iodev IODevice, INOUT anytype Data \num Time)"#,
        "Reads a value written by WriteAnyBin into a variable or persistent.",
    ),
    routine(
        r#"PROC WriteRawBytes(VAR iodev IODevice, VAR rawbytes RawData \num NoOfBytes)"#,
        "Writes the valid bytes (or the first NoOfBytes) of a rawbytes to a binary device.",
    ),
    routine(
        r#"PROC ReadRawBytes(VAR iodev IODevice, VAR rawbytes RawData \num Time)"#,
        "Reads available bytes from a binary device into a rawbytes from index 1.",
    ),
    // --- rawbytes support -------------------------------------------------------------------------------
    routine(
        r#"PROC ClearRawBytes(VAR rawbytes RawData \num FromIndex)"#,
        "Zeroes a rawbytes, all of it or from FromIndex on, and adjusts its valid length.",
    ),
    routine(
        r#"PROC CopyRawBytes(VAR rawbytes FromRawData, num FromIndex, VAR rawbytes ToRawData, num ToIndex \num NoOfBytes)"#,
        "Copies bytes from one rawbytes to another at the given positions.",
    ),
    routine(
        r#"PROC PackRawBytes(anytype Value, VAR rawbytes RawData \switch Network, num StartIndex \switch Hex1 | inttypes IntX | switch Float4 | switch ASCII)"#,
        "Packs a num, dnum, byte or string into a rawbytes at StartIndex.",
    ),
    routine(
        r#"PROC UnpackRawBytes(VAR rawbytes RawData \switch Network, num StartIndex, INOUT anytype Value \switch Hex1 | inttypes IntX | switch Float4 | num ASCII)"#,
        "Unpacks a byte, num, dnum or string from a rawbytes starting at StartIndex.",
    ),
    routine(
        r#"PROC PackDNHeader(string Service, string Path, VAR rawbytes RawData)"#,
        "Packs a DeviceNet explicit-message header into a rawbytes from index 1.",
    ),
    routine(r#"FUNC num RawBytesLen(VAR rawbytes RawData)"#, "Returns the number of valid bytes in a rawbytes."),
    // --- File and directory operations (§1.16) ---------------------------------------------------------
    routine(r#"PROC MakeDir(string Path)"#, "Creates a new directory."),
    routine(r#"PROC RemoveDir(string Path)"#, "Removes an empty directory."),
    routine(r#"PROC OpenDir(VAR dir Dev, string Path)"#, "Opens a directory so its entries can be read with ReadDir."),
    routine(r#"PROC CloseDir(VAR dir Dev)"#, "Closes a directory opened with OpenDir."),
    routine(
        r#"FUNC bool ReadDir(VAR dir Dev, VAR string FileName)"#,
        "Reads the next entry name of an open directory; FALSE when none is left.",
    ),
    routine(r#"PROC RemoveFile(string Path)"#, "Deletes a file."),
    routine(r#"PROC RenameFile(string OldPath, string NewPath)"#, "Gives an existing file a new name."),
    routine(r#"PROC CopyFile(string OldPath, string NewPath)"#, "Copies an existing file to a new path."),
    routine(
        r#"FUNC bool IsFile(string Path \switch Directory | switch Fifo | switch RegFile | switch BlockSpec | switch CharSpec)"#,
        "Tells whether a path exists, or whether it is of the given file kind.",
    ),
    routine(
        r#"FUNC num FSSize(string Name \switch Total | switch Free \switch Kbyte \switch Mbyte)"#,
        "Returns the total or free size of the file system holding the given file.",
    ),
    routine(r#"FUNC num FileSize(string Path)"#, "Returns the size of a file in bytes."),
];
