//! Drawing a JWildfire flame solid ([`super::JwfSolid`]): every bucket of JWildfire's raster
//! keeps the nearest point plotted there (its depth seen by the camera, its place before the
//! camera and its colour coordinate); when the render is done, normals come from the places
//! of neighbouring buckets, screen-space ambient occlusion from the depths around each bucket,
//! and each bucket is lit by the flame's distant lights through its material (ambient,
//! diffuse and a Phong highlight); the lit buckets go through JWildfire's spatial filter and
//! are composed over the background by their coverage.
//!
//! The facts come from JWildfire 9.00's `RasterFloatIntForSolidRendering`,
//! `NormalsCalculator`, `AOCalculator`, `LogDensityFilter` (its solid branches and
//! `addSolidColors`) and `GammaCorrectionFilter`. Not drawn: shadows, reflection maps, and the
//! materials of points whose material coordinate is not 0 (ugnis' points carry none; in
//! JWildfire's flames whose xforms keep the default material 0 it halves at every step and
//! is 0 once the orbit has settled).

use image::DynamicImage;
use rayon::prelude::*;

use super::JwfRaster;
use super::develop::{ToneMap, background, to_image};
use super::kernel::{JwfFilter, JwfKernel};
use super::own_colour::NearestKey;
use super::solid::{JwfMaterial, JwfSolid};
use crate::flame::chaos::{Chaos, Lanes};
use crate::flame::geometry::Geometry;
use crate::flame::histogram::PlotPalette;
use crate::flame::model::Flame;
use crate::flame::tonemap::OutputFormat;
use crate::flame::variations::own_rgb;
use crate::rng::FastRng;

/// One bucket: depth (larger is nearer; [`NO_DEPTH`]: nothing plotted), the point's x, y, z
/// before the camera, its colour coordinate, and the bits of its own colour (0: none; see
/// [`crate::flame::variations::own_rgb`]).
pub type SolidCell = [f32; 6];

/// The depth of a bucket nothing was plotted in (JWildfire's `ZBUF_ZMIN`).
pub const NO_DEPTH: f32 = -f32::MAX;

/// Bytes of one bucket of a worker's [`SolidPlane`].
pub const SOLID_CELL_BYTES: u64 = std::mem::size_of::<SolidCell>() as u64;

/// Bytes per bucket the development of a solid flame adds: the merged plane, the normals,
/// the occlusion (raw and smoothed) and the lit colours.
pub const SOLID_DEVELOP_BYTES: u64 = SOLID_CELL_BYTES + 12 + 8 + 16;

/// A worker's buckets of a solid flame.
#[derive(Clone, Debug)]
pub struct SolidPlane {
    pub cells: Vec<SolidCell>,
}

impl SolidPlane {
    pub fn new(n: usize) -> SolidPlane {
        SolidPlane {
            cells: vec![[NO_DEPTH, 0.0, 0.0, 0.0, 0.0, 0.0]; n],
        }
    }

    /// Keep the nearer of each bucket's points (this plane's on a tie).
    pub fn merge(&mut self, o: &SolidPlane) {
        for (a, b) in self.cells.iter_mut().zip(&o.cells) {
            if b[0] > a[0] {
                *a = *b;
            }
        }
    }
}

/// Whether `flame` is drawn solid by a render of geometry `geom`.
pub fn draws_solid(flame: &Flame, geom: &Geometry) -> bool {
    flame.renders_as_jwildfire() && flame.jwf.solid.enabled && geom.jwf.is_some()
}

/// Buckets per unit before the camera (JWildfire's depth is in these units too).
fn buckets_per_unit(geom: &Geometry) -> f64 {
    let m = &geom.bucket_from_world;
    (m.a * m.d - m.b * m.c).abs().sqrt()
}

/// Iterate `n` samples of a solid flame into `plane`. JWildfire draws solid flames without
/// its antialiasing offsets. Returns the bad values met.
pub(crate) fn iterate_solid(
    chaos: &Chaos,
    geom: &Geometry,
    plane: &mut SolidPlane,
    lanes: &mut Lanes,
    n: u64,
    rng: &mut FastRng,
) -> u64 {
    let map = geom.bucket_map();
    let scale = buckets_per_unit(geom);
    let cells = &mut plane.cells;
    chaos.run_lanes_world(n, rng, lanes, |xs, ys, zs, cs, vs, rgb, w| {
        let m = xs
            .len()
            .min(ys.len())
            .min(zs.len())
            .min(cs.len())
            .min(vs.len())
            .min(w[0].len())
            .min(w[1].len())
            .min(w[2].len());
        for j in 0..m {
            if vs[j].is_nan() || vs[j] <= 0.0 || !(w[0][j] + w[1][j] + w[2][j]).is_finite() {
                continue;
            }
            let (i, inside) = map.index_jwildfire(xs[j], ys[j], (0.0, 0.0));
            let d = (zs[j] * scale) as f32;
            if !inside || !d.is_finite() {
                continue;
            }
            if let Some(c) = cells.get_mut(i as usize)
                && d > c[0]
            {
                let own = rgb.get(j).copied().unwrap_or(0);
                *c = [
                    d,
                    w[0][j] as f32,
                    w[1][j] as f32,
                    w[2][j] as f32,
                    cs[j] as f32,
                    f32::from_bits(own),
                ];
            }
        }
    })
}

/// The neighbour pairs whose cross products give a bucket's normal, in JWildfire's order
/// (`NormalsCalculator`): the four edge neighbours, the four corners, then the eight mixed
/// pairs, each as ((dx, dy), (dx, dy)).
const PAIRS: [((i32, i32), (i32, i32)); 16] = [
    ((0, 1), (1, 0)),
    ((1, 0), (0, -1)),
    ((0, -1), (-1, 0)),
    ((-1, 0), (0, 1)),
    ((-1, 1), (1, 1)),
    ((1, 1), (1, -1)),
    ((1, -1), (-1, -1)),
    ((-1, -1), (-1, 1)),
    ((0, 1), (1, 1)),
    ((1, 1), (1, 0)),
    ((1, 0), (1, -1)),
    ((1, -1), (0, -1)),
    ((0, -1), (-1, -1)),
    ((-1, -1), (-1, 0)),
    ((-1, 0), (-1, 1)),
    ((-1, 1), (0, 1)),
];

/// Neighbour pairs a normal averages at most (JWildfire's final pass).
const NORMAL_SAMPLES: usize = 8;

const EPS: f64 = 1e-8;

/// The unit normal of every bucket (`None` where nothing was plotted or the neighbours give
/// none): the sum of the cross products of the differences to up to [`NORMAL_SAMPLES`]
/// neighbour pairs that were both plotted, normalised.
fn normals(cells: &[SolidCell], bw: usize, bh: usize) -> Vec<Option<[f32; 3]>> {
    (0..bh)
        .into_par_iter()
        .flat_map_iter(|y| {
            (0..bw).map(move |x| {
                let c = cells[y * bw + x];
                if c[0] == NO_DEPTH {
                    return None;
                }
                let p = [c[1] as f64, c[2] as f64, c[3] as f64];
                let at = |dx: i32, dy: i32| -> Option<[f64; 3]> {
                    let (nx, ny) = (x as i64 + dx as i64, y as i64 + dy as i64);
                    if nx < 0 || ny < 0 || nx >= bw as i64 || ny >= bh as i64 {
                        return None;
                    }
                    let q = cells[ny as usize * bw + nx as usize];
                    (q[0] != NO_DEPTH)
                        .then(|| [p[0] - q[1] as f64, p[1] - q[2] as f64, p[2] - q[3] as f64])
                };
                let mut n = [0.0; 3];
                let mut samples = 0;
                for &((ax, ay), (bx, by)) in &PAIRS {
                    if let (Some(a), Some(b)) = (at(ax, ay), at(bx, by)) {
                        samples += 1;
                        n[0] += a[1] * b[2] - a[2] * b[1];
                        n[1] += a[2] * b[0] - a[0] * b[2];
                        n[2] += a[0] * b[1] - a[1] * b[0];
                    }
                    if samples >= NORMAL_SAMPLES {
                        break;
                    }
                }
                let r = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                (samples > 0 && r > EPS).then(|| n.map(|v| (v / r) as f32))
            })
        })
        .collect()
}

/// JWildfire's rounding of a coordinate to a whole bucket (halves away from zero).
fn ftoi(v: f64) -> i64 {
    if v > 0.0 {
        (v + 0.5) as i64
    } else if v < 0.0 {
        -((v.abs() + 0.5) as i64)
    } else {
        0
    }
}

/// JWildfire's screen-space ambient occlusion (`AOCalculator`): around each bucket with a
/// normal, along a few directions, the highest horizon the depths rise to against the tangent
/// plane the normal spans, each new height adding its rise, fading with the distance; then
/// smoothed by a Gaussian (and scaled by 0.1) when the blur radius reaches 0.42 buckets.
fn occlusion(
    s: &JwfSolid,
    cells: &[SolidCell],
    nrm: &[Option<[f32; 3]>],
    bw: usize,
    bh: usize,
) -> Vec<f32> {
    let img = ((bw * bw + bh * bh) as f64).sqrt();
    let search = s.ao_search_radius.clamp(0.25, 120.0);
    let blur = s.ao_blur_radius.clamp(0.25, 10.0) * img / 500.0;
    let falloff = s.ao_falloff.clamp(0.0, 10.0);
    let r_samples = s.ao_radius_samples.clamp(1, 128) as usize;
    let a_samples = s.ao_azimuth_samples.clamp(1, 128) as usize;
    let sphere = search * img / 500.0;
    let r_step = sphere / r_samples as f64;
    let a_step = std::f64::consts::TAU / a_samples as f64;
    let jitter = r_step / 10.0;
    const BIAS: f64 = 0.001;
    let z_at = |x: f64, y: f64| -> f64 {
        let xi = ftoi(x).clamp(0, bw as i64 - 1) as usize;
        let yi = ftoi(y).clamp(0, bh as i64 - 1) as usize;
        cells[yi * bw + xi][0] as f64
    };
    let raw: Vec<f32> = (0..bh)
        .into_par_iter()
        .flat_map_iter(|i| {
            let mut rng = FastRng::for_stream(32_851_137, i as u64);
            (0..bw)
                .map(|j| {
                    let k = i * bw + j;
                    let (Some(n), z0) = (nrm[k], cells[k][0] as f64) else {
                        return 0.0;
                    };
                    let [nx, ny, nz] = n.map(|v| v as f64);
                    let (x0, y0) = (j as f64, i as f64);
                    let mut ao = 0.0;
                    let mut angle = (0.5 - rng.f01()) * a_step / 4.0;
                    for _ in 0..a_samples {
                        let (dy, dx) = angle.sin_cos();
                        let mut r0 = r_step;
                        let mut prev = 0.0;
                        for _ in 0..r_samples {
                            let r = r0 + (0.5 - rng.f01()) * jitter;
                            let x = x0 + r * dx + (0.5 - rng.f01()) * jitter;
                            let y = y0 + r * dy + (0.5 - rng.f01()) * jitter;
                            let h = (z_at(x, y) - z0).atan2(r) + BIAS;
                            // JWildfire takes the direction from the picture's corner to the
                            // sampled place as the tangent's direction.
                            let rr = (x * x + y * y).sqrt();
                            let (rx, ry) = (x / rr, y / rr);
                            let tt = nx * rx + ry * ny;
                            let tx = -(ry * nx * ny - rx * ny * ny - rx * nz * nz) / tt;
                            let ty = (ry * nx * nx + ry * nz * nz - nx * rx * ny) / tt;
                            let tz = (-ry * ny * nz - nx * rx * nz) / tt;
                            let ta = tz.atan2((tx * tx + ty * ty).sqrt());
                            let v = h.sin() - ta.sin();
                            if v > prev {
                                prev = v;
                                let d = r / sphere;
                                ao += v * (-d * d * falloff).exp() * 0.5;
                            }
                            r0 += r_step;
                        }
                        angle += a_step;
                    }
                    ao as f32
                })
                .collect::<Vec<f32>>()
        })
        .collect();
    if blur < 0.42 {
        return raw;
    }
    let f = JwfFilter::new(JwfKernel::Gaussian, blur, 1);
    let size = f.size.max(1);
    let centre = size / 2;
    (0..bh)
        .into_par_iter()
        .flat_map_iter(|i| {
            let (f, raw) = (&f, &raw);
            (0..bw).map(move |j| {
                let mut v = 0.0;
                for k in 0..size {
                    let px = j as i64 + k as i64 - centre as i64;
                    if px < 0 || px >= bw as i64 {
                        continue;
                    }
                    for l in 0..size {
                        let py = i as i64 + l as i64 - centre as i64;
                        if py < 0 || py >= bh as i64 {
                            continue;
                        }
                        let t = f.taps.get(l * size + k).copied().unwrap_or(0.0);
                        v += raw[py as usize * bw + px as usize] as f64 * t;
                    }
                }
                (v * 0.1) as f32
            })
        })
        .collect()
}

/// The lit colour of a bucket (0..=255 units) as JWildfire's `addSolidColors` lights it:
/// the object's colour `obj` (0..=1) times the ambient strength, plus for each light facing
/// the surface its colour (plus a third of the ambient object colour) times the diffuse
/// response, plus the material's highlight colour times the Phong response.
fn shade(
    s: &JwfSolid,
    mat: &JwfMaterial,
    lights: &[[f64; 3]],
    obj: [f64; 3],
    n: [f64; 3],
    ao: f64,
) -> [f64; 3] {
    let ao_int = s.ao_intensity.clamp(0.0, 4.0);
    let (ambient, diffuse) = if s.ao_enabled {
        (
            (mat.ambient - ao * ao_int).max(0.0),
            (mat.diffuse - ao * ao_int * s.ao_affect_diffuse).max(0.0),
        )
    } else {
        (mat.ambient.max(0.0), mat.diffuse.max(0.0))
    };
    let mut c = obj.map(|v| v * ambient);
    for (l, d) in s.lights.iter().zip(lights) {
        let cosa = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
        if cosa > EPS {
            let k = mat.light_diff.eval(cosa) * diffuse * l.intensity;
            for ch in 0..3 {
                c[ch] += (l.color[ch] + obj[ch] * ambient / 3.0) * k;
            }
        }
        if mat.phong > EPS {
            // The light reflected about the normal, seen along the view axis (0, 0, 1).
            let vr = d[2] - 2.0 * cosa * n[2];
            if vr < EPS {
                let k = mat.light_diff.eval(-vr).powf(mat.phong_size) * mat.phong * l.intensity;
                for (v, p) in c.iter_mut().zip(mat.phong_color) {
                    *v += p * k;
                }
            }
        }
    }
    c.map(|v| v * 255.0)
}

/// Develop a solid flame from the merged `plane` into the picture (its rows `out_rows`).
#[allow(clippy::too_many_arguments)] // the parts of one develop step, as for the density flames
pub(crate) fn develop_solid(
    flame: &Flame,
    geom: &Geometry,
    filters: &JwfRaster,
    plane: &SolidPlane,
    pal: &PlotPalette,
    format: OutputFormat,
    out_rows: std::ops::Range<usize>,
) -> Option<DynamicImage> {
    let s = &flame.jwf.solid;
    let (bw, bh) = (geom.bw, geom.bh);
    let cells = &plane.cells;
    if cells.len() != bw * bh {
        return None;
    }
    let nrm = normals(cells, bw, bh);
    let ao = if s.ao_enabled {
        occlusion(s, cells, &nrm, bw, bh)
    } else {
        Vec::new()
    };
    let lights: Vec<[f64; 3]> = s.lights.iter().map(|l| l.direction()).collect();
    // The material of material coordinate 0 (see the module's note).
    let mat = s.material(0.0);
    // JWildfire's palette colours run to 200/256 of full, and are balanced.
    // JWildfire's palette colours run to 200/256 of their bytes; a colour of the point's own
    // counts its bytes as they are.
    let bal = flame.jwf.balance.map(|b| b / 255.0);
    let top = pal.colors.len().saturating_sub(1);
    let palette = |p: [f32; 4]| [p[0], p[1], p[2]].map(|v| v as f64 * 200.0 / 256.0);
    let lit: Vec<Option<[f32; 3]>> = (0..bw * bh)
        .into_par_iter()
        .map_init(
            || NearestKey::new(pal),
            |near, k| {
                let n = nrm[k]?;
                let Some(mat) = &mat else {
                    return Some([0.0; 3]);
                };
                let own = cells[k][5].to_bits();
                let bytes = if own == 0 {
                    palette(pal.lookup(cells[k][4] as f64))
                } else if own & own_rgb::INDEX != 0 {
                    palette(pal.colors[(own as usize & 0xff).min(top)])
                } else if own & own_rgb::NEAREST != 0 {
                    near.find(own).map(f64::from)
                } else {
                    own_rgb::channels(own).map(f64::from)
                };
                let obj = [0, 1, 2].map(|ch| bytes[ch] * bal[ch]);
                let a = ao.get(k).copied().unwrap_or(0.0) as f64;
                let c = shade(s, mat, &lights, obj, n.map(|v| v as f64), a);
                Some(c.map(|v| v as f32))
            },
        )
        .collect();
    let os = filters.os;
    let (w, h) = (geom.width, geom.height);
    let f = &filters.primary;
    let at = |x: isize, y: isize| -> Option<[f32; 3]> {
        if x < 0 || y < 0 || x >= bw as isize || y >= bh as isize {
            return None;
        }
        lit[y as usize * bw + x as usize]
    };
    let tm = ToneMap::new(flame, format.transparent);
    let rows: Vec<usize> = out_rows.collect();
    let pixels: Vec<Vec<([f64; 3], f64)>> = rows
        .par_iter()
        .map(|&py| {
            (0..w)
                .map(|px| {
                    let (x0, nx) = filters.window(f, px);
                    let (y0, ny) = filters.window(f, py);
                    let mut c = [0.0; 3];
                    let mut cover = 0.0;
                    if f.is_empty() {
                        // The mean of the lit buckets of the pixel, covering their share.
                        let mut count = 0usize;
                        for i in 0..ny {
                            for j in 0..nx {
                                if let Some(l) = at(x0 + j as isize, y0 + i as isize) {
                                    count += 1;
                                    for ch in 0..3 {
                                        c[ch] += l[ch] as f64;
                                    }
                                }
                            }
                        }
                        if count > 0 {
                            c = c.map(|v| v / count as f64);
                            cover = count as f64 / (os * os) as f64;
                        }
                    } else {
                        for i in 0..ny {
                            for j in 0..nx {
                                if let Some(l) = at(x0 + j as isize, y0 + i as isize) {
                                    let t = f.taps.get(i * f.size + j).copied().unwrap_or(0.0)
                                        / (os * os) as f64;
                                    cover += t;
                                    for ch in 0..3 {
                                        c[ch] += t * l[ch] as f64;
                                    }
                                }
                            }
                        }
                    }
                    let bg = background(&flame.jwf.background, flame.background, px, py, w, h);
                    tm.solid_pixel(c, cover.max(0.0), bg)
                })
                .collect()
        })
        .collect();
    to_image(&pixels, w, rows.len(), format)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tilted plane z = 0.5·x plotted on a grid: every inner bucket's normal is the plane's
    /// (up to sign: JWildfire does not turn normals towards the viewer), and the corner and
    /// edge buckets get one too.
    #[test]
    fn normals_of_a_plane() {
        let (bw, bh) = (6, 5);
        let mut cells = vec![[NO_DEPTH, 0.0, 0.0, 0.0, 0.0, 0.0]; bw * bh];
        for y in 0..bh {
            for x in 0..bw {
                let (wx, wy) = (x as f32 * 0.1, y as f32 * 0.1);
                cells[y * bw + x] = [wx * 0.5, wx, wy, wx * 0.5, 0.0, 0.0];
            }
        }
        // One empty bucket: no normal there.
        cells[2 * bw + 3][0] = NO_DEPTH;
        let n = normals(&cells, bw, bh);
        let want = {
            let l = (1.0f64 + 0.25).sqrt();
            [-0.5 / l, 0.0, 1.0 / l]
        };
        for (k, v) in n.iter().enumerate() {
            if k == 2 * bw + 3 {
                assert!(v.is_none());
                continue;
            }
            let v = v.expect("a normal");
            let dot: f64 = (0..3).map(|i| v[i] as f64 * want[i]).sum();
            assert!((dot.abs() - 1.0).abs() < 1e-5, "{k}: {v:?}");
        }
    }

    /// A light along the view axis (travelling along −z): a surface facing it gets ambient
    /// plus full diffuse (with its third of the object colour) and no highlight (the
    /// reflection goes back to the viewer, which JWildfire's test `vr < ε` leaves out); a
    /// surface edge-on gets ambient plus the full highlight; one facing away ambient only.
    #[test]
    fn shade_by_normal() {
        let mut s = JwfSolid {
            ao_enabled: false,
            ..JwfSolid::default()
        };
        s.lights.truncate(1);
        s.lights[0].altitude = 0.0;
        s.lights[0].azimuth = 0.0;
        s.lights[0].intensity = 0.5;
        let mat = s.materials[0].clone();
        let d = [s.lights[0].direction()];
        let obj = [0.4, 0.2, 0.0];
        let check = |n: [f64; 3], want: [f64; 3]| {
            let c = shade(&s, &mat, &d, obj, n, 0.0);
            for ch in 0..3 {
                assert!((c[ch] - want[ch] * 255.0).abs() < 1e-9, "{n:?}: {c:?}");
            }
        };
        let amb = obj.map(|v| v * mat.ambient);
        check(
            [0.0, 0.0, -1.0],
            [0, 1, 2].map(|ch| amb[ch] + (1.0 + amb[ch] / 3.0) * mat.diffuse * 0.5),
        );
        check(
            [1.0, 0.0, 0.0],
            [0, 1, 2].map(|ch| amb[ch] + mat.phong_color[ch] * mat.phong * 0.5),
        );
        check([0.0, 0.0, 1.0], amb);
    }

    #[test]
    fn ftoi_rounds_halves_away_from_zero() {
        assert_eq!([2.5, 2.49, -2.5, -0.2, 0.0].map(ftoi), [3, 2, -3, 0, 0]);
    }
}
