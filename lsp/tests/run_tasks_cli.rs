//! `rapid run` of a controller's tasks end to end: a backup's every task
//! together (the semistatic one first, every line named by its task),
//! `--task` for one, a deadlock reported with each task's line; a program
//! the controller would not load does not run; `rapid test` runs tests on
//! the controller `rapid check` checks.

mod support;

use std::path::Path;

use support::{rapid, scratch, text, write};

/// (exit code, stdout, stderr) of `rapid ARGS` in `dir`.
fn run(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let out = rapid(dir, args);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

const SYS_CFG: &str = "SYS:CFG_1.0:6:0::
#
CAB_TASKS:

      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask

      -Name \"T_ROB2\" -Type \"NORMAL\" -MotionTask

      -Name \"T_WATCH\" -Type \"SEMISTATIC\" -Entry \"watch\"
";

const ROB1: &str = "MODULE Main1
  PERS num nDone := 0;
  PERS tasks tlRobots{2} := [[\"T_ROB1\"], [\"T_ROB2\"]];
  VAR syncident syncStart;
  PROC main()
    TPWrite \"ready\";
    WaitSyncTask syncStart, tlRobots;
    Incr nDone;
    TPWrite GetTaskName() + \" done\";
  ENDPROC
ENDMODULE
";

const ROB2: &str = "MODULE Main2
  PERS num nDone := 0;
  PERS tasks tlRobots{2} := [[\"T_ROB1\"], [\"T_ROB2\"]];
  VAR syncident syncStart;
  PROC main()
    WaitTime 1;
    WaitSyncTask syncStart, tlRobots;
    WaitUntil nDone = 1;
    Incr nDone;
    TPWrite \"done \"\\Num:=nDone;
  ENDPROC
ENDMODULE
";

const WATCH: &str = "MODULE Watch
  PROC watch()
    TPWrite \"watching\";
    WHILE TRUE DO
      WaitTime 0.5;
    ENDWHILE
  ENDPROC
ENDMODULE
";

fn backup(name: &str) -> support::Scratch {
    let dir = scratch(name);
    write(
        &dir,
        &[
            ("cell/SYSPAR/SYS.cfg", SYS_CFG),
            ("cell/RAPID/TASK1/PROGMOD/Main1.mod", ROB1),
            ("cell/RAPID/TASK2/PROGMOD/Main2.mod", ROB2),
            ("cell/RAPID/TASK3/PROGMOD/Watch.mod", WATCH),
        ],
    );
    dir
}

#[test]
fn a_backup_runs_every_task_together() {
    let dir = backup("run-tasks");
    let (code, out, err) = run(&dir, &["run", "cell"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        out,
        "[T_WATCH] watching\n[T_ROB1] ready\n[T_ROB1] T_ROB1 done\n[T_ROB2] done 2\n"
    );
    assert_eq!(err, "");
    // The same program, the same lines, every run.
    assert_eq!(run(&dir, &["run", "cell"]).1, out);
}

#[test]
fn a_backup_without_its_syspar_takes_the_task_names_backinfo_then_rapid_toml_give() {
    // Neither: the names the program uses are given to the numbered
    // folders (`T_ROBn` to `TASKn`), and the run says so.
    let dir = scratch("run-tasks-unnamed");
    write(
        &dir,
        &[
            ("cell/RAPID/TASK1/PROGMOD/Main1.mod", ROB1),
            ("cell/RAPID/TASK2/PROGMOD/Main2.mod", ROB2),
        ],
    );
    let (code, out, err) = run(&dir, &["run", "cell"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        out,
        "[T_ROB1] ready\n[T_ROB1] T_ROB1 done\n[T_ROB2] done 2\n"
    );
    assert!(
        err.contains("note: the backup does not say what its tasks are called (no SYS.cfg, no BACKINFO): TASK2 is taken to be T_ROB2, as RobotWare calls the task of robot 2"),
        "{err}"
    );
    // A name no folder can be given stays no task's: the run says where
    // names come from.
    let dir = scratch("run-tasks-unnamed-other");
    write(
        &dir,
        &[
            (
                "cell/RAPID/TASK1/PROGMOD/Main1.mod",
                &ROB1.replace("T_ROB2", "T_PAINT"),
            ),
            (
                "cell/RAPID/TASK2/PROGMOD/Main2.mod",
                &ROB2.replace("T_ROB2", "T_PAINT"),
            ),
        ],
    );
    let (code, _, err) = run(&dir, &["run", "cell"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("there is no task T_PAINT in the controller (its tasks: T_ROB1, TASK2)"),
        "{err}"
    );
    assert!(
        err.contains("= help: the tasks have their folders' names"),
        "{err}"
    );
    let sources = [
        (
            "run-tasks-backinfo",
            "cell/BACKINFO/backinfo.txt",
            ">>SYSTEM_ID:\nCell\n\n>>TASK1: (T_ROB1,,)\n\n>>TASK2: (T_ROB2,,)\n",
        ),
        (
            "run-tasks-toml",
            "rapid.toml",
            "[controller]\ntasks = [\"T_ROB1\", \"T_ROB2\"]\n",
        ),
    ];
    for (name, file, text) in sources {
        let dir = scratch(name);
        write(
            &dir,
            &[
                (file, text),
                ("cell/RAPID/TASK1/PROGMOD/Main1.mod", ROB1),
                ("cell/RAPID/TASK2/PROGMOD/Main2.mod", ROB2),
            ],
        );
        let (code, out, err) = run(&dir, &["run", "cell"]);
        assert_eq!(code, Some(0), "{file}: {err}");
        assert_eq!(
            out, "[T_ROB1] ready\n[T_ROB1] T_ROB1 done\n[T_ROB2] done 2\n",
            "{file}"
        );
        let (code, out, _) = run(&dir, &["check", "cell"]);
        assert_eq!(code, Some(0), "{file}: {out}");
        if file == "rapid.toml" {
            write(&dir, &[(file, "[controller]\ntasks = [\"T ROB1\"]\n")]);
            let (code, _, err) = run(&dir, &["run", "cell"]);
            assert_eq!(code, Some(2), "{err}");
            assert!(err.contains("`T ROB1` is not a task name"), "{err}");
        }
    }
}

#[test]
fn a_folder_of_dated_backups_asks_for_one_and_each_runs() {
    let dir = backup("run-dated-backups");
    let main = |day: &str| {
        format!("MODULE Main\n  PROC main()\n    TPWrite \"{day}\";\n  ENDPROC\nENDMODULE\n")
    };
    write(
        &dir,
        &[
            (
                "repo/2026-01-05/RAPID/TASK1/PROGMOD/Main.mod",
                &main("monday"),
            ),
            (
                "repo/2026-01-06/RAPID/TASK1/PROGMOD/Main.mod",
                &main("tuesday"),
            ),
        ],
    );
    let (code, out, err) = run(&dir, &["run", "repo"]);
    assert_eq!((code, out.as_str()), (Some(2), ""), "{err}");
    assert!(
        err.contains("the folder holds 2 controller backups (2 tasks); name the backup to run (e.g. repo/2026-01-05, repo/2026-01-06)"),
        "{err}"
    );
    let (code, out, err) = run(&dir, &["run", "repo/2026-01-06"]);
    assert_eq!((code, out.as_str()), (Some(0), "tuesday\n"), "{err}");
}

#[test]
fn one_task_runs_alone_with_task() {
    let dir = backup("run-one-task");
    let (code, out, err) = run(
        &dir,
        &["run", "cell", "--task", "T_WATCH", "--max-time", "2"],
    );
    assert_eq!(code, Some(1), "{err}");
    assert_eq!(out, "watching\n");
    assert!(err.contains("simulated time budget (2 s)"), "{err}");
}

#[test]
fn a_deadlock_names_each_task_and_its_line() {
    let dir = backup("run-deadlock");
    // T_ROB2 never arrives at the rendezvous: it waits for a flag first;
    // the watcher has ended (while it runs, it might set the flag: the
    // tasks wait until the time budget runs out).
    let rob2 = ROB2.replace("    WaitTime 1;\n", "    WaitUntil nDone = 5;\n");
    write(&dir, &[("cell/RAPID/TASK2/PROGMOD/Main2.mod", &rob2)]);
    let (code, _, err) = run(&dir, &["run", "cell", "--max-time", "5"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains(
            "[T_ROB1] error: the simulated time budget (5 s) ran out (WaitSyncTask syncstart waits)"
        ),
        "{err}"
    );
    let watch = WATCH.replace("WHILE TRUE DO", "WHILE FALSE DO");
    write(&dir, &[("cell/RAPID/TASK3/PROGMOD/Watch.mod", &watch)]);
    let (code, out, err) = run(&dir, &["run", "cell"]);
    assert_eq!(code, Some(1), "{err}");
    assert_eq!(out, "[T_WATCH] watching\n[T_ROB1] ready\n");
    assert!(
        err.contains(
            "[T_ROB1] error: deadlock: WaitSyncTask syncstart waits forever: every task waits"
        ),
        "{err}"
    );
    assert!(err.contains("Main1.mod:7:"), "{err}");
    assert!(err.contains("[T_ROB2] error: deadlock"), "{err}");
    assert!(err.contains("Main2.mod:6:"), "{err}");
}

#[test]
fn a_program_with_a_syntax_error_does_not_run() {
    let dir = scratch("run-syntax");
    write(
        &dir,
        &[(
            "m.mod",
            "MODULE m\n  PROC main()\n    TPWrite \"hi\";\n    p;\n  ENDPROC\n  PROC p(\\num a | \\switch none)\n    TPWrite \"p\";\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let (code, out, err) = run(&dir, &["run", "m.mod"]);
    assert_eq!(code, Some(2), "{err}");
    assert_eq!(out, "");
    assert!(err.contains("would not load the program"), "{err}");
    assert!(err.contains("m.mod:6:17: error[E001]"), "{err}");
}

#[test]
fn tests_run_on_the_controller_rapid_check_checks() {
    let dir = backup("test-controller");
    // The task id comes from SYS.cfg: a task rebuilt without its
    // controller's names would not know it.
    write(
        &dir,
        &[(
            "cell/RAPID/TASK1/PROGMOD/Here_test.mod",
            "MODULE Here_test\n  PROC knows_its_task()\n    VAR robtarget p;\n    p := CRobT(\\TaskRef:=T_ROB1Id);\n    AssertEqualStr GetTaskName(), \"T_ROB1\";\n  ENDPROC\nENDMODULE\n",
        )],
    );
    let (code, out, err) = run(&dir, &["test", "cell/RAPID/TASK1"]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(out.contains("PASS  Here_test.knows_its_task"), "{out}");
}
