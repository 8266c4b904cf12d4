//! Tests of the lane runner: its statistics against the scalar chaos game, restarts, hidden
//! samples and bad values.

use super::*;
use crate::flame::chaos::SUB_BATCH;
use crate::flame::model::{Affine, Flame, Xform};
use crate::flame::variations;

#[test]
fn lanes_match_the_scalar_statistics() {
    // A flame with a non-trivial variation mix: the mean and spread of the plotted points
    // and colours agree between the scalar and the lane runner.
    let mut f = Flame::default();
    let mut a = Xform::linear(Affine::new(0.6, -0.3, 0.4, 0.5, 0.2, -0.1), 1.0, 0.0);
    a.vars = vec![
        crate::flame::model::Var::new(variations::SWIRL, 0.6),
        crate::flame::model::Var::new(variations::POLAR, 0.4),
    ];
    let mut b = Xform::linear(Affine::new(-0.5, 0.2, 0.1, 0.7, -0.3, 0.4), 2.0, 1.0);
    b.vars = vec![crate::flame::model::Var::new(variations::SPHERICAL, 0.8)];
    b.post = Affine::new(0.9, 0.0, 0.0, 0.9, 0.1, 0.0);
    f.xforms = vec![a, b];
    let mut fx = Xform::linear(Affine::new(1.0, 0.1, 0.0, 1.0, 0.0, 0.0), 0.0, 0.5);
    fx.vars = vec![crate::flame::model::Var::new(variations::SINUSOIDAL, 1.0)];
    fx.opacity = 0.7;
    f.final_xform = Some(fx);
    let ch = Chaos::new(&f).unwrap();
    let stats = |lanes: bool| {
        let mut rng = FastRng::new(11);
        let mut sc = Lanes::new();
        let (mut n, mut sx, mut sy, mut sc2, mut sxx) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for _ in 0..40 {
            // Bounded statistics: the spherical xform gives heavy tails.
            let mut plot = |x: f64, y: f64, c: f64, _v: f64| {
                n += 1.0;
                sx += x.clamp(-3.0, 3.0);
                sy += y.clamp(-3.0, 3.0);
                sc2 += c;
                sxx += (x.abs() < 0.5) as u8 as f64;
            };
            if lanes {
                ch.run_lanes(10_000, &mut rng, &mut sc, |xs, ys, _zs, cs, vs, _rgb| {
                    for j in 0..xs.len() {
                        if vs[j] >= 0.0 {
                            plot(xs[j], ys[j], cs[j], vs[j]);
                        }
                    }
                });
            } else {
                ch.run_sub_batch(10_000, &mut rng, |p, v| plot(p.x, p.y, p.c, v));
            }
        }
        (n, sx / n, sy / n, sc2 / n, sxx / n)
    };
    let a = stats(false);
    let b = stats(true);
    assert_eq!(a.0, 400_000.0);
    assert_eq!(b.0, 400_000.0);
    for (p, q) in [(a.1, b.1), (a.2, b.2), (a.3, b.3), (a.4, b.4)] {
        assert!((p - q).abs() < 0.01, "{a:?} vs {b:?}");
    }
}

/// Run the lane runner and bin the plotted points on an 8×8 grid over [−1, 2]²; also the
/// mean colour, the number of samples and of bad values.
fn lane_grid(ch: &Chaos, seed: u64) -> ([f64; 64], f64, f64, u64) {
    let mut rng = FastRng::new(seed);
    let mut ln = Lanes::new();
    let (mut grid, mut n, mut c) = ([0.0; 64], 0.0, 0.0);
    let mut bad = 0;
    for _ in 0..30 {
        bad += ch.run_lanes(10_000, &mut rng, &mut ln, |xs, ys, _zs, cs, vs, _rgb| {
            for j in 0..xs.len() {
                if vs[j] >= 0.0 {
                    assert!(xs[j].is_finite() && ys[j].is_finite());
                    let cell = |v: f64| (((v + 1.0) / 3.0 * 8.0).clamp(0.0, 7.0)) as usize;
                    grid[cell(ys[j]) * 8 + cell(xs[j])] += 1.0;
                    n += 1.0;
                    c += cs[j];
                }
            }
        });
    }
    (grid.map(|g| g / n), n, c / n, bad)
}

#[test]
fn affine_ifs_steps_orbits_in_place_with_the_same_statistics() {
    // Unequal weights, a colour blend and a linear weight other than 1: the in-place rows
    // and the grouped general path plot the same distribution.
    let mut f = Flame::default();
    for (i, (e, ff, w)) in [(0.0, 0.0, 1.0), (0.5, 0.0, 2.0), (0.25, 0.5, 0.5)]
        .into_iter()
        .enumerate()
    {
        let mut x = Xform::linear(Affine::new(0.5, 0.1, -0.1, 0.5, e, ff), w, i as f64 / 2.0);
        x.vars[0].weight = 0.9;
        x.color_speed = 0.3;
        f.xforms.push(x);
    }
    let ch = Chaos::new(&f).unwrap();
    assert!(ch.affine.is_some());
    let general = Chaos {
        affine: None,
        ..Chaos::new(&f).unwrap()
    };
    let (a, na, ca, _) = lane_grid(&ch, 3);
    let (b, nb, cb, _) = lane_grid(&general, 3);
    assert_eq!((na, nb), (300_000.0, 300_000.0));
    assert!((ca - cb).abs() < 0.01, "{ca} vs {cb}");
    let l1: f64 = a.iter().zip(&b).map(|(p, q)| (p - q).abs()).sum();
    assert!(l1 < 0.02, "cell frequencies differ by {l1}");
    // A post-affine, a final xform or xaos take the general path.
    let mut g = f.clone();
    g.xforms[1].post = Affine::new(0.9, 0.0, 0.0, 0.9, 0.0, 0.0);
    assert!(Chaos::new(&g).unwrap().affine.is_none());
}

#[test]
fn orbits_restart_as_often_as_flam3s() {
    // One xform contracting slowly to the origin: only fresh orbits plot points away from
    // it. flam3 starts one orbit per sub-batch; the lane runner restarts one orbit per call,
    // so the share of such points is about the same (long-lived orbits alone: ~20× fewer).
    let mut f = Flame::default();
    f.xforms.push(Xform::linear(
        Affine::new(0.9, 0.0, 0.0, 0.9, 0.0, 0.0),
        1.0,
        0.0,
    ));
    let ch = Chaos::new(&f).unwrap();
    let (calls, n) = (5000, 200);
    let mut rng = FastRng::new(8);
    let (mut far, mut total) = (0.0, 0.0);
    for _ in 0..calls {
        ch.run_sub_batch(n, &mut rng, |p, _| {
            far += (p.x.abs() > 0.01) as u8 as f64;
            total += 1.0;
        });
    }
    let scalar = far / total;
    let mut ln = Lanes::new();
    let (mut far, mut total) = (0.0, 0.0);
    for _ in 0..calls {
        ch.run_lanes(n, &mut rng, &mut ln, |xs, _ys, _zs, _cs, vs, _rgb| {
            for (x, v) in xs.iter().zip(vs) {
                if *v >= 0.0 {
                    far += (x.abs() > 0.01) as u8 as f64;
                    total += 1.0;
                }
            }
        });
    }
    let lanes = far / total;
    assert!(scalar > 0.05, "{scalar}");
    assert!(
        (0.5..1.5).contains(&(lanes / scalar)),
        "{lanes} vs {scalar}"
    );
}

#[test]
fn a_first_call_draws_one_fresh_path_as_flam3s_first_sub_batch() {
    // flam3's first sub-batch of a thread draws the path of one fresh orbit towards the
    // attractor; the lane runner's first call starts all its orbits, and only one of them
    // (the call's restart) may show its path: about 30 of 10 000 samples away from the
    // origin here (0.9^k < 0.01 after ~45 steps, 15 of them fused), not one path per lane.
    let mut f = Flame::default();
    f.xforms.push(Xform::linear(
        Affine::new(0.9, 0.0, 0.0, 0.9, 0.0, 0.0),
        1.0,
        0.0,
    ));
    let ch = Chaos::new(&f).unwrap();
    for seed in 0..4 {
        let mut rng = FastRng::new(seed);
        let mut ln = Lanes::new();
        let (mut far, mut total) = (0u64, 0u64);
        ch.run_lanes(
            SUB_BATCH,
            &mut rng,
            &mut ln,
            |xs, ys, _zs, _cs, vs, _rgb| {
                for ((x, y), v) in xs.iter().zip(ys).zip(vs) {
                    if *v >= 0.0 {
                        far += (x.abs().max(y.abs()) > 0.01) as u64;
                        total += 1;
                    }
                }
            },
        );
        assert_eq!(total, SUB_BATCH);
        assert!(
            far <= 60,
            "seed {seed}: {far} of {total} samples off the attractor"
        );
    }
}

#[test]
fn hidden_samples_count_and_add_nothing() {
    // crop_stars hides what falls outside its star: those samples come to the origin,
    // count as samples, and are plotted with visibility 0, in the lanes and the scalar
    // loop alike.
    let crop = variations::by_name("crop_stars").unwrap();
    let mut a = Xform::linear(Affine::new(0.9, 0.3, -0.3, 0.9, 0.2, 0.1), 1.0, 0.0);
    a.vars = vec![crate::flame::model::Var::new(crop, 1.0)];
    let mut b = Xform::linear(Affine::new(0.6, 0.0, 0.0, 0.6, -0.3, 0.2), 1.0, 1.0);
    b.vars = vec![crate::flame::model::Var::new(variations::SPHERICAL, 0.5)];
    let f = Flame {
        xforms: vec![a, b],
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    assert!(ch.hides && ch.xforms[0].hides && !ch.xforms[1].hides);
    let at_origin = |x: f64, y: f64| x == 0.0 && y == 0.0;
    let mut rng = FastRng::new(2);
    let mut ln = Lanes::new();
    let (mut n, mut hidden) = (0u64, 0u64);
    for _ in 0..20 {
        ch.run_lanes(10_000, &mut rng, &mut ln, |xs, ys, _zs, _cs, vs, _rgb| {
            for j in 0..xs.len() {
                if vs[j] < 0.0 {
                    continue;
                }
                n += 1;
                if vs[j] == 0.0 {
                    hidden += 1;
                    assert!(at_origin(xs[j], ys[j]));
                } else {
                    assert!(!at_origin(xs[j], ys[j]), "a hidden point was drawn");
                }
            }
        });
    }
    assert_eq!(n, 200_000);
    let (mut m, mut hidden_scalar) = (0u64, 0u64);
    for _ in 0..20 {
        ch.run_sub_batch(10_000, &mut rng, |p, v| {
            m += 1;
            if v == 0.0 {
                hidden_scalar += 1;
                assert!(at_origin(p.x, p.y));
            }
        });
    }
    assert_eq!(m, 200_000);
    let (fl, fs) = (hidden as f64 / 2e5, hidden_scalar as f64 / 2e5);
    assert!(fl > 0.05 && (fl - fs).abs() < 0.02, "{fl} vs {fs}");
}

#[test]
fn affine_ifs_replaces_bad_values_and_keeps_plotting() {
    // An expanding map sends orbits past the bad-value limit: they restart at random
    // points, are counted, and every plotted point is finite.
    let mut f = Flame::default();
    f.xforms.push(Xform::linear(
        Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0),
        1.0,
        0.0,
    ));
    f.xforms.push(Xform::linear(
        Affine::new(1e30, 0.0, 0.0, 1e30, 0.0, 0.0),
        1.0,
        1.0,
    ));
    let ch = Chaos::new(&f).unwrap();
    assert!(ch.affine.is_some());
    let (_, n, _, bad) = lane_grid(&ch, 4);
    assert_eq!(n, 300_000.0);
    assert!(bad > 1000, "{bad} bad values");
}

/// Under JWildfire's rule a point's hide flag travels with it (JWildfire 9.00's
/// `XYZPoint.doHide`, copied by `XForm.transformPoint` from the point read to the point
/// written): an xform without hiding variations passes it on, a crop decides afresh.
/// Map 0 sends every point to (5, 5) through a crop that hides it, map 1 sends every point
/// to the origin through a crop that shows it, and map 2 (linear) keeps the point where it
/// is, hidden or not. So every sample at (5, 5) is hidden (map 0's third of them and map 2's
/// sixth, after map 0), and every sample at the origin is drawn (map 1's third and map 2's
/// sixth); a flag per step would draw map 2's samples at (5, 5).
#[test]
fn jwildfire_carries_the_hide_flag_with_the_point() {
    use crate::flame::PaletteIndex;
    use crate::flame::model::Var;
    let crop = variations::by_name("crop").unwrap();
    let zero = variations::info(crop)
        .params
        .iter()
        .position(|p| p.name == "crop_zero")
        .unwrap();
    let cropped = |e: f64| {
        let mut x = Xform::linear(Affine::new(0.0, 0.0, 0.0, 0.0, e, e), 1.0, 0.0);
        let mut v = Var::new(crop, 1.0);
        v.params[zero] = 1.0;
        x.vars = vec![v];
        // The crop gives the origin for a point it hides: the post map moves it to (5, 5).
        x.post = Affine::new(1.0, 0.0, 0.0, 1.0, e, e);
        x
    };
    let f = Flame {
        xforms: vec![
            cropped(5.0),
            cropped(0.0),
            Xform::linear(Affine::IDENTITY, 1.0, 0.5),
        ],
        palette_index: PaletteIndex::JWildfire,
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    assert!(ch.carry_hide);
    assert!(ch.xforms[0].hides && ch.xforms[1].hides && !ch.xforms[2].hides);
    // (hidden at (5, 5), drawn at (5, 5), drawn at the origin, anything else)
    let mut lanes = [0u64; 4];
    let mut scalar = [0u64; 4];
    let tally = |t: &mut [u64; 4], x: f64, y: f64, v: f64| {
        let k = match (x, y, v > 0.0) {
            (5.0, 5.0, false) => 0,
            (5.0, 5.0, true) => 1,
            (0.0, 0.0, true) => 2,
            _ => 3,
        };
        t[k] += 1;
    };
    let mut rng = FastRng::new(4);
    let mut ln = Lanes::new();
    for _ in 0..4 {
        ch.run_lanes(10_000, &mut rng, &mut ln, |xs, ys, _zs, _cs, vs, _rgb| {
            for j in 0..xs.len() {
                if vs[j] >= 0.0 {
                    tally(&mut lanes, xs[j], ys[j], vs[j]);
                }
            }
        });
        ch.run_sub_batch(10_000, &mut rng, |p, v| tally(&mut scalar, p.x, p.y, v));
    }
    for t in [lanes, scalar] {
        assert_eq!(t.iter().sum::<u64>(), 40_000);
        assert_eq!((t[1], t[3]), (0, 0), "{t:?}");
        for k in [0, 2] {
            assert!((t[k] as f64 / 40_000.0 - 0.5).abs() < 0.03, "{t:?}");
        }
    }
}

/// Under JWildfire's rule a bad point is kept and the orbit goes on from it (JWildfire 9.00's
/// `DefaultRenderIterationState` transforms whatever the point holds and checks it only
/// every 1000 iterations). Map 0 (weight 3) scales by 10²⁰⁰, so two of its steps in a row
/// make any point infinite; map 1, `sineblur`, ignores its input and brings the orbit back.
/// A step is then bad with probability (3/4)², and 7/16 of the samples are drawn: JWildfire
/// 9.00 itself, iterating this flame 4·10⁶ times from two seeds, met 56.0 % and 56.1 % bad
/// steps. An orbit left bad until the next check would draw a few per cent.
#[test]
fn jwildfire_orbits_come_back_from_bad_values() {
    use crate::flame::PaletteIndex;
    use crate::flame::model::Var;
    let big = Xform::linear(Affine::new(1e200, 0.0, 0.0, 1e200, 0.0, 0.0), 3.0, 0.0);
    let mut blur = Xform::linear(Affine::IDENTITY, 1.0, 1.0);
    blur.vars = vec![Var::new(variations::by_name("sineblur").unwrap(), 1.0)];
    let f = Flame {
        xforms: vec![big, blur],
        palette_index: PaletteIndex::JWildfire,
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    assert!(ch.jwf_bad_values && ch.xforms.iter().all(|x| x.keeps_bad));
    let mut rng = FastRng::new(5);
    let mut ln = Lanes::new();
    let mut drawn = 0u64;
    for _ in 0..40 {
        ch.run_lanes(10_000, &mut rng, &mut ln, |xs, ys, zs, _cs, vs, _rgb| {
            for j in 0..xs.len() {
                if vs[j] >= 0.0 {
                    assert!(xs[j].is_finite() && ys[j].is_finite() && zs[j].is_finite());
                    drawn += 1;
                }
            }
        });
    }
    // Every step past the first fuse is one of the 400 000 samples asked for: drawn, or
    // bad and drawing nothing.
    let share = drawn as f64 / 400_000.0;
    assert!((share - 7.0 / 16.0).abs() < 0.01, "{share}");
}

/// A flame JWildfire draws with an orbit variation (hopalong takes the next point of
/// Martin's map at every call, whatever its input): the first orbits are fused one step, so
/// the picture starts near the start of the variation's orbit, as JWildfire's render thread
/// draws it after a 44-step fuse. Fused 1000 steps, the 256 orbits skipped its first 256 000
/// points (sidwellr's hopalong example lost its inner rings: 17.9 dB against JWildfire's
/// picture).
#[test]
fn jwildfire_orbit_variations_draw_their_orbit_from_its_start() {
    use crate::flame::PaletteIndex;
    use crate::flame::model::Var;
    let id = variations::by_name("hopalong").unwrap();
    let (a, b, c, x0, y0) = (0.46, 0.8, -0.006, 0.97, 0.71);
    let mut x = Xform::linear(Affine::IDENTITY, 1.0, 0.0);
    let mut v = Var::new(id, 1.0);
    v.params = vec![2.0, a, b, c, x0, y0];
    x.vars = vec![v];
    let f = Flame {
        xforms: vec![x],
        palette_index: PaletteIndex::JWildfire,
        ..Flame::default()
    };
    let ch = Chaos::new(&f).unwrap();
    // The map's orbit from the start, point k at index k − 1.
    let mut orbit = std::collections::HashMap::new();
    let (mut px, mut py) = (x0, y0);
    for k in 1..=20_000u64 {
        let s = if px > 0.0 {
            1.0
        } else if px < 0.0 {
            -1.0
        } else {
            0.0
        };
        (px, py) = (py - s * (b * px - c).abs().sqrt(), a - px);
        orbit.entry((px.to_bits(), py.to_bits())).or_insert(k);
    }
    let mut rng = FastRng::new(3);
    let mut ln = Lanes::new();
    let mut first = u64::MAX;
    let mut drawn = 0u64;
    ch.run_lanes(10_000, &mut rng, &mut ln, |xs, ys, _zs, _cs, vs, _rgb| {
        for j in 0..xs.len() {
            if vs[j] >= 0.0 {
                let k = orbit.get(&(xs[j].to_bits(), ys[j].to_bits()));
                assert!(k.is_some(), "({}, {}) is no early point", xs[j], ys[j]);
                first = first.min(*k.unwrap());
                drawn += 1;
            }
        }
    });
    assert_eq!(drawn, 10_000);
    // One step of the 256 orbits is fused: the first point drawn is the orbit's 257th.
    assert_eq!(first, LANES as u64 + 1);
}
