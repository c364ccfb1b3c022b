//! User text tables: `TextTabInstall` reads a text table file from the
//! controller's files, `TextTabGet` gives an installed table's number,
//! `TextGet` a text of it, `TextTabFreeToUse` whether a name is free.
//!
//! A text table file (Latin-1), as ABB's own text definition files are
//! written: lines starting with `#` are comments; `NAME::` starts the
//! table `NAME`; `INDEX:` (a whole number, a `#` comment may follow)
//! starts a text, which is the next line (`""` for an empty one). The
//! tables are the controller's, shared by its tasks; a table installed
//! again keeps its first texts.

use rapid_evaluator::Value;

use super::{Args, Cx, Done};
use crate::machine::{R, invalid};

/// An installed table: its name and texts by index.
#[derive(Clone, Debug, Default)]
pub(crate) struct TextTable {
    name: String,
    texts: Vec<(u32, String)>,
}

/// The tables of a text table file, or the line that does not fit and
/// what was expected there.
fn parse(text: &str) -> Result<Vec<TextTable>, (usize, String)> {
    let mut tables: Vec<TextTable> = Vec::new();
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
    while let Some((n, line)) = lines.next() {
        let line = line.trim_end_matches('\r');
        let head = line.trim();
        if head.is_empty() || head.starts_with('#') {
            continue;
        }
        if let Some(name) = head.strip_suffix("::") {
            tables.push(TextTable {
                name: name.trim().to_owned(),
                texts: Vec::new(),
            });
            continue;
        }
        let index = head
            .split_once(':')
            .filter(|(_, rest)| rest.trim().is_empty() || rest.trim().starts_with('#'))
            .and_then(|(i, _)| i.trim().parse::<u32>().ok());
        let Some(index) = index else {
            return Err((n, "expected `NAME::`, `INDEX:` or a `#` comment".to_owned()));
        };
        let Some(table) = tables.last_mut() else {
            return Err((n, "expected the table's name (`NAME::`) first".to_owned()));
        };
        let Some((_, text)) = lines.next() else {
            return Err((n + 1, format!("expected the text of index {index}")));
        };
        let text = text.trim_end_matches('\r');
        let text = if text.trim() == "\"\"" { "" } else { text };
        table.texts.push((index, text.to_owned()));
    }
    Ok(tables)
}

/// `TextTabInstall File`.
pub(crate) fn text_tab_install(cx: &mut Cx<'_>, a: &mut Args) -> R<Done> {
    let path = cx.string(a, "File")?;
    let bytes = match cx.sh.files.read(&path) {
        Ok(b) => b,
        Err(e) => return super::files::file_error(cx, "TextTabInstall", "ERR_FILEOPEN", e),
    };
    let text: String = bytes.iter().map(|&b| char::from(b)).collect();
    let tables = match parse(&text) {
        Ok(t) => t,
        Err((line, what)) => {
            return invalid(format!("TextTabInstall: {path}:{line}: {what}"));
        }
    };
    for t in tables {
        if number(cx, &t.name).is_none() {
            cx.sh.text_tables.push(t);
        }
    }
    Ok(Done::Next)
}

/// The number of the installed table `name` (any case), from 1.
fn number(cx: &Cx<'_>, name: &str) -> Option<usize> {
    cx.sh
        .text_tables
        .iter()
        .position(|t| t.name.eq_ignore_ascii_case(name))
        .map(|i| i + 1)
}

/// `TextTabGet(TableName)`.
pub(crate) fn text_tab_get(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = cx.string(a, "TableName")?;
    match number(cx, &name) {
        Some(n) => Ok(Value::Num(n as f32)),
        None => invalid(format!(
            "TextTabGet: no text table {name} is installed (TextTabInstall installs it)"
        )),
    }
}

/// `TextGet(Table, Index)`.
pub(crate) fn text_get(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let table = cx.num(a, "Table")?;
    let index = cx.num(a, "Index")?;
    let Some(t) = (table >= 1.0 && table.fract() == 0.0)
        .then(|| cx.sh.text_tables.get(table as usize - 1))
        .flatten()
    else {
        return invalid(format!("TextGet: there is no text table {table}"));
    };
    match t.texts.iter().find(|(i, _)| f64::from(*i) == index) {
        Some((_, text)) => Ok(Value::Str(text.clone())),
        None => invalid(format!(
            "TextGet: text table {} has no text {index}",
            t.name
        )),
    }
}

/// `TextTabFreeToUse(TableName)`: no table of that name is installed.
pub(crate) fn text_tab_free_to_use(cx: &mut Cx<'_>, a: &mut Args) -> R<Value> {
    let name = cx.string(a, "TableName")?;
    Ok(Value::Bool(number(cx, &name).is_none()))
}

#[cfg(test)]
mod tests {
    use super::parse;

    #[test]
    fn a_text_table_file_gives_its_tables_and_texts() {
        let file = "# texts of the cell\ncell::\n#\n0: #tStart\nPress start\n1:\n\"\"\n2: #tDone\nDone: 100 %\nother::\n7:\nseven\n";
        let tables = parse(file).expect("a text table file");
        let got: Vec<(&str, Vec<(u32, &str)>)> = tables
            .iter()
            .map(|t| {
                (
                    t.name.as_str(),
                    t.texts.iter().map(|(i, s)| (*i, s.as_str())).collect(),
                )
            })
            .collect();
        assert_eq!(
            got,
            vec![
                (
                    "cell",
                    vec![(0, "Press start"), (1, ""), (2, "Done: 100 %")]
                ),
                ("other", vec![(7, "seven")]),
            ]
        );
    }

    #[test]
    fn a_line_that_does_not_fit_is_named_with_what_was_expected() {
        assert_eq!(
            parse("cell::\nhello\n").err(),
            Some((2, "expected `NAME::`, `INDEX:` or a `#` comment".to_owned()))
        );
        assert_eq!(
            parse("1:\ntext\n").err(),
            Some((1, "expected the table's name (`NAME::`) first".to_owned()))
        );
        assert_eq!(
            parse("cell::\n3:").err(),
            Some((3, "expected the text of index 3".to_owned()))
        );
    }
}
