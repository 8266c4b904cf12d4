//! The output rule: saves never replace a device, a pipe, a directory, an input of the command
//! or another of its outputs, and never write through a symbolic link.

use super::*;

/// `mknod` a character device (the null device's numbers) in `dir`; None (with the reason
/// printed) where device nodes cannot be made.
#[cfg(unix)]
fn device_node(dir: &Path, name: &str) -> Option<PathBuf> {
    let p = dir.join(name);
    match Command::new("mknod").arg(&p).args(["c", "1", "3"]).output() {
        Ok(o) if o.status.success() => Some(p),
        Ok(o) => {
            println!(
                "skipping the device node case: mknod failed ({})",
                String::from_utf8_lossy(&o.stderr).trim()
            );
            None
        }
        Err(e) => {
            println!("skipping the device node case: no mknod ({e})");
            None
        }
    }
}

#[cfg(unix)]
fn fifo(dir: &Path, name: &str) -> PathBuf {
    let p = dir.join(name);
    assert!(Command::new("mkfifo").arg(&p).status().unwrap().success());
    p
}

#[cfg(unix)]
fn is_fifo(p: &Path) -> bool {
    use std::os::unix::fs::FileTypeExt;
    std::fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_fifo())
}

#[cfg(unix)]
#[test]
fn saves_refuse_devices_pipes_and_directories() {
    let dir = common::temp_dir("hard-out-kind");
    let f = small_flame(&dir, "1");
    let png = dir.join("out.png");
    // A named pipe as the state, the view, the scene image, the converted gradient.
    let pipe = fifo(&dir, "p.ugs");
    let (code, _, err) = ugnis(&["render", s(&f), "-o", s(&png), "--save-state", s(&pipe)]);
    assert_clean_error(code, &err, &["cannot write", "p.ugs", "named pipe"]);
    assert!(is_fifo(&pipe) && !png.exists());
    let view = fifo(&dir, "v.esc");
    let (code, _, err) = ugnis(&[
        "escape",
        "julia",
        "--size",
        "16x16",
        "-o",
        s(&png),
        "--save-view",
        s(&view),
    ]);
    assert_clean_error(code, &err, &["v.esc", "named pipe"]);
    assert!(is_fifo(&view));
    let map = dir.join("g.map");
    std::fs::write(&map, "0 0 0\n255 0 0\n").unwrap();
    let ugr = fifo(&dir, "g.ugr");
    let (code, _, err) = ugnis(&["convert", s(&map), s(&ugr)]);
    assert_clean_error(code, &err, &["g.ugr", "named pipe"]);
    assert!(is_fifo(&ugr));
    // A link to a pipe is refused as the pipe is.
    let link = dir.join("link.png");
    std::os::unix::fs::symlink(dir.join("p.ugs"), &link).unwrap();
    let (code, _, err) = ugnis(&["render", s(&f), "-o", s(&link)]);
    assert_clean_error(code, &err, &["link to a named pipe"]);
    // A device node (we make our own; never one under /dev).
    if let Some(dev) = device_node(&dir, "dev.png") {
        let (code, _, err) = ugnis(&["render", s(&f), "-o", s(&dev)]);
        assert_clean_error(code, &err, &["dev.png", "is a device"]);
        use std::os::unix::fs::FileTypeExt;
        let t = std::fs::symlink_metadata(&dev).unwrap().file_type();
        assert!(t.is_char_device(), "the device node was replaced");
    }
    // Library saves (the editor's) follow the same rule.
    let img = image::DynamicImage::new_rgb8(2, 2);
    let e = ugnis::io::png::save(&pipe, &img, &Default::default()).unwrap_err();
    assert!(e.to_string().contains("named pipe"), "{e}");
    assert!(is_fifo(&pipe));
    // Nothing else was written: no temporary file, no output.
    let mut names = listing(&dir);
    names.retain(|n| !["dev.png"].contains(&n.as_str()));
    assert_eq!(
        names,
        ["g.map", "g.ugr", "link.png", "p.ugs", "q.flame", "v.esc"]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_output_is_never_an_input_or_another_output() {
    let dir = common::temp_dir("hard-out-same");
    let f = small_flame(&dir, "1");
    let flame_text = std::fs::read(&f).unwrap();
    // `render in.flame --save-state in.flame` (the image goes to in.png).
    let (code, _, err) = ugnis(&["render", s(&f), "--save-state", s(&f)]);
    assert_clean_error(code, &err, &["q.flame", "both an input and an output"]);
    // The same file by another spelling.
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    let dotted = dir.join("sub/../q.flame");
    let (code, _, err) = ugnis(&[
        "render",
        s(&f),
        "-o",
        s(&dir.join("a.png")),
        "--save-state",
        s(&dotted),
    ]);
    assert_clean_error(code, &err, &["is the input"]);
    assert_eq!(std::fs::read(&f).unwrap(), flame_text);
    // One name for two outputs.
    let same = dir.join("same.png");
    let (code, _, err) = ugnis(&["render", s(&f), "-o", s(&same), "--save-state", s(&same)]);
    assert_clean_error(code, &err, &["same.png", "named for two outputs"]);
    // merge: a part as the merged state; the image as the state.
    let part = dir.join("p0.ugs");
    let (code, _, err) = ugnis(&["render", s(&f), "--part", "0/2", "--save-state", s(&part)]);
    assert_eq!(code, 0, "{err}");
    let part_bytes = std::fs::read(&part).unwrap();
    let (code, _, err) = ugnis(&["merge", s(&part), "--save-state", s(&part)]);
    assert_clean_error(code, &err, &["p0.ugs", "both an input and an output"]);
    let (code, _, err) = ugnis(&["merge", s(&part), "-o", s(&same), "--save-state", s(&same)]);
    assert_clean_error(code, &err, &["named for two outputs"]);
    assert_eq!(std::fs::read(&part).unwrap(), part_bytes);
    // convert onto itself, escape over its own view.
    let map = dir.join("g.map");
    std::fs::write(&map, "0 0 0\n255 0 0\n").unwrap();
    let (code, _, err) = ugnis(&["convert", s(&map), s(&map)]);
    assert_clean_error(code, &err, &["both an input and an output"]);
    #[cfg(unix)]
    {
        // A hard link and a symbolic link to an input are the input.
        let hard = dir.join("hard.map");
        std::fs::hard_link(&map, &hard).unwrap();
        let (code, _, err) = ugnis(&["convert", s(&map), s(&hard)]);
        assert_clean_error(code, &err, &["hard.map", "is the input", "g.map"]);
        let soft = dir.join("soft.ugs");
        std::os::unix::fs::symlink(&f, &soft).unwrap();
        let (code, _, err) = ugnis(&[
            "render",
            s(&f),
            "-o",
            s(&dir.join("b.png")),
            "--save-state",
            s(&soft),
        ]);
        assert_clean_error(code, &err, &["soft.ugs", "is the input"]);
    }
    assert_eq!(std::fs::read(&f).unwrap(), flame_text);
    // A scene texture's file is an input of the scene.
    let tex = dir.join("tex.png");
    write_png(&tex, 4, 4, [200, 10, 10]);
    let sc = dir.join("t.toml");
    std::fs::write(
        &sc,
        "[[texture]]\nname = \"t\"\nkind = \"image\"\nfile = \"tex.png\"\n\
         [[object]]\nkind = \"jug\"\ntexture = \"t\"\n",
    )
    .unwrap();
    let tex_bytes = std::fs::read(&tex).unwrap();
    let (code, _, err) = ugnis(&["scene", s(&sc), "-o", s(&tex), "--size", "32x32"]);
    assert_clean_error(code, &err, &["tex.png", "input"]);
    assert_eq!(std::fs::read(&tex).unwrap(), tex_bytes);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_at_the_target_is_replaced_not_followed() {
    let dir = common::temp_dir("hard-out-link");
    let f = small_flame(&dir, "1");
    let victim = dir.join("victim.png");
    std::fs::write(&victim, b"precious").unwrap();
    let link = dir.join("out.png");
    std::os::unix::fs::symlink(&victim, &link).unwrap();
    let (code, _, err) = ugnis(&["render", s(&f), "-o", s(&link)]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
    let m = std::fs::symlink_metadata(&link).unwrap();
    assert!(m.is_file(), "the link itself is replaced by the picture");
    assert!(image::open(&link).is_ok());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_failed_batch_leaves_no_thumbnail_and_old_outputs_stay() {
    let dir = common::temp_dir("hard-out-batch");
    let thumbs = dir.join("t");
    let fla = dir.join("b.fla");
    // The batch file cannot be written (its name is a directory): no thumbnail is left.
    std::fs::create_dir_all(&fla).unwrap();
    let (code, _, err) = ugnis(&[
        "random",
        "--count",
        "3",
        "--seed",
        "1",
        "--size",
        "16x16",
        "--quality",
        "1",
        "--thumbs",
        s(&thumbs),
        "-o",
        s(&fla),
    ]);
    assert_clean_error(code, &err, &["b.fla"]);
    assert_eq!(listing(&thumbs), Vec::<String>::new());
    std::fs::remove_dir_all(&fla).unwrap();
    // A thumbnail name taken by a pipe is refused before anything is generated.
    #[cfg(unix)]
    {
        let p = thumbs.join("random-002.png");
        assert!(Command::new("mkfifo").arg(&p).status().unwrap().success());
        let (code, _, err) = ugnis(&[
            "random",
            "--count",
            "3",
            "--seed",
            "1",
            "--thumbs",
            s(&thumbs),
            "-o",
            s(&fla),
        ]);
        assert_clean_error(code, &err, &["random-002.png", "named pipe"]);
        assert!(!fla.exists());
        std::fs::remove_file(&p).unwrap();
    }
    // A batch whose last save fails (a file size limit, as on a full disk) leaves the old
    // batch and no thumbnail: everything is put in place together at the end.
    std::fs::write(&fla, b"old batch").unwrap();
    let cmd = format!(
        "trap '' XFSZ; ulimit -f 24 && exec '{}' random --count 40 --min-xforms 40 \
         --max-xforms 40 --seed 1 --size 16x16 --quality 1 --thumbs '{}' -o '{}'",
        bin(),
        s(&thumbs),
        s(&fla)
    );
    let out = Command::new("sh").arg("-c").arg(cmd).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(std::fs::read(&fla).unwrap(), b"old batch");
    assert_eq!(listing(&thumbs), Vec::<String>::new());
    assert_eq!(listing(&dir), ["b.fla", "t"]);
    std::fs::remove_dir_all(&dir).unwrap();
}
