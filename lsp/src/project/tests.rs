//! The loader on a file system in memory.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use rapid_analyzer::controller::ControllerOverride;

use super::load::load;
use super::*;

/// Files in memory; a folder is any prefix of a file's path.
#[derive(Default)]
struct Memory {
    files: BTreeMap<PathBuf, Vec<u8>>,
}

impl Memory {
    fn with(files: &[(&str, &str)]) -> Memory {
        let mut m = Memory::default();
        for (path, text) in files {
            m.files
                .insert(PathBuf::from(path), text.as_bytes().to_vec());
        }
        m
    }

    fn is_folder(&self, path: &Path) -> bool {
        self.files.keys().any(|f| f != path && f.starts_with(path))
    }
}

impl Environment for Memory {
    fn kind(&self, path: &Path) -> std::io::Result<Kind> {
        match self.files.get(path) {
            Some(bytes) => Ok(Kind::File(bytes.len() as u64)),
            None if self.is_folder(path) => Ok(Kind::Folder),
            None => Err(std::io::Error::from(std::io::ErrorKind::NotFound)),
        }
    }

    fn read(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        self.files
            .get(path)
            .cloned()
            .ok_or_else(|| std::io::Error::from(std::io::ErrorKind::NotFound))
    }

    fn read_head(&self, path: &Path, buf: &mut [u8]) -> std::io::Result<usize> {
        let bytes = self.read(path)?;
        let n = bytes.len().min(buf.len());
        buf[..n].copy_from_slice(&bytes[..n]);
        Ok(n)
    }

    fn walk(&self, root: &Path, max_depth: Option<usize>, excluded: &Excluder) -> Vec<Walked> {
        let mut out = Vec::new();
        for path in self.files.keys() {
            let Ok(rest) = path.strip_prefix(root) else {
                continue;
            };
            let depth = rest.components().count();
            if max_depth.is_some_and(|d| depth > d) {
                continue;
            }
            // Left out with a folder above it, or by itself.
            let mut above = path.parent();
            let mut left_out = excluded(path, false);
            while let Some(dir) = above.filter(|d| d.starts_with(root) && *d != root) {
                left_out |= excluded(dir, true);
                above = dir.parent();
            }
            if !left_out {
                out.push(Walked::Entry(path.clone(), Kind::File(0)));
            }
        }
        out
    }

    fn name(&self, path: &Path) -> String {
        path.to_string_lossy().into_owned()
    }
}

fn nothing_excluded() -> Excluder {
    Arc::new(|_, _| false)
}

const MAIN: &str =
    "MODULE Main\n  PROC main()\n    helper;\n    SetDO doGrip, 1;\n  ENDPROC\nENDMODULE\n";
const HELPER: &str = "MODULE Helper(SYSMODULE)\n  PROC helper()\n  ENDPROC\nENDMODULE\n";
const EIO: &str = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n  -Name \"doGrip\" -SignalType \"DO\"\n";

/// The tasks of a workspace, each with its files' names, sorted.
fn tasks(loaded: &mut Loaded) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = loaded
        .workspace
        .tasks()
        .iter()
        .map(|t| {
            let mut units: Vec<String> = t.units.iter().map(|u| u.path.clone()).collect();
            units.sort();
            (t.key.clone(), units)
        })
        .collect();
    out.sort();
    out
}

fn codes(loaded: &mut Loaded, path: &str) -> Vec<&'static str> {
    loaded
        .workspace
        .diagnostics(path)
        .iter()
        .map(|d| d.rule.code)
        .collect()
}

#[test]
fn a_backup_is_grouped_by_its_task_folders_with_its_syspar() {
    let env = Memory::with(&[
        ("/b/RAPID/TASK1/PROGMOD/Main.mod", MAIN),
        ("/b/RAPID/TASK1/SYSMOD/Helper.sys", HELPER),
        ("/b/RAPID/TASK2/PROGMOD/Main.mod", MAIN),
        ("/b/SYSPAR/EIO.cfg", EIO),
        ("/b/notes.txt", "not RAPID"),
    ]);
    let found = discover_in(&env, &[PathBuf::from("/b")], nothing_excluded(), None);
    assert_eq!(found.configs, [PathBuf::from("/b/SYSPAR/EIO.cfg")]);
    assert_eq!(found.files.len(), 3);
    let sources = Sources {
        found: Some(&found),
        ..Sources::default()
    };
    let mut loaded = load(&env, &sources, &ControllerOverride::default());
    assert_eq!(
        tasks(&mut loaded),
        [
            (
                "/b/RAPID/TASK1".to_owned(),
                vec![
                    "/b/RAPID/TASK1/PROGMOD/Main.mod".to_owned(),
                    "/b/RAPID/TASK1/SYSMOD/Helper.sys".to_owned()
                ]
            ),
            (
                "/b/RAPID/TASK2".to_owned(),
                vec!["/b/RAPID/TASK2/PROGMOD/Main.mod".to_owned()]
            ),
        ]
    );
    // The signal of SYSPAR is known to both tasks; only TASK2 lacks `helper`.
    assert!(codes(&mut loaded, "/b/RAPID/TASK1/PROGMOD/Main.mod").is_empty());
    assert_eq!(
        codes(&mut loaded, "/b/RAPID/TASK2/PROGMOD/Main.mod").len(),
        1
    );
}

#[test]
fn checking_one_module_of_a_backup_loads_the_rest_of_its_task() {
    let env = Memory::with(&[
        ("/b/RAPID/TASK1/PROGMOD/Main.mod", MAIN),
        ("/b/RAPID/TASK1/SYSMOD/Helper.sys", HELPER),
        ("/b/SYSPAR/EIO.cfg", EIO),
    ]);
    let given = [PathBuf::from("/b/RAPID/TASK1/PROGMOD/Main.mod")];
    let found = discover_in(&env, &given, nothing_excluded(), None);
    let context = context::task_context(
        &env,
        &found.files,
        &found.programs,
        &given,
        nothing_excluded(),
    );
    assert_eq!(context.configs, [PathBuf::from("/b/SYSPAR/EIO.cfg")]);
    let sources = Sources {
        found: Some(&found),
        context: Some(&context),
        extra: None,
    };
    let mut loaded = load(&env, &sources, &ControllerOverride::default());
    assert!(codes(&mut loaded, "/b/RAPID/TASK1/PROGMOD/Main.mod").is_empty());
    assert_eq!(loaded.keys.iter().collect::<Vec<_>>(), ["/b/RAPID/TASK1"]);
}

#[test]
fn a_program_file_groups_the_modules_it_lists() {
    let pgf = "<?xml version=\"1.0\"?>\n<Program>\n  <Module>Main.mod</Module>\n  <Module>../lib/Helper.sys</Module>\n</Program>\n";
    let env = Memory::with(&[
        ("/p/app/App.pgf", pgf),
        ("/p/app/Main.mod", MAIN),
        ("/p/app/EIO.cfg", EIO),
        ("/p/lib/Helper.sys", HELPER),
        // RAPID text in a `.pgf` is a module, not a program.
        ("/p/other/Text.pgf", HELPER),
    ]);
    let found = discover_in(&env, &[PathBuf::from("/p")], nothing_excluded(), None);
    assert_eq!(found.programs, [PathBuf::from("/p/app/App.pgf")]);
    assert!(found.files.contains(&PathBuf::from("/p/other/Text.pgf")));
    let sources = Sources {
        found: Some(&found),
        ..Sources::default()
    };
    let mut loaded = load(&env, &sources, &ControllerOverride::default());
    let groups = tasks(&mut loaded);
    assert!(groups.contains(&(
        "/p/app/App.pgf".to_owned(),
        vec!["/p/app/Main.mod".to_owned(), "/p/lib/Helper.sys".to_owned()]
    )));
    assert!(codes(&mut loaded, "/p/app/Main.mod").is_empty());
    // Checking the program's module alone loads what the program lists
    // in another folder.
    let given = [PathBuf::from("/p/app/Main.mod")];
    let one = discover_in(&env, &given, nothing_excluded(), None);
    let context =
        context::task_context(&env, &one.files, &one.programs, &given, nothing_excluded());
    assert!(context.files.contains(&PathBuf::from("/p/lib/Helper.sys")));
    assert_eq!(context.programs, [PathBuf::from("/p/app/App.pgf")]);
    let sources = Sources {
        found: Some(&one),
        context: Some(&context),
        extra: None,
    };
    let mut loaded = load(&env, &sources, &ControllerOverride::default());
    assert!(codes(&mut loaded, "/p/app/Main.mod").is_empty());
}

#[test]
fn extra_paths_join_the_tasks_under_their_own_names() {
    let env = Memory::with(&[
        ("/p/a/Main.mod", MAIN),
        ("/p/b/Main.mod", MAIN),
        ("/shared/Helper.sys", HELPER),
        ("/shared/io/EIO.cfg", EIO),
    ]);
    let found = discover_in(&env, &[PathBuf::from("/p/a")], nothing_excluded(), None);
    let extra = discover_in(&env, &[PathBuf::from("/shared")], nothing_excluded(), None);
    let sources = Sources {
        found: Some(&found),
        context: None,
        extra: Some(&extra),
    };
    let mut loaded = load(&env, &sources, &ControllerOverride::default());
    assert!(codes(&mut loaded, "/p/a/Main.mod").is_empty());
    let task = loaded.workspace.task_of("/p/a/Main.mod");
    let mut names: Vec<&str> = task.units.iter().map(|u| u.path.as_str()).collect();
    names.sort();
    assert_eq!(names, ["/p/a/Main.mod", "/shared/Helper.sys"]);
    // Only the files asked for are checked.
    let checked: Vec<String> = loaded
        .workspace
        .checks()
        .iter()
        .map(|(_, u)| u.path.clone())
        .collect();
    assert_eq!(checked, ["/p/a/Main.mod"]);
}

#[test]
fn an_oversize_file_is_skipped_and_leaves_its_task_incomplete() {
    let mut env = Memory::with(&[("/p/Main.mod", MAIN)]);
    let big = vec![b' '; usize::try_from(MAX_FILE_BYTES).unwrap_or(0) + 1];
    env.files.insert(PathBuf::from("/p/Big.mod"), big);
    let found = discover_in(&env, &[PathBuf::from("/p")], nothing_excluded(), None);
    let sources = Sources {
        found: Some(&found),
        ..Sources::default()
    };
    let loaded = load(&env, &sources, &ControllerOverride::default());
    let big = found
        .files
        .iter()
        .position(|f| f == Path::new("/p/Big.mod"))
        .and_then(|i| loaded.read.get(i));
    assert!(matches!(big, Some(Err(Skip::TooLarge(_)))), "{big:?}");
    assert_eq!(
        big.and_then(|r| r.as_ref().err()).map(ToString::to_string),
        Some("skipped: 8.4 MB is more than the 8 MB a module may have here".to_owned())
    );
    assert!(loaded.asked.contains("/p/Main.mod"));
}

#[cfg(unix)]
#[test]
fn a_latin1_file_name_and_text_are_read() {
    use std::os::unix::ffi::OsStrExt;
    let mut env = Memory::default();
    // `Grün.mod` in Latin-1: not UTF-8, as old controllers write it.
    let name = PathBuf::from(std::ffi::OsStr::from_bytes(b"/p/Gr\xfcn.mod"));
    env.files.insert(
        name.clone(),
        b"MODULE Gruen\n  ! gr\xfcn\n  PROC main()\n  ENDPROC\nENDMODULE\n".to_vec(),
    );
    let found = discover_in(&env, &[PathBuf::from("/p")], nothing_excluded(), None);
    assert_eq!(found.files, std::slice::from_ref(&name));
    let sources = Sources {
        found: Some(&found),
        ..Sources::default()
    };
    let mut loaded = load(&env, &sources, &ControllerOverride::default());
    let file = loaded.read[0].as_ref().map_err(ToString::to_string);
    assert!(file.is_ok_and(|f| f.text.contains("grün")));
    let key = env.name(&name);
    assert_eq!(key, "/p/Gr\u{fffd}n.mod");
    assert!(codes(&mut loaded, &key).is_empty());
}

#[test]
fn paths_named_with_dots_are_one_file() {
    let name = |p: &str| DiskAsNamed.name(Path::new(p));
    assert_eq!(name("./Cell.mod"), "Cell.mod");
    assert_eq!(name("Cell.mod"), "Cell.mod");
    assert_eq!(name("./a/./b/MOC.cfg"), name("a/b/MOC.cfg"));
    assert_eq!(name("../cell/Cell.mod"), "../cell/Cell.mod");
    assert_eq!(super::plain(Path::new("./")), Path::new("."));
}

/// The cache of names answers what the disk answers, for a file, a link
/// to it, a relative path and a path that does not exist, asked twice.
#[test]
fn named_once_names_as_the_disk_does() {
    let dir = std::env::temp_dir().join(format!("rapid-named-once-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let file = dir.join("Cell.mod");
    std::fs::write(&file, "MODULE Cell\nENDMODULE\n").expect("write");
    let link = dir.join("Link.mod");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&file, &link).expect("symlink");
    let paths = [
        file.clone(),
        link,
        dir.join("Missing.mod"),
        PathBuf::from("Cell.mod"),
    ];
    let once = NamedOnce::new(&Disk);
    for _ in 0..2 {
        for p in &paths {
            assert_eq!(once.name(p), Disk.name(p), "{}", p.display());
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
