//! `rapid run` with the controller's world: the operator's answers
//! (`--answers`, `--answer`), signals no EIO.cfg declares, sockets on the
//! host's loopback (`--socket-map`): the built binary, its output and its
//! exit codes.

mod support;

use support::{rapid, scratch, show, write};

const DIALOG: &str = "MODULE Cell
  VAR num key;
  VAR num parts;
  PROC main()
    TPReadFK key, \"Start the cell?\", \"Start\", \"Skip\", stEmpty, stEmpty, stEmpty;
    TPWrite \"key \"\\Num:=key;
    parts := UINumEntry(\\Header:=\"Batch\" \\Message:=\"Parts\" \\MinValue:=1 \\MaxValue:=50);
    TPWrite \"parts \"\\Num:=parts;
  ENDPROC
ENDMODULE
";

#[test]
fn the_operator_answers_from_a_file_then_from_the_options() {
    let dir = scratch("run-answers");
    write(
        &dir,
        &[("Cell.mod", DIALOG), ("answers.txt", "# the cell\nSkip\n")],
    );
    let out = rapid(
        &dir,
        &[
            "run",
            "Cell.mod",
            "--answers",
            "answers.txt",
            "--answer",
            "12",
        ],
    );
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nkey 2\nparts 12\n--- stderr\n"
    );
}

#[test]
fn in_a_pipe_without_answers_the_run_stops_waiting_for_the_operator() {
    let dir = scratch("run-no-operator");
    write(&dir, &[("Cell.mod", DIALOG)]);
    let out = rapid(&dir, &["run", "Cell.mod", "--answer", "1"]);
    insta::assert_snapshot!(show(&out));
}

#[test]
fn an_answer_that_does_not_fit_the_question_is_named() {
    let dir = scratch("run-bad-answer");
    write(&dir, &[("Cell.mod", DIALOG)]);
    let out = rapid(
        &dir,
        &["run", "Cell.mod", "--answer", "Go", "--answer", "1"],
    );
    insta::assert_snapshot!(show(&out));
    let out = rapid(&dir, &["run", "Cell.mod", "--answer", "@soon 1"]);
    assert_eq!(out.status.code(), Some(2), "{}", show(&out));
    assert!(show(&out).contains("delay in seconds"), "{}", show(&out));
}

#[test]
fn signals_no_eio_cfg_declares_are_taken_from_their_use_with_a_note() {
    let dir = scratch("run-taken-signals");
    write(
        &dir,
        &[(
            "Gripper.mod",
            "MODULE Gripper
  PROC main()
    WaitDI part_present, 1;
    SetDO grip_close, 1;
    TPWrite \"closed \"\\Num:=DOutput(grip_close);
    IF part_present = 1 SetAO conveyor_speed, 2.5;
    TPWrite \"speed \"\\Num:=AOutput(conveyor_speed);
  ENDPROC
ENDMODULE
",
        )],
    );
    let out = rapid(&dir, &["run", "Gripper.mod", "--set", "part_present=1@0.5"]);
    insta::assert_snapshot!(show(&out));
}
