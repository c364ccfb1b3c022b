//! The oracle of the check in parts: a project checked part by part, with
//! the trees kept or released, reports what the same project loaded as one
//! workspace reports.

use std::path::{Path, PathBuf};

use super::*;
use crate::project::{Disk, Loaded, assemble, discover, read_and_parse_with};

/// Every file's diagnostics, as text, by the file's analyzer name.
type Report = Vec<(String, Vec<String>)>;

fn render(by_path: HashMap<String, Vec<Diagnostic>>) -> Report {
    let mut out: Report = by_path
        .into_iter()
        .map(|(p, d)| (p, d.iter().map(|d| format!("{d:?}")).collect()))
        .collect();
    out.sort();
    out
}

/// The project as one workspace, as `rapid check` loaded it before parts.
fn whole(project: &Project<'_>) -> Report {
    let (read, units) = read_and_parse_with(&Disk, &project.found.files, &|| {}, false);
    let sources = Sources {
        found: Some(project.found),
        context: Some(project.context),
        extra: Some(project.extra),
    };
    let Loaded {
        mut workspace,
        asked,
        keys,
        ..
    } = assemble(&Disk, &sources, project.controller, read, units);
    let all = |_: &Path| Selection::all();
    render(check_loaded(
        &mut workspace,
        &asked,
        &keys,
        &all,
        &ProgressBar::hidden(),
    ))
}

fn in_parts(project: &Project<'_>, keep_trees: u64) -> Report {
    let all = |_: &Path| Selection::all();
    let outcomes = check_in_parts(project, &all, &ProgressBar::hidden(), keep_trees);
    let by_path = outcomes
        .into_iter()
        .filter_map(|o| match o {
            Outcome::Checked(c) => Some((unit_path(&c.file.path), c.diagnostics)),
            Outcome::Skipped(..) => None,
        })
        .collect();
    render(by_path)
}

/// Checks `dir` both ways (`extra` as the extra paths) and compares.
fn same_both_ways(dir: &Path, extra: &[PathBuf]) {
    let found = discover(&[dir.to_path_buf()]);
    let context = Discovery::default();
    let extra = discover(extra);
    let controller = rapid_analyzer::controller::ControllerOverride::default();
    let project = Project {
        env: &Disk,
        found: &found,
        context: &context,
        extra: &extra,
        controller: &controller,
    };
    let expected = whole(&project);
    assert!(!expected.is_empty());
    for keep in [u64::MAX, 0, 64 * 1024] {
        let got = in_parts(&project, keep);
        assert_eq!(got.len(), expected.len(), "keeping {keep} bytes of trees");
        for (g, e) in got.iter().zip(&expected) {
            assert_eq!(g, e, "keeping {keep} bytes of trees");
        }
    }
}

/// A folder of its own under the temporary directory, removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("rapid-parts-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        Scratch(dir)
    }

    fn write(&self, files: &[(&str, &str)]) {
        for (path, text) in files {
            let path = self.0.join(path);
            if let Some(dir) = path.parent() {
                let _ = std::fs::create_dir_all(dir);
            }
            let _ = std::fs::write(path, text);
        }
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

const SYS_CFG: &str = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n  -Name \"T_ROB1\"\n#\nCAB_TASK_MODULES:\n  -File \"HOME:/Tool.sys\" -ModName \"Tool\" -Task \"T_ROB1\"\n";
const EIO_CFG: &str = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n  -Name \"diPart\" -SignalType \"DI\"\n";

/// Backups with their HOME, SYSPAR and shared persistents, two copies of
/// one backup, a program that lists a module of another folder, versions of
/// a program side by side, a library in the extra paths, and names that
/// nothing declares.
#[test]
fn a_project_in_parts_reports_what_one_workspace_reports() {
    let dir = Scratch::new("layouts");
    let main = "MODULE MainModule\n  PERS num nShared := 1;\n  CONST num n := 4;\n  VAR num arr{n};\n  PROC main()\n    ToolOn;\n    Lib;\n    WaitDI diPart, 1;\n    arr{1} := 10 / (n - 4);\n    Missing;\n  ENDPROC\nENDMODULE\n";
    let task2 = "MODULE Other\n  PERS string nShared := \"x\";\n  PROC main()\n    Missing;\n  ENDPROC\nENDMODULE\n";
    let tool = "MODULE Tool(SYSMODULE)\n  PROC ToolOn()\n  ENDPROC\nENDMODULE\n";
    let mut files = Vec::new();
    for b in ["cell/2024-01-01_BACKUP", "cell/2024-02-01_BACKUP"] {
        files.push((
            format!("{b}/RAPID/TASK1/PROGMOD/MainModule.mod"),
            main.to_owned(),
        ));
        files.push((
            format!("{b}/RAPID/TASK2/PROGMOD/Other.mod"),
            task2.to_owned(),
        ));
        files.push((format!("{b}/HOME/Tool.sys"), tool.to_owned()));
        files.push((format!("{b}/SYSPAR/SYS.cfg"), SYS_CFG.to_owned()));
        files.push((format!("{b}/SYSPAR/EIO.cfg"), EIO_CFG.to_owned()));
    }
    let versions = [
        (
            "versions/v1.mod",
            "MODULE V1\n  PROC main()\n    helper;\n  ENDPROC\nENDMODULE\n",
        ),
        (
            "versions/v2.mod",
            "MODULE V2\n  PROC main()\n    helper;\n    Missing;\n  ENDPROC\nENDMODULE\n",
        ),
        (
            "versions/common.mod",
            "MODULE Common\n  PROC helper()\n  ENDPROC\n  PROC dup()\n  ENDPROC\nENDMODULE\n",
        ),
        (
            "versions/dup.mod",
            "MODULE Dup\n  PROC dup()\n  ENDPROC\nENDMODULE\n",
        ),
        (
            "prog/a.pgf",
            "<Program>\n  <Module>A.mod</Module>\n  <Module>../shared/B.mod</Module>\n</Program>\n",
        ),
        (
            "prog/A.mod",
            "MODULE A\n  PROC main()\n    fromB;\n  ENDPROC\nENDMODULE\n",
        ),
        (
            "shared/B.mod",
            "MODULE B\n  PROC fromB()\n    Lib;\n  ENDPROC\nENDMODULE\n",
        ),
    ];
    files.extend(
        versions
            .iter()
            .map(|(p, t)| ((*p).to_owned(), (*t).to_owned())),
    );
    let files: Vec<(&str, &str)> = files
        .iter()
        .map(|(p, t)| (p.as_str(), t.as_str()))
        .collect();
    dir.write(&files);
    let lib = Scratch::new("lib");
    lib.write(&[(
        "Lib.sys",
        "MODULE Lib(SYSMODULE)\n  PROC Lib()\n  ENDPROC\nENDMODULE\n",
    )]);
    same_both_ways(&dir.0, std::slice::from_ref(&lib.0));
}

/// The corpus of real code, in parts or as one workspace.
#[test]
fn the_corpus_in_parts_reports_what_one_workspace_reports() {
    let Some(corpus) = std::env::var_os("RAPID_CORPUS")
        .map(PathBuf::from)
        .or_else(|| Some(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpus")))
        .filter(|d| d.is_dir())
    else {
        eprintln!("no corpus of real RAPID code: skipped");
        return;
    };
    same_both_ways(&corpus, &[]);
}
