//! `rapid run` of programs whose repository keeps a module away from the
//! task that uses it: the module is taken from another task of the backup
//! or from the repository around the program (a folder with `.git` or
//! `rapid.toml`), with a note; without one, the run stops where the name
//! is used. A signal one task takes from its use (no `EIO.cfg`) is every
//! task's.

mod support;

use support::{rapid_out, scratch, write};

const MAIN: &str = "MODULE Main1
  PROC main()
    Greet;
    TPWrite \"done\";
  ENDPROC
ENDMODULE
";

const LIB: &str = "MODULE Lib(SYSMODULE)
  PROC Greet()
    TPWrite \"hello from \" + GetTaskName();
  ENDPROC
ENDMODULE
";

#[test]
fn a_backup_task_takes_the_module_it_lacks_from_another_task() {
    let dir = scratch("run-incomplete-backup");
    let gantry = "MODULE Gantry_Main
  PROC main()
    TPWrite \"gantry\";
  ENDPROC
ENDMODULE
";
    let watch = "MODULE Watch
  PROC main()
    VAR jointtarget j;
    WaitTime 1;
    j := CJointT(\\TaskName:=\"T_Gantry\");
    j := CJointT(\\TaskRef:=T_GantryId);
    TPWrite \"read the gantry\";
  ENDPROC
ENDMODULE
";
    write(
        &dir,
        &[
            ("cell/RAPID/TASK1/PROGMOD/Main1.mod", MAIN),
            ("cell/RAPID/TASK2/SYSMOD/Lib.sys", LIB),
            ("cell/RAPID/TASK2/PROGMOD/Gantry_Main.mod", gantry),
            ("cell/RAPID/TASK3/PROGMOD/Watch.mod", watch),
        ],
    );
    let (code, out, err) = rapid_out(&dir, &["run", "cell"]);
    assert_eq!(code, Some(0), "{err}");
    let mut lines: Vec<&str> = out.lines().collect();
    lines.sort_unstable();
    assert_eq!(
        lines,
        [
            "[TASK1] done",
            "[TASK1] hello from TASK1",
            "[TASK3] read the gantry",
            "[T_Gantry] gantry",
        ]
    );
    assert!(
        err.contains("note: task TASK1 lacks a module that declares `Greet`: simulated with module Lib of cell/RAPID/TASK2/SYSMOD/Lib.sys, the repository's nearest that declares it"),
        "{err}"
    );
    assert!(
        err.contains("TASK2 is taken to be T_Gantry, its modules are named for it"),
        "{err}"
    );
    // Listing what a run would stop at says what it takes too.
    let (code, out, err) = rapid_out(&dir, &["run", "cell", "--list-unsupported"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(out, "0 calls the simulation does not support\n");
    assert!(
        err.contains("lacks a module that declares `Greet`"),
        "{err}"
    );
}

#[test]
fn a_program_takes_the_module_it_lacks_from_its_repository() {
    let dir = scratch("run-incomplete-repository");
    write(
        &dir,
        &[
            ("repo/programs/cell/Main1.mod", MAIN),
            ("repo/library/Lib.sys", LIB),
        ],
    );
    // Not a repository: the module is nowhere the run looks.
    let (code, _, err) = rapid_out(&dir, &["run", "repo/programs/cell"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("`Greet` is declared nowhere"), "{err}");
    // A git repository, or a project with its rapid.toml.
    for (file, text) in [(".git/HEAD", "ref: refs/heads/main\n"), ("rapid.toml", "")] {
        let root = scratch("run-incomplete-repository-marked");
        write(
            &root,
            &[
                ("repo/programs/cell/Main1.mod", MAIN),
                ("repo/library/Lib.sys", LIB),
                (&format!("repo/{file}"), text),
            ],
        );
        let (code, out, err) = rapid_out(&root, &["run", "repo/programs/cell"]);
        assert_eq!(code, Some(0), "{file}: {err}");
        assert_eq!(out, "hello from T_ROB1\ndone\n");
        assert!(
            err.contains("simulated with module Lib of repo/library/Lib.sys"),
            "{err}"
        );
    }
}

#[test]
fn a_signal_one_task_takes_from_its_use_is_every_task_s() {
    let dir = scratch("run-incomplete-signal");
    write(
        &dir,
        &[
            (
                "cell/RAPID/TASK1/PROGMOD/A.mod",
                "MODULE A\n  PROC main()\n    TPWrite \"a \"\\Num:=GInput(giPart);\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "cell/RAPID/TASK2/PROGMOD/B.mod",
                "MODULE B\n  PROC main()\n    VAR num n;\n    WaitTime 0.5;\n    n := giPart;\n    TPWrite \"b \"\\Num:=n;\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let (code, out, err) = rapid_out(&dir, &["run", "cell", "--set", "giPart=5"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(out, "[TASK1] a 5\n[TASK2] b 5\n");
}
