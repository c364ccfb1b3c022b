//! Files, in a sandbox folder: every device (`HOME:`, `TEMP:`...) is that
//! folder, and no path leaves it. Without a sandbox, file instructions are
//! not supported.

use std::collections::HashMap;
use std::io::Write as _;
use std::path::{Component, Path, PathBuf};

use rapid_evaluator::Value;

use super::Args;
use crate::machine::{FaultKind, Machine, R, fault, invalid, named_error};

#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    Read,
    Write,
    Append,
}

struct OpenFile {
    mode: Mode,
    /// What is read (the whole file, read when opened).
    data: Vec<u8>,
    pos: usize,
    file: Option<std::fs::File>,
}

pub(crate) struct Files {
    sandbox: Option<PathBuf>,
    open: HashMap<i32, OpenFile>,
    next: i32,
}

impl Files {
    pub(crate) fn new(sandbox: Option<PathBuf>) -> Files {
        Files {
            sandbox,
            open: HashMap::new(),
            next: 0,
        }
    }
}

/// The sandbox path of a controller path (`HOME:/logs/a.txt`).
fn resolve(m: &Machine, name: &str, what: &'static str) -> R<PathBuf> {
    let Some(root) = &m.ctl.files.sandbox else {
        return fault(FaultKind::Unsupported(format!(
            "{what} (file instructions need a sandbox folder: --sandbox DIR)"
        )));
    };
    let rest = match name.split_once(':') {
        Some((dev, rest)) if !dev.contains(['/', '\\']) => rest,
        _ => name,
    };
    let mut out = root.clone();
    for c in Path::new(&rest.replace('\\', "/")).components() {
        match c {
            Component::Normal(p) => out.push(p),
            Component::RootDir | Component::CurDir => {}
            _ => {
                return fault(named_error(
                    &m.prog,
                    "ERR_FILEACC",
                    format!("{name}: the path leaves the sandbox folder"),
                ));
            }
        }
    }
    Ok(out)
}

/// `Open` fails with `ERR_FILEOPEN`, whatever the reason.
fn file_error<T>(m: &Machine, name: &str, e: &std::io::Error) -> R<T> {
    fault(named_error(&m.prog, "ERR_FILEOPEN", format!("{name}: {e}")))
}

fn handle(m: &mut Machine, a: &Args<'_>) -> R<i32> {
    let v = m.req(a, "IODevice")?;
    Ok(v.field("handle").and_then(Value::as_f64).unwrap_or(0.0) as i32)
}

fn open_file<'m>(m: &'m mut Machine, a: &Args<'_>) -> R<&'m mut OpenFile> {
    let h = handle(m, a)?;
    if !m.ctl.files.open.contains_key(&h) {
        return fault(named_error(
            &m.prog,
            "ERR_FILEACC",
            format!("{}: the file is not open", a.name),
        ));
    }
    match m.ctl.files.open.get_mut(&h) {
        Some(f) => Ok(f),
        None => invalid("the file is not open"),
    }
}

/// `Open Object [\File] IODevice [\Read] | [\Write] | [\Append] [\Bin]`.
pub(crate) fn open(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let mut name = m.string(a, "Object")?;
    if let Some(f) = m.opt_string(a, "File")? {
        if !name.ends_with(['/', ':']) {
            name.push('/');
        }
        name.push_str(&f);
    }
    let path = resolve(m, &name, "Open")?;
    let mode = if m.given(a, "Read") {
        Mode::Read
    } else if m.given(a, "Append") {
        Mode::Append
    } else {
        Mode::Write
    };
    let entry = match mode {
        Mode::Read => match std::fs::read(&path) {
            Ok(data) => OpenFile {
                mode,
                data,
                pos: 0,
                file: None,
            },
            Err(e) => return file_error(m, &name, &e),
        },
        Mode::Write | Mode::Append => {
            let f = std::fs::OpenOptions::new()
                .create(true)
                .write(true)
                .append(mode == Mode::Append)
                .truncate(mode == Mode::Write)
                .open(&path);
            match f {
                Ok(f) => OpenFile {
                    mode,
                    data: Vec::new(),
                    pos: 0,
                    file: Some(f),
                },
                Err(e) => return file_error(m, &name, &e),
            }
        }
    };
    m.ctl.files.next += 1;
    let h = m.ctl.files.next;
    m.ctl.files.open.insert(h, entry);
    let p = m.place_arg(a, "IODevice")?;
    m.store(
        &p,
        Value::Record {
            ty: "iodev".to_owned(),
            fields: vec![("handle".to_owned(), Value::Num(h as f32))],
        },
    )
}

/// `Close IODevice`.
pub(crate) fn close(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let h = handle(m, a)?;
    m.ctl.files.open.remove(&h);
    Ok(())
}

fn write_bytes(m: &mut Machine, a: &Args<'_>, bytes: &[u8]) -> R<()> {
    let name = a.name;
    let f = open_file(m, a)?;
    let ok = f.mode != Mode::Read
        && f.file
            .as_mut()
            .is_some_and(|file| file.write_all(bytes).is_ok());
    if ok {
        Ok(())
    } else {
        fault(named_error(
            &m.prog,
            "ERR_FILEACC",
            format!("{name}: the file is not open for writing"),
        ))
    }
}

/// Latin-1 bytes of a RAPID string.
fn latin1(s: &str) -> Vec<u8> {
    s.chars().map(|c| u32::from(c).min(255) as u8).collect()
}

/// `Write IODevice, String [\Num] ... [\NoNewLine]`.
pub(crate) fn write(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let mut text = m.string(a, "String")?;
    text.push_str(&super::output::value_suffix(m, a)?);
    if !m.given(a, "NoNewLine") {
        text.push('\n');
    }
    write_bytes(m, a, &latin1(&text))
}

/// `WriteStrBin IODevice, Str`.
pub(crate) fn write_str_bin(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let s = m.string(a, "Str")?;
    write_bytes(m, a, &latin1(&s))
}

/// `WriteBin IODevice, Buffer, NChar`.
pub(crate) fn write_bin(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let buffer = m.req(a, "Buffer")?;
    let n = m.num(a, "NChar")? as usize;
    let Value::Array(items) = buffer else {
        return invalid("WriteBin: Buffer must be an array of num");
    };
    let bytes: Vec<u8> = items
        .iter()
        .take(n)
        .map(|v| v.as_f64().unwrap_or(0.0).clamp(0.0, 255.0) as u8)
        .collect();
    write_bytes(m, a, &bytes)
}

/// `Rewind IODevice`.
pub(crate) fn rewind(m: &mut Machine, a: &Args<'_>) -> R<()> {
    let f = open_file(m, a)?;
    f.pos = 0;
    Ok(())
}

fn readable<'m>(m: &'m mut Machine, a: &Args<'_>) -> R<&'m mut OpenFile> {
    let name = a.name;
    let prog = m.prog.clone();
    let f = open_file(m, a)?;
    if f.mode != Mode::Read {
        return fault(named_error(
            &prog,
            "ERR_FILEACC",
            format!("{name}: the file is not open for reading"),
        ));
    }
    Ok(f)
}

/// Reads up to a delimiter (not more than 80 characters): the part read,
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
    while let Some(&b) = f.data.get(f.pos) {
        if delims.contains(&b) {
            f.pos += 1;
            break;
        }
        if out.len() >= 80 {
            break;
        }
        out.push(char::from(b));
        f.pos += 1;
    }
    Some(out)
}

fn delimiters(m: &mut Machine, a: &Args<'_>, extra_cr: bool) -> R<Vec<u8>> {
    let mut d = vec![b'\n'];
    if let Some(s) = m.opt_string(a, "Delim")? {
        d.extend(latin1(&s));
        if extra_cr {
            d.push(b'\r');
        }
    }
    Ok(d)
}

/// `ReadStr(IODevice [\Delim] [\RemoveCR] [\DiscardHeaders])`: `"EOF"` at
/// the end of the file.
pub(crate) fn read_str(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let delims = delimiters(m, a, false)?;
    let discard = m.given(a, "DiscardHeaders");
    let remove_cr = m.given(a, "RemoveCR");
    let f = readable(m, a)?;
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
pub(crate) fn read_num(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let delims = delimiters(m, a, true)?;
    let f = readable(m, a)?;
    let Some(s) = read_part(f, &delims, true) else {
        return Ok(Value::Num(9.999e36));
    };
    match rapid_evaluator::parse_num_literal(s.trim()) {
        Ok(x) => Ok(Value::Num(x as f32)),
        Err(_) => fault(named_error(
            &m.prog,
            "ERR_RCVDATA",
            format!("ReadNum: {s:?} is not a number"),
        )),
    }
}

/// `ReadBin(IODevice)`: the next byte, -1 at the end of the file.
pub(crate) fn read_bin(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let f = readable(m, a)?;
    Ok(Value::Num(match f.data.get(f.pos) {
        Some(&b) => {
            f.pos += 1;
            f32::from(b)
        }
        None => -1.0,
    }))
}

/// `IsFile(Path [\Directory] | [\RegFile] ...)`.
pub(crate) fn is_file(m: &mut Machine, a: &Args<'_>) -> R<Value> {
    let name = m.string(a, "Path")?;
    let path = resolve(m, &name, "IsFile")?;
    let meta = std::fs::metadata(&path).ok();
    Ok(Value::Bool(match meta {
        None => false,
        Some(meta) if m.given(a, "Directory") => meta.is_dir(),
        Some(meta) if m.given(a, "RegFile") => meta.is_file(),
        Some(_) => true,
    }))
}

fn fs_op(
    m: &mut Machine,
    a: &Args<'_>,
    param: &str,
    op: fn(&Path) -> std::io::Result<()>,
) -> R<()> {
    let name = m.string(a, param)?;
    let path = resolve(m, &name, a.name)?;
    op(&path).or_else(|e| {
        let code = if e.kind() == std::io::ErrorKind::NotFound {
            "ERR_FILNOTFND"
        } else {
            "ERR_FILEACC"
        };
        fault(named_error(
            &m.prog,
            code,
            format!("{}: {name}: {e}", a.name),
        ))
    })
}

/// `RemoveFile Path`.
pub(crate) fn remove_file(m: &mut Machine, a: &Args<'_>) -> R<()> {
    fs_op(m, a, "Path", |p| std::fs::remove_file(p))
}

/// `MakeDir Path`.
pub(crate) fn make_dir(m: &mut Machine, a: &Args<'_>) -> R<()> {
    fs_op(m, a, "Path", |p| std::fs::create_dir(p))
}

/// `RemoveDir Path`.
pub(crate) fn remove_dir(m: &mut Machine, a: &Args<'_>) -> R<()> {
    fs_op(m, a, "Path", |p| std::fs::remove_dir(p))
}
