//! `rapid fmt` end to end: the built binary on files in a scratch folder.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Output, Stdio};

mod support;
use support::*;

/// A module indented by 4 with one line typed a column in.
const UNFORMATTED: &str =
    "MODULE M\n VAR num a:=1;\n    VAR num b:=2;\n    VAR num c:=3;\nENDMODULE\n";
/// Its layout: only that line's indentation changes.
const FORMATTED: &str =
    "MODULE M\n    VAR num a:=1;\n    VAR num b:=2;\n    VAR num c:=3;\nENDMODULE\n";

fn rapid(dir: &Path, args: &[&str], stdin: Option<&[u8]>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .arg("fmt")
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the rapid binary runs");
    let mut input = child.stdin.take().expect("stdin");
    input
        .write_all(stdin.unwrap_or_default())
        .expect("stdin written");
    drop(input);
    child.wait_with_output().expect("rapid finishes")
}

#[test]
fn rewrites_files_in_place() {
    let dir = scratch("in-place");
    std::fs::write(dir.join("a.mod"), UNFORMATTED).expect("written");
    std::fs::write(dir.join("b.mod"), FORMATTED).expect("written");
    let out = rapid(&dir, &[], None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        std::fs::read_to_string(dir.join("a.mod")).expect("read"),
        FORMATTED
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("b.mod")).expect("read"),
        FORMATTED
    );
    assert_eq!(
        text(&out.stderr),
        "1 file reformatted (1 line), 1 left unchanged\n"
    );
}

#[test]
fn check_lists_files_that_would_change_and_exits_1() {
    let dir = scratch("check");
    std::fs::write(dir.join("a.mod"), UNFORMATTED).expect("written");
    std::fs::write(dir.join("b.mod"), FORMATTED).expect("written");
    // two lines typed out of place in a module indented by 4
    std::fs::write(
        dir.join("c.mod"),
        "MODULE C\n    PROC p()\n    x:=1;\n        y:=2;\n      z:=3;\n    ENDPROC\nENDMODULE\n",
    )
    .expect("written");
    let out = rapid(&dir, &["--check", "."], None);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stdout),
        format!(
            "{}: 1 line would change\n{}: 2 lines would change\n",
            Path::new(".").join("a.mod").display(),
            Path::new(".").join("c.mod").display()
        )
    );
    assert_eq!(
        text(&out.stderr),
        "2 files would be reformatted (3 lines), 1 left unchanged\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("a.mod")).expect("read"),
        UNFORMATTED
    );

    let out = rapid(&dir, &["--check", "b.mod"], None);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(text(&out.stdout), "");
}

#[test]
fn diff_prints_a_unified_diff_and_exits_1() {
    let dir = scratch("diff");
    std::fs::write(dir.join("a.mod"), UNFORMATTED).expect("written");
    let out = rapid(&dir, &["--diff", "a.mod"], None);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stdout),
        "--- a/a.mod\n+++ b/a.mod\n@@ -1,5 +1,5 @@\n MODULE M\n- VAR num a:=1;\n+    VAR num a:=1;\n     VAR num b:=2;\n     VAR num c:=3;\n ENDMODULE\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("a.mod")).expect("read"),
        UNFORMATTED
    );
}

#[test]
fn dash_reads_stdin_and_writes_stdout() {
    let dir = scratch("stdin");
    let out = rapid(&dir, &["-"], Some(UNFORMATTED.as_bytes()));
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(text(&out.stdout), FORMATTED);

    let out = rapid(&dir, &["--check", "-"], Some(UNFORMATTED.as_bytes()));
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "<stdin>: 1 line would change\n");

    // broken input goes through unchanged, with the error on stderr
    let broken = b"MODULE M\nPROC p()\nx := ;\nENDPROC\nENDMODULE\n";
    let out = rapid(&dir, &["-"], Some(broken));
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(out.stdout, broken);
    assert!(
        text(&out.stderr).starts_with("rapid: <stdin>:3:"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn encoding_and_line_endings_are_kept() {
    let dir = scratch("encoding");
    // Latin-1 ("Größe" with 0xF6 and 0xDF), CRLF, no final line break
    // (written flat, so indented by the default)
    let latin1 =
        b"MODULE M\r\n! Gr\xF6\xDFe\r\nVAR num a:=1;\r\nPROC p()\r\na:=2;\r\nENDPROC\r\nENDMODULE";
    std::fs::write(dir.join("a.mod"), latin1).expect("written");
    let out = rapid(&dir, &["a.mod"], None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        std::fs::read(dir.join("a.mod")).expect("read"),
        b"MODULE M\r\n    ! Gr\xF6\xDFe\r\n    VAR num a:=1;\r\n    PROC p()\r\n        a:=2;\r\n    ENDPROC\r\nENDMODULE"
    );
}

#[test]
fn files_with_syntax_errors_are_left_untouched() {
    let dir = scratch("syntax");
    let broken = "MODULE M\nPROC p()\nx := ;\nENDPROC\nENDMODULE\n";
    std::fs::write(dir.join("broken.mod"), broken).expect("written");
    std::fs::write(dir.join("fine.mod"), UNFORMATTED).expect("written");
    let out = rapid(&dir, &["broken.mod", "fine.mod"], None);
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(stderr.starts_with("rapid: broken.mod:3:"), "{stderr}");
    assert!(stderr.contains("syntax error, not formatted"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(dir.join("broken.mod")).expect("read"),
        broken
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("fine.mod")).expect("read"),
        FORMATTED
    );
}

#[test]
fn rapid_toml_sets_the_layout() {
    let dir = scratch("config");
    std::fs::create_dir_all(dir.join("src")).expect("folder");
    std::fs::write(
        dir.join("rapid.toml"),
        "[format]\nstyle = \"spaced\"\nindent-width = 2\n",
    )
    .expect("written");
    std::fs::write(dir.join("src/a.mod"), UNFORMATTED).expect("written");
    let out = rapid(&dir, &["src"], None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        std::fs::read_to_string(dir.join("src/a.mod")).expect("read"),
        "MODULE M\n  VAR num a := 1;\n  VAR num b := 2;\n  VAR num c := 3;\nENDMODULE\n"
    );
}

#[test]
fn a_bad_configuration_exits_2_naming_file_line_and_key() {
    let dir = scratch("bad-config");
    std::fs::write(
        dir.join("custom.toml"),
        "[format]\nindent-width = 2\ntab-width = 8\n",
    )
    .expect("written");
    std::fs::write(dir.join("a.mod"), UNFORMATTED).expect("written");
    let out = rapid(&dir, &["--config", "custom.toml", "a.mod"], None);
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(
        stderr.starts_with("rapid: custom.toml:3: unknown field `tab-width`"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("a.mod")).expect("read"),
        UNFORMATTED
    );
}

#[test]
fn excluded_files_are_left_alone() {
    let dir = scratch("exclude");
    std::fs::create_dir_all(dir.join("old")).expect("folder");
    std::fs::write(dir.join("rapid.toml"), "exclude = [\"old/**\"]\n").expect("written");
    std::fs::write(dir.join("old/a.mod"), UNFORMATTED).expect("written");
    std::fs::write(dir.join("b.mod"), UNFORMATTED).expect("written");
    let out = rapid(&dir, &["."], None);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        std::fs::read_to_string(dir.join("old/a.mod")).expect("read"),
        UNFORMATTED
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("b.mod")).expect("read"),
        FORMATTED
    );
}

#[test]
fn the_styles_that_normalise_set_the_blanks_inside_lines() {
    let dir = scratch("styles");
    let input = "MODULE M\nPROC p()\nreg1 := reg1+1; MoveL p10, v1000,z50,tool0\\WObj := wobj0;\nENDPROC\nENDMODULE\n";
    for (style, line) in [
        (
            "tight",
            "reg1:=reg1+1;\n        MoveL p10,v1000,z50,tool0\\WObj:=wobj0;",
        ),
        (
            "spaced",
            "reg1 := reg1 + 1;\n        MoveL p10, v1000, z50, tool0\\WObj:=wobj0;",
        ),
    ] {
        std::fs::write(
            dir.join("rapid.toml"),
            format!("[format]\nstyle = \"{style}\"\n"),
        )
        .expect("written");
        let out = rapid(&dir, &["-"], Some(input.as_bytes()));
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        assert_eq!(
            text(&out.stdout),
            format!("MODULE M\n    PROC p()\n        {line}\n    ENDPROC\nENDMODULE\n")
        );
    }
}
