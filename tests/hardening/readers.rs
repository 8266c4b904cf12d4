//! Every reader at its limit: a file with the most entries it accepts is read in a time linear
//! in its size (printed to the test log), and one more is refused at once.

use super::*;

/// Parse `text` with `read`, print the time and check it against `max` (several times what a
/// linear reader takes here, far below what a quadratic one took).
fn timed<T, E: std::fmt::Display>(
    what: &str,
    text: &str,
    max: Duration,
    read: impl Fn(&str) -> Result<T, E>,
) -> Result<T, E> {
    let t = Instant::now();
    let r = read(text);
    let took = t.elapsed();
    println!(
        "{what}: {:.1} MiB in {:.3} s",
        text.len() as f64 / (1 << 20) as f64,
        took.as_secs_f64()
    );
    assert!(took < max, "{what} took {took:?}");
    r
}

/// CPU time the calling thread has used.
fn thread_cpu_time() -> Duration {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime only writes the timespec it is given.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    assert_eq!(rc, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID)");
    Duration::new(ts.tv_sec as u64, ts.tv_nsec as u32)
}

/// Read `make(n)` and `make(n / 4)`: four times the entries must take about four times as
/// long (a quadratic reader takes sixteen times). Returns the result for `n`.
fn linear<T, E: std::fmt::Display>(
    what: &str,
    n: usize,
    make: impl Fn(usize) -> String,
    read: impl Fn(&str) -> Result<T, E>,
) -> T {
    let time = |k: usize| {
        let text = make(k);
        // The best of three, in this thread's CPU time: a busy machine preempts long runs more
        // often than short ones, which skews wall-clock ratios, not CPU time.
        let mut best = Duration::MAX;
        let mut out = None;
        for _ in 0..3 {
            let t = thread_cpu_time();
            let r = read(&text);
            best = best.min(thread_cpu_time().saturating_sub(t));
            out = Some(r);
        }
        (best, text.len(), out.unwrap())
    };
    let (quarter, _, _) = time(n / 4);
    let (full, bytes, r) = time(n);
    println!(
        "{what}: {n} in {:.3} s ({:.1} MiB), {} in {:.3} s",
        full.as_secs_f64(),
        bytes as f64 / (1 << 20) as f64,
        n / 4,
        quarter.as_secs_f64()
    );
    assert!(
        full < quarter * 8 + Duration::from_millis(30),
        "{what}: {n} took {full:?}, {} took {quarter:?}: not linear",
        n / 4
    );
    assert!(full < Duration::from_secs(5), "{what} took {full:?}");
    match r {
        Ok(v) => v,
        Err(e) => panic!("{what}: {e}"),
    }
}

fn ifs_text(entries: usize, rows: usize) -> String {
    let row = " .5 0 0 .5 0 0 .33\n";
    (0..entries)
        .map(|k| format!("tri{k} {{\n{}}}\n", row.repeat(rows)))
        .collect()
}

#[test]
fn ifs_files_are_read_in_linear_time_up_to_their_limits() {
    use ugnis::io::ifs::{MAX_ENTRIES, MAX_ROWS, parse};
    // Entries whose first 18 characters are the same: each is compared with those before.
    let same = |n: usize| -> String {
        (0..n)
            .map(|k| format!("same_long_prefix_x{k} {{\n .5 0 0 .5 0 0 1\n}}\n"))
            .collect()
    };
    let p = linear("ifs: entries of one name", MAX_ENTRIES, same, |t| {
        parse(t, "same.ifs")
    });
    assert_eq!(p.value.entries.len(), MAX_ENTRIES);
    let repeats = p.warnings.iter().filter(|w| w.code == "IFS012").count();
    assert_eq!(repeats, MAX_ENTRIES - 1);
    let p = linear(
        "ifs: entries",
        MAX_ENTRIES,
        |n| ifs_text(n, 3),
        |t| parse(t, "big.ifs"),
    );
    assert_eq!(p.value.entries.len(), MAX_ENTRIES);
    // Written back (names checked as Fractint compares them) and read again.
    let written = linear(
        "ifs: writing entries",
        MAX_ENTRIES,
        |n| ifs_text(n, 3),
        |t| ugnis::io::ifs::write(&parse(t, "w.ifs").unwrap().value),
    );
    assert_eq!(parse(&written, "w.ifs").unwrap().value, p.value);
    let e = timed(
        "ifs: 50,000 entries (refused)",
        &ifs_text(5 * MAX_ENTRIES, 3),
        Duration::from_secs(3),
        |t| parse(t, "huge.ifs"),
    )
    .unwrap_err();
    assert!(e.message.contains("more than 10000 entries"), "{e}");
    let p = linear(
        "ifs: rows of one entry",
        MAX_ROWS,
        |n| ifs_text(1, n),
        |t| parse(t, "rows.ifs"),
    );
    assert_eq!(p.value.entries[0].rows.len(), MAX_ROWS);
    let e = parse(&ifs_text(1, MAX_ROWS + 1), "rows.ifs").unwrap_err();
    assert!(e.message.contains("more than 1000 rows"), "{e}");
    // Through the command line: the entries become flames.
    let dir = common::temp_dir("hard-ifs-limit");
    let f = dir.join("big.ifs");
    std::fs::write(&f, ifs_text(MAX_ENTRIES, 3)).unwrap();
    let t = Instant::now();
    let (code, out, err) = ugnis(&["info", s(&f)]);
    println!(
        "ugnis info of 10,000 entries: {:.3} s",
        t.elapsed().as_secs_f64()
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("10000 entries"), "{out}");
    assert!(t.elapsed() < Duration::from_secs(5));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn every_other_reader_is_read_in_linear_time_at_its_limit() {
    use ugnis::io::flam3_xml::{MAX_FLAMES, MAX_XFORMS, ReadOptions, read};
    let opts = ReadOptions::default();
    // Flame files: the most flames (each name checked once, as in a .fla), the most xforms
    // of one flame; one more of each is refused.
    let batch = |n: usize| {
        let flames: String = (0..n)
            .map(|k| {
                format!(
                    "<flame name=\"f{k}\" size=\"8 8\"><xform weight=\"1\" linear=\"1\"/></flame>\n"
                )
            })
            .collect();
        format!("<flames>{flames}</flames>")
    };
    let fla = ReadOptions {
        file: "batch.fla".into(),
        fla: true,
        ..ReadOptions::default()
    };
    let p = linear("fla: flames", MAX_FLAMES, batch, |t| read(t, &fla));
    assert_eq!(p.value.flames.len(), MAX_FLAMES);
    assert!(read(&batch(MAX_FLAMES + 1), &opts).is_err());
    let xforms = |n: usize| {
        format!(
            "<flame size=\"8 8\">{}</flame>",
            "<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>".repeat(n)
        )
    };
    let p = linear("flame xml: xforms", MAX_XFORMS, xforms, |t| read(t, &opts));
    assert_eq!(p.value.flames[0].xforms.len(), MAX_XFORMS);
    assert!(read(&xforms(MAX_XFORMS + 1), &opts).is_err());
    // Gradients: .ugr at its most gradients, .ggr at its most segments, a long .map.
    let ugr = |n: usize| -> String {
        (0..n)
            .map(|k| format!("g{k} {{\ngradient:\n index=0 color={k} index=200 color=0\n}}\n"))
            .collect()
    };
    let max_ugr = ugnis::io::ugr::MAX_GRADIENTS;
    let p = linear("ugr: gradients", max_ugr, ugr, |t| {
        ugnis::io::ugr::parse(t, "big.ugr")
    });
    assert_eq!(p.value.len(), max_ugr);
    assert!(ugnis::io::ugr::parse(&ugr(max_ugr + 1), "big.ugr").is_err());
    let ggr = |n: usize| -> String {
        let mut s = format!("GIMP Gradient\nName: big\n{n}\n");
        for k in 0..n {
            let (a, b) = (k as f64 / n as f64, (k + 1) as f64 / n as f64);
            s.push_str(&format!("{a} {} {b} 0 0 0 1 1 1 1 1 0 0\n", (a + b) / 2.0));
        }
        s
    };
    let max_ggr = ugnis::io::ggr::MAX_SEGMENTS;
    let p = linear("ggr: segments", max_ggr, ggr, |t| {
        ugnis::io::ggr::parse(t, "big.ggr", "big")
    });
    assert_eq!(p.value.name, "big");
    assert!(ugnis::io::ggr::parse(&ggr(max_ggr + 1), "big.ggr", "big").is_err());
    let map = |n: usize| -> String { (0..n).map(|k| format!("{} 0 0\n", k % 256)).collect() };
    linear("map: lines", 100_000, map, |t| {
        ugnis::io::map::parse(t, "long.map", "long")
    });
    // L-system files at their most entries.
    let l = |n: usize| -> String {
        (0..n)
            .map(|k| format!("p{k} {{\n  angle 8\n  axiom x\n  x=f[+x]f[-x]+x\n}}\n"))
            .collect()
    };
    let max_l = ugnis::io::lsystem::MAX_ENTRIES;
    let p = linear("lsystem: entries", max_l, l, |t| {
        ugnis::io::lsystem::parse(t, "big.l")
    });
    assert_eq!(p.value.entries.len(), max_l);
    // A scene of the most objects (one patch each).
    let scene = |n: usize| -> String {
        "[[object]]\nkind = \"bilinear\"\ncorners = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]]\n"
            .repeat(n)
    };
    let max_objects = ugnis::io::scene::MAX_OBJECTS;
    let base = std::env::temp_dir();
    let p = linear("scene: objects", max_objects, scene, |t| {
        ugnis::io::scene::parse_spec(t, "big.toml", &base).map_err(|e| e.to_string())
    });
    assert_eq!(p.spec.objects.len(), max_objects);
    assert!(ugnis::io::scene::parse_spec(&scene(max_objects + 1), "big.toml", &base).is_err());
}
