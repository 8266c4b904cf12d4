//! Tests of `escape_view`.

use super::*;
use crate::escape::centre::Centre;

#[test]
fn round_trip_every_kind() {
    for kind in [
        "mandelbrot",
        "multibrot",
        "burning-ship",
        "julia",
        "newton",
        "logistic",
        "cubic",
        "warped-julia",
    ] {
        let mut d = EscapeDoc::new(family_from_name(kind).unwrap());
        d.params.max_iter = 777;
        d.params.coloring = Coloring::Histogram;
        d.view = d.view.with_centre(Centre::from_f64([0.125, -0.25]));
        d.gradient_source = "lagoon".into();
        d.params.palette.gradient = gradient::builtin_named("lagoon").unwrap();
        d.params.palette.offset = 0.5;
        let text = write(&d);
        let back = parse(&text, "t.esc", None).unwrap();
        assert!(back.warnings.is_empty(), "{kind}: {:?}", back.warnings);
        let b = back.value;
        assert_eq!(b.params.family, d.params.family, "{kind}");
        assert_eq!(b.params, d.params, "{kind}");
        assert_eq!((b.width, b.height), (d.width, d.height));
        assert!((b.view.half_height() - d.view.half_height()).abs() < 1e-12);
        assert_eq!(b.view.center(), d.view.center());
    }
}

#[test]
fn deep_zoom_views_keep_every_digit() {
    let mut d = EscapeDoc::new(Family::Mandelbrot { power: 2 });
    let c =
        parse_center("-0.743643887037158704752191506114774, 0.131825904205311970493132056385139")
            .unwrap();
    d.view = d.view.with_centre(c.clone());
    d.view.set_half_height(3e-21);
    let text = write(&d);
    assert!(
        text.contains("center = -0.7436438870371587047521915061147"),
        "{text}"
    );
    assert!(text.contains("width = 8e-21"), "{text}");
    let b = parse(&text, "deep.esc", None).unwrap().value;
    assert_eq!(b.view.centre().format(), c.format());
    assert!((b.view.half_height() / 3e-21 - 1.0).abs() < 1e-12);
    // Writing again gives the same text.
    assert_eq!(write(&b), text);
    // The default bilinear tolerance is not written; another one round-trips.
    assert!(!text.contains("bla_tolerance"), "{text}");
    let mut t = d.clone();
    t.params.bla_eps = 1e-6;
    let loose = write(&t);
    assert!(loose.contains("bla_tolerance = 1e-6"), "{loose}");
    assert_eq!(
        parse(&loose, "deep.esc", None).unwrap().value.params,
        t.params
    );
    // A shallow view is written as before (shortest f64).
    let mut s = d.clone();
    s.view.set_half_height(0.5);
    assert!(write(&s).contains("center = -0.7436438870371587, 0.13182590420531198"));
}

#[test]
fn views_of_1e_minus_1000_and_thousands_of_digits_round_trip() {
    let mut d = EscapeDoc::new(Family::Mandelbrot { power: 2 });
    let x = format!("-1.{}", "7".repeat(1020));
    d.view = d
        .view
        .with_centre(parse_center(&format!("{x}, 0")).unwrap());
    d.set_world_width_fx(parse_width("2.5e-1000").unwrap());
    let text = write(&d);
    assert!(
        text.contains("width = 2.5e-1000"),
        "{}",
        &text[text.len() - 300..]
    );
    assert!(text.contains(&x[..1000]));
    let b = parse(&text, "deep.esc", None).unwrap().value;
    assert_eq!(write(&b), text);
    assert!((b.world_width_fx().log10() - d.world_width_fx().log10()).abs() < 1e-12);
    // Widths and centres out of range say why.
    for (bad, what) in [
        ("width = 1e-100000\n", "deep-zoom limit"),
        ("width = nan\n", "not a number"),
        ("width = -1\n", "positive"),
        ("width = 1e99\n", "too large"),
    ] {
        let e = parse(&format!("kind = mandelbrot\n{bad}"), "v.esc", None)
            .err()
            .unwrap();
        assert!(e.to_string().contains(what), "{bad}: {e}");
    }
    let long = format!("center = 0.{}, 0\n", "1".repeat(100_000));
    let e = parse(&format!("kind = mandelbrot\n{long}"), "v.esc", None)
        .err()
        .unwrap();
    assert!(e.to_string().contains("20000 digits"), "{e}");
}

#[test]
fn bad_files_say_where() {
    let cases = [
        ("kind = mandelbrot\nmax_iter = lots\n", 2, "ESC003"),
        ("center = 0, 0\n", 0, "ESC002"),
        ("kind = snowflake\n", 1, "ESC002"),
        ("kind = julia\nc = 1, 2, 3\n", 2, "ESC003"),
        ("kind = mandelbrot\npower = 12\n", 2, "ESC004"),
        ("kind = warped-julia\nalpha = 0.6, 0.8\n", 2, "ESC004"),
        ("kind = mandelbrot\nno equals sign\n", 2, "ESC001"),
        (
            "kind = mandelbrot\ngradient = /no/such/file.map\n",
            2,
            "ESC005",
        ),
        ("kind = newton\npoly = 1\n", 2, "ESC003"),
        ("kind = mandelbrot\nsize = 0x10\n", 2, "ESC004"),
        ("kind = mandelbrot\nbla_tolerance = 0.5\n", 2, "ESC004"),
        ("kind = mandelbrot\nbla_tolerance = nan\n", 2, "ESC003"),
    ];
    for (text, line, code) in cases {
        let e = parse(text, "v.esc", None)
            .err()
            .unwrap_or_else(|| panic!("accepted {text:?}"));
        assert_eq!(e.code, code, "{text:?}: {e}");
        if line > 0 {
            assert_eq!(e.pos, Pos::LineCol(line, 1), "{text:?}");
        }
        assert!(e.to_string().contains("v.esc"));
    }
    let w = parse("kind = mandelbrot\nzoom = 3\n", "v.esc", None).unwrap();
    assert_eq!(w.warnings.len(), 1);
}
