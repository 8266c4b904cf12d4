//! `knots3D`, JWildfire's knotted tubes: a tube around one of JWildfire's 24 stock knot curves,
//! as a triangle mesh built once, with points uniform on a random triangle.
//!
//! The formulas follow JWildfire's (Andreas Maschke and contributors, LGPL-2.1) mathematics,
//! written anew. JWildfire's conventions are kept: `atan_xy` is its `getPrecalcAtan`
//! (atan2(x, y)), weights multiply the output linearly, integer parameters are rounded (those it
//! truncates, `(int) value`, are stored as reals and truncated where used), and random numbers
//! are drawn in the order JWildfire draws them, so that the tests can replay JWildfire's own code
//! on the same stream.

use std::f64::consts::PI;

use super::*;
use Trig::{Cos, Sin};

pub(super) static DEFS: &[VarDef] = &[VarDef::new("knots3D", knots3d)
    .params(&[
        p_int("knots3D_presetId", 0.0, NEG_INF, INF),
        p_int("knots3D_steps", 1000.0, 1.0, 1_000_000.0),
        p("knots3D_radius", 1.05),
        p_int("knots3D_facets", 4.0, 1.0, 1000.0),
        p("knots3D_param_a", 0.0),
        p("knots3D_param_b", 0.0),
        p("knots3D_param_c", 0.0),
        p("knots3D_param_d", 0.0),
        p("knots3D_param_e", 0.0),
        p("knots3D_param_f", 0.0),
        p("knots3D_param_g", 0.0),
        p("knots3D_param_h", 0.0),
        p("knots3D_scale_x", 0.02),
        p("knots3D_scale_y", 0.02),
        p("knots3D_scale_z", 0.02),
        p("knots3D_offset_x", 0.0),
        p("knots3D_offset_y", 0.0),
        p("knots3D_offset_z", 0.0),
        p_int("knots3D_subdiv_level", 0.0, 0.0, 6.0),
        p_int("knots3D_subdiv_smooth_passes", 12.0, 0.0, 24.0),
        p("knots3D_subdiv_smooth_lambda", 0.42),
        p("knots3D_subdiv_smooth_mu", -0.45),
        p_int("knots3D_blend_colormap", 1.0, 0.0, 1.0),
        p("knots3D_displ_amount", 0.1),
        p_int("knots3D_blend_displ_map", 1.0, 0.0, 1.0),
        p_int("knots3D_receive_only_shadows", 0.0, 0.0, 1.0),
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z)
    .shared(
        &[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17],
        knots3d_faces,
    )];

/// The function of a Fourier knot term.
#[derive(Clone, Copy)]
enum Trig {
    Cos,
    Sin,
}

impl Trig {
    fn of(self, a: f64) -> f64 {
        match self {
            Cos => a.cos(),
            Sin => a.sin(),
        }
    }
}

/// One term c·cos(k·t) or c·sin(k·t) of a Fourier knot coordinate: (c, k, function).
type KnotTerm = (i16, u8, Trig);

enum KnotCurve {
    /// x, y and z as sums of terms.
    Fourier([&'static [KnotTerm]; 3]),
    /// ((a + b·cos(c·t))·cos(d·t), (a + b·cos(c·t))·sin(d·t), b·sin(c·t)).
    Torus,
    /// (a·cos(b·t + e), a·cos(c·t + f), a·cos(d·t + g)).
    Lissajous,
}

/// knots3D's stock curves, by preset id (JWildfire's knots3d_wf presets 0-23): Fourier sums
/// Σ c·cos(k·t) / c·sin(k·t) per axis (terms (c, k, Cos|Sin)), torus knots and Lissajous knots.
#[rustfmt::skip]
static KNOT_CURVES: [KnotCurve; 24] = [
    KnotCurve::Fourier([
        &[(-10, 1, Cos), (-2, 5, Cos), (15, 2, Sin)],
        &[(-15, 2, Cos), (10, 1, Sin), (-2, 5, Sin)],
        &[(10, 3, Cos)],
    ]),
    KnotCurve::Fourier([
        &[(-22, 1, Cos), (-128, 1, Sin), (-44, 3, Cos), (-78, 3, Sin)],
        &[(-10, 2, Cos), (-27, 2, Sin), (38, 4, Cos), (46, 4, Sin)],
        &[(70, 3, Cos), (-40, 3, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-22, 1, Cos), (-128, 1, Sin), (-44, 3, Cos), (-78, 3, Sin)],
        &[(11, 1, Cos), (-43, 3, Cos), (34, 5, Cos), (-39, 5, Sin)],
        &[(70, 3, Cos), (-40, 3, Sin), (8, 5, Cos), (-9, 5, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(10, 1, Cos), (10, 3, Cos)],
        &[(6, 1, Sin), (10, 3, Sin)],
        &[(4, 3, Sin), (-10, 6, Sin)],
    ]),
    KnotCurve::Torus,
    KnotCurve::Torus,
    KnotCurve::Fourier([
        &[(41, 1, Cos), (-18, 1, Sin), (-83, 2, Cos), (-83, 2, Sin), (-11, 3, Cos), (27, 3, Sin)],
        &[(6, 1, Cos), (27, 1, Sin), (-113, 2, Cos), (30, 2, Sin), (11, 3, Cos), (-27, 3, Sin)],
        &[(45, 1, Sin), (-30, 2, Cos), (113, 2, Sin), (-11, 3, Cos), (27, 3, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(32, 1, Cos), (-51, 1, Sin), (-104, 2, Cos), (-34, 2, Sin), (104, 3, Cos), (-91, 3, Sin)],
        &[(94, 1, Cos), (41, 1, Sin), (113, 2, Cos), (-68, 3, Cos), (-124, 3, Sin)],
        &[(16, 1, Cos), (73, 1, Sin), (-211, 2, Cos), (-39, 2, Sin), (-99, 3, Cos), (-21, 3, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(88, 1, Cos), (115, 1, Sin), (-475, 2, Cos), (-127, 2, Sin), (-87, 3, Cos), (36, 3, Sin),
          (11, 4, Cos), (-19, 4, Sin)],
        &[(89, 1, Cos), (-32, 1, Sin), (-172, 2, Cos), (294, 2, Sin), (76, 3, Cos), (102, 3, Sin),
          (-61, 4, Cos), (113, 4, Sin)],
        &[(44, 1, Cos), (-69, 1, Sin), (34, 2, Cos), (223, 2, Sin), (16, 3, Cos), (120, 3, Sin),
          (42, 4, Cos), (-125, 4, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-33, 1, Cos), (43, 1, Sin), (214, 2, Sin), (-101, 3, Cos), (-47, 3, Sin), (11, 4, Sin)],
        &[(-57, 1, Cos), (99, 1, Sin), (-54, 2, Cos), (-159, 2, Sin), (-117, 3, Cos), (-5, 3, Sin),
          (-31, 4, Cos), (-45, 4, Sin)],
        &[(34, 1, Cos), (-21, 1, Sin), (-100, 2, Cos), (-93, 2, Sin), (-27, 3, Cos), (-16, 3, Sin),
          (52, 4, Cos), (84, 4, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(12, 1, Cos), (20, 1, Sin), (-163, 2, Cos), (76, 2, Sin), (-87, 3, Cos), (-15, 3, Sin),
          (-21, 4, Cos), (14, 4, Sin), (24, 5, Cos), (-50, 5, Sin)],
        &[(29, 1, Cos), (78, 1, Sin), (-180, 2, Cos), (58, 2, Sin), (88, 3, Cos), (72, 3, Sin),
          (-14, 4, Sin)],
        &[(-30, 1, Cos), (-78, 1, Sin), (-111, 2, Cos), (37, 2, Sin), (-67, 3, Cos), (-51, 3, Sin),
          (31, 4, Cos), (8, 4, Sin), (-11, 5, Cos), (65, 5, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-6, 1, Cos), (-21, 1, Sin), (-195, 2, Cos), (92, 2, Sin), (-64, 3, Cos), (-23, 3, Sin),
          (-6, 4, Cos), (13, 4, Sin), (24, 5, Cos), (15, 5, Sin), (41, 6, Sin)],
        &[(-21, 1, Cos), (-24, 1, Sin), (-207, 2, Cos), (-72, 2, Sin), (112, 3, Cos), (-7, 3, Sin),
          (-13, 4, Cos), (-40, 4, Sin), (-27, 5, Cos), (-3, 5, Sin), (-17, 6, Cos)],
        &[(-18, 1, Cos), (-13, 1, Sin), (113, 2, Cos), (-107, 2, Sin), (86, 3, Cos), (-9, 3, Sin),
          (-26, 4, Cos), (-7, 4, Sin), (24, 5, Cos), (33, 5, Sin), (21, 6, Cos), (31, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-40, 1, Cos), (32, 1, Sin), (69, 2, Cos), (-12, 2, Sin), (120, 3, Cos), (-52, 3, Sin),
          (-56, 4, Cos), (46, 4, Sin), (-17, 5, Sin), (14, 6, Cos), (19, 6, Sin)],
        &[(90, 1, Cos), (89, 1, Sin), (-142, 2, Cos), (147, 2, Sin), (74, 3, Cos), (85, 3, Sin),
          (-56, 4, Sin), (23, 5, Cos), (16, 6, Cos), (7, 6, Sin)],
        &[(52, 1, Cos), (64, 1, Sin), (53, 2, Cos), (35, 2, Sin), (77, 3, Cos), (-87, 3, Sin),
          (101, 4, Cos), (-19, 4, Sin), (-5, 5, Cos), (2, 5, Sin), (3, 6, Cos), (9, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(54, 1, Cos), (-4, 1, Sin), (-239, 2, Cos), (-44, 2, Sin), (-45, 3, Cos), (-17, 3, Sin),
          (-33, 4, Cos), (-27, 4, Sin), (19, 5, Cos), (19, 5, Sin), (-8, 6, Cos), (15, 6, Sin)],
        &[(-16, 1, Cos), (-43, 1, Sin), (11, 2, Cos), (170, 2, Sin), (-22, 3, Cos), (41, 3, Sin),
          (21, 4, Cos), (2, 5, Cos), (-12, 5, Sin), (-43, 6, Cos), (26, 6, Sin)],
        &[(-55, 1, Sin), (-78, 2, Cos), (189, 2, Sin), (-38, 3, Cos), (41, 3, Sin), (10, 4, Cos),
          (-16, 4, Sin), (-38, 5, Cos), (18, 5, Sin), (22, 6, Cos), (-15, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(10, 1, Cos), (115, 1, Sin), (-184, 2, Cos), (10, 2, Sin), (101, 3, Sin), (23, 4, Cos),
          (55, 4, Sin), (-38, 5, Cos), (-6, 5, Sin), (-14, 6, Cos), (8, 6, Sin), (16, 6, Cos),
          (14, 6, Sin)],
        &[(42, 1, Cos), (-104, 1, Sin), (-252, 2, Cos), (47, 2, Sin), (-21, 3, Cos), (-65, 3, Sin),
          (-23, 4, Cos), (-23, 4, Sin), (36, 5, Cos), (-10, 5, Sin), (-13, 6, Cos), (2, 6, Sin),
          (-18, 7, Cos), (-9, 7, Sin)],
        &[(30, 1, Sin), (20, 2, Cos), (19, 2, Sin), (6, 3, Cos), (-31, 3, Sin), (-4, 4, Cos),
          (-24, 4, Sin), (-44, 5, Cos), (-50, 5, Sin), (31, 6, Cos), (39, 6, Sin), (-16, 7, Cos),
          (23, 7, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-14, 1, Cos), (-19, 1, Sin), (-53, 2, Cos), (-120, 2, Sin), (71, 3, Cos), (-50, 3, Sin),
          (-47, 4, Cos), (-86, 4, Sin), (9, 5, Cos), (-5, 5, Sin), (12, 6, Cos), (22, 6, Sin)],
        &[(-11, 1, Cos), (13, 1, Sin), (-294, 2, Cos), (112, 2, Sin), (29, 3, Cos), (-22, 3, Sin),
          (4, 4, Cos), (11, 4, Sin), (-6, 5, Cos), (-14, 6, Cos), (18, 6, Sin)],
        &[(28, 1, Cos), (9, 1, Sin), (-39, 2, Cos), (-60, 2, Sin), (-60, 3, Cos), (21, 3, Sin),
          (50, 4, Cos), (-11, 4, Sin), (44, 5, Cos), (-63, 5, Sin), (14, 6, Cos), (9, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(32, 1, Cos), (10, 1, Sin), (-12, 2, Cos), (10, 2, Sin), (48, 3, Cos), (75, 3, Sin),
          (-32, 4, Cos), (12, 4, Sin), (3, 5, Cos), (-8, 5, Sin), (-2, 6, Cos), (-4, 6, Sin)],
        &[(-16, 1, Cos), (-10, 1, Sin), (-90, 2, Cos), (129, 2, Sin), (-6, 3, Cos), (-8, 3, Sin),
          (-19, 4, Cos), (-6, 4, Sin), (-8, 5, Cos), (6, 5, Sin), (4, 6, Cos), (13, 6, Sin)],
        &[(-12, 1, Cos), (1, 1, Sin), (-55, 2, Cos), (32, 2, Sin), (-10, 3, Cos), (-13, 3, Sin),
          (2, 4, Cos), (26, 4, Sin), (17, 5, Cos), (9, 5, Sin), (15, 6, Cos), (-21, 6, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(5, 1, Cos), (5, 1, Sin), (-163, 2, Cos), (-80, 2, Sin), (-28, 3, Cos), (15, 3, Sin),
          (-20, 4, Cos), (13, 4, Sin), (-11, 5, Cos), (-12, 5, Sin), (4, 6, Cos), (-19, 6, Sin),
          (12, 7, Cos), (2, 7, Sin)],
        &[(-31, 1, Cos), (6, 1, Sin), (-113, 2, Cos), (81, 2, Sin), (87, 3, Cos), (4, 3, Sin),
          (5, 4, Cos), (18, 4, Sin), (-4, 5, Cos), (11, 5, Sin), (-17, 6, Cos), (5, 6, Sin),
          (-6, 7, Cos), (-13, 7, Sin)],
        &[(-11, 1, Cos), (-3, 1, Sin), (21, 2, Cos), (31, 2, Sin), (8, 3, Cos), (2, 3, Sin),
          (2, 4, Cos), (13, 4, Sin), (27, 5, Cos), (7, 5, Sin), (-8, 6, Cos), (-29, 6, Sin),
          (11, 7, Cos), (-8, 7, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-17, 1, Cos), (80, 1, Sin), (-70, 2, Cos), (-190, 2, Sin), (-26, 3, Cos), (-145, 3, Sin),
          (-62, 4, Cos), (-31, 4, Sin), (26, 5, Cos), (13, 5, Sin), (-2, 6, Cos), (8, 6, Sin),
          (-10, 7, Cos), (9, 7, Sin)],
        &[(102, 1, Cos), (-151, 1, Sin), (-36, 2, Cos), (-25, 2, Sin), (200, 3, Cos), (-18, 3, Sin),
          (-30, 4, Cos), (28, 4, Sin), (-7, 5, Cos), (2, 5, Sin), (13, 6, Cos), (-11, 6, Sin),
          (-5, 7, Cos), (-1, 7, Sin)],
        &[(58, 1, Cos), (-17, 1, Sin), (-5, 2, Cos), (-27, 2, Sin), (66, 3, Cos), (-38, 3, Sin),
          (28, 4, Cos), (-80, 4, Sin), (-35, 5, Cos), (28, 5, Sin), (-26, 6, Cos), (-34, 6, Sin),
          (32, 7, Cos), (1, 7, Sin)],
    ]),
    KnotCurve::Fourier([
        &[(-5, 1, Cos), (8, 2, Cos), (83, 2, Sin), (87, 3, Cos), (100, 3, Sin), (-5, 4, Cos),
          (22, 4, Sin), (-10, 5, Cos), (10, 5, Sin), (-2, 6, Cos), (-10, 6, Sin), (5, 7, Cos),
          (6, 7, Sin)],
        &[(17, 1, Cos), (21, 1, Sin), (-174, 2, Cos), (13, 2, Sin), (-15, 3, Cos), (3, 3, Sin),
          (-9, 4, Cos), (46, 4, Sin), (16, 5, Cos), (-25, 5, Sin), (-21, 6, Cos), (7, 6, Sin),
          (-9, 7, Cos), (-3, 7, Sin)],
        &[(-28, 1, Cos), (9, 1, Sin), (110, 2, Cos), (4, 2, Sin), (11, 3, Cos), (-6, 3, Sin),
          (-46, 4, Cos), (-17, 4, Sin), (32, 5, Cos), (-9, 5, Sin), (-12, 6, Cos), (-9, 6, Sin),
          (-9, 7, Cos), (18, 7, Sin)],
    ]),
    KnotCurve::Lissajous,
    KnotCurve::Lissajous,
    KnotCurve::Lissajous,
    KnotCurve::Lissajous,
];

/// Point `step` of `steps` along a knot curve (t = 2π·step/steps); `k` = params a…h.
fn knot_point(curve: &KnotCurve, k: &[f64], step: usize, steps: f64) -> [f64; 3] {
    let t = 2.0 * PI * step as f64 / steps;
    match curve {
        KnotCurve::Fourier(axes) => axes.map(|terms| {
            terms
                .iter()
                .fold(0.0, |s, &(c, m, f)| s + c as f64 * f.of(m as f64 * t))
        }),
        KnotCurve::Torus => {
            let ring = k[0] + k[1] * (k[2] * t).cos();
            let (sd, cd) = (k[3] * t).sin_cos();
            [ring * cd, ring * sd, k[1] * (k[2] * t).sin()]
        }
        KnotCurve::Lissajous => [
            k[0] * (k[1] * t + k[4]).cos(),
            k[0] * (k[2] * t + k[5]).cos(),
            k[0] * (k[3] * t + k[6]).cos(),
        ],
    }
}

/// An affine rotation through `angle` about the axis through `at` with direction `dir` (as in
/// Ammeraal's "Interactive 3D Computer Graphics"): rows of a 4×3 matrix.
struct AxisRotation([f64; 12]);

impl AxisRotation {
    fn new(at: [f64; 3], dir: [f64; 3], angle: f64) -> Self {
        let (sal, cal) = angle.sin_cos();
        let cal1 = 1.0 - cal;
        let [v1, v2, v3] = dir;
        let rho = (v1 * v1 + v2 * v2 + v3 * v3).sqrt();
        let (theta, cph, sph) = if rho == 0.0 {
            (0.0, 1.0, 0.0)
        } else {
            let theta = if v1 == 0.0 {
                if v2 >= 0.0 { 0.5 * PI } else { 1.5 * PI }
            } else if v1 < 0.0 {
                (v2 / v1).atan() + PI
            } else {
                (v2 / v1).atan()
            };
            let cph = v3 / rho;
            (theta, cph, (1.0 - cph * cph).sqrt())
        };
        let (sth, cth) = theta.sin_cos();
        let cph2 = cph * cph;
        let sph2 = 1.0 - cph2;
        let cth2 = cth * cth;
        let sth2 = 1.0 - cth2;
        let r11 = (cal * cph2 + sph2) * cth2 + cal * sth2;
        let r12 = sal * cph + cal1 * sph2 * cth * sth;
        let r13 = sph * (cph * cth * cal1 - sal * sth);
        let r21 = sph2 * cth * sth * cal1 - sal * cph;
        let r22 = sth2 * (cal * cph2 + sph2) + cal * cth2;
        let r23 = sph * (cph * sth * cal1 + sal * cth);
        let r31 = sph * (cph * cth * cal1 + sal * sth);
        let r32 = sph * (cph * sth * cal1 - sal * cth);
        let r33 = cal * sph2 + cph2;
        let [a1, a2, a3] = at;
        let r41 = a1 - a1 * r11 - a2 * r21 - a3 * r31;
        let r42 = a2 - a1 * r12 - a2 * r22 - a3 * r32;
        let r43 = a3 - a1 * r13 - a2 * r23 - a3 * r33;
        AxisRotation([r11, r12, r13, r21, r22, r23, r31, r32, r33, r41, r42, r43])
    }

    fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        let r = &self.0;
        [
            p[0] * r[0] + p[1] * r[3] + p[2] * r[6] + r[9],
            p[0] * r[1] + p[1] * r[4] + p[2] * r[7] + r[10],
            p[0] * r[2] + p[1] * r[5] + p[2] * r[8] + r[11],
        ]
    }
}

/// JWildfire's `Tools.FTOI`: round half away from zero, saturating.
fn ftoi(v: f64) -> i32 {
    if v > 0.0 {
        (v + 0.5) as i32
    } else if v < 0.0 {
        (-(v.abs() + 0.5)) as i32
    } else {
        0
    }
}

/// A mesh with single-precision vertices merged when they agree to 1e-4, as JWildfire stores
/// them.
#[derive(Default)]
struct KnotMesh {
    vertices: Vec<[f32; 3]>,
    index: std::collections::HashMap<(i32, i32, i32), usize>,
    faces: Vec<[usize; 3]>,
}

impl KnotMesh {
    fn add(&mut self, p: [f64; 3]) {
        let key = (ftoi(p[0] * 1e4), ftoi(p[1] * 1e4), ftoi(p[2] * 1e4));
        if !self.index.contains_key(&key) {
            self.index.insert(key, self.vertices.len());
            self.vertices.push([p[0] as f32, p[1] as f32, p[2] as f32]);
        }
    }
    fn get(&self, i: usize) -> Option<[f64; 3]> {
        self.vertices
            .get(i)
            .map(|v| [v[0] as f64, v[1] as f64, v[2] as f64])
    }
}

/// Sweeps a ring of `facets` points (radius `radius`) along the knot curve, rotating it from
/// one curve segment to the next about the intersection line of the segments' planes; then
/// joins consecutive rings with triangles.
fn knot_tube(curve: &KnotCurve, k: &[f64], steps: usize, radius: f64, facets: usize) -> KnotMesh {
    let mut mesh = KnotMesh::default();
    let pt = |i: usize| knot_point(curve, k, i, steps as f64);
    let (c0, c1, c2) = (pt(0), pt(1), pt(2));
    let n = facets;
    // Normal (a, b, c) of the plane of the current ring, and its offset d.
    let (mut a, mut b, mut c) = (c2[0] - c0[0], c2[1] - c0[1], c2[2] - c0[2]);
    let mut d = a * c1[0] + b * c1[1] + c * c1[2];
    let tiny = |x: f64| x.abs() < 1e-5;
    let (mut rx, mut ry, mut rz) = if tiny(a) && tiny(b) {
        (0.0, c, -b)
    } else {
        (b, -a, 0.0)
    };
    let len = (rx * rx + ry * ry + rz * rz).sqrt();
    rx /= len;
    ry /= len;
    rz /= len;
    mesh.add([
        c1[0] + rx * radius,
        c1[1] + ry * radius,
        c1[2] + rz * radius,
    ]);
    let turn = AxisRotation::new(c1, [a, b, c], 2.0 * PI / n as f64);
    for i in 1..n {
        let Some(prev) = mesh.get(i - 1) else { break };
        mesh.add(turn.apply(prev));
    }
    'rings: for j in 1..steps {
        let prev_ring = (j - 1) * n;
        let pa = pt(j - 1);
        let pb = pt(j);
        let (dx, dy, dz) = (pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]);
        let c1 = a * a + b * b + c * c;
        let c2 = a * dx + b * dy + c * dz;
        let c0 = d - a * pa[0] - b * pa[1] - c * pa[2];
        let mid = [
            0.5 * (pa[0] + pb[0]),
            0.5 * (pa[1] + pb[1]),
            0.5 * (pa[2] + pb[2]),
        ];
        let d0 = dx * mid[0] + dy * mid[1] + dz * mid[2];
        let e1 = dx * a + dy * b + dz * c;
        let e2 = dx * dx + dy * dy + dz * dz;
        let e0 = d0 - dx * pa[0] - dy * pa[1] - dz * pa[2];
        let denom = c1 * e2 - c2 * e1;
        if denom.abs() < 1e-12 {
            // Same direction: the ring is repeated (and merges with the previous one).
            for i in 0..n {
                let Some(v) = mesh.get(prev_ring + i) else {
                    break 'rings;
                };
                mesh.add(v);
            }
        } else {
            let lambda = (c0 * e2 - c2 * e0) / denom;
            let mu = (c1 * e0 - c0 * e1) / denom;
            let centre = [
                pa[0] + lambda * a + mu * dx,
                pa[1] + lambda * b + mu * dy,
                pa[2] + lambda * c + mu * dz,
            ];
            let ap = [pa[0] - centre[0], pa[1] - centre[1], pa[2] - centre[2]];
            let bp = [pb[0] - centre[0], pb[1] - centre[1], pb[2] - centre[2]];
            let axis = [
                ap[1] * bp[2] - bp[1] * ap[2],
                bp[0] * ap[2] - ap[0] * bp[2],
                ap[0] * bp[1] - bp[0] * ap[1],
            ];
            let cosphi = (ap[0] * bp[0] + ap[1] * bp[1] + ap[2] * bp[2])
                / ((ap[0] * ap[0] + ap[1] * ap[1] + ap[2] * ap[2])
                    * (bp[0] * bp[0] + bp[1] * bp[1] + bp[2] * bp[2]))
                    .sqrt();
            let phi = if cosphi == 0.0 {
                0.5 * PI
            } else {
                ((1.0 - cosphi * cosphi).sqrt() / cosphi).atan()
            };
            let rot = AxisRotation::new(centre, axis, phi);
            for i in 0..n {
                let Some(v) = mesh.get(prev_ring + i) else {
                    break 'rings;
                };
                mesh.add(rot.apply(v));
            }
            let normal = AxisRotation::new([0.0; 3], axis, phi).apply([a, b, c]);
            (a, b, c) = (normal[0], normal[1], normal[2]);
        }
        d = a * pb[0] + b * pb[1] + c * pb[2];
    }
    // Two triangles per quad between rings j-1 and j (vertex indices as JWildfire numbers them).
    for j in 1..steps {
        let cur = j * n;
        let prev = cur - n;
        for i in 0..n.saturating_sub(1) {
            mesh.faces.push([cur + i + 1, prev + i, prev + i + 1]);
            mesh.faces.push([prev + i, cur + i + 1, cur + i]);
        }
        mesh.faces.push([cur, prev + n - 1, prev]);
        mesh.faces.push([prev + n - 1, cur, cur + n - 1]);
    }
    mesh
}

/// knots3D's shared data: the count of triangles, then 9 coordinates per triangle (from
/// parameters 0–17: the curve, the tube and its placement).
fn knots3d_faces(q: &[f64], _: &[String]) -> Vec<f64> {
    let [
        preset,
        steps,
        radius,
        facets,
        curve_params @ ..,
        scale_x,
        scale_y,
        scale_z,
        offset_x,
        offset_y,
        offset_z,
    ] = params_of::<18>(q);
    let mut out = vec![0.0];
    if !(0.0..24.0).contains(&preset) {
        return out;
    }
    let curve = &KNOT_CURVES[preset as usize];
    let (steps, facets) = (steps as usize, facets as usize);
    let mesh = knot_tube(curve, &curve_params, steps, radius, facets);
    let (scale, offset) = ([scale_x, scale_y, scale_z], [offset_x, offset_y, offset_z]);
    let placed: Vec<[f64; 3]> = mesh
        .vertices
        .iter()
        .map(|p| std::array::from_fn(|i| (p[i] as f64 * scale[i] + offset[i]) as f32 as f64))
        .collect();
    let mut count = 0;
    for f in &mesh.faces {
        // Faces that point past the merged vertex list are left out.
        if f.iter().all(|&i| i < placed.len()) {
            for &i in f {
                out.extend_from_slice(&placed[i]);
            }
            count += 1;
        }
    }
    out[0] = count as f64;
    out
}

/// knots3D: a tube of `facets` sides and radius `radius` around one of JWildfire's stock knot
/// curves (preset id), as a triangle mesh scaled and offset; points are uniform on a random
/// triangle. Custom formulas (preset -1) are not supported and give no output.
fn knots3d(v: &Prepared, _t: &VarIn, _acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let q = v.data();
    let n = q[0] as usize;
    if n == 0 {
        return [0.0; 3];
    }
    let k = ((rng.f01() * n as f64) as usize).min(n - 1);
    let f = &q[1 + 9 * k..][..9];
    let s = rng.f01().sqrt();
    let r2 = rng.f01();
    let (a, b, c) = (1.0 - s, s * (1.0 - r2), r2 * s);
    [
        v.w * (a * f[0] + b * f[3] + c * f[6]),
        v.w * (a * f[1] + b * f[4] + c * f[7]),
        v.w * (a * f[2] + b * f[5] + c * f[8]),
    ]
}

#[cfg(test)]
mod tests;
