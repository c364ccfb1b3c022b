//! `rapid check` on input that is not a tidy folder of modules: each case
//! gets a clear message, no panic, and the other files are still checked.

use std::path::Path;
use std::process::Output;

mod support;
use support::*;

/// `rapid check` with `args` in `dir`.
fn check(dir: &Path, args: &[&str]) -> Output {
    rapid(dir, &[&["check"], args].concat())
}

fn show(out: &Output) -> String {
    format!(
        "exit {:?}\n--- stdout\n{}--- stderr\n{}",
        out.status.code(),
        text(&out.stdout),
        text(&out.stderr)
    )
}

/// A module with one known finding, so "the rest is still checked" shows.
const GOOD: &str = "MODULE Good\n    PROC main()\n        Missing;\n    ENDPROC\nENDMODULE\n";

/// Checks `dir` and asserts the good module was checked, no panic
/// happened, and stderr says `message` about the bad entry.
fn assert_rest_checked(dir: &Path, message: &str, code: i32) -> Output {
    let out = check(dir, &["--format", "concise"]);
    let stdout = text(&out.stdout);
    let stderr = text(&out.stderr);
    assert!(!stderr.contains("panicked"), "{}", show(&out));
    assert!(
        stdout.contains("Good.mod:3:9: info[W101]"),
        "{}",
        show(&out)
    );
    assert!(stderr.contains(message), "{}", show(&out));
    assert_eq!(out.status.code(), Some(code), "{}", show(&out));
    out
}

#[test]
fn binary_and_encrypted_modules_are_skipped() {
    let dir = scratch("binary");
    std::fs::write(dir.join("Good.mod"), GOOD).expect("written");
    std::fs::write(dir.join("Blob.mod"), b"MODULE\0\x01\x02").expect("written");
    std::fs::write(dir.join("Secret.sys"), b"\xFD\x12\x34\x56\x78").expect("written");
    assert_rest_checked(&dir, "Blob.mod: skipped: a binary file", 0);
    assert_rest_checked(&dir, "Secret.sys: skipped: an encrypted module", 0);
    // They are listed as skipped in machine formats too.
    let out = check(&dir, &["--format", "junit"]);
    assert!(text(&out.stdout).contains("<skipped message=\"skipped: a binary file"));
    let out = check(&dir, &["--format", "sarif"]);
    let log: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let notes = log["runs"][0]["invocations"][0]["toolExecutionNotifications"]
        .as_array()
        .expect("notifications");
    assert_eq!(notes.len(), 2, "{log}");
}

#[test]
fn a_broken_symbolic_link_is_an_io_error() {
    let dir = scratch("broken-link");
    std::fs::write(dir.join("Good.mod"), GOOD).expect("written");
    std::os::unix::fs::symlink(dir.join("gone.mod"), dir.join("Dangling.mod")).expect("link");
    // A dangling link that is no module is nobody's business.
    std::os::unix::fs::symlink(dir.join("gone.txt"), dir.join("notes.txt")).expect("link");
    let out = assert_rest_checked(&dir, "Dangling.mod: a broken symbolic link", 2);
    assert!(!text(&out.stderr).contains("notes.txt"), "{}", show(&out));
}

#[test]
fn an_unreadable_file_is_an_io_error() {
    let dir = scratch("unreadable");
    std::fs::write(dir.join("Good.mod"), GOOD).expect("written");
    let locked = dir.join("Locked.mod");
    std::fs::write(&locked, GOOD).expect("written");
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o000)).expect("chmod");
    if std::fs::read(&locked).is_ok() {
        // Running as root: permissions do not stop reading. A path that is
        // missing is the unreadable file then.
        let out = check(&dir, &["--format", "concise", "Good.mod", "Missing.mod"]);
        assert_eq!(out.status.code(), Some(2), "{}", show(&out));
        assert!(text(&out.stdout).contains("Good.mod:3:9"), "{}", show(&out));
        assert!(
            text(&out.stderr).contains("Missing.mod: No such file"),
            "{}",
            show(&out)
        );
    } else {
        assert_rest_checked(&dir, "Locked.mod: cannot read it: Permission denied", 2);
    }
}

#[test]
fn an_empty_folder_says_so() {
    let dir = scratch("empty");
    std::fs::create_dir_all(dir.join("nothing/here")).expect("folder");
    let out = check(&dir, &["nothing"]);
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("no RAPID files found in nothing"),
        "{}",
        show(&out)
    );
    assert!(
        text(&out.stdout).contains("Checked 0 files"),
        "{}",
        show(&out)
    );
}

#[test]
fn a_folder_cycle_through_links_is_walked_once() {
    let dir = scratch("cycle");
    std::fs::create_dir_all(dir.join("a/b")).expect("folder");
    std::fs::write(dir.join("a/b/Good.mod"), GOOD).expect("written");
    std::os::unix::fs::symlink(dir.join("a"), dir.join("a/b/loop")).expect("link");
    let out = assert_rest_checked(&dir, "a link leads back to a folder above it", 0);
    assert_eq!(
        text(&out.stdout).matches("Good.mod").count(),
        1,
        "{}",
        show(&out)
    );
}

#[test]
fn a_50_mb_file_is_handled() {
    let dir = scratch("huge");
    std::fs::write(dir.join("Good.mod"), GOOD).expect("written");
    // 50 MB of declarations: generated, not read from anywhere.
    let mut huge = String::from("MODULE Huge\n");
    let line = "    CONST num c := 1; ! a constant with a comment to make the line long enough\n";
    while huge.len() < 50_000_000 {
        huge.push_str(line);
    }
    huge.push_str("ENDMODULE\n");
    std::fs::write(dir.join("Huge.mod"), &huge).expect("written");
    let out = check(&dir, &["--format", "concise", "--select", "E001"]);
    assert!(!text(&out.stderr).contains("panicked"), "{}", show(&out));
    assert!(
        text(&out.stderr).contains("Huge.mod: skipped: 50.0 MB is more than the 8 MB"),
        "{}",
        show(&out)
    );
    assert!(text(&out.stdout).is_empty(), "{}", show(&out));
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
}

#[test]
fn fifos_and_devices_named_like_modules_are_skipped_with_a_word() {
    let dir = scratch("fifo");
    std::fs::write(dir.join("Good.mod"), GOOD).expect("written");
    let fifo = |name: &str| {
        let made = std::process::Command::new("mkfifo")
            .arg(dir.join(name))
            .status()
            .expect("mkfifo runs");
        assert!(made.success(), "mkfifo {name}");
    };
    fifo("Pipe.mod");
    fifo("EIO.cfg");
    std::os::unix::fs::symlink("/dev/null", dir.join("Null.sys")).expect("link");
    // Reading any of them would block for ever or read nothing: each is
    // named, the rest is checked, and the run is not held up.
    let out = assert_rest_checked(
        &dir,
        "Pipe.mod: skipped: a FIFO (named pipe), not a file",
        0,
    );
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("EIO.cfg: skipped: a FIFO"),
        "{}",
        show(&out)
    );
    assert!(
        stderr.contains("Null.sys: skipped: a character device"),
        "{}",
        show(&out)
    );
    // Named on the command line, too.
    let out = check(&dir, &["Pipe.mod", "Good.mod", "--format", "concise"]);
    assert!(
        text(&out.stderr).contains("Pipe.mod: skipped: a FIFO"),
        "{}",
        show(&out)
    );
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
}

#[test]
fn folders_named_in_any_script_are_checked() {
    // The fourth byte of `josé` and of `机器人程序` is inside a character
    // (task grouping once sliced folder names there).
    for folder in [
        "home/josé/robot",
        "机器人程序/RAPID/TASK1/PROGMOD",
        "Müller Straße",
    ] {
        let dir = scratch("non-ascii");
        let at = dir.join(folder);
        std::fs::create_dir_all(&at).expect("folder");
        std::fs::write(at.join("Good.mod"), GOOD).expect("written");
        let out = check(&dir, &["--format", "concise", folder]);
        assert!(!text(&out.stderr).contains("panicked"), "{}", show(&out));
        assert!(
            text(&out.stdout).contains("Good.mod:3:9: info[W101]"),
            "{}",
            show(&out)
        );
        assert_eq!(out.status.code(), Some(0), "{}", show(&out));
    }
}

/// `rapid check` with `args` in `dir`, killed after `limit` (a generous
/// bound: the output is what the test looks at).
fn check_within(dir: &Path, args: &[&str], limit: std::time::Duration) -> Output {
    let child = std::process::Command::new(env!("CARGO_BIN_EXE_rapid"))
        .arg("check")
        .args(args)
        .current_dir(dir)
        .env_remove("CI")
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the rapid binary runs");
    let id = child.id();
    let (tx, rx) = std::sync::mpsc::channel::<()>();
    let watchdog = std::thread::spawn(move || {
        if rx.recv_timeout(limit).is_err() {
            let _ = std::process::Command::new("kill")
                .args(["-9", &id.to_string()])
                .status();
        }
    });
    let out = child.wait_with_output().expect("output");
    let _ = tx.send(());
    let _ = watchdog.join();
    out
}

#[test]
fn many_findings_on_one_long_line_cost_each_a_bounded_share() {
    // 10,000 duplicate declarations on one line of 100 KB: each finding's
    // column and snippet once read the whole line before it, and the human
    // report printed the whole line with each (1 GB).
    let dir = scratch("long-line");
    let n = 10_000;
    let module = format!("MODULE D\n{}\nENDMODULE\n", "VAR num a;".repeat(n));
    std::fs::write(dir.join("D.mod"), &module).expect("written");
    let limit = std::time::Duration::from_secs(120);
    let out = check_within(&dir, &["--format", "concise"], limit);
    let stdout = text(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{}", show(&out));
    assert_eq!(stdout.matches("[E106]").count(), n - 1);
    let last = format!("D.mod:2:{}: error[E106]", (n - 1) * 10 + 9);
    assert!(stdout.contains(&last), "{last}");
    let out = check_within(&dir, &["--format", "human"], limit);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout).matches("[duplicate-declaration]").count(),
        n - 1
    );
    assert!(
        out.stdout.len() < n * 1200,
        "{} bytes of report for {n} findings",
        out.stdout.len()
    );
    let out = check_within(&dir, &["--format", "sarif"], limit);
    let log: serde_json::Value = serde_json::from_slice(&out.stdout).expect("SARIF");
    let results = log["runs"][0]["results"].as_array().map_or(0, Vec::len);
    assert_eq!(results, n - 1);
}
