//! The report of `rapid diff` as text for people (grouped, coloured on a
//! terminal), as Markdown for a pull-request comment, and as JSON.

use std::io::{self, Write};

use anstyle::{AnsiColor, Style};
use rapid_analyzer::diff::builtins::BuiltinChanges;
use rapid_analyzer::diff::config::{AttrChange, ConfigDiff, InstanceDiff};
use rapid_analyzer::diff::{
    DataDiff, Hunk, ModuleDiff, Motion, Report, RoutineDiff, Status, Tag, TaskDiff,
};

use super::Titles;

const BOLD: Style = Style::new().bold();
const ADDED: Style = AnsiColor::Green.on_default();
const REMOVED: Style = AnsiColor::Red.on_default();
const CHANGED: Style = AnsiColor::Yellow.on_default();
const DIM: Style = AnsiColor::Cyan.on_default();

/// Values longer than this are cut in the human and Markdown reports (the
/// JSON has them whole).
const MAX_VALUE: usize = 160;

fn paint(style: Style, text: &str) -> String {
    format!("{style}{text}{style:#}")
}

fn status_style(s: Status) -> Style {
    match s {
        Status::Added => ADDED,
        Status::Removed => REMOVED,
        Status::Changed => CHANGED,
    }
}

/// A length or angle with up to three decimals (`12.3`, `0.05`, `5`).
pub fn amount(x: f64) -> String {
    if x > 0.0 && x < 0.0005 {
        return "<0.001".to_owned();
    }
    let s = format!("{x:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

fn cut(s: &str) -> String {
    if s.chars().count() <= MAX_VALUE {
        return s.to_owned();
    }
    let head: String = s.chars().take(MAX_VALUE).collect();
    format!("{head}…")
}

/// How far something moved, in words: `12.3 mm, 2°, conf [0,0,0,0] →
/// [0,-1,0,0], eax_a 9E9 → 100`.
pub fn motion_words(m: &Motion) -> String {
    let mut parts = Vec::new();
    let turned = m.rotation_deg.is_some_and(|a| a > 0.0);
    if let Some(d) = m.translation_mm.filter(|d| *d > 0.0 || !turned) {
        parts.push(format!("{} mm", amount(d)));
    }
    if let Some(a) = m.rotation_deg.filter(|a| *a > 0.0) {
        parts.push(format!("{}°", amount(a)));
    }
    if let Some(j) = m.joints_deg {
        let axes: Vec<String> = m
            .joints
            .iter()
            .map(|c| format!("{} {} → {}", last(&c.path), c.old, c.new))
            .collect();
        parts.push(format!("joints up to {}° ({})", amount(j), axes.join(", ")));
    }
    if let Some((o, n)) = &m.conf {
        parts.push(format!("conf {o} → {n}"));
    }
    for e in &m.external_axes {
        parts.push(format!("{} {} → {}", last(&e.path), e.old, e.new));
    }
    if let Some(r) = &m.reach {
        parts.push(if r.reachable {
            format!("reachable ({})", r.detail)
        } else {
            format!("not reachable: {}", r.detail)
        });
    }
    parts.join(", ")
}

fn last(path: &str) -> &str {
    path.rsplit('.').next().unwrap_or(path)
}

/// The frames inside a value that moved (`tframe 10 mm, uframe 2°`).
fn frames_words(m: &Motion) -> Option<String> {
    if m.frames.is_empty() {
        return None;
    }
    let parts: Vec<String> = m
        .frames
        .iter()
        .map(|f| {
            let mut p = vec![f.path.clone()];
            if let Some(d) = f.translation_mm.filter(|d| *d > 0.0) {
                p.push(format!("{} mm", amount(d)));
            }
            if let Some(a) = f.rotation_deg.filter(|a| *a > 0.0) {
                p.push(format!("{}°", amount(a)));
            }
            p.join(" ")
        })
        .collect();
    Some(parts.join(", "))
}

/// A motion in words for one line: the frame that moved by its name when
/// it is the only one inside the value (`EdgePos 12 mm`), else the
/// value's own distance and angle with the frames after them.
fn moved_words(m: &Motion) -> Vec<String> {
    let mut out = Vec::new();
    if m.frames.len() == 1 {
        out.extend(frames_words(m));
        let rest = Motion {
            translation_mm: None,
            rotation_deg: None,
            ..m.clone()
        };
        out.push(motion_words(&rest));
    } else {
        out.push(motion_words(m));
        out.extend(frames_words(m).map(|f| format!("[{f}]")));
    }
    out.retain(|s| !s.is_empty());
    out
}

/// What changed of a datum, in words (without its motion).
fn data_words(d: &DataDiff) -> String {
    let (old, new) = (d.old.as_ref(), d.new.as_ref());
    let mut parts = Vec::new();
    if d.changed.iter().any(|c| *c != "value")
        && let (Some(o), Some(n)) = (old, new)
    {
        parts.push(format!("{} → {}", o.declaration, n.declaration));
    }
    if !d.fields.is_empty() {
        let fields: Vec<String> = d
            .fields
            .iter()
            .map(|f| {
                let path = if f.path.is_empty() { "value" } else { &f.path };
                format!("{path} {} → {}", cut(&f.old), cut(&f.new))
            })
            .collect();
        parts.push(fields.join(", "));
    } else if d.changed.contains(&"value") && d.motion.is_none() {
        let value = |s: Option<&rapid_analyzer::diff::DataSide>| {
            s.and_then(|s| s.value.clone())
                .unwrap_or_else(|| "(none)".to_owned())
        };
        parts.push(format!("{} → {}", cut(&value(old)), cut(&value(new))));
    }
    if d.derived {
        parts.push("(its expression is unchanged: data it uses changed)".to_owned());
    }
    parts.join("; ")
}

fn summary_words(report: &Report) -> String {
    let s = report.summary();
    let mut parts = Vec::new();
    let mut count = |n: usize, one: &str, many: &str| {
        if n > 0 {
            parts.push(format!("{n} {}", if n == 1 { one } else { many }));
        }
    };
    count(s.modules_added, "module added", "modules added");
    count(s.modules_removed, "module removed", "modules removed");
    count(s.modules_changed, "module changed", "modules changed");
    count(s.routines, "routine", "routines");
    count(s.moves, "position moved", "positions moved");
    count(s.data, "datum", "data");
    count(s.types, "type", "types");
    count(s.config, "configuration entry", "configuration entries");
    count(s.builtins, "built-in signature", "built-in signatures");
    let mut out = if parts.is_empty() {
        "No changes".to_owned()
    } else {
        parts.join(", ")
    };
    if report.ignored_moves > 0 {
        out.push_str(&format!(
            "; {} smaller {} left out",
            report.ignored_moves,
            if report.ignored_moves == 1 {
                "move"
            } else {
                "moves"
            }
        ));
    }
    out.push('.');
    out
}

fn attr_words(a: &AttrChange) -> String {
    let v = |x: &Option<String>| match x.as_deref() {
        None => "(none)".to_owned(),
        Some("") => "(set)".to_owned(),
        Some(s) => s.to_owned(),
    };
    match (&a.old, &a.new) {
        (None, Some(n)) if n.is_empty() => a.name.clone(),
        (None, Some(n)) | (Some(n), None) => format!("{} {n}", a.name),
        _ => format!("{} {} → {}", a.name, v(&a.old), v(&a.new)),
    }
}

fn instance_words(i: &InstanceDiff) -> String {
    let what = match i.label {
        Some(label) if i.status == Status::Changed => label,
        _ => i.status.word(),
    };
    let attrs: Vec<String> = i
        .attributes
        .iter()
        .filter(|a| !(i.status != Status::Changed && a.name.eq_ignore_ascii_case("name")))
        .map(attr_words)
        .collect();
    let kind = match i.label {
        Some(label) if i.status != Status::Changed => format!(" ({label})"),
        _ => String::new(),
    };
    format!(
        "{} {}{kind} {what}: {}",
        i.type_name,
        i.instance,
        attrs.join(", ")
    )
}

fn module_counts(m: &ModuleDiff) -> String {
    let n = |x: usize, one: &str, many: &str| format!("{x} {}", if x == 1 { one } else { many });
    format!(
        "{}, {}",
        n(m.routines.len(), "routine", "routines"),
        n(m.data.len(), "datum", "data")
    )
}

fn file_of(m: &ModuleDiff) -> String {
    match (&m.old_file, &m.new_file) {
        (Some(o), Some(n)) if o != n => format!("{o} → {n}"),
        (_, Some(f)) | (Some(f), None) => f.clone(),
        (None, None) => String::new(),
    }
}

fn routine_title(r: &RoutineDiff) -> String {
    let line = match (r.old_line, r.new_line) {
        (Some(o), Some(n)) if o != n => format!("line {o} → {n}"),
        (_, Some(l)) | (Some(l), None) => format!("line {l}"),
        (None, None) => String::new(),
    };
    format!("{} {} {} ({line})", r.kind, r.name, r.status.word())
}

fn hunk_header(h: &Hunk) -> String {
    let old = h.lines.iter().find_map(|l| l.old_line);
    let new = h.lines.iter().find_map(|l| l.new_line);
    match (old, new) {
        (Some(o), Some(n)) if o != n => format!("@@ line {o} → {n} @@"),
        (Some(l), _) | (None, Some(l)) => format!("@@ line {l} @@"),
        (None, None) => "@@".to_owned(),
    }
}

/// A hunk line as a unified diff writes it: `-`, `+` or a blank, then the
/// line indented by its depth.
fn diff_line(tag: Tag, depth: u16, text: &str) -> (char, String) {
    let mark = match tag {
        Tag::Context => ' ',
        Tag::Removed => '-',
        Tag::Added => '+',
    };
    (
        mark,
        format!("{mark} {}{text}", "  ".repeat(usize::from(depth))),
    )
}

// ---------------------------------------------------------------------------
// Human.

pub fn human(out: &mut dyn Write, report: &Report, titles: &Titles) -> io::Result<()> {
    writeln!(
        out,
        "{} {} → {}",
        paint(BOLD, "rapid diff"),
        titles.old,
        titles.new
    )?;
    for t in &report.tasks {
        human_task(out, t)?;
    }
    if !report.config.is_empty() {
        writeln!(out, "\n{}", paint(BOLD, "Configuration"))?;
        for c in &report.config {
            human_config(out, c)?;
        }
    }
    if let Some(b) = report.builtins.as_ref().filter(|b| !b.changed.is_empty()) {
        human_builtins(out, b)?;
    }
    writeln!(out, "\n{}", summary_words(report))
}

fn human_task(out: &mut dyn Write, t: &TaskDiff) -> io::Result<()> {
    let renamed = t
        .old_name
        .as_ref()
        .map(|o| format!(" (was {o})"))
        .unwrap_or_default();
    writeln!(
        out,
        "\n{} {}{renamed}",
        paint(BOLD, &format!("Task {}", t.name)),
        paint(status_style(t.status), t.status.word())
    )?;
    for m in &t.modules {
        let file = file_of(m);
        if m.status != Status::Changed {
            writeln!(
                out,
                "  {} {} ({file}: {})",
                paint(BOLD, &m.name),
                paint(status_style(m.status), m.status.word()),
                module_counts(m)
            )?;
            continue;
        }
        writeln!(
            out,
            "  {} {} ({file})",
            paint(BOLD, &m.name),
            paint(CHANGED, "changed")
        )?;
        if let Some((o, n)) = &m.attributes {
            writeln!(
                out,
                "    {} ({}) → ({})",
                paint(CHANGED, "attributes"),
                o.join(", "),
                n.join(", ")
            )?;
        }
        let width = m
            .data
            .iter()
            .map(|d| d.name.chars().count())
            .max()
            .unwrap_or(0);
        for d in &m.data {
            human_data(out, d, width)?;
        }
        for r in m.types.iter().chain(&m.routines) {
            human_routine(out, r)?;
        }
    }
    Ok(())
}

fn human_data(out: &mut dyn Write, d: &DataDiff, width: usize) -> io::Result<()> {
    let moved = d.motion.as_ref().filter(|m| m.is_move());
    let (word, style) = match (d.status, moved) {
        (Status::Changed, Some(_)) => ("moved", CHANGED),
        (s, _) => (s.word(), status_style(s)),
    };
    let mut what = Vec::new();
    if let Some(m) = &d.motion {
        what.extend(moved_words(m));
    }
    let rest = data_words(d);
    if !rest.is_empty() {
        what.push(rest);
    }
    let declaration = match d.status {
        Status::Changed => String::new(),
        _ => d
            .new
            .as_ref()
            .or(d.old.as_ref())
            .map(|s| {
                let value = s.value.as_ref().map(|v| format!(" := {}", cut(v)));
                format!("{}{}", s.declaration, value.unwrap_or_default())
            })
            .unwrap_or_default(),
    };
    writeln!(
        out,
        "    {} {:width$}  {}{declaration}",
        paint(style, &format!("{word:8}")),
        d.name,
        what.join("; "),
    )
}

fn human_routine(out: &mut dyn Write, r: &RoutineDiff) -> io::Result<()> {
    writeln!(
        out,
        "    {}",
        paint(status_style(r.status), &routine_title(r))
    )?;
    for h in &r.hunks {
        if r.status == Status::Changed {
            writeln!(out, "      {}", paint(DIM, &hunk_header(h)))?;
        }
        for l in &h.lines {
            let (mark, text) = diff_line(l.tag, l.depth, &l.text);
            let style = match mark {
                '-' => REMOVED,
                '+' => ADDED,
                _ => Style::new(),
            };
            writeln!(out, "      {}", paint(style, &text))?;
        }
    }
    Ok(())
}

fn human_config(out: &mut dyn Write, c: &ConfigDiff) -> io::Result<()> {
    writeln!(
        out,
        "  {} {}",
        paint(BOLD, &c.file),
        paint(status_style(c.status), c.status.word())
    )?;
    for i in &c.instances {
        writeln!(
            out,
            "    {}",
            paint(status_style(i.status), &instance_words(i))
        )?;
    }
    Ok(())
}

fn human_builtins(out: &mut dyn Write, b: &BuiltinChanges) -> io::Result<()> {
    writeln!(
        out,
        "\n{}",
        paint(
            BOLD,
            &format!(
                "Built-ins used whose signature differs (RobotWare {} → {})",
                b.old_robotware, b.new_robotware
            )
        )
    )?;
    for c in &b.changed {
        writeln!(out, "  {} ({})", paint(BOLD, &c.name), c.kind)?;
        writeln!(out, "    {}", paint(REMOVED, &format!("- {}", c.old)))?;
        writeln!(out, "    {}", paint(ADDED, &format!("+ {}", c.new)))?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Markdown.

/// Text for a table cell: `|` escaped, line breaks made blanks.
fn cell(s: &str) -> String {
    s.replace('|', "\\|").replace(['\n', '\r'], " ")
}

/// Inline code that holds any text (a longer fence when it has backticks).
fn code(s: &str) -> String {
    let s = cell(s);
    if s.contains('`') {
        format!("`` {s} ``")
    } else {
        format!("`{s}`")
    }
}

pub fn markdown(out: &mut dyn Write, report: &Report, titles: &Titles) -> io::Result<()> {
    writeln!(
        out,
        "### rapid diff: {} → {}\n",
        code(&titles.old),
        code(&titles.new)
    )?;
    writeln!(out, "**{}**", summary_words(report))?;
    for t in &report.tasks {
        markdown_task(out, t)?;
    }
    if !report.config.is_empty() {
        writeln!(out, "\n#### Configuration\n")?;
        writeln!(out, "| File | Type | Instance | Change |")?;
        writeln!(out, "| --- | --- | --- | --- |")?;
        for c in &report.config {
            if c.instances.is_empty() {
                writeln!(out, "| {} | | | {} |", code(&c.file), c.status.word())?;
            }
            for i in &c.instances {
                let words = instance_words(i);
                let change = words.split_once(": ").map_or(words.as_str(), |(_, w)| w);
                let what = match i.label {
                    Some(l) if i.status == Status::Changed => l,
                    _ => i.status.word(),
                };
                writeln!(
                    out,
                    "| {} | {} | {} | {what}: {} |",
                    code(&c.file),
                    code(&i.type_name),
                    code(&i.instance),
                    cell(change)
                )?;
            }
        }
    }
    if let Some(b) = report.builtins.as_ref().filter(|b| !b.changed.is_empty()) {
        writeln!(
            out,
            "\n#### Built-ins used whose signature differs (RobotWare {} → {})\n",
            b.old_robotware, b.new_robotware
        )?;
        writeln!(
            out,
            "| Built-in | RobotWare {} | RobotWare {} |",
            b.old_robotware, b.new_robotware
        )?;
        writeln!(out, "| --- | --- | --- |")?;
        for c in &b.changed {
            writeln!(
                out,
                "| {} | {} | {} |",
                code(&c.name),
                code(&c.old),
                code(&c.new)
            )?;
        }
    }
    Ok(())
}

fn markdown_task(out: &mut dyn Write, t: &TaskDiff) -> io::Result<()> {
    let renamed = t
        .old_name
        .as_ref()
        .map(|o| format!(" (was {})", code(o)))
        .unwrap_or_default();
    writeln!(
        out,
        "\n#### Task {}{renamed}: {}",
        code(&t.name),
        t.status.word()
    )?;
    for m in &t.modules {
        let file = code(&file_of(m));
        if m.status != Status::Changed {
            writeln!(
                out,
                "\n- Module {} {} ({file}: {})",
                code(&m.name),
                m.status.word(),
                module_counts(m)
            )?;
            continue;
        }
        writeln!(out, "\n**Module {}** changed ({file})", code(&m.name))?;
        if let Some((o, n)) = &m.attributes {
            writeln!(out, "\nAttributes: ({}) → ({})", o.join(", "), n.join(", "))?;
        }
        let (moves, other): (Vec<&DataDiff>, Vec<&DataDiff>) = m
            .data
            .iter()
            .partition(|d| d.motion.as_ref().is_some_and(Motion::is_move));
        if !moves.is_empty() {
            writeln!(out, "\n| Moved | Distance | Rotation | Also |")?;
            writeln!(out, "| --- | ---: | ---: | --- |")?;
            for d in moves {
                let Some(mo) = &d.motion else { continue };
                let also = Motion {
                    translation_mm: None,
                    rotation_deg: None,
                    ..mo.clone()
                };
                let mut extra = vec![motion_words(&also)];
                extra.extend(frames_words(mo));
                extra.push(data_words(d));
                extra.retain(|s| !s.is_empty());
                let turned = mo.rotation_deg.filter(|a| *a > 0.0);
                let dist = mo
                    .translation_mm
                    .filter(|d| *d > 0.0 || turned.is_none())
                    .map(|x| format!("{} mm", amount(x)));
                let rot = turned.map(|x| format!("{}°", amount(x)));
                writeln!(
                    out,
                    "| {} | {} | {} | {} |",
                    code(&d.name),
                    dist.unwrap_or_default(),
                    rot.unwrap_or_default(),
                    cell(&extra.join("; "))
                )?;
            }
        }
        if !other.is_empty() {
            writeln!(out, "\n| Data | Change |")?;
            writeln!(out, "| --- | --- |")?;
            for d in other {
                let side = d.new.as_ref().or(d.old.as_ref());
                let decl = side.map_or(d.name.clone(), |s| s.declaration.clone());
                let change = match d.status {
                    Status::Changed => data_words(d),
                    s => {
                        let value = side.and_then(|s| s.value.as_ref());
                        match value {
                            Some(v) => format!("{}: {}", s.word(), code(&cut(v))),
                            None => s.word().to_owned(),
                        }
                    }
                };
                writeln!(out, "| {} | {} |", code(&decl), cell(&change))?;
            }
        }
        for r in m.types.iter().chain(&m.routines) {
            writeln!(
                out,
                "\n<details><summary><code>{}</code></summary>\n\n```diff",
                routine_title(r).replace('&', "&amp;").replace('<', "&lt;")
            )?;
            for h in &r.hunks {
                if r.status == Status::Changed {
                    writeln!(out, "{}", hunk_header(h))?;
                }
                for l in &h.lines {
                    writeln!(out, "{}", diff_line(l.tag, l.depth, &l.text).1)?;
                }
            }
            writeln!(out, "```\n\n</details>")?;
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// JSON.

pub fn json(out: &mut dyn Write, report: &Report, titles: &Titles) -> io::Result<()> {
    serde_json::to_writer_pretty(&mut *out, &super::to_json(report, titles))?;
    writeln!(out)
}

#[cfg(test)]
mod tests {
    use rapid_analyzer::diff::{FieldChange, Reach};

    use super::*;

    #[test]
    fn amounts_keep_three_decimals_at_most() {
        assert_eq!(amount(12.3), "12.3");
        assert_eq!(amount(5.0), "5");
        assert_eq!(amount(0.0504), "0.05");
        assert_eq!(amount(0.0001), "<0.001");
        assert_eq!(amount(0.0), "0");
    }

    #[test]
    fn a_motion_in_words_with_the_reach_a_robot_model_gives() {
        let m = Motion {
            translation_mm: Some(12.3),
            rotation_deg: Some(2.0),
            conf: Some(("[0,0,0,0]".into(), "[0,-1,0,0]".into())),
            external_axes: vec![FieldChange {
                path: "extax.eax_a".into(),
                old: "9E+09".into(),
                new: "100".into(),
            }],
            reach: Some(Reach {
                reachable: false,
                detail: "beyond axis 3's limit".into(),
            }),
            ..Motion::default()
        };
        assert_eq!(
            motion_words(&m),
            "12.3 mm, 2°, conf [0,0,0,0] → [0,-1,0,0], eax_a 9E+09 → 100, not reachable: beyond axis 3's limit"
        );
    }

    #[test]
    fn markdown_cells_and_code_hold_any_text() {
        assert_eq!(cell("a|b\nc"), "a\\|b c");
        assert_eq!(code("x`y"), "`` x`y ``");
    }
}
