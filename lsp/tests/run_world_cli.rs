//! `rapid run` with the controller's world: the operator's answers
//! (`--answers`, `--answer`), signals no EIO.cfg declares, sockets on the
//! host's loopback (`--socket-map`): the built binary, its output and its
//! exit codes.

mod support;

use support::{rapid, scratch, show, text, write};

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
fn what_the_pendant_shows_is_traced_on_stderr_apart_from_the_lines() {
    let dir = scratch("run-pendant-trace");
    let module = "MODULE Cell
  PROC main()
    TPErase;
    TPWrite \"ready\";
    TPShow TP_LATEST;
    UIMsgWrite \"Cell\", \"Loading\";
  ENDPROC
ENDMODULE
";
    write(&dir, &[("Cell.mod", module)]);
    let out = rapid(&dir, &["run", "Cell.mod"]);
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nready\nCell: Loading\n--- stderr\n\
         [TPErase at Cell.mod:3] the operator window is cleared\n\
         [TPShow at Cell.mod:5] the pendant shows the window shown before\n"
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
    assert!(
        show(&out).contains("--answer #1: \"soon\" is not a delay in seconds"),
        "{}",
        show(&out)
    );
    // An answer of a file is named by its file and line.
    write(&dir, &[("answers.txt", "# the cell\nStart\n\n99\n")]);
    let out = rapid(&dir, &["run", "Cell.mod", "--answers", "answers.txt"]);
    assert_eq!(out.status.code(), Some(1), "{}", show(&out));
    assert!(
        show(&out).contains("the answer \"99\" (answers.txt:4) to UINumEntry"),
        "{}",
        show(&out)
    );
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

/// `rapid ARGS` in `dir`, running while the test talks to it.
fn run_in_background(dir: &std::path::Path, args: &[&str]) -> std::process::Child {
    std::process::Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(args)
        .current_dir(dir)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("rapid runs")
}

/// A free port of the loopback interface.
fn free_port() -> u16 {
    let l = std::net::TcpListener::bind("127.0.0.1:0").expect("a port");
    l.local_addr().expect("an address").port()
}

const SERVER: &str = "MODULE Server
  VAR socketdev server;
  VAR socketdev client;
  VAR string request;
  VAR string address;
  VAR num n;
  PROC main()
    SocketCreate server;
    SocketBind server, \"192.168.125.1\", 1025;
    SocketListen server;
    TPWrite \"listening \"\\Bool:=SocketGetStatus(server) = SOCKET_LISTENING;
    SocketAccept server, client \\ClientAddress:=address \\Time:=20;
    TPWrite \"client from \" + address;
    SocketReceive client \\Str:=request \\NoRecBytes:=n \\Time:=20;
    TPWrite \"request \" + request + \" (\" + NumToStr(n, 0) + \" bytes)\";
    SocketSend client \\Str:=\"pose 1 2 3\";
    SocketReceive client \\Str:=request \\Time:=20;
  ERROR
    IF ERRNO = ERR_SOCK_CLOSED THEN
      TPWrite \"the client left\";
      SocketClose client;
      SocketClose server;
      TPWrite \"closed \"\\Bool:=SocketGetStatus(server) = SOCKET_CLOSED;
      RETURN;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
";

#[test]
fn a_client_in_the_harness_talks_to_a_rapid_server() {
    use std::io::{Read, Write};
    let dir = scratch("run-socket-server");
    write(&dir, &[("Server.mod", SERVER)]);
    let port = free_port();
    let map = format!("192.168.125.1:1025=127.0.0.1:{port}");
    let child = run_in_background(&dir, &["run", "Server.mod", "--socket-map", &map]);
    let started = std::time::Instant::now();
    let mut stream = loop {
        match std::net::TcpStream::connect(("127.0.0.1", port)) {
            Ok(s) => break s,
            Err(e) if started.elapsed().as_secs() < 20 => {
                let _ = e;
                std::thread::sleep(std::time::Duration::from_millis(50));
            }
            Err(e) => panic!("the RAPID server never listened: {e}"),
        }
    };
    stream.write_all(b"where").expect("sent");
    let mut reply = [0u8; 10];
    stream.read_exact(&mut reply).expect("a reply");
    assert_eq!(&reply, b"pose 1 2 3");
    drop(stream);
    let out = child.wait_with_output().expect("rapid ends");
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nlistening TRUE\nclient from 127.0.0.1\nrequest where (5 bytes)\nthe client left\nclosed TRUE\n--- stderr\n"
    );
}

const CLIENT: &str = "MODULE Client
  VAR socketdev sock;
  VAR rawbytes raw;
  VAR byte data{4};
  VAR num value;
  VAR string text;
  PROC main()
    SocketCreate sock;
    SocketConnect sock, \"10.0.0.5\", 3000 \\Time:=20;
    TPWrite \"connected \"\\Bool:=SocketGetStatus(sock) = SOCKET_CONNECTED;
    PackRawBytes 258, raw, 1 \\IntX:=UINT;
    PackRawBytes \"ok\", raw, RawBytesLen(raw) + 1 \\ASCII;
    SocketSend sock \\RawData:=raw;
    SocketReceive sock \\Data:=data \\ReadNoOfBytes:=4 \\Time:=20;
    TPWrite \"bytes \"\\Num:=data{1} + data{2} + data{3} + data{4};
    SocketReceive sock \\RawData:=raw \\ReadNoOfBytes:=4 \\Time:=20;
    UnpackRawBytes raw \\Network, 1, value \\IntX:=DINT;
    TPWrite \"value \"\\Num:=value;
    SocketReceive sock \\Str:=text \\Time:=1;
  ERROR
    TPWrite \"timed out \"\\Bool:=ERRNO = ERR_SOCK_TIMEOUT;
    SocketClose sock;
  ENDPROC
ENDMODULE
";

#[test]
fn a_rapid_client_talks_to_a_server_in_the_harness() {
    use std::io::{Read, Write};
    let dir = scratch("run-socket-client");
    write(&dir, &[("Client.mod", CLIENT)]);
    let listener = std::net::TcpListener::bind("127.0.0.1:0").expect("a port");
    let port = listener.local_addr().expect("an address").port();
    let server = std::thread::spawn(move || {
        let (mut s, _) = listener.accept().expect("the robot connects");
        let mut got = [0u8; 4];
        s.read_exact(&mut got).expect("a message");
        s.write_all(&[1, 2, 3, 4]).expect("sent");
        s.write_all(&(-7i32).to_be_bytes()).expect("sent");
        // Keep the connection open past the robot's 1 s receive.
        std::thread::sleep(std::time::Duration::from_millis(1500));
        got
    });
    let map = format!("10.0.0.5:3000=127.0.0.1:{port}");
    let out = rapid(&dir, &["run", "Client.mod", "--socket-map", &map]);
    assert_eq!(server.join().expect("the server"), [2, 1, b'o', b'k']);
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nconnected TRUE\nbytes 10\nvalue -7\ntimed out TRUE\n--- stderr\n"
    );
}

const POLLING: &str = "MODULE Poller
  VAR socketdev sock;
  VAR string text;
  VAR num polls;
  PROC main()
    SocketCreate sock;
    SocketConnect sock, \"10.0.0.7\", 3001 \\Time:=20;
    TPWrite \"waiting \"\\Num:=SocketPeek(sock);
    WHILE SocketPeek(sock) < 5 DO
      WaitTime 0.1;
      Incr polls;
    ENDWHILE
    TPWrite \"ready \"\\Num:=SocketPeek(sock);
    TPWrite \"polled \"\\Bool:=polls >= 3;
    SocketReceive sock \\Str:=text;
    TPWrite \"got \" + text;
    TPWrite \"then \"\\Num:=SocketPeek(sock);
    WHILE TRUE DO
      WaitTime 0.1;
      polls := SocketPeek(sock);
    ENDWHILE
  ERROR
    TPWrite \"closed \"\\Bool:=ERRNO = ERR_SOCK_CLOSED;
  ENDPROC
ENDMODULE
";

/// `SocketPeek` counts what waits to be read without reading it; while a
/// socket is open to a real peer, the simulated clock keeps pace with
/// real time, so a polling loop of `WaitTime 0.1` waits for the peer (a
/// second of simulated time would not be enough otherwise).
#[test]
fn a_rapid_client_polls_with_socket_peek_in_real_time() {
    use std::io::Write;
    let dir = scratch("run-socket-peek");
    write(&dir, &[("Poller.mod", POLLING)]);
    let listener = std::net::TcpListener::bind("127.0.0.1:0").expect("a port");
    let port = listener.local_addr().expect("an address").port();
    let server = std::thread::spawn(move || {
        let (mut s, _) = listener.accept().expect("the robot connects");
        std::thread::sleep(std::time::Duration::from_millis(400));
        s.write_all(b"hel").expect("sent");
        std::thread::sleep(std::time::Duration::from_millis(300));
        s.write_all(b"lo").expect("sent");
        std::thread::sleep(std::time::Duration::from_millis(250));
    });
    let map = format!("10.0.0.7:3001=127.0.0.1:{port}");
    let out = rapid(
        &dir,
        &[
            "run",
            "Poller.mod",
            "--socket-map",
            &map,
            "--max-time",
            "20",
        ],
    );
    server.join().expect("the server");
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nwaiting 0\nready 5\npolled TRUE\ngot hello\nthen 0\nclosed TRUE\n--- stderr\n"
    );
}

#[test]
fn list_unsupported_names_each_call_a_run_would_stop_at() {
    let dir = scratch("run-list-unsupported");
    write(
        &dir,
        &[(
            "Cell.mod",
            "MODULE Cell
  VAR egmident egm;
  PROC main()
    TPWrite \"start\";
    IF FALSE THEN
      EGMGetId egm;
    ENDIF
    vision;
  ENDPROC
  PROC vision()
    EGMReset egm;
  ENDPROC
ENDMODULE
",
        )],
    );
    let out = rapid(&dir, &["run", "Cell.mod", "--list-unsupported"]);
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nCell.mod:6:7: EGMGetId\nCell.mod:11:5: EGMReset\n2 calls the simulation does not support\n--- stderr\n"
    );
}

#[test]
fn a_backup_s_configuration_and_backinfo_answer_read_cfg_data_and_get_sys_info() {
    let dir = scratch("run-cfg-data");
    let module = "MODULE Calib
  VAR num x;
  PROC main()
    ReadCfgData \"/MOC/SINGLE/TRACK\", \"base_frame_pos_x\", x;
    TPWrite \"x \"\\Num:=x;
    WriteCfgData \"/MOC/SINGLE/TRACK\", \"base_frame_pos_x\", 2.5;
    ReadCfgData \"/MOC/SINGLE/TRACK\", \"base_frame_pos_x\", x;
    TPWrite \"x \"\\Num:=x;
    TPWrite GetSysInfo(\\SystemName) + \" \" + GetSysInfo(\\SWVersion) + \" \" + GetSysInfo(\\SerialNo) + \" \" + GetSysInfo(\\LanIp);
    ReadCfgData \"/MOC/SINGLE/BELT\", \"base_frame_pos_x\", x;
  ENDPROC
ENDMODULE
";
    write(
        &dir,
        &[
            ("Cell/RAPID/TASK1/PROGMOD/Calib.mod", module),
            (
                "Cell/BACKINFO/backinfo.txt",
                ">>SYSTEM_ID:\nCell_7\n\n>>PRODUCTS_ID:\nRobotWare Version: 6.13.02.00\n",
            ),
            (
                "Cell/SYSPAR/MOC.cfg",
                "MOC:CFG_1.0:6:0::\n#\nSINGLE:\n\n      -name \"TRACK\" -base_frame_pos_x 1.25\n#\nROBOT_SERIAL_NUMBER:\n\n      -name \"rob1\" -robot_serial_number_high_part \"120\" -robot_serial_number_low_part 501234\n",
            ),
            (
                "Cell/SYSPAR/SYS.cfg",
                "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n",
            ),
        ],
    );
    let out = rapid(&dir, &["run", "Cell"]);
    let shown = show(&out);
    assert!(
        shown.starts_with(
            "exit 1\n--- stdout\nx 1.25\nx 2.5\nCell_7 6.13.02.00 120-501234 VC\n--- stderr\n"
        ),
        "{shown}"
    );
    assert!(shown.contains("ERR_CFG_NOTFND"), "{shown}");
    // Only the run's memory changed.
    let moc = std::fs::read_to_string(dir.join("Cell/SYSPAR/MOC.cfg")).expect("MOC.cfg");
    assert!(moc.contains("-base_frame_pos_x 1.25"));
}

/// File instructions see the controller's `HOME:`: a backup's `HOME`
/// folder, copied into the run's sandbox, so a program reads its
/// configuration files and writes its logs without changing the backup;
/// `--sandbox DIR` is used as it is.
#[test]
fn a_backup_s_home_files_are_what_home_holds_and_stay_unchanged() {
    let dir = scratch("run-home");
    let module = "MODULE Cfg
  VAR iodev f;
  VAR string line;
  PROC main()
    Open \"HOME:/cell/config.txt\", f \\Read;
    line := ReadStr(f);
    Close f;
    TPWrite \"config \" + line;
    Open \"HOME:/cell/config.txt\", f \\Append;
    Write f, \"changed\";
    Close f;
    Open \"HOME:/log.txt\", f \\Write;
    Write f, \"ran\";
    Close f;
    TPWrite \"logged\";
  ENDPROC
ENDMODULE
";
    write(
        &dir,
        &[
            ("Cell/RAPID/TASK1/PROGMOD/Cfg.mod", module),
            ("Cell/HOME/cell/config.txt", "speed=250\n"),
        ],
    );
    let out = rapid(&dir, &["run", "Cell"]);
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nconfig speed=250\nlogged\n--- stderr\n"
    );
    let config = std::fs::read_to_string(dir.join("Cell/HOME/cell/config.txt")).expect("kept");
    assert_eq!(config, "speed=250\n");
    assert!(!dir.join("Cell/HOME/log.txt").exists());
    // A sandbox given is the HOME: the file is not there.
    let empty = dir.join("empty");
    std::fs::create_dir_all(&empty).expect("a folder");
    let out = rapid(
        &dir,
        &["run", "Cell", "--sandbox", &empty.to_string_lossy()],
    );
    assert!(
        show(&out).contains("HOME:/cell/config.txt"),
        "{}",
        show(&out)
    );
}

/// A backup's program loads its part programs from `HOME` one at a time
/// (`Load`, a late-bound call, `UnLoad`): they declare the same names and
/// are not in the program when it starts, as on the controller.
#[test]
fn a_backup_loads_its_part_programs_from_home_one_at_a_time() {
    let dir = scratch("run-load-parts");
    let main = "MODULE Main
  VAR string file;
  PROC main()
    Load \\Dynamic, \"HOME:/Parts/Part1.mod\";
    %\"RunPart\"%;
    UnLoad \"HOME:/Parts/Part1.mod\";
    FOR i FROM 2 TO 3 DO
      file := \"Part\" + NumToStr(i, 0) + \".mod\";
      Load \\Dynamic, \"HOME:/Parts\" \\File:=file;
      %\"RunPart\"%;
      UnLoad \"HOME:/Parts\" \\File:=file;
    ENDFOR
    TPWrite \"loaded \"\\Bool:=ModExist(\"Part3\");
  ENDPROC
ENDMODULE
";
    let part = |n: u32| {
        format!(
            "MODULE Part{n}\n  CONST num nHoles := {n};\n  PROC RunPart()\n    TPWrite \"part {n}: \"\\Num:=nHoles;\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (p1, p2, p3) = (part(1), part(2), part(3));
    write(
        &dir,
        &[
            ("Cell/RAPID/TASK1/PROGMOD/Main.mod", main),
            ("Cell/HOME/Parts/Part1.mod", &p1),
            ("Cell/HOME/Parts/Part2.mod", &p2),
            ("Cell/HOME/Parts/Part3.mod", &p3),
        ],
    );
    let out = rapid(&dir, &["run", "Cell"]);
    let shown = show(&out);
    assert!(
        shown.starts_with(
            "exit 0\n--- stdout\npart 1: 1\npart 2: 2\npart 3: 3\nloaded FALSE\n--- stderr\n"
        ),
        "{shown}"
    );
    let out = rapid(&dir, &["check", "Cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", show(&out));
}

/// A backup runs its tasks together, whatever its `HOME` holds: the
/// modules there (a service program with a `main` of its own) are files
/// the program may load, not tasks.
#[test]
fn a_backup_runs_its_tasks_whatever_its_home_holds() {
    let dir = scratch("run-backup-home");
    let task = |n: u32| {
        format!("MODULE Main{n}\n  PROC main()\n    TPWrite \"task {n}\";\n  ENDPROC\nENDMODULE\n")
    };
    let (t1, t2) = (task(1), task(2));
    write(
        &dir,
        &[
            ("Cell/RAPID/TASK1/PROGMOD/Main1.mod", &t1),
            ("Cell/RAPID/TASK2/PROGMOD/Main2.mod", &t2),
            (
                "Cell/HOME/Service/Service.mod",
                "MODULE Service\n  PROC main()\n    TPWrite \"service\";\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let out = rapid(&dir, &["run", "Cell"]);
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\n[TASK1] task 1\n[TASK2] task 2\n--- stderr\n"
    );
    // The service program runs when named, by its folder or its module.
    for named in ["Cell/HOME/Service", "Cell/HOME/Service/Service.mod"] {
        let out = rapid(&dir, &["run", named]);
        assert_eq!(show(&out), "exit 0\n--- stdout\nservice\n--- stderr\n");
    }
}

/// A procedure the program calls by name, from a module it loads first
/// (`Load`, no late binding): the controller links the call when the
/// module comes; a call it still cannot link stops the run at its line.
#[test]
fn a_call_by_name_links_to_the_module_a_load_brought() {
    let dir = scratch("run-load-link");
    write(
        &dir,
        &[
            (
                "Cell/RAPID/TASK1/PROGMOD/Main.mod",
                "MODULE Main\n  PROC main()\n    Load \\Dynamic, \"HOME:/Part.mod\";\n    PartProc 2;\n    UnLoad \"HOME:/Part.mod\";\n    PartProc 3;\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "Cell/HOME/Part.mod",
                "MODULE Part\n  PROC PartProc(num n)\n    TPWrite \"part \"\\Num:=n;\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let out = rapid(&dir, &["run", "Cell"]);
    let shown = show(&out);
    assert!(
        shown.starts_with("exit 1\n--- stdout\npart 2\n--- stderr\n"),
        "{shown}"
    );
    assert!(
        shown.contains("`PartProc` is declared nowhere") && shown.contains("Main.mod:6:5"),
        "{shown}"
    );
}

/// A HOME module the program also names directly (a library loaded by
/// `SYS.cfg`, its `Load` guarded by `ModExist`) is in the program from
/// the start: without it the program would not load.
#[test]
fn a_home_module_the_program_names_directly_is_there_from_the_start() {
    let dir = scratch("run-load-library");
    write(
        &dir,
        &[
            (
                "Cell/RAPID/TASK1/PROGMOD/Main.mod",
                "MODULE Main\n  PROC main()\n    IF NOT ModExist(\"Lib\") Load \"HOME:/Lib.sys\";\n    LibHello;\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "Cell/HOME/Lib.sys",
                "MODULE Lib (SYSMODULE)\n  PROC LibHello()\n    TPWrite \"hello from lib\";\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "Cell/SYSPAR/SYS.cfg",
                "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n",
            ),
        ],
    );
    let out = rapid(&dir, &["run", "Cell"]);
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nhello from lib\n--- stderr\n"
    );
}

#[test]
fn a_project_folder_keeps_its_controller_s_home_inside() {
    let dir = scratch("run-project-home");
    write(
        &dir,
        &[
            (
                "cell/Main.mod",
                "MODULE Main\n  PROC main()\n    Load \\Dynamic, \"HOME:/Part.mod\";\n    %\"RunPart\"%;\n    UnLoad \"HOME:/Part.mod\";\n  ENDPROC\nENDMODULE\n",
            ),
            (
                "cell/HOME/Part.mod",
                "MODULE Part\n  PROC RunPart()\n    TPWrite \"part\";\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    // The folder, a module of it, and the folder as the current one.
    for (at, path) in [("", "cell"), ("", "cell/Main.mod"), ("cell", "Main.mod")] {
        let out = rapid(&dir.join(at), &["run", path]);
        assert_eq!(
            (out.status.code(), text(&out.stdout)),
            (Some(0), "part\n".to_owned()),
            "{path}: {}",
            text(&out.stderr)
        );
    }
}

#[test]
fn rapid_toml_names_the_controller_get_sys_info_describes() {
    let dir = scratch("run-sys-info-toml");
    let module = "MODULE Who
  PROC main()
    TPWrite GetSysInfo(\\SystemName) + \" \" + GetSysInfo(\\SerialNo) + \" \" + GetSysInfo(\\LanIp) + \" \" + GetSysInfo(\\CtrlId) + \" \" + GetSysInfo(\\CtrlLang) + \" \" + GetSysInfo(\\SWVersion);
  ENDPROC
ENDMODULE
";
    write(&dir, &[("cell/Who.mod", module)]);
    let out = rapid(&dir, &["run", "cell/Who.mod"]);
    assert_eq!(show(&out), "exit 0\n--- stdout\n  VC  en \n--- stderr\n");
    write(
        &dir,
        &[(
            "rapid.toml",
            "[controller]\nrobotware = \"6.15\"\nsystem-name = \"Cell_7\"\nserial-number = \"1600-505123\"\nlan-ip = \"192.168.125.1\"\ncontroller-id = \"Line 3\"\nlanguage = \"de\"\n",
        )],
    );
    let out = rapid(&dir, &["run", "cell/Who.mod"]);
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nCell_7 1600-505123 192.168.125.1 Line 3 de 6.15\n--- stderr\n"
    );
}

const UDP_SERVER: &str = "MODULE Udp
  VAR socketdev udp;
  VAR string msg;
  VAR string peer;
  VAR num peer_port;
  VAR num n;
  PROC main()
    SocketCreate udp \\UDP;
    SocketBind udp, \"192.168.125.1\", 6510;
    TPWrite \"bound \"\\Bool:=SocketGetStatus(udp) = SOCKET_BOUND;
    SocketReceiveFrom udp \\Str:=msg \\NoRecBytes:=n, peer, peer_port \\Time:=20;
    TPWrite \"got \" + msg + \" (\" + NumToStr(n, 0) + \" bytes) from \" + peer;
    SocketSendTo udp, peer, peer_port \\Str:=\"ack \" + msg;
    SocketReceiveFrom udp \\Str:=msg, peer, peer_port \\Time:=1;
  ERROR
    TPWrite \"timed out \"\\Bool:=ERRNO = ERR_SOCK_TIMEOUT;
    SocketClose udp;
  ENDPROC
ENDMODULE
";

#[test]
fn a_client_in_the_harness_exchanges_datagrams_with_a_rapid_udp_socket() {
    let dir = scratch("run-socket-udp");
    write(&dir, &[("Udp.mod", UDP_SERVER)]);
    let port = {
        let s = std::net::UdpSocket::bind("127.0.0.1:0").expect("a port");
        s.local_addr().expect("an address").port()
    };
    let map = format!("192.168.125.1:6510=127.0.0.1:{port}");
    let child = run_in_background(&dir, &["run", "Udp.mod", "--socket-map", &map]);
    let client = std::net::UdpSocket::bind("127.0.0.1:0").expect("a client socket");
    client
        .set_read_timeout(Some(std::time::Duration::from_millis(200)))
        .expect("a timeout");
    let started = std::time::Instant::now();
    let mut reply = [0u8; 64];
    // Datagrams sent before the RAPID socket is bound are lost: send until
    // the answer comes.
    let n = loop {
        client.send_to(b"hello", ("127.0.0.1", port)).expect("sent");
        match client.recv_from(&mut reply) {
            Ok((n, _)) => break n,
            Err(e) if started.elapsed().as_secs() < 20 => {
                let _ = e;
            }
            Err(e) => panic!("no answer from the RAPID socket: {e}"),
        }
    };
    assert_eq!(&reply[..n], b"ack hello");
    let out = child.wait_with_output().expect("rapid ends");
    assert_eq!(
        show(&out),
        "exit 0\n--- stdout\nbound TRUE\ngot hello (5 bytes) from 127.0.0.1\ntimed out TRUE\n--- stderr\n"
    );
}

/// A MultiMove backup keeps its tasks in `RAPID/TASKn`: each moves the
/// robot of its `SYS.cfg` mechanical unit group (`MOC.cfg`), not a robot
/// found from the folder's name.
#[test]
fn each_multimove_task_moves_the_robot_of_its_unit_group() {
    let dir = scratch("run-multimove");
    let module = |name: &str, x: u32| {
        format!(
            "MODULE {name}\n  PROC main()\n    MoveJ [[{x},0,500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n  ENDPROC\nENDMODULE\n"
        )
    };
    write(
        &dir,
        &[
            ("Cell/RAPID/TASK1/PROGMOD/A.mod", &module("A", 500)),
            ("Cell/RAPID/TASK2/PROGMOD/B.mod", &module("B", 1200)),
            (
                "Cell/SYSPAR/SYS.cfg",
                "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask -UseMechanicalUnitGroup \"rob1\"\n\n      -Name \"T_ROB2\" -Type \"NORMAL\" -MotionTask -UseMechanicalUnitGroup \"rob2\"\n",
            ),
            (
                "Cell/SYSPAR/MOC.cfg",
                "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT_GROUP:\n\n      -name \"rob1\" -robot \"ROB_1\"\n\n      -name \"rob2\" -robot \"ROB_2\"\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n\n      -name \"ROB_2\" -use_robot_type \"ROB2_2600_1.85_12_03\"\n",
            ),
        ],
    );
    let out = rapid(&dir, &["run", "Cell", "--report"]);
    let shown = show(&out);
    assert!(shown.starts_with("exit 0\n"), "{shown}");
    assert!(!shown.contains("no robot is named"), "{shown}");
    // x 1200 is out of the IRB 120's reach, not of the IRB 2600's; each
    // task's closest axis is measured against its own robot's limits (the
    // IRB 120's axis 5 turns to 120 degrees, the IRB 2600's axis 3 to 75).
    assert!(
        shown.contains(
            "T_ROB1: closest to a limit: axis 5 at 98.70 degrees, 21.30 from its limit 120.00"
        ),
        "{shown}"
    );
    assert!(
        shown.contains(
            "T_ROB2: closest to a limit: axis 3 at 21.55 degrees, 53.45 from its limit 75.00"
        ),
        "{shown}"
    );
}
