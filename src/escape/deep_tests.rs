//! Deep zoom against the truth: every pixel of small grids iterated directly in big fixed
//! point at the same pixel centres, at depths where the differences are f64 (1e-40, 1e-100)
//! and where they must be extended (1e-330, 1e-1000).

use super::*;
use crate::escape::family::Family;
use crate::escape::view::View;

fn settings(max_iter: u32, want_de: bool) -> IterSettings {
    IterSettings {
        max_iter,
        bailout2: 256.0 * 256.0,
        strict: true,
        period_tol: 0.0,
        want_de,
    }
}

/// The escape count and continuous count of z0 under the map with parameter c, directly in
/// fixed point.
fn exact(map: Map, z0: [IBig; 2], c: [IBig; 2], bits: u32, s: &IterSettings) -> (u32, f64, bool) {
    let b = bits as usize;
    let [mut x, mut y] = z0;
    let to = |v: &IBig| fix_to_f64(v, bits);
    for n in 1..=s.max_iter {
        let (nx, ny) = big_step(map, &x, &y, b);
        x = nx + &c[0];
        y = ny + &c[1];
        let r2 = to(&x).powi(2) + to(&y).powi(2);
        if !(r2 <= s.bailout2) {
            return (n, smooth_count(n, r2, map.degree() as f64), false);
        }
    }
    (s.max_iter, s.max_iter as f64, true)
}

/// The reference orbit of a `w`×`h` grid of `view` (at its centre, covering its corners) for
/// `map` (or the Julia set of `julia`), and the grid's pixel size.
fn reference_of(
    map: Map,
    julia: Option<C>,
    view: &View,
    w: u32,
    h: u32,
    s: &IterSettings,
) -> (Reference, Fx) {
    let pixel = view.pixel_size_fx(h);
    let radius = view.offset_from_pixel_fx(0.0, 0.0, w, h).abs();
    let extent = Extent {
        pixel,
        radius,
        bla_eps: crate::escape::bla::EPSILON,
    };
    let r = Reference::new(map, view.centre(), julia, extent, s, &Default::default());
    (r.unwrap(), pixel)
}

/// Render a `w`×`h` grid of `view` by perturbation and directly; the fraction of pixels
/// whose continuous counts agree within 0.05, and the number of distinct integer counts.
fn agreement(family: &Family, view: &View, w: u32, h: u32, s: &IterSettings) -> (f64, usize) {
    let map = |power| if power == 3 { Map::Cube } else { Map::Square };
    let (map, julia) = match *family {
        Family::Mandelbrot { power } => (map(power), None),
        Family::Julia { power, c } => (map(power), Some(c)),
        Family::BurningShip => (Map::Ship, None),
        _ => unreachable!(),
    };
    let (r, pixel) = reference_of(map, julia, view, w, h, s);
    // The truth with twice the digits the reference gets.
    let bits = bits_for(pixel) * if julia.is_some() { 4 } else { 2 };
    let (mut good, mut counts) = (0, Vec::new());
    let dcs: Vec<Cx> = (0..h)
        .flat_map(|j| (0..w).map(move |i| view.offset_from_pixel_fx(i as f64, j as f64, w, h)))
        .collect();
    // The renderer's path: the interleaved plain loop where it can.
    let many = iterate_many(&r, &dcs, s, pixel);
    for j in 0..h {
        for i in 0..w {
            let dc = dcs[(j * w + i) as usize];
            let got = many[(j * w + i) as usize];
            let one = iterate(&r, dc, s, pixel);
            assert_eq!(got.inside, one.inside, "{i}, {j}");
            let p = view
                .centre()
                .shifted(Fx::new(dc.re, dc.e), Fx::new(dc.im, dc.e))
                .to_binary(bits);
            let (n, nu, inside) = match julia {
                None => exact(map, [IBig::ZERO, IBig::ZERO], p, bits, s),
                Some(c) => {
                    let cb = Centre::from_f64_exact([c.re, c.im]).to_binary(bits);
                    exact(map, p, cb, bits, s)
                }
            };
            counts.push(n);
            let same = if inside {
                got.inside
            } else {
                !got.inside && (got.nu - nu).abs() < 0.05
            };
            good += same as u32;
        }
    }
    counts.sort();
    counts.dedup();
    (good as f64 / (w * h) as f64, counts.len())
}

fn deep_view(x: &str, y: &str, half: &str) -> View {
    View::from_centre(Centre::parse(x, y).unwrap(), Fx::parse(half).unwrap())
}

#[test]
fn mandelbrot_agrees_with_exact_iteration_at_four_depths() {
    // Near the Misiurewicz point i (its structure repeats at every depth), offset so that
    // the reference is an ordinary boundary point; 1e-330 needs extended differences.
    let s = settings(6000, false);
    for (half, min_counts) in [
        ("1e-40", 10),
        ("1e-100", 10),
        ("1e-330", 10),
        ("1e-1000", 10),
    ] {
        let view = deep_view("0", "1", half);
        let (frac, distinct) = agreement(&Family::Mandelbrot { power: 2 }, &view, 16, 12, &s);
        assert!(distinct >= min_counts, "{half}: {distinct} counts");
        assert!(frac >= 0.99, "{half}: {frac}");
    }
}

#[test]
fn seahorse_valley_with_a_reference_inside_agrees() {
    // A centre deep in seahorse valley whose orbit stays bounded for all 20000 iterations:
    // pixels rebase onto it again and again.
    let s = settings(20_000, false);
    let view = deep_view(
        "-0.743643887037158704752191506114774",
        "0.131825904205311970493132056385139",
        "1e-25",
    );
    let (frac, distinct) = agreement(&Family::Mandelbrot { power: 2 }, &view, 16, 12, &s);
    assert!(distinct >= 10, "{distinct} counts");
    // After 16,000 iterations a few chaotic pixels next to the boundary end 2–3 iterations
    // apart (f64 rounding of the differences; the truth is the same at twice its digits).
    assert!(frac >= 0.97, "{frac}");
}

#[test]
fn julia_sets_and_the_cubic_zoom_deep_too() {
    // The Julia set of z² + i (a dendrite) around 0, which lies on it: 0 → i → −1 + i → −i,
    // a repelling 2-cycle.
    let c = C::new(0.0, 1.0);
    let s = settings(4000, false);
    for half in ["1e-50", "1e-320"] {
        let view = deep_view("0", "0", half);
        let (frac, distinct) = agreement(&Family::Julia { power: 2, c }, &view, 12, 9, &s);
        assert!(distinct >= 5, "{half}: {distinct} counts");
        assert!(frac >= 0.99, "julia {half}: {frac}");
    }
    // z³ + c at a Misiurewicz point: 0 → c → c³ + c lands on a fixed point when
    // c² = ω − 1, ω = e^(2πi/3) (f64 places it to 1e-16, so the view stays above that).
    let s = settings(3000, false);
    let w = C::new(-1.5, 3f64.sqrt() / 2.0);
    let m = C::from_polar(w.abs().sqrt(), w.im.atan2(w.re) / 2.0);
    let view = View::from_centre(
        Centre::from_f64_exact([m.re, m.im]),
        Fx::parse("1e-13").unwrap(),
    );
    let (frac, distinct) = agreement(&Family::Mandelbrot { power: 3 }, &view, 12, 9, &s);
    assert!(distinct >= 5, "cubic: {distinct} counts");
    assert!(frac >= 0.99, "cubic: {frac}");
}

#[test]
fn burning_ship_agrees_with_exact_iteration() {
    // A point c ≈ −1.136 − 0.620i where 0 → c → … lands after four steps on the fixed point
    // z ≈ 1.705 + 0.257i (solved by Newton's method to 205 digits), which the ship's
    // Jacobian (2|z| times a rotation or reflection) repels by 3.45: its structure repeats at
    // every depth. The orbit stays off the axes, so the fold's signs are those of the
    // reference and the difference terms must not cancel (the diffabs form). The digits
    // keep the reference on the cycle (and bounded) longer than the pixels take to escape:
    // pixels that outlive their reference restart from its start with a full-size value and
    // keep f64's absolute accuracy only. At 1e-100, 3 of the 192 pixels leave the cycle's
    // neighbourhood at a full-size distance from the reference and wander near it for another
    // 50–100 iterations: the rounding of their f64 differences (a few ulps at the departure)
    // grows ten orders there and they end up to 20 iterations off, as they would in any
    // program that keeps differences in f64.
    let x = "-1.135970435068669382740841251730673933311924870876766725685875127621889688\
             767121405072274975276750023921156479446428973090212757396385213938417834756\
             849637107266137647023656531165227992031188066647728934534";
    let y = "-0.620043386399648200978028882876077721013041924053031614563946013305331487\
             942996783102213960061646547603087438578052911231800480602098334794794166210\
             898372624575163846941793646094380205244377968751786864654";
    let s = settings(6000, false);
    for half in ["1e-40", "1e-100"] {
        let view = deep_view(x, y, half);
        let (frac, distinct) = agreement(&Family::BurningShip, &view, 16, 12, &s);
        assert!(distinct >= 10, "{half}: {distinct} counts");
        assert!(frac >= 0.98, "{half}: {frac}");
    }
}

/// The centre of Fractalshades' example "12 - Burning ship deep" (a period-9,622 miniship of
/// size 3.4e-265), its imaginary part negated: Fractalshades iterates y ← 2|xy| − b.
const SHIP_DEEP_X: &str = "-1.99638112292592965329403782831125346996664185255135402827974584999638456165654\
     33002317348463723892008844734003260474022592153652996510000493079672207971742209203082500\
     39037884064184875313550754352410343246674089430454249309097057276774162871180276065193880\
     170743903875782";
const SHIP_DEEP_Y: &str = "-0.00000476330372839277074601469236202986586671169161209597457133172150779470960\
     76040509814670657369206760374813788282766429440720697568351829534511099050778810611398876\
     61561617020726899218853890425452233104923366681895875677542245236396274857406762304353824\
     848557938906613374564";

#[test]
fn burning_ship_bilinear_steps_agree_with_exact_iteration() {
    // On the way to a deep miniship: at 1e-30 pixels escape after 600–1,000 iterations, at
    // 1e-100 after 4,700–5,300, most of them skipped by the ship's matrix steps.
    let s = settings(20_000, false);
    for half in ["1e-30", "1e-100"] {
        let view = deep_view(SHIP_DEEP_X, SHIP_DEEP_Y, half);
        let (frac, distinct) = agreement(&Family::BurningShip, &view, 16, 12, &s);
        assert!(distinct >= 10, "{half}: {distinct} counts");
        assert!(frac >= 0.99, "{half}: {frac}");
    }
}

#[test]
fn the_cubic_zooms_deep_with_its_bilinear_steps() {
    // The Misiurewicz point of z³ + c with c² = ω − 1, ω = e^(2πi/3) (0 → c → cω, a fixed
    // point repelling by 3√3), here to 210 digits: its structure repeats at every depth.
    let x = "0.34062501931660664019439424403783088897721010254912530311970263261451737734879523\
             43630988949291399753177594601305713199721022589856485166787850209875432320051377\
             24559654474662298990842181784879059644210903965593";
    let y = "1.27122987841870623913561299102106497672841432822677767821367914369348079134474419\
             69146767160282631933396985181626638437283262450381644243328982863195606645889473\
             2239665737140153026796895069189345277005717120038";
    let s = settings(3000, false);
    for half in ["1e-60", "1e-200"] {
        let view = deep_view(x, y, half);
        // The bilinear steps cover the first iterations of every pixel.
        let (r, _) = reference_of(Map::Cube, None, &view, 12, 9, &s);
        let dc = view.offset_from_pixel_fx(0.0, 0.0, 12, 9);
        assert!(
            r.main.bla.find(1, dc.abs(), 3000).unwrap().len >= 16,
            "{half}"
        );
        let (frac, distinct) = agreement(&Family::Mandelbrot { power: 3 }, &view, 12, 9, &s);
        assert!(distinct >= 5, "cubic {half}: {distinct} counts");
        assert!(frac >= 0.99, "cubic {half}: {frac}");
    }
}

#[test]
fn burning_ship_agrees_with_exact_iteration_with_extended_differences() {
    // The preperiodic point of `burning_ship_agrees_with_exact_iteration`, refined by Newton's
    // method to 420 digits, at 1e-330: offsets below f64's range, so the first hundred-odd
    // iterations take the extended loop and its matrix steps.
    let x = "-1.13597043506866938274084125173067393331192487087676672568587512762188968876712\
             14050722749752767500239211564794464289730902127573963852139384178347568496371072\
             66137647023656531165227992031188066647728934534275054232848671953679689359348862\
             33917858662586860583909102189897166095959350578499009400554486824178550889798994\
             51419198999470641572881975390534817687734279811309181928150625797318206589839585\
             32347081713399691153";
    let y = "-0.62004338639964820097802888287607772101304192405303161456394601330533148794299\
             67831022139600616465476030874385780529112318004806020983347947941662108983726245\
             75163846941793646094380205244377968751786864653958163894484187501979079856952099\
             51909275514907110540722902288055286560653902057444365913195526154158586999381011\
             58751318059234965050835604834362185707178988736111087699810220183771449838939249\
             82203047980704727236";
    let s = settings(3000, false);
    let view = deep_view(x, y, "1e-330");
    let (frac, distinct) = agreement(&Family::BurningShip, &view, 16, 12, &s);
    assert!(distinct >= 10, "{distinct} counts");
    // 190 of 192 pixels, the same with every iteration perturbed singly (no bilinear steps):
    // the two others leave the cycle at a full-size distance, where f64 rounding of their
    // differences grows (see `burning_ship_agrees_with_exact_iteration`).
    assert!(frac >= 0.98, "{frac}");
}

#[test]
fn burning_ship_steps_skip_most_iterations() {
    let s = settings(20_000, true);
    let view = deep_view(SHIP_DEEP_X, SHIP_DEEP_Y, "1e-100");
    let (w, h) = (8, 6);
    let (r, pixel) = reference_of(Map::Ship, None, &view, w, h, &s);
    assert!(r.main.ship.len() > 4000, "{}", r.main.ship.len());
    let dc = view.offset_from_pixel_fx(1.0, 1.0, w, h);
    let st = r.main.ship.find(1, dc.abs(), 10_000).unwrap();
    assert!(st.len >= 64, "first step {}", st.len);
    // Distance estimates through the matrix steps: pixels next to the boundary are within
    // a few pixels of it.
    let des: Vec<f32> = (0..w)
        .map(|i| {
            iterate(
                &r,
                view.offset_from_pixel_fx(i as f64, 2.0, w, h),
                &s,
                pixel,
            )
            .de
        })
        .collect();
    assert!(
        des.iter().all(|d| d.is_finite() && *d > 0.0 && *d < 50.0),
        "{des:?}"
    );
}

#[test]
fn bilinear_steps_skip_most_iterations() {
    // At 1e-100 near i, pixels escape after about 270 iterations; the table covers them in
    // a few dozen steps.
    let s = settings(6000, false);
    let view = deep_view("0", "1", "1e-100");
    let (w, h) = (8, 6);
    let (r, pixel) = reference_of(Map::Square, None, &view, w, h, &s);
    assert_eq!(r.main.z.len(), 6001, "the reference at i never escapes");
    assert!(r.main.bla.len() > 5000);
    let dc = view.offset_from_pixel_fx(1.0, 1.0, w, h);
    let p = iterate(&r, dc, &s, pixel);
    assert!(!p.inside && p.n > 200, "{p:?}");
    let st = r.main.bla.find(1, dc.abs(), 10_000).unwrap();
    assert!(st.len >= 128, "first step {}", st.len);
    // The plain loop's quadratic steps land where the single steps do, for differences up
    // to their radius and offsets up to the view's largest (the worst relative difference
    // found is about 1e-14).
    let last = r.main.z.len() - 1;
    let radius = view.offset_from_pixel_fx(0.0, 0.0, w, h).abs().to_f64();
    let (mut checked, mut worst) = (0, 0.0f64);
    for m in (1..last).step_by(2) {
        for k in 0..(m - 1).trailing_zeros().min(16) as usize {
            let j = (m - 1) >> (k + 1);
            let rad = r.main.bla.plain_radius(k, j);
            if rad <= 0.0 {
                continue;
            }
            let len = (2usize << k).min(last - m);
            let [a, b] = r.main.bla.plain_linear(k, j);
            let [c, dd, e] = r.main.bla.plain_quad(k, j);
            for (f, dc) in [
                (0.9, C::new(radius, 0.0)),
                (0.3, C::new(0.0, -radius)),
                (0.01, C::ZERO),
            ] {
                // |re| + |im| of the difference is f times the radius.
                let d0 = C::new(0.6 * f * rad, -0.4 * f * rad);
                let q = (a + c * d0 + dd * dc) * d0 + (b + e * dc) * dc;
                let mut d = d0;
                for zi in &r.main.z[m..m + len] {
                    d = d * (*zi * 2.0 + d) + dc;
                }
                let err = (q - d).abs() / d.abs();
                worst = worst.max(err);
                assert!(err < 1e-12, "m {m} level {k}: {q:?} against {d:?}");
                checked += 1;
            }
        }
    }
    eprintln!("{checked} steps, worst relative error {worst:e}");
    assert!(checked > 1000, "{checked}");
}

#[test]
fn distance_estimates_are_in_pixels_at_any_depth() {
    // Pixels next to the boundary of a deep view are within a few pixels of it.
    let s = settings(6000, true);
    for half in ["1e-30", "1e-400"] {
        let view = deep_view("0", "1", half);
        let (w, h) = (8, 6);
        let (r, pixel) = reference_of(Map::Square, None, &view, w, h, &s);
        let des: Vec<f32> = (0..w)
            .map(|i| {
                iterate(
                    &r,
                    view.offset_from_pixel_fx(i as f64, 2.0, w, h),
                    &s,
                    pixel,
                )
                .de
            })
            .collect();
        assert!(
            des.iter().all(|d| d.is_finite() && *d > 0.0 && *d < 20.0),
            "{half}: {des:?}"
        );
    }
}

/// The pixels of a `w`×`h` grid of the Mandelbrot `view` through the plain loop: all
/// interleaved as the renderer runs them, and each alone.
fn interleaved_and_alone(
    view: &View,
    w: u32,
    h: u32,
    s: &IterSettings,
) -> [Vec<deep_plain::End>; 2] {
    let (r, _) = reference_of(Map::Square, None, view, w, h, s);
    let dcs: Vec<C> = (0..h)
        .flat_map(|j| (0..w).map(move |i| view.offset_from_pixel_fx(i as f64, j as f64, w, h)))
        .map(|dc| dc.to_c())
        .collect();
    let o = deep_plain::Orbits {
        main: (&r.main.z, &r.main.bla),
        base: (&r.main.z, &r.main.bla),
    };
    let lane = |dc: C| deep_plain::Lane {
        m: 0,
        n: 0,
        on_base: false,
        d: C::ZERO,
        dc,
    };
    let mut together = vec![deep_plain::End::Inside; dcs.len()];
    let mut todo = dcs.iter().enumerate();
    deep_plain::run(
        &o,
        Map::Square,
        s,
        || todo.next().map(|(k, &dc)| (k, lane(dc))),
        |k, e| together[k] = e,
    );
    let alone = dcs
        .iter()
        .map(|&dc| {
            let mut end = deep_plain::End::Inside;
            let mut one = Some(((), lane(dc)));
            deep_plain::run(&o, Map::Square, s, || one.take(), |_, e| end = e);
            end
        })
        .collect();
    [together, alone]
}

#[test]
fn interleaved_pixels_keep_every_bit_of_one_pixel_alone() {
    // Seahorse valley at 1e-25: pixels escape early and late, take bilinear steps, rebase
    // and reach the limit; and a Misiurewicz view whose reference never escapes.
    let s = settings(20_000, false);
    let views = [
        deep_view(
            "-0.743643887037158704752191506114774",
            "0.131825904205311970493132056385139",
            "1e-25",
        ),
        deep_view("0", "1", "1e-60"),
    ];
    for (v, view) in views.iter().enumerate() {
        let [together, alone] = interleaved_and_alone(view, 37, 23, &s);
        let escaped = together
            .iter()
            .filter(|e| **e != deep_plain::End::Inside)
            .count();
        assert!(escaped > 100, "view {v}: {escaped} escaped");
        for (k, (a, b)) in together.iter().zip(&alone).enumerate() {
            let bits = |e: &deep_plain::End| match *e {
                deep_plain::End::Escaped { n, z, r2 } => {
                    Some((n, z.re.to_bits(), z.im.to_bits(), r2.to_bits()))
                }
                deep_plain::End::Inside => None,
            };
            assert_eq!(bits(a), bits(b), "view {v}, pixel {k}");
        }
    }
}

/// Fraction of a 16×12 grid of seahorse valley at width 1e-25 (30,000 iterations, the
/// bench's view) within 0.05 of exact iteration, at the bilinear tolerance `eps`.
fn seahorse_bench_accuracy(eps: f64) -> usize {
    let s = settings(30_000, false);
    let (w, h) = (16, 12);
    // Width 1e-25: half the height is 1e-25 · 12 / 16 / 2.
    let view = &deep_view(
        "-0.743643887037158704752191506114774",
        "0.131825904205311970493132056385139",
        "3.75e-26",
    );
    let pixel = view.pixel_size_fx(h);
    let radius = view.offset_from_pixel_fx(0.0, 0.0, w, h).abs();
    let x = Extent {
        pixel,
        radius,
        bla_eps: eps,
    };
    let r = Reference::new(Map::Square, view.centre(), None, x, &s, &Default::default()).unwrap();
    let bits = bits_for(pixel) * 2;
    let dcs: Vec<Cx> = (0..h)
        .flat_map(|j| (0..w).map(move |i| view.offset_from_pixel_fx(i as f64, j as f64, w, h)))
        .collect();
    let got = iterate_many(&r, &dcs, &s, pixel);
    dcs.iter()
        .zip(&got)
        .filter(|(dc, g)| {
            let p = view
                .centre()
                .shifted(Fx::new(dc.re, dc.e), Fx::new(dc.im, dc.e))
                .to_binary(bits);
            let (_, nu, inside) = exact(Map::Square, [IBig::ZERO, IBig::ZERO], p, bits, &s);
            if inside {
                g.inside
            } else {
                !g.inside && (g.nu - nu).abs() < 0.05
            }
        })
        .count()
}

#[test]
#[ignore = "slow (exact iteration of 192 pixels for 30,000 iterations): run with --ignored"]
fn the_bench_view_is_as_exact_as_fractalshades_at_matched_tolerance() {
    // Fractalshades gets 99.0 % of this grid within 0.05 at its bilinear tolerance 1e-14
    // (benches/deep_zoom.py --accuracy). UGNIS_BLA_EPS=a,b,… also reports other tolerances.
    let extra: Vec<f64> = std::env::var("UGNIS_BLA_EPS")
        .unwrap_or_default()
        .split(',')
        .filter_map(|v| v.trim().parse().ok())
        .collect();
    for eps in extra {
        eprintln!("eps {eps:e}: {} of 192", seahorse_bench_accuracy(eps));
    }
    let good = seahorse_bench_accuracy(crate::escape::bla::EPSILON);
    eprintln!("default eps: {good} of 192");
    assert!(good >= 190, "{good} of 192");
}
