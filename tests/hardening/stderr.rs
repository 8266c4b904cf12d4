//! A standard error that cannot be written (a closed pipe, a full disk) never turns a warning
//! into a panic: the messages are dropped and the command does its work.

use super::*;

/// A warning on stderr (a clamped thread count) and a picture to write.
fn warning_args<'a>(f: &'a Path, out: &'a Path) -> Vec<&'a str> {
    vec![
        "render",
        s(f),
        "-o",
        s(out),
        "--threads",
        "100000",
        "--progress",
        "plain",
    ]
}

#[test]
fn a_closed_stderr_pipe_drops_the_messages() {
    let dir = common::temp_dir("hard-stderr-pipe");
    let f = small_flame(&dir, "20");
    let out = dir.join("w.png");
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let status = Command::new(bin())
        .args(warning_args(&f, &out))
        .env("UGNIS_PROGRESS_SECONDS", "0")
        .stderr(writer)
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(0));
    assert!(image::open(&out).is_ok());
    // An error message that cannot be written: still exit 1, not a panic's 101.
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let status = Command::new(bin())
        .args(["render", s(&dir.join("missing.flame")), "-o", s(&out)])
        .stderr(writer)
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(1));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn a_full_stderr_file_drops_the_messages() {
    // stderr is a file that may not grow (a file size limit of 0 blocks, as a full disk):
    // every write to it fails. The picture goes to a pipe-free place: standard output is not
    // used, and the PNG is refused too (the limit is for every file), so the command fails
    // with status 1 and without a panic.
    let dir = common::temp_dir("hard-stderr-full");
    let f = small_flame(&dir, "20");
    let out = dir.join("w.png");
    let err_file = dir.join("err.txt");
    let args: Vec<String> = warning_args(&f, &out)
        .iter()
        .map(|a| format!("'{a}'"))
        .collect();
    let cmd = format!(
        "trap '' XFSZ; ulimit -f 0 && exec '{}' {} 2>'{}'",
        bin(),
        args.join(" "),
        s(&err_file)
    );
    let status = Command::new("sh")
        .arg("-c")
        .arg(cmd)
        .env("UGNIS_PROGRESS_SECONDS", "0")
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(1));
    assert_eq!(std::fs::metadata(&err_file).unwrap().len(), 0);
    assert_eq!(listing(&dir), ["err.txt", "q.flame"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_command_line_writes_stderr_only_through_its_quiet_macro() {
    // `eprintln!` panics when stderr cannot be written; the command line uses `stderr!`.
    let src = common::root().join("src");
    let mut files = vec![src.join("main.rs")];
    for e in std::fs::read_dir(src.join("cli")).unwrap() {
        files.push(e.unwrap().path());
    }
    for p in files {
        let text = std::fs::read_to_string(&p).unwrap();
        for (i, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            assert!(
                !code.contains("eprintln!") && !code.contains("eprint!("),
                "{}:{}: use stderr! instead: {line}",
                p.display(),
                i + 1
            );
        }
    }
}
