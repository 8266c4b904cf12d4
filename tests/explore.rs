//! Explore engine against the file formats: IFS presets as flames (the same conversion as
//! `.ifs` import), the `.l` fixture read, written and read back, SVG output.

mod common;

use ugnis::explore::ifs::presets;
use ugnis::explore::lsystem::Angle;
use ugnis::flame::NewFlame;
use ugnis::io;

#[test]
fn ifs_presets_convert_like_ifs_import() {
    let lib = io::ifs::parse(
        "fern {\n 0 0 0 .16 0 0 .01\n .85 .04 -.04 .85 0 1.6 .85\n .2 -.26 .23 .22 0 1.6 .07\n \
         -.15 .28 .26 .24 0 .44 .07\n }\n",
        "fern.ifs",
    )
    .unwrap()
    .value;
    let defaults = NewFlame::default();
    let from_file = io::ifs::entry_to_flame(&lib.entries[0], &defaults);
    let from_preset = presets::fractint_fern().to_flame(&defaults);
    assert_eq!(from_file.xforms, from_preset.xforms);
    assert_eq!(from_file.kind, from_preset.kind);
    // And every preset survives a trip through a .ifs file (y-conjugated back).
    for p in presets::all() {
        let f = p.to_flame(&defaults);
        let (entry, _) = io::ifs::flame_to_entry(&f).unwrap();
        for (row, (m, q)) in entry
            .rows
            .iter()
            .zip(p.maps.iter().zip(p.normalised_probs()))
        {
            let want = [m.a, m.b, m.c, m.d, m.e, m.f, q];
            for (x, y) in row.iter().zip(want) {
                assert!((x - y).abs() < 1e-12, "{}: {row:?} vs {want:?}", p.name);
            }
        }
    }
}

#[test]
fn own_l_file_reads_writes_and_reads_back() {
    let p = io::read_lsystems(&common::fixture("explore.l")).unwrap();
    assert!(p.warnings.is_empty(), "{:?}", p.warnings);
    let names: Vec<&str> = p.value.entries.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "KochCurve",
            "Snowflake",
            "TwinDragon",
            "Bush",
            "Rainbow",
            "Pinwheel",
            "Empty"
        ]
    );
    assert!(
        p.value
            .entries
            .iter()
            .all(|e| matches!(e.angle, Angle::Divisions(_)))
    );
    let dir = common::temp_dir("explore-l");
    let out = dir.join("again.l");
    io::write_lsystems(&out, &p.value.entries).unwrap();
    let q = io::read_lsystems(&out).unwrap();
    assert!(q.warnings.is_empty());
    assert_eq!(q.value, p.value);
    // Every entry compiles and its walk gives as many segments as predicted.
    for e in &q.value.entries {
        let c = e.compile().unwrap();
        for order in 0..5 {
            let n = c.segments(order).unwrap().count() as f64;
            assert_eq!(n, c.counts(order).segments, "{} order {order}", e.name);
        }
    }
    // Rainbow: one segment per order, colours counting up from 1.
    let r = q.value.get("rainbow").unwrap().compile().unwrap();
    let colours: Vec<i64> = r.segments(5).unwrap().map(|s| s.color).collect();
    assert_eq!(colours, [1, 2, 3, 4, 5]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn svg_of_the_snowflake() {
    let p = io::read_lsystems(&common::fixture("explore.l")).unwrap();
    let c = p.value.get("snowflake").unwrap().compile().unwrap();
    let dir = common::temp_dir("explore-svg");
    let out = dir.join("s.svg");
    io::svg::save_lsystem(&out, &c, 3, 400, 400, Some([255, 255, 255])).unwrap();
    let s = std::fs::read_to_string(&out).unwrap();
    // A closed curve of 3·4³ segments in one path, inside the 400×400 view.
    assert_eq!(s.matches("<path").count(), 1);
    assert_eq!(s.matches('L').count(), 192);
    assert!(s.contains(r#"viewBox="0 0 400 400""#));
    let nums: Vec<f64> = s
        .split(['M', 'L', ' ', '"'])
        .filter_map(|t| t.parse().ok())
        .collect();
    assert!(nums.iter().all(|v| (0.0..=400.0).contains(v)));
    // Too many segments for an SVG: refused before the file is created.
    let big = dir.join("big.svg");
    let e = io::svg::save_lsystem(&big, &c, 12, 400, 400, None).unwrap_err();
    assert!(e.to_string().contains("write a PNG"), "{e}");
    assert!(!big.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
