//! JWildfire's `taprats` (Jesus Sosa's variation on Craig S. Kaplan's Taprats, the Islamic
//! star pattern designer): one of 49 tilings (`Id`), a rosette (`Rosette Q`, `Rosett  S`) or
//! a star (`Star D`, `Star S`; `Rosette(1/0)` 0) in each of its regular tiles of more than four
//! sides, repeated over the window ±1.5, drawn in one of Taprats' styles (`style`: plain,
//! outline, interlace, emboss, filled, sketch; bands `width` wide, interlacing cut back by
//! `gap`, `fill` for solid bands). The drawing is a list of segments and triangles made once;
//! each call returns a random point of one of them, picked uniformly, with its colour, as
//! JWildfire's `DrawFunc` does (segments 0.005 thick).
//!
//! Formulas and data follow JWildfire 9.00's `TapratsFunc` and `DrawFunc` (LGPL-2.1) and the
//! Taprats code it ships (`csk.taprats`, GPL-3.0), written anew; see `jwf_tp_map`,
//! `jwf_tp_figures`, `jwf_tp_infer`, `jwf_tp_render` and the tilings in `jwf_tp_tiling`.
//! Without `Infer(1/0)` the other tiles stay empty; with it each gets a figure inferred from
//! its neighbours' (`jwf_tp_infer`).

use super::jwf_tp_figures::{Figure, construct};
use super::jwf_tp_infer::infer;
use super::jwf_tp_map::Map;
use super::jwf_tp_render::{FIG, draw};
use super::jwf_tp_tiling::TILINGS;
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("taprats", taprats)
    .params(&[
        p_int("taprats_Id", 0.0, 0.0, 48.0),
        p_int("taprats_style", 2.0, 0.0, 5.0),
        p("taprats_width", 0.06),
        p("taprats_gap", 0.08),
        p_int("taprats_fill", 0.0, 0.0, 1.0),
        p_range("taprats_Rosette Q", 0.0, -1.0, 0.9),
        p_int("taprats_Rosett  S", 2.0, 1.0, 2.0),
        p_int("taprats_Rosette(1/0)", 1.0, 0.0, 1.0),
        p_range("taprats_Star D", 3.0, 1.0, 3.5),
        p_int("taprats_Star S", 2.0, 1.0, 3.0),
        p_int("taprats_Infer(1/0)", 0.0, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
    .shared(&[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10], taprats_figures)];

/// JWildfire's clamp of a parameter, truncated to an integer.
fn int_in(v: f64, lo: f64, hi: f64) -> i32 {
    if v.is_nan() {
        lo as i32
    } else {
        v.clamp(lo, hi) as i32
    }
}

/// The figure table: the design's segments and triangles ([`FIG`] values each).
fn taprats_figures(p: &[f64], _texts: &[String]) -> Vec<f64> {
    let [
        id,
        style,
        width,
        gap,
        fill,
        q,
        s,
        rosette,
        sd,
        ss,
        inferring,
    ] = params_of(p);
    let tiling = &TILINGS[int_in(id, 0.0, (TILINGS.len() - 1) as f64) as usize];
    let q = if q.is_nan() { 0.0 } else { q.clamp(-1.0, 0.9) };
    let sd = if sd.is_nan() { 1.0 } else { sd.clamp(1.0, 3.5) };
    let shapes: Vec<Figure> = tiling
        .features
        .iter()
        .map(|f| {
            if f.is_regular() && f.sides > 4 {
                if int_in(rosette, 0.0, 1.0) == 1 {
                    Figure::Rosette {
                        n: f.sides,
                        q,
                        s: int_in(s, 1.0, 2.0),
                    }
                } else {
                    Figure::Star {
                        n: f.sides,
                        d: sd,
                        s: int_in(ss, 1.0, 3.0),
                    }
                }
            } else {
                Figure::Empty
            }
        })
        .collect();
    let mut figures: Vec<Map> = shapes.iter().map(Figure::map).collect();
    if int_in(inferring, 0.0, 1.0) == 1 {
        // Once for each placed tile without a star or rosette, in the tiling's order, each
        // inference seeing the figures inferred before it.
        for (f, feature) in tiling.features.iter().enumerate() {
            if shapes[f] != Figure::Empty {
                continue;
            }
            for _ in feature.placements {
                figures[f] = infer(tiling, &figures, f);
            }
        }
    }
    let map = construct(tiling, &figures);
    let finite = |x: f64| if x.is_finite() { x } else { 0.0 };
    draw(
        &map,
        int_in(style, 0.0, 5.0),
        finite(width),
        finite(gap),
        int_in(fill, 0.0, 1.0) == 1,
    )
}

/// A random point of the segment a–b as JWildfire's `plotLine` draws it, moved by up to half
/// of `thick` across each axis.
fn line_point(rng: &mut FastRng, [x1, y1, x2, y2]: [f64; 4], thick: f64) -> (f64, f64) {
    let (x, y) = super::jwf_h5_draw::line_point(rng, x1, y1, x2, y2);
    let xo = (rng.f01() - 0.5) * thick;
    let yo = (rng.f01() - 0.5) * thick;
    (x + xo, y + yo)
}

/// A uniform random point of a triangle.
fn triangle_point(rng: &mut FastRng, [x1, y1, x2, y2, x3, y3]: [f64; 6]) -> (f64, f64) {
    let sr = rng.f01().sqrt();
    let r2 = rng.f01();
    let (a, b, c) = (1.0 - sr, sr * (1.0 - r2), r2 * sr);
    (a * x1 + b * x2 + c * x3, a * y1 + b * y2 + c * y3)
}

/// taprats: a random point of a random figure of the design, weighted, with its colour.
fn taprats(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let table = v.data();
    let count = table.len() / FIG;
    if count == 0 {
        return [0.0; 3];
    }
    let i = ((rng.f01() * count as f64) as usize).min(count - 1);
    let Some(f) = table[i * FIG..(i + 1) * FIG].first_chunk::<FIG>() else {
        return [0.0; 3];
    };
    let (x, y) = if f[0] == 3.0 {
        triangle_point(rng, [f[1], f[2], f[3], f[4], f[5], f[6]])
    } else {
        line_point(rng, [f[1], f[2], f[3], f[4]], 0.005)
    };
    acc.color = f[7];
    [v.w * x, v.w * y, 0.0]
}

#[cfg(test)]
mod tests {
    use super::super::jwf_tp_map::{apply, dist};
    use super::*;

    /// Each tiling's features, moved by the translations, meet only at edges: the translated
    /// copies of every tile's corners stay within the lattice's reach and no two placed tiles
    /// of one unit share a centre.
    #[test]
    fn tilings_place_distinct_tiles() {
        assert_eq!(TILINGS.len(), 49);
        for t in TILINGS {
            let det = t.t1[0] * t.t2[1] - t.t1[1] * t.t2[0];
            assert!(det.abs() > 1e-6, "{}: degenerate translations", t.name);
            let mut centres = Vec::new();
            for f in t.features {
                let poly = f.polygon();
                assert_eq!(poly.len(), f.sides, "{}", t.name);
                let c = poly
                    .iter()
                    .fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
                let c = [c[0] / poly.len() as f64, c[1] / poly.len() as f64];
                for pl in f.placements {
                    centres.push(apply(pl, c));
                }
            }
            for (i, a) in centres.iter().enumerate() {
                for b in &centres[i + 1..] {
                    assert!(dist(*a, *b) > 1e-6, "{}: two tiles at {a:?}", t.name);
                }
            }
        }
    }

    /// Every tiling, with inference, in the interlaced and the filled style (and stars
    /// instead of rosettes): a bounded list of finite figures, built in bounded time.
    #[test]
    fn every_tiling_draws() {
        let defaults: Vec<f64> = DEFS[0].params.iter().map(|p| p.default).collect();
        let start = std::time::Instant::now();
        let mut slowest = (0.0, 0);
        for id in 0..TILINGS.len() {
            for (style, fill, rosette) in [(2.0, 0.0, 1.0), (4.0, 1.0, 0.0)] {
                let mut p = defaults.clone();
                (p[0], p[1], p[4], p[7], p[10]) = (id as f64, style, fill, rosette, 1.0);
                let t0 = std::time::Instant::now();
                let table = taprats_figures(&p, &[]);
                let took = t0.elapsed().as_secs_f64();
                if took > slowest.0 {
                    slowest = (took, id);
                }
                assert!(!table.is_empty(), "Id {id} style {style}: nothing drawn");
                assert!(table.len() <= FIG * super::super::jwf_tp_render::MAX_FIGURES);
                assert!(table.iter().all(|v| v.is_finite()), "Id {id}");
            }
        }
        println!(
            "98 designs in {:.2} s, slowest {:.2} s (Id {})",
            start.elapsed().as_secs_f64(),
            slowest.0,
            slowest.1
        );
    }

    /// The default design (csk_7, rosettes): the heptagons' rosettes repeated; the map has
    /// no duplicate vertices and its tiles' rosettes meet at their tips (the vertices of
    /// degree 4 are crossings inside a rosette or tips shared by two).
    #[test]
    fn default_design() {
        let defaults: Vec<f64> = DEFS[0].params.iter().map(|p| p.default).collect();
        let table = taprats_figures(&defaults, &[]);
        assert!(table.len() >= FIG * 100);
        assert_eq!(table.len() % FIG, 0);
        // Interlace without fill: eight segments per edge, six of colour 1.
        let n = table.len() / FIG;
        assert_eq!(n % 8, 0);
        let ones = table.chunks(FIG).filter(|f| f[7] == 1.0).count();
        assert_eq!(ones * 8, n * 6);
        let rosette = Figure::Rosette { n: 7, q: 0.0, s: 2 }.map();
        let map: Map = construct(&TILINGS[0], &[Map::default(), rosette]);
        for (i, &a) in map.pos.iter().enumerate() {
            for &b in &map.pos[i + 1..] {
                assert!(dist(a, b) > 1e-7);
            }
        }
        assert_eq!(n, 8 * map.edges.len());
    }
}
