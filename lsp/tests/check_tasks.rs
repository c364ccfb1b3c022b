//! How `rapid check` groups files into tasks: `.pgf` program files, RAPID
//! text in a `.pgf`, controller backups, and the versions of a program
//! that a plain folder holds side by side.

use std::path::Path;

mod support;
use support::*;

fn check(dir: &Path) -> (Option<i32>, String) {
    let out = rapid(dir, &["check", "--format", "concise", "."]);
    let mut lines: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| l.replace('\\', "/"))
        .collect();
    lines.sort();
    (out.status.code(), lines.join("\n"))
}

const MAIN_A: &str = "MODULE A\n  PROC main()\n    TPWrite \"a\";\n  ENDPROC\nENDMODULE\n";
const MAIN_B: &str = "MODULE B\n  PROC main()\n    TPWrite \"b\";\n  ENDPROC\nENDMODULE\n";

#[test]
fn modules_of_a_plain_folder_that_clash_are_versions_checked_apart() {
    let dir = scratch("plain");
    // A and B both declare `main`: two versions of a program. Each is
    // checked with the rest of the folder (Common), never with the other.
    let a = MAIN_A.replace("TPWrite \"a\";", "TPWrite \"a\";\n    helper;");
    let b = MAIN_B.replace(
        "TPWrite \"b\";",
        "TPWrite \"b\";\n    helper;\n    onlyInA;",
    );
    let common = "MODULE Common\n  PROC helper()\n  ENDPROC\nENDMODULE\n";
    let a = a.replace("ENDMODULE", "  PROC onlyInA()\n  ENDPROC\nENDMODULE");
    write(
        &dir,
        &[("A.mod", &a), ("B.mod", &b), ("Common.mod", common)],
    );
    let (code, out) = check(&dir);
    assert_eq!(code, Some(0), "{out}");
    assert!(!out.contains("E107"), "{out}");
    // B cannot see A's routine: they are never loaded together.
    assert_eq!(out.matches("info[W101]").count(), 1, "{out}");
    assert!(out.contains("B.mod:5:5: info[W101]"), "{out}");
}

#[test]
fn a_backup_task_is_certain_and_its_clashes_are_errors() {
    let dir = scratch("backup");
    let c = MAIN_A.replace("MODULE A", "MODULE C");
    write(
        &dir,
        &[
            ("BACKUP/RAPID/TASK1/PROGMOD/A.mod", MAIN_A),
            ("BACKUP/RAPID/TASK1/PROGMOD/B.mod", MAIN_B),
            ("BACKUP/RAPID/TASK2/PROGMOD/C.mod", &c),
        ],
    );
    let (code, out) = check(&dir);
    assert_eq!(code, Some(1), "{out}");
    // TASK2's main does not clash with TASK1's.
    assert_eq!(out.matches("error[E107]").count(), 2, "{out}");
    assert!(!out.contains("C.mod"), "{out}");
}

#[test]
fn program_files_group_the_modules_they_list() {
    let dir = scratch("pgf");
    write(
        &dir,
        &[
            ("A.mod", MAIN_A),
            ("B.mod", MAIN_B),
            (
                "a.pgf",
                "<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>\n<Program>\n\t<Module>A.mod</Module>\n</Program>\n",
            ),
            (
                "b.pgf",
                "<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>\n<Program>\n\t<Module>B.mod</Module>\n</Program>\n",
            ),
        ],
    );
    let (code, out) = check(&dir);
    assert_eq!((code, out.as_str()), (Some(0), ""));
}

#[test]
fn rapid_text_in_a_pgf_file_is_checked_as_a_module() {
    let dir = scratch("pgf-rapid");
    write(
        &dir,
        &[(
            "Prog.pgf",
            "MODULE P\n  PROC main()\n    x := 1\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let (code, out) = check(&dir);
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("Prog.pgf:3:") && out.contains("error[E002]"),
        "{out}"
    );
}

#[test]
fn unresolved_names_are_errors_only_in_a_complete_backup() {
    let dir = scratch("complete");
    let main =
        "MODULE Main\n  PROC main()\n    MoveJ pHoem, v1000, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    write(
        &dir,
        &[
            (
                "B/SYSPAR/SYS.cfg",
                "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n  -Name \"T_ROB1\" -Type \"NORMAL\"\n",
            ),
            ("B/RAPID/TASK1/PROGMOD/Main.mod", main),
            // The same program outside a backup: a partial folder.
            ("loose/Main.mod", main),
        ],
    );
    let (code, out) = check(&dir);
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("B/RAPID/TASK1/PROGMOD/Main.mod:3:11: error[W101]"),
        "{out}"
    );
    assert!(out.contains("loose/Main.mod:3:11: info[W101]"), "{out}");
    // An encrypted module of the task could declare the name: a note, as
    // outside a backup (no declared name is one edit from it).
    std::fs::write(
        dir.join("B/RAPID/TASK1/SYSMOD/Secret.sys"),
        b"\xFD\x12\x34\x56\x78",
    )
    .or_else(|_| {
        std::fs::create_dir_all(dir.join("B/RAPID/TASK1/SYSMOD"))?;
        std::fs::write(
            dir.join("B/RAPID/TASK1/SYSMOD/Secret.sys"),
            b"\xFD\x12\x34\x56\x78",
        )
    })
    .expect("written");
    let (code, out) = check(&dir);
    assert_eq!(code, Some(0), "{out}");
    assert!(
        out.contains("B/RAPID/TASK1/PROGMOD/Main.mod:3:11: info[W101]"),
        "{out}"
    );
}

#[test]
fn a_name_the_task_lacks_is_one_finding_with_every_use_related() {
    let dir = scratch("once-per-task");
    let a = "MODULE A\n  PROC main()\n    Missing;\n    Missing;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC other()\n    Missing;\n    TPWrite nLost;\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("prog/A.mod", a), ("prog/B.mod", b)]);
    let (code, out) = check(&dir);
    assert_eq!(code, Some(0), "{out}");
    insta::assert_snapshot!(out, @r"
    prog/A.mod:3:5: info[W101] no routine named `Missing` is declared in this task or built in (unresolved-name)
    prog/B.mod:4:13: info[W101] no data named `nLost` is declared in this task or built in (if it is an I/O signal, give the controller's EIO.cfg) (unresolved-name)
    ");
    // The human report names the other uses, in this file and the other.
    let out = rapid(&dir, &["check", "prog"]);
    let human = String::from_utf8_lossy(&out.stdout).replace('\\', "/");
    assert!(
        human.contains("= note: used here too: 4:5, prog/B.mod:3:5"),
        "{human}"
    );
}

/// A name one file takes for a signal (`SetDO doLamp, 1`) is that signal
/// where another file of the task reads it: its use there is related to
/// the signal's one finding, not an unresolved name.
#[test]
fn a_signal_taken_in_one_file_is_not_unresolved_in_another() {
    let dir = scratch("signal-per-task");
    let a = "MODULE A\n  PROC main()\n    SetDO doLamp, 1;\n    show;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC show()\n    TPWrite \"\" \\Num:=doLamp;\n    TPWrite \"\" \\Num:=nLost;\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("prog/A.mod", a), ("prog/B.mod", b)]);
    let (code, out) = check(&dir);
    assert_eq!(code, Some(0), "{out}");
    insta::assert_snapshot!(out, @r"
    prog/A.mod:3:11: info[I103] `doLamp` is taken to be an I/O signal (`signaldo`); without the controller's EIO.cfg it cannot be checked (unconfigured-signal)
    prog/B.mod:4:22: info[W101] no data named `nLost` is declared in this task or built in (if it is an I/O signal, give the controller's EIO.cfg) (unresolved-name)
    ");
    let out = rapid(&dir, &["check", "prog"]);
    let human = String::from_utf8_lossy(&out.stdout).replace('\\', "/");
    assert!(
        human.contains("= note: used here too: prog/B.mod:3:22"),
        "{human}"
    );
    assert!(!human.contains("no data named `doLamp`"), "{human}");
}

#[test]
fn modules_of_a_controller_home_that_no_task_loads_have_notes_not_warnings() {
    let dir = scratch("home-notes");
    let spare = "MODULE Spare\n  PROC spare()\n    MoveJ pFromTask, v1000, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    // A user's folder named `home` is not a controller's HOME.
    write(
        &dir,
        &[("b/HOME/Spare.mod", spare), ("home/u/Spare.mod", spare)],
    );
    let (code, out) = check(&dir);
    assert_eq!(code, Some(0), "{out}");
    insta::assert_snapshot!(out, @r"
    b/HOME/Spare.mod:3:11: info[W101] no data named `pFromTask` is declared in this task or built in (if it is an I/O signal, give the controller's EIO.cfg) (unresolved-name)
    home/u/Spare.mod:3:11: info[W101] no data named `pFromTask` is declared in this task or built in (if it is an I/O signal, give the controller's EIO.cfg) (unresolved-name)
    ");
}
