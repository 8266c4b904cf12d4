//! JWildfire's escape-time point sets, the `fract_*_wf` family (`fract_julia_wf`,
//! `fract_mandelbrot_wf`, `fract_dragon_wf`, `fract_meteors_wf`, `fract_pearls_wf`,
//! `fract_salamander_wf`): each call picks random starting points in a window until one
//! escapes after neither too few nor too many iterations, and places the point there (the
//! iteration count sets its height and colour); in "buddhabrot" mode a starting point that
//! escapes late enough is kept, and each call moves one step along its orbit instead.
//!
//! They share one frame: the window, the clipping of iteration counts, the height, the colour
//! and the orbit mode, around each fractal's own step. The formulas follow JWildfire's
//! (Andreas Maschke and contributors, LGPL-2.1) mathematics, written anew; random numbers
//! are drawn in the order JWildfire draws them.

use super::*;

/// Most iterations per starting point (each call may run several starting points).
const MAX_ITER: f64 = 10000.0;

/// Starting points a buddhabrot orbit tries before the point is hidden.
const ORBIT_TRIES: usize = 250;

/// The parameters all the family shares, named `NAME_…`, with `custom` (the fractal's own)
/// after `buddhabrot_mode`, and the window and clipping defaults of each fractal.
macro_rules! fract_params {
    ($n:literal, [$($custom:expr),*], $xmin:expr, $xmax:expr, $ymin:expr, $ymax:expr,
     $clip_min:expr, $scale:expr, $offsetx:expr) => {
        &[
            p_int(concat!($n, "_max_iter"), 100.0, 1.0, MAX_ITER).limited(),
            p(concat!($n, "_xmin"), $xmin),
            p(concat!($n, "_xmax"), $xmax),
            p(concat!($n, "_ymin"), $ymin),
            p(concat!($n, "_ymax"), $ymax),
            p_int(concat!($n, "_buddhabrot_mode"), 0.0, NEG_INF, INF),
            $($custom,)*
            p_int(concat!($n, "_direct_color"), 1.0, NEG_INF, INF),
            p(concat!($n, "_scalez"), 1.0),
            p_int(concat!($n, "_clip_iter_min"), $clip_min, NEG_INF, INF),
            p_int(concat!($n, "_clip_iter_max"), -5.0, NEG_INF, INF),
            p_int(concat!($n, "_max_clip_iter"), 3.0, NEG_INF, MAX_ITER).limited(),
            p_int(concat!($n, "_buddhabrot_min_iter"), 7.0, NEG_INF, MAX_ITER).limited(),
            p(concat!($n, "_scale"), $scale),
            p(concat!($n, "_offsetx"), $offsetx),
            p(concat!($n, "_offsety"), 0.0),
            p(concat!($n, "_offsetz"), 0.0),
            p_range(concat!($n, "_z_fill"), 0.0, 0.0, 1.0),
            p_int(concat!($n, "_z_logscale"), 0.0, 0.0, 1.0),
            p_int(concat!($n, "_color_only"), 0.0, 0.0, 1.0),
        ]
    };
}

pub(super) const FLAGS: u32 = flag::JWILDFIRE
    | flag::RANDOM
    | flag::STATEFUL
    | flag::WRITES_Z
    | flag::SETS_COLOR
    | flag::HIDES;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("fract_julia_wf", fract_julia)
        .params(fract_params!(
            "fract_julia_wf",
            [
                p_int("fract_julia_wf_power", 2.0, 2.0, 64.0).limited(),
                p("fract_julia_wf_xseed", 0.35),
                p("fract_julia_wf_yseed", 0.09)
            ],
            -1.0,
            1.0,
            -1.2,
            1.2,
            4.0,
            3.8,
            0.0
        ))
        .flags(FLAGS),
    VarDef::new("fract_mandelbrot_wf", fract_mandelbrot)
        .params(fract_params!(
            "fract_mandelbrot_wf",
            [p_int("fract_mandelbrot_wf_power", 2.0, 2.0, 64.0).limited()],
            -2.35,
            0.75,
            -1.2,
            1.2,
            3.0,
            4.0,
            0.55
        ))
        .flags(FLAGS),
    VarDef::new("fract_dragon_wf", fract_dragon)
        .params(fract_params!(
            "fract_dragon_wf",
            [
                p("fract_dragon_wf_xseed", 1.4),
                p("fract_dragon_wf_yseed", 0.85)
            ],
            -0.25,
            1.2,
            -0.75,
            0.75,
            4.0,
            5.0,
            -0.5
        ))
        .flags(FLAGS),
    VarDef::new("fract_meteors_wf", fract_meteors)
        .params(fract_params!(
            "fract_meteors_wf",
            [],
            -1.7,
            1.7,
            -1.1,
            1.1,
            3.0,
            5.7,
            0.0
        ))
        .flags(FLAGS),
    VarDef::new("fract_pearls_wf", fract_pearls)
        .params(fract_params!(
            "fract_pearls_wf",
            [
                p("fract_pearls_wf_xseed", 0.0),
                p("fract_pearls_wf_yseed", -0.31)
            ],
            -2.0,
            2.0,
            -2.0,
            2.0,
            1.0,
            2.45,
            0.0
        ))
        .flags(FLAGS),
    VarDef::new("fract_salamander_wf", fract_salamander)
        .params(fract_params!(
            "fract_salamander_wf",
            [
                p("fract_salamander_wf_xseed", 0.8),
                p("fract_salamander_wf_yseed", -0.15)
            ],
            -2.0,
            2.0,
            -2.0,
            2.0,
            1.0,
            2.45,
            0.0
        ))
        .flags(FLAGS),
];

/// One fractal's step, from the orbit's current point (x, y), its squares and its start.
#[derive(Clone, Copy)]
pub(super) enum Step {
    /// z^power + seed.
    Julia { power: i64, cx: f64, cy: f64 },
    /// z^power + start.
    Mandelbrot { power: i64 },
    /// seed·(z − z²).
    Dragon { cx: f64, cy: f64 },
    /// start·z − start·conj(z)/|z|² with the imaginary part's sign flipped (JWildfire's
    /// "meteors").
    Meteors,
    /// The same with a fixed seed for the start (JWildfire's "pearls").
    Pearls { cx: f64, cy: f64 },
    /// seed·z² − 1.
    Salamander { cx: f64, cy: f64 },
    /// A formula of JWildfire's `fract_formula_*_wf` ([`super::jwf_h9a_fract`]) of z, the
    /// power and the seed (the start when `seed` is `None`).
    Formula {
        form: super::jwf_h9a_fract::Form,
        power: f64,
        seed: Option<(f64, f64)>,
    },
}

/// An orbit: its current point, start, squares of the point before the last step (the escape
/// test reads them) and the steps taken since its start.
#[derive(Clone, Copy, Default)]
struct Orbit {
    x: f64,
    y: f64,
    sx: f64,
    sy: f64,
    xs: f64,
    ys: f64,
    n: i64,
}

/// z^power (power ≥ 2) plus (ax, ay), JWildfire's expansions for 2, 3, 4 and the fifth power
/// multiplied on for more.
fn power_plus(x: f64, y: f64, xs: f64, ys: f64, power: i64, ax: f64, ay: f64) -> (f64, f64) {
    match power {
        2 => (xs - ys + ax, 2.0 * x * y + ay),
        3 => (xs * x - 3.0 * x * ys + ax, 3.0 * xs * y - ys * y + ay),
        4 => (
            xs * xs + ys * ys - 6.0 * xs * ys + ax,
            4.0 * x * y * (xs - ys) + ay,
        ),
        _ => {
            let mut x2 = x * (xs * xs - 10.0 * xs * ys + 5.0 * ys * ys);
            let mut y2 = y * (ys * ys - 10.0 * xs * ys + 5.0 * xs * xs);
            for _ in 5..power {
                (x2, y2) = (x * x2 - y * y2, x * y2 + x2 * y);
            }
            (x2 + ax, y2 + ay)
        }
    }
}

impl Orbit {
    fn start(x0: f64, y0: f64) -> Orbit {
        Orbit {
            x: x0,
            y: y0,
            sx: x0,
            sy: y0,
            ..Orbit::default()
        }
    }

    fn escaped(&self) -> bool {
        self.xs + self.ys >= 4.0
    }

    fn step(&mut self, s: Step) {
        let (x, y) = (self.x, self.y);
        let (xs, ys) = (x * x, y * y);
        (self.xs, self.ys) = (xs, ys);
        (self.x, self.y) = match s {
            Step::Julia { power, cx, cy } => power_plus(x, y, xs, ys, power, cx, cy),
            Step::Mandelbrot { power } => power_plus(x, y, xs, ys, power, self.sx, self.sy),
            Step::Dragon { cx, cy } => {
                let (u, w) = (x - xs + ys, y - 2.0 * x * y);
                (u * cx - w * cy, u * cy + w * cx)
            }
            Step::Meteors => {
                let (a, b, r2) = (self.sx, self.sy, xs + ys);
                (
                    (a * x - b * y) - (a * x + b * y) / r2,
                    (a * y + b * x) + (a * y - b * x) / r2,
                )
            }
            Step::Pearls { cx, cy } => {
                let r2 = xs + ys;
                (
                    cx * x - cy * y - (cx * x + cy * y) / r2,
                    cx * y + cy * x + (cx * y - cy * x) / r2,
                )
            }
            Step::Salamander { cx, cy } => {
                let (u, w) = (xs - ys, 2.0 * x * y);
                (u * cx - w * cy - 1.0, u * cy + w * cx)
            }
            Step::Formula { form, power, seed } => {
                let (cx, cy) = seed.unwrap_or((self.sx, self.sy));
                super::jwf_h9a_fract::perform(&form, power, x, y, cx, cy)
            }
        };
        self.n += 1;
    }

    /// Restarts at (x0, y0) and steps until it escapes or `max` steps: JWildfire's count (one
    /// more than the steps taken).
    fn run(&mut self, s: Step, x0: f64, y0: f64, max: i64) -> i64 {
        *self = Orbit::start(x0, y0);
        let mut count = 0;
        loop {
            let more = count < max;
            count += 1;
            if !more || self.escaped() {
                return count;
            }
            self.step(s);
        }
    }
}

/// The shared parameters, wherever the fractal's own put them.
struct Frame {
    max_iter: i64,
    window: [f64; 4],
    buddhabrot: bool,
    direct_color: bool,
    scalez: f64,
    clip_min: i64,
    clip_max: i64,
    clip_tries: i64,
    orbit_skip: i64,
    scale: f64,
    offset: [f64; 3],
    z_fill: f64,
    z_log: bool,
    color_only: bool,
}

impl Frame {
    /// The shared parameters of `q` (the fractal's `own` parameters after the sixth).
    fn of(q: &[f64], own: usize) -> Frame {
        let at = |k: usize| q[if k < 6 { k } else { k + own }];
        Frame {
            max_iter: at(0) as i64,
            window: [at(1), at(2), at(3), at(4)],
            buddhabrot: at(5) as i64 > 0,
            direct_color: at(6) as i64 != 0,
            scalez: at(7),
            clip_min: at(8) as i64,
            clip_max: at(9) as i64,
            clip_tries: at(10) as i64,
            orbit_skip: at(11) as i64,
            scale: at(12),
            offset: [at(13), at(14), at(15)],
            z_fill: at(16),
            z_log: at(17) as i64 == 1,
            color_only: at(18) as i64 > 0,
        }
    }

    /// A random point of the window (x drawn first).
    fn random_start(&self, rng: &mut FastRng) -> (f64, f64) {
        let [xmin, xmax, ymin, ymax] = self.window;
        let x = (xmax - xmin) * rng.f01() + xmin;
        (x, (ymax - ymin) * rng.f01() + ymin)
    }
}

/// The orbit carried between calls in buddhabrot mode (slots 0–6 of the state; slot 6 is 1
/// while an orbit is being followed, 0 when a new one must be chosen).
fn load_orbit(v: &Prepared) -> (Orbit, i64, bool) {
    let s = &v.state;
    let o = Orbit {
        x: s.get(0),
        y: s.get(1),
        sx: s.get(2),
        sy: s.get(3),
        n: s.get(4) as i64,
        ..Orbit::default()
    };
    (o, s.get(5) as i64, s.get(6) != 1.0)
}

fn store_orbit(v: &Prepared, o: &Orbit, max: i64, choose: bool) {
    let s = &v.state;
    for (i, x) in [o.x, o.y, o.sx, o.sy, o.n as f64, max as f64]
        .iter()
        .enumerate()
    {
        s.set(i, *x);
    }
    s.set(6, if choose { 0.0 } else { 1.0 });
}

/// Buddhabrot mode: one step along the kept orbit (a new one, started where a random start
/// escapes after more than `orbit_skip` steps and advanced by them, when it has run its
/// course); hidden when 250 starts fail.
fn orbit_step(v: &Prepared, f: &Frame, s: Step, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let (mut o, mut max, choose) = load_orbit(v);
    if choose {
        let mut start = None;
        for _ in 0..ORBIT_TRIES {
            let (x0, y0) = f.random_start(rng);
            let count = o.run(s, x0, y0, f.max_iter);
            if o.escaped() {
                max = count;
                if count > f.orbit_skip {
                    start = Some((x0, y0));
                    break;
                }
            }
        }
        let Some((x0, y0)) = start else {
            store_orbit(v, &o, max, true);
            acc.hide = true;
            return [0.0; 3];
        };
        o = Orbit::start(x0, y0);
        for _ in 0..f.orbit_skip {
            o.step(s);
        }
    }
    o.step(s);
    store_orbit(v, &o, max, o.n >= max);
    let k = f.scale * v.w;
    acc.color = (acc.color + o.n as f64 / max as f64).clamp(0.0, 1.0);
    [k * (o.x + f.offset[0]), k * (o.y + f.offset[1]), 0.0]
}

/// The family's call: buddhabrot mode, or a random start (the input point with `color_only`)
/// tried up to `max_clip_iter` times until its count is not clipped, the point hidden when
/// none is kept.
pub(super) fn fract(
    v: &Prepared,
    own: usize,
    s: Step,
    t: &VarIn,
    acc: &mut Acc,
    rng: &mut FastRng,
) -> V3 {
    let f = Frame::of(&v.p[..v.def.params.len()], own);
    if f.buddhabrot {
        return orbit_step(v, &f, s, acc, rng);
    }
    acc.hide = false;
    let mut o = Orbit::default();
    let (mut x0, mut y0, mut count) = (0.0, 0.0, 0);
    for i in 0..f.clip_tries {
        (x0, y0) = if f.color_only {
            (t.x, t.y)
        } else {
            f.random_start(rng)
        };
        count = o.run(s, x0, y0, f.max_iter);
        let clipped = (f.clip_max < 0 && count >= f.max_iter + f.clip_max)
            || (f.clip_min > 0 && count <= f.clip_min);
        if !clipped {
            break;
        }
        if i == f.clip_tries - 1 {
            acc.hide = true;
            return [0.0; 3];
        }
    }
    let k = f.scale * v.w;
    let max = f.max_iter as f64;
    let height = |c: i64| {
        let u = c as f64 / max;
        let u = if f.z_log { (1.0 + u).log10() } else { u };
        k * (f.scalez / 10.0 * u + f.offset[2])
    };
    let mut z = height(count);
    if f.z_fill > 1e-8 && rng.f01() < f.z_fill {
        z += (height(count - 1) - z) * rng.f01();
    }
    if f.direct_color {
        let mut c = acc.color + count as f64 / max;
        if c > 1.0 {
            c -= 1.0;
        }
        acc.color = c.clamp(0.0, 1.0);
    }
    if f.color_only {
        return [0.0, 0.0, z];
    }
    [k * (x0 + f.offset[0]), k * (y0 + f.offset[1]), z]
}

fn fract_julia(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., power, cx, cy] = v.params::<9>();
    let s = Step::Julia {
        power: (power as i64).max(2),
        cx,
        cy,
    };
    fract(v, 3, s, t, acc, rng)
}

fn fract_mandelbrot(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., power] = v.params::<7>();
    let s = Step::Mandelbrot {
        power: (power as i64).max(2),
    };
    fract(v, 1, s, t, acc, rng)
}

fn fract_dragon(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., cx, cy] = v.params::<8>();
    fract(v, 2, Step::Dragon { cx, cy }, t, acc, rng)
}

fn fract_meteors(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    fract(v, 0, Step::Meteors, t, acc, rng)
}

fn fract_pearls(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., cx, cy] = v.params::<8>();
    fract(v, 2, Step::Pearls { cx, cy }, t, acc, rng)
}

fn fract_salamander(v: &Prepared, t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [.., cx, cy] = v.params::<8>();
    fract(v, 2, Step::Salamander { cx, cy }, t, acc, rng)
}
