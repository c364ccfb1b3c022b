//! Files, through the world's [`crate::world::FileSystem`]: `Open`,
//! `Write`, `ReadStr`... The controller keeps the open files (an `iodev`
//! holds its handle); what is read is read whole when the file is opened.

use std::collections::HashMap;

use rapid_evaluator::{MAX_STRING_LEN, Value};

use super::{Args, Cx, Done};
use crate::machine::{FaultKind, R, fault, invalid, named_error};
use crate::world::{FileError, FileKind};

#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    Read,
    Write,
    Append,
}

struct OpenFile {
    path: String,
    mode: Mode,
    /// What is read (the whole file, read when opened).
    data: Vec<u8>,
    pos: usize,
}

/// The files and folders the program has open, by handle.
#[derive(Default)]
pub(crate) struct OpenFiles {
    open: HashMap<i32, OpenFile>,
    /// An open folder (`OpenDir`): its entries and how many were read.
    dirs: HashMap<i32, (Vec<String>, usize)>,
    next: i32,
    /// When the run last changed, read or renamed each file (simulated
    /// seconds), by [`crate::world::path_key`]; a file the run has not
    /// touched dates from its start.
    stamps: HashMap<String, Stamp>,
}

/// The times `FileTime` gives of a file the run touched.
#[derive(Clone, Copy, Default)]
struct Stamp {
    modified: f64,
    accessed: f64,
    changed: f64,
}

/// Notes that the run wrote the file `path` now (or only read it).
pub(super) fn touch(cx: &mut Cx<'_>, path: &str, written: bool) {
    let now = cx.now();
    let s = cx
        .sh
        .open
        .stamps
        .entry(crate::world::path_key(path))
        .or_default();
    s.accessed = now;
    if written {
        s.modified = now;
        s.changed = now;
    }
}

/// The fault of a file operation that failed.
pub(super) fn file_error<T>(cx: &Cx<'_>, what: &str, code: &str, e: FileError) -> R<T> {
    match e {
        FileError::Unsupported(why) => fault(FaultKind::Unsupported(format!("{what} ({why})"))),
        FileError::Denied(m) => fault(named_error(&cx.m.prog, "ERR_FILEACC", m)),
        FileError::NotFound(m) | FileError::Other(m) => fault(named_error(&cx.m.prog, code, m)),
    }
}

fn handle(cx: &mut Cx<'_>, a: &Args) -> R<i32> {
    handle_of(cx, a, "IODevice")
}

/// The handle an `iodev` or `dir` argument holds.
fn handle_of(cx: &mut Cx<'_>, a: &Args, param: &str) -> R<i32> {
    let v = cx.req(a, param)?;
    Ok(super::handle_in(&v).unwrap_or(0.0) as i32)
}

fn open_file<'c>(cx: &'c mut Cx<'_>, a: &Args) -> R<&'c mut OpenFile> {
    let h = handle(cx, a)?;
    if !cx.sh.open.open.contains_key(&h) {
        return fault(named_error(
            &cx.m.prog,
            "ERR_FILEACC",
            format!("{}: the file is not open", a.name),
        ));
    }
    match cx.sh.open.open.get_mut(&h) {
        Some(f) => Ok(f),
        None => invalid("the file is not open"),
    }
}

/// `Open Object [\File] IODevice [\Read] | [\Write] | [\Append] [\Bin]`.
pub(crate) fn open(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let name = super::modules::full_path(cx, a, "Object", "File")?.unwrap_or_default();
    let mode = if a.given("Read") {
        Mode::Read
    } else if a.given("Append") {
        Mode::Append
    } else {
        Mode::Write
    };
    let data = match mode {
        Mode::Read => match cx.sh.files.read(&name) {
            Ok(data) => data,
            Err(e) => return file_error(cx, "Open", "ERR_FILEOPEN", e),
        },
        Mode::Write | Mode::Append => {
            if let Err(e) = cx.sh.files.write(&name, &[], mode == Mode::Append) {
                return file_error(cx, "Open", "ERR_FILEOPEN", e);
            }
            Vec::new()
        }
    };
    touch(cx, &name, mode != Mode::Read);
    cx.sh.open.next += 1;
    let h = cx.sh.open.next;
    cx.sh.open.open.insert(
        h,
        OpenFile {
            path: name,
            mode,
            data,
            pos: 0,
        },
    );
    store_handle(cx, a, "IODevice", "iodev", h)
}

/// Gives the `iodev` or `dir` argument `param` the handle `h`.
fn store_handle(cx: &mut Cx<'_>, a: &Args, param: &str, ty: &str, h: i32) -> R<Done> {
    let p = cx.place_arg(a, param)?;
    cx.store(&p, super::handle_value(ty, f64::from(h)))?;
    Ok(Done::Next)
}

/// `Close IODevice`.
pub(crate) fn close(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let h = handle(cx, a)?;
    cx.sh.open.open.remove(&h);
    Ok(Done::Next)
}

pub(super) fn write_bytes(cx: &mut Cx<'_>, a: &Args, bytes: &[u8]) -> R<Done> {
    let name = a.name;
    let f = open_file(cx, a)?;
    if f.mode == Mode::Read {
        return fault(named_error(
            &cx.m.prog,
            "ERR_FILEACC",
            format!("{name}: the file is not open for writing"),
        ));
    }
    let path = f.path.clone();
    if let Err(e) = cx.sh.files.write(&path, bytes, true) {
        return file_error(cx, name, "ERR_FILEACC", e);
    }
    touch(cx, &path, true);
    Ok(Done::Next)
}

/// Latin-1 bytes of a RAPID string.
pub(super) fn latin1(s: &str) -> Vec<u8> {
    s.chars().map(|c| u32::from(c).min(255) as u8).collect()
}

/// `Write IODevice, String [\Num] ... [\NoNewLine]`.
pub(crate) fn write(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let mut text = cx.string(a, "String")?;
    text.push_str(&super::output::value_suffix(cx, a)?);
    if !a.given("NoNewLine") {
        text.push('\n');
    }
    write_bytes(cx, a, &latin1(&text))
}

/// `WriteStrBin IODevice, Str`.
pub(crate) fn write_str_bin(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let s = cx.string(a, "Str")?;
    write_bytes(cx, a, &latin1(&s))
}

/// `WriteBin IODevice, Buffer, NChar`.
pub(crate) fn write_bin(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let buffer = cx.req(a, "Buffer")?;
    let n = cx.num(a, "NChar")? as usize;
    let Value::Array(items) = buffer else {
        return invalid("WriteBin: Buffer must be an array of num");
    };
    let bytes: Vec<u8> = items
        .iter()
        .take(n)
        .map(|v| v.as_f64().unwrap_or(0.0).clamp(0.0, 255.0) as u8)
        .collect();
    write_bytes(cx, a, &bytes)
}

/// `WriteRawBytes IODevice, RawData [\NoOfBytes]`: the valid bytes of
/// `RawData` (or its first `NoOfBytes`).
pub(crate) fn write_raw_bytes(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let data = super::rawbytes::bytes(&cx.req(a, "RawData")?);
    let n = match cx.opt_num(a, "NoOfBytes")? {
        Some(n) if n < 0.0 || n.fract() != 0.0 || n as usize > data.len() => {
            return fault(named_error(
                &cx.m.prog,
                "ERR_OUTOFBND",
                format!(
                    "WriteRawBytes: NoOfBytes {n} outside 0..{} (the valid bytes)",
                    data.len()
                ),
            ));
        }
        Some(n) => n as usize,
        None => data.len(),
    };
    write_bytes(cx, a, &data[..n])
}

/// `ReadRawBytes IODevice, RawData [\Time]`: the bytes of the file from
/// where it was read up to, as many as a `rawbytes` holds (1024); at the
/// end of the file, `ERR_RANYBIN_EOF` (a file has every byte at once:
/// `\Time` never runs out).
pub(crate) fn read_raw_bytes(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let place = cx.place_arg(a, "RawData")?;
    let f = readable(cx, a)?;
    let end = (f.pos + super::rawbytes::MAX_BYTES).min(f.data.len());
    let read = f.data.get(f.pos..end).unwrap_or_default().to_vec();
    f.pos = end.max(f.pos);
    if read.is_empty() {
        return fault(named_error(
            &cx.m.prog,
            "ERR_RANYBIN_EOF",
            "ReadRawBytes: the end of the file".to_owned(),
        ));
    }
    cx.store(&place, super::rawbytes::value(&read))?;
    Ok(Done::Next)
}

/// `Rewind IODevice`.
pub(crate) fn rewind(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let f = open_file(cx, a)?;
    f.pos = 0;
    Ok(Done::Next)
}

/// The bytes of the file `IODevice` (open for reading) not read yet, and
/// where reading is, to move on.
pub(super) fn unread<'c>(cx: &'c mut Cx<'_>, a: &Args) -> R<(&'c [u8], &'c mut usize)> {
    let OpenFile { data, pos, .. } = readable(cx, a)?;
    Ok((data.get(*pos..).unwrap_or_default(), pos))
}

fn readable<'c>(cx: &'c mut Cx<'_>, a: &Args) -> R<&'c mut OpenFile> {
    let name = a.name;
    let prog = cx.m.prog.clone();
    let f = open_file(cx, a)?;
    if f.mode != Mode::Read {
        return fault(named_error(
            &prog,
            "ERR_FILEACC",
            format!("{name}: the file is not open for reading"),
        ));
    }
    Ok(f)
}

/// Reads up to a delimiter (not more than a string holds): the part read,
/// or `None` at the end of the file.
fn read_part(f: &mut OpenFile, delims: &[u8], discard_headers: bool) -> Option<String> {
    if discard_headers {
        while f.data.get(f.pos).is_some_and(|b| delims.contains(b)) {
            f.pos += 1;
        }
    }
    if f.pos >= f.data.len() {
        return None;
    }
    let mut out = String::new();
    let mut n = 0;
    while let Some(&b) = f.data.get(f.pos) {
        if delims.contains(&b) {
            f.pos += 1;
            break;
        }
        if n >= MAX_STRING_LEN {
            break;
        }
        out.push(char::from(b));
        n += 1;
        f.pos += 1;
    }
    Some(out)
}

fn delimiters(cx: &mut Cx<'_>, a: &Args, extra_cr: bool) -> R<Vec<u8>> {
    let mut d = vec![b'\n'];
    if let Some(s) = cx.opt_string(a, "Delim")? {
        d.extend(latin1(&s));
        if extra_cr {
            d.push(b'\r');
        }
    }
    Ok(d)
}

/// `ReadStr(IODevice [\Delim] [\RemoveCR] [\DiscardHeaders])`: `"EOF"` at
/// the end of the file.
pub(crate) fn read_str(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let delims = delimiters(cx, a, false)?;
    let discard = a.given("DiscardHeaders");
    let remove_cr = a.given("RemoveCR");
    let f = readable(cx, a)?;
    Ok(Value::Str(match read_part(f, &delims, discard) {
        None => "EOF".to_owned(),
        Some(mut s) => {
            if remove_cr && s.ends_with('\r') {
                s.pop();
            }
            s
        }
    }))
}

/// `ReadNum(IODevice [\Delim])`: 9.999E36 at the end of the file.
pub(crate) fn read_num(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let delims = delimiters(cx, a, true)?;
    let f = readable(cx, a)?;
    let Some(s) = read_part(f, &delims, true) else {
        return Ok(Value::Num(9.999e36));
    };
    match rapid_evaluator::parse_num_literal(s.trim()) {
        Ok(x) => Ok(Value::Num(x as f32)),
        Err(_) => fault(named_error(
            &cx.m.prog,
            "ERR_RCVDATA",
            format!("ReadNum: {s:?} is not a number"),
        )),
    }
}

/// `ReadBin(IODevice)`: the next byte, -1 at the end of the file.
pub(crate) fn read_bin(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let f = readable(cx, a)?;
    Ok(Value::Num(match f.data.get(f.pos) {
        Some(&b) => {
            f.pos += 1;
            f32::from(b)
        }
        None => -1.0,
    }))
}

/// `ReadStrBin(IODevice, NoOfChars [\Time])`: the next `NoOfChars`
/// bytes as text (fewer at the end of the file; `EOF` when none is left).
pub(crate) fn read_str_bin(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let n = cx.num(a, "NoOfChars")?.clamp(0.0, 80.0) as usize;
    let f = readable(cx, a)?;
    if f.pos >= f.data.len() {
        return Ok(Value::Str("EOF".to_owned()));
    }
    let end = (f.pos + n).min(f.data.len());
    let text: String = f.data[f.pos..end].iter().map(|&b| char::from(b)).collect();
    f.pos = end;
    Ok(Value::Str(text))
}

/// `IsFile(Path [\Directory] | [\RegFile] ...)`.
pub(crate) fn is_file(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = cx.string(a, "Path")?;
    let kind = cx.sh.files.kind(&name);
    Ok(Value::Bool(match kind {
        None => false,
        Some(k) if a.given("Directory") => k == FileKind::Directory,
        Some(k) if a.given("RegFile") => k == FileKind::File,
        Some(_) => true,
    }))
}

/// `FileSize(Path)`: the file's size in bytes.
pub(crate) fn file_size(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = cx.string(a, "Path")?;
    let r = cx.sh.files.read(&name).map(|bytes| bytes.len());
    match r {
        Ok(n) => Ok(Value::Num(n as f32)),
        Err(e) => {
            done_or_error(cx, a, Err(e))?;
            Ok(Value::Num(0.0))
        }
    }
}

/// `FileTime(Path [\ModifyTime] | [\AccessTime] | [\StatCTime])`: when
/// the file was last changed (the default), read or written, or had its
/// status changed, in seconds since 1970 on the simulated clock: a file
/// the run has not touched dates from the run's start; `ERR_FILEACC` when
/// it does not exist.
pub(crate) fn file_time(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = cx.string(a, "Path")?;
    if cx.sh.files.kind(&name).is_none() {
        return fault(named_error(
            &cx.m.prog,
            "ERR_FILEACC",
            format!("FileTime: {name} does not exist"),
        ));
    }
    let stamp = cx
        .sh
        .open
        .stamps
        .get(&crate::world::path_key(&name))
        .copied()
        .unwrap_or_default();
    let t = if a.given("AccessTime") {
        stamp.accessed
    } else if a.given("StatCTime") {
        stamp.changed
    } else {
        stamp.modified
    };
    Ok(super::data::epoch_value(t))
}

/// `ClearIOBuff IODevice`: empties a serial channel's input buffer; a
/// file has none, so nothing changes.
pub(crate) fn clear_io_buff(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    cx.req(a, "IODevice")?;
    Ok(Done::Next)
}

fn fs_op(
    cx: &mut Cx<'_>,
    a: &Args,
    op: fn(&mut dyn crate::world::FileSystem, &str) -> Result<(), FileError>,
) -> R<Done> {
    let name = cx.string(a, "Path")?;
    let r = op(cx.sh.files.as_mut(), &name);
    done_or_error(cx, a, r)
}

/// A file operation's result: the next statement, `ERR_FILNOTFND` for a
/// path that names nothing, else `ERR_FILEACC`.
fn done_or_error(cx: &Cx<'_>, a: &Args, r: Result<(), FileError>) -> R<Done> {
    match r {
        Ok(()) => Ok(Done::Next),
        Err(FileError::NotFound(m)) => fault(named_error(
            &cx.m.prog,
            "ERR_FILNOTFND",
            format!("{}: {m}", a.name),
        )),
        Err(e) => file_error(cx, a.name, "ERR_FILEACC", e),
    }
}

/// `RemoveFile Path`.
pub(crate) fn remove_file(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    fs_op(cx, a, |fs, p| fs.remove_file(p))
}

/// `RenameFile OldPath, NewPath` (a file or a folder): `ERR_FILEEXIST`
/// when `NewPath` exists, `ERR_FILNOTFND` when `OldPath` does not.
pub(crate) fn rename_file(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (from, to) = two_paths(cx, a)?;
    let r = cx.sh.files.rename(&from, &to);
    if r.is_ok() {
        // The file keeps its times; renaming changes its status.
        let mut stamp = cx
            .sh
            .open
            .stamps
            .remove(&crate::world::path_key(&from))
            .unwrap_or_default();
        stamp.changed = cx.now();
        cx.sh.open.stamps.insert(crate::world::path_key(&to), stamp);
    }
    done_or_error(cx, a, r)
}

/// `CopyFile OldPath, NewPath` (a file): `ERR_FILEEXIST` when `NewPath`
/// exists, `ERR_FILNOTFND` when `OldPath` does not.
pub(crate) fn copy_file(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let (from, to) = two_paths(cx, a)?;
    let r = cx
        .sh
        .files
        .read(&from)
        .and_then(|data| cx.sh.files.write(&to, &data, false));
    if r.is_ok() {
        touch(cx, &from, false);
        touch(cx, &to, true);
    }
    done_or_error(cx, a, r)
}

/// The two paths of `RenameFile` and `CopyFile`; `ERR_FILEEXIST` when the
/// new one names something already.
fn two_paths(cx: &mut Cx<'_>, a: &Args) -> R<(String, String)> {
    let from = cx.string(a, "OldPath")?;
    let to = cx.string(a, "NewPath")?;
    if cx.sh.files.kind(&to).is_some() {
        return fault(named_error(
            &cx.m.prog,
            "ERR_FILEEXIST",
            format!("{}: {to} exists already", a.name),
        ));
    }
    Ok((from, to))
}

/// `MakeDir Path`.
pub(crate) fn make_dir(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    fs_op(cx, a, |fs, p| fs.make_dir(p))
}

/// `RemoveDir Path`.
pub(crate) fn remove_dir(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    fs_op(cx, a, |fs, p| fs.remove_dir(p))
}

/// `OpenDir Dev, Path`: the folder's entries, `.` and `..` first as the
/// controller lists them (loaded code skips them by name), then the rest
/// sorted by name; `ERR_FILEACC` for a path that is no folder.
pub(crate) fn open_dir(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let path = cx.string(a, "Path")?;
    let names = match cx.sh.files.list(&path) {
        Ok(names) => names,
        Err(e) => return file_error(cx, "OpenDir", "ERR_FILEACC", e),
    };
    let entries = [".", ".."]
        .into_iter()
        .map(str::to_owned)
        .chain(names)
        .collect();
    cx.sh.open.next += 1;
    let h = cx.sh.open.next;
    cx.sh.open.dirs.insert(h, (entries, 0));
    store_handle(cx, a, "Dev", "dir", h)
}

/// `ReadDir(Dev, FileName)`: TRUE with the next entry's name in
/// `FileName`, FALSE after the last; `ERR_FILEACC` for a folder not open.
pub(crate) fn read_dir(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let h = handle_of(cx, a, "Dev")?;
    let Some((entries, read)) = cx.sh.open.dirs.get_mut(&h) else {
        return fault(named_error(
            &cx.m.prog,
            "ERR_FILEACC",
            "ReadDir: the folder is not open (OpenDir)".to_owned(),
        ));
    };
    let Some(name) = entries.get(*read).cloned() else {
        return Ok(Value::Bool(false));
    };
    *read += 1;
    let p = cx.place_arg(a, "FileName")?;
    cx.store(&p, Value::Str(name))?;
    Ok(Value::Bool(true))
}

/// `CloseDir Dev`.
pub(crate) fn close_dir(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let h = handle_of(cx, a, "Dev")?;
    cx.sh.open.dirs.remove(&h);
    Ok(Done::Next)
}
