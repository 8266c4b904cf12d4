//! Steve Witham's "Mandala" maps (http://www.tiac.net/~sw/2005/03/Mandala/index.html), as
//! Jesus Sosa's JWildfire variations `mandala` and `mandala2` draw them: a rotation by
//! `num`/`denom` of a turn done on integer pixels as three skews (or Minsky's two), optionally
//! with a wobbling angle and wrapped coordinates; each pixel of a `width` × `width` square is
//! coloured by the length of its orbit under `denom` such rotations. `mandala` draws a random
//! coloured pixel as a small square; `mandala2` samples the square's pixels directly.
//!
//! The formulas follow JWildfire 9.00 (`MandalaFunc`, `Mandala2Func`, `js.mandala.RotatorMap`,
//! LGPL-2.1), written anew. Colours go through `java.awt.Color`'s HSB conversions, reproduced
//! here in `f32` as Java computes them.

use std::f64::consts::PI;

use super::jwf_m_draw::nblur_point;
use super::*;

pub(super) static DEFS: &[VarDef] = &[
    VarDef::new("mandala", mandala)
        .params(&[
            p_int("mandala_width", 300.0, 100.0, 1000.0).limited(),
            p_range("mandala_size", 0.6, 0.0, 1.0),
            p_int("mandala_num", 1.0, 1.0, 15.0),
            p_int("mandala_denom", 3.0, 3.0, 16.0).limited(),
            p_int("mandala_minsky", 0.0, 0.0, 1.0),
            p_int("mandala_wobble", 0.0, 0.0, 9.0),
            p_int("mandala_wrap_range", 0.0, 0.0, 9.0),
            p_int("mandala_hskew", 0.0, 0.0, 23.0),
            p_int("mandala_color id", 1.0, 0.0, 1.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .shared(&[0, 2, 3, 4, 5, 6, 7, 8], mandala_pixels),
    VarDef::new("mandala2", mandala2)
        .params(&[
            p_int("mandala2_width", 500.0, 100.0, 2000.0).limited(),
            p_int("mandala2_num", 1.0, 1.0, 15.0),
            p_int("mandala2_denom", 3.0, 3.0, 16.0).limited(),
            p_int("mandala2_minsky", 0.0, 0.0, 1.0),
            p_int("mandala2_wobble", 0.0, 0.0, 9.0),
            p_int("mandala2_wrap_range", 0.0, 0.0, 9.0),
            p_int("mandala2_hskew", 0.0, 0.0, 23.0),
            p_int("mandala2_color id", 0.0, 0.0, 3.0),
        ])
        .flags(flag::JWILDFIRE | flag::RANDOM | flag::SETS_COLOR)
        .shared(&[0, 1, 2, 3, 4, 5, 6, 7], mandala2_pixels),
];

/// Wrap ranges (multiples of the square's size; 0: the skew tables grow instead).
const WRAP: [f64; 9] = [0.0, 12.0, 8.0, 6.0, 4.0, 3.0, 2.0, 1.5, 1.0];
/// Extra horizontal skews.
const SKEW: [i64; 23] = [
    0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 12, 15, 16, 23, 24, 25, 31, 32, 36, 47, 48, 63, 64,
];
/// Longest orbit followed, in rotations by a whole turn (`denom` steps); a longer one is coloured
/// as the non-cycling ones.
const MAX_STEPS: i64 = 20000;
/// Bound on the work of one map: the single skew steps of all orbits together (about a second).
/// The pixels not reached within it are left undrawn (`mandala`) or black (`mandala2`).
const WORK: u64 = 300_000_000;
/// Bound on the skew tables when they grow (unwrapped orbits drifting away).
const MAX_TABLE: i64 = 1 << 22;

/// Java's `Math.round`: the nearest integer, halves up (exact below the halves).
fn java_round(x: f64) -> i64 {
    let f = x.floor();
    (if x - f >= 0.5 { f + 1.0 } else { f }) as i64
}

/// `num` and `denom` as JWildfire's setters leave them when set in that order on a new object
/// (denominator 3): a numerator whose double is a multiple of the denominator is raised by one,
/// and so is a denominator dividing twice the numerator.
fn fraction(num: f64, denom: f64) -> (i64, i64) {
    let mut n = num.max(1.0) as i64;
    if (2 * n) % 3 == 0 {
        n += 1;
    }
    let n = n.clamp(1, 15);
    let mut d = denom.max(3.0) as i64;
    if (2 * n) % d == 0 {
        d += 1;
    }
    (n, d.clamp(3, 16))
}

/// The rotation as skew tables (`RotatorMap`'s `hskew1`, `vskew`, `hskew2`) over the range
/// `min ..= max` of coordinates, and how coordinates outside it are brought back.
struct Skews {
    num: f64,
    denom: f64,
    minsky: bool,
    wobble: f64,
    wrap: bool,
    extra: i64,
    size: i64,
    base: i64,
    min: i64,
    max: i64,
    h1: Vec<i64>,
    v: Vec<i64>,
    h2: Vec<i64>,
}

impl Skews {
    fn new(
        width: i64,
        (num, denom): (i64, i64),
        minsky: bool,
        wobble: f64,
        wrap: f64,
        extra: i64,
    ) -> Skews {
        let show_base = -width / 2;
        let mut size = if wrap == 0.0 {
            width * 2
        } else {
            (width as f64 * wrap) as i64
        };
        size |= 1;
        let mut base = size / 2;
        if base + show_base + width > size {
            base = size - (show_base + width);
        }
        let mut s = Skews {
            num: num as f64,
            denom: denom as f64,
            minsky,
            wobble,
            wrap: wrap != 0.0,
            extra,
            size,
            base,
            min: 0,
            max: 0,
            h1: Vec::new(),
            v: Vec::new(),
            h2: Vec::new(),
        };
        s.tables();
        s
    }

    /// Fills the tables for the current size (the angle wobbles slowly with the coordinate).
    fn tables(&mut self) {
        self.min = -self.base;
        self.max = self.min + self.size - 1;
        let n = self.size as usize;
        self.h1 = vec![0; n];
        self.v = vec![0; n];
        self.h2 = vec![0; n];
        let low = self.num / ((1.0 + self.wobble) * self.denom);
        let high = self.num / ((1.0 - self.wobble) * self.denom);
        for k in 0..n {
            let i = k as i64 - self.base;
            let fi = i as f64;
            let x = fi * 2.0 * PI / 512.0;
            let angle = PI * 2.0 * (low - (x.cos() - 1.0) / 2.0 * (high - low));
            if self.minsky {
                // HAKMEM items 149 (Minsky) and 151 (Gosper): an ellipse.
                let eps = (2.0 * (1.0 - angle.cos())).sqrt();
                let r = java_round(eps * fi + 1e-8);
                self.h1[k] = -r + self.extra;
                self.v[k] = r;
                self.h2[k] = 0;
            } else {
                let s = angle.sin();
                let c = (angle.cos() - 1.0) / s;
                self.h1[k] = java_round(c * fi);
                self.v[k] = java_round(s * fi + 1e-8);
                self.h2[k] = self.h1[k] + self.extra;
            }
        }
    }

    /// A coordinate out of range brought back: wrapped, or the tables grown to take it (None
    /// past [`MAX_TABLE`]).
    fn fix(&mut self, c: i64) -> Option<i64> {
        if !self.wrap && (self.base + c < 0 || self.base + c >= self.size) {
            while self.base + c < 0 || self.base + c >= self.size {
                self.size *= 2;
                self.base = self.size / 2;
                if self.size > MAX_TABLE {
                    return None;
                }
            }
            self.tables();
        }
        Some(c - self.size * (self.base + c).div_euclid(self.size))
    }

    /// One whole turn: `denom` rotations, each three skews (None when the tables would grow
    /// too far).
    fn turn(&mut self, (mut x, mut y): (i64, i64)) -> Option<(i64, i64)> {
        for _ in 0..self.denom as i64 {
            x += self.h1[(y + self.base) as usize];
            if x < self.min || x > self.max {
                x = self.fix(x)?;
            }
            y += self.v[(x + self.base) as usize];
            if y < self.min || y > self.max {
                y = self.fix(y)?;
            }
            x += self.h2[(y + self.base) as usize];
            if x < self.min || x > self.max {
                x = self.fix(x)?;
            }
        }
        Some((x, y))
    }
}

/// Walks the orbits of the pixels of the `width` × `width` square (columns first, as
/// `RotatorMap.drawMap`): each pixel not yet reached starts an orbit, followed until it
/// returns (or [`MAX_STEPS`] turns, when it counts `MAX_STEPS + 1`; `endless` follows a wrapped
/// orbit to its end as `mandala2` does, within the work bound); then the orbit is retraced
/// and `mark` gets each pixel of the square it meets before a marked one, with the orbit's
/// length. The parameters are `(width, num, denom, minsky, wobble, wrap_range, hskew)` as
/// stored.
fn walk(q: [f64; 7], endless: bool, mut mark: impl FnMut(i64, i64, i64)) {
    let [width, num, denom, minsky, wobble, wrap, hskew] = q;
    let width = width as i64;
    let pick = |v: f64, n: usize| (v.max(0.0) as usize).min(n) % n;
    let wobble = match pick(wobble, 9) {
        0 => 0.0,
        k => 10f64.powf(-6.0 + 0.5 * k as f64),
    };
    let wrap = WRAP[pick(wrap, WRAP.len())];
    let extra = SKEW[pick(hskew, SKEW.len())];
    let mut sk = Skews::new(
        width,
        fraction(num, denom),
        minsky == 1.0,
        wobble,
        wrap,
        extra,
    );
    let steps_per_turn = 3 * sk.denom as u64;
    let show = -width / 2;
    let w = width as usize;
    let mut seen = vec![false; w * w];
    let on_screen = |x: i64, y: i64| {
        (x >= show && x < show + width && y >= show && y < show + width)
            .then(|| (x - show) as usize * w + (y - show) as usize)
    };
    let mut work = 0u64;
    for x in show..show + width {
        for y in show..show + width {
            if seen[(x - show) as usize * w + (y - show) as usize] {
                continue;
            }
            let (mut px, mut py) = (x, y);
            let mut n = 1;
            loop {
                work += steps_per_turn;
                if work > WORK {
                    return;
                }
                let Some(p) = sk.turn((px, py)) else { return };
                (px, py) = p;
                if (px, py) == (x, y) {
                    break;
                }
                if n > MAX_STEPS && !(endless && sk.wrap) {
                    break;
                }
                n = if n > MAX_STEPS { MAX_STEPS + 1 } else { n + 1 };
            }
            (px, py) = (x, y);
            for _ in 0..n {
                if let Some(k) = on_screen(px, py) {
                    if seen[k] {
                        break;
                    }
                    seen[k] = true;
                    mark(px, py, n);
                }
                work += steps_per_turn;
                if work > WORK {
                    return;
                }
                let Some(p) = sk.turn((px, py)) else { return };
                (px, py) = p;
                if (px, py) == (x, y) {
                    break;
                }
            }
        }
    }
}

/// `java.awt.Color.HSBtoRGB` (in `f32`, as Java computes it): red, green, blue bytes.
fn hsb_to_rgb(hue: f32, sat: f32, bright: f32) -> [i32; 3] {
    let byte = |v: f32| (v * 255.0 + 0.5) as i32;
    if sat == 0.0 {
        return [byte(bright); 3];
    }
    let h = (hue - f64::from(hue).floor() as f32) * 6.0;
    let f = h - f64::from(h).floor() as f32;
    let p = bright * (1.0 - sat);
    let q = bright * (1.0 - sat * f);
    let t = bright * (1.0 - sat * (1.0 - f));
    let (r, g, b) = match h as i32 {
        0 => (bright, t, p),
        1 => (q, bright, p),
        2 => (p, bright, t),
        3 => (p, q, bright),
        4 => (t, p, bright),
        5 => (bright, p, q),
        _ => return [0; 3],
    };
    [byte(r), byte(g), byte(b)]
}

/// The hue `java.awt.Color.RGBtoHSB` finds for red, green, blue bytes (in `f32`).
fn rgb_hue([r, g, b]: [i32; 3]) -> f32 {
    let max = r.max(g).max(b);
    let min = r.min(g).min(b);
    if max == 0 || max == min {
        return 0.0;
    }
    let span = (max - min) as f32;
    let (rc, gc, bc) = (
        (max - r) as f32 / span,
        (max - g) as f32 / span,
        (max - b) as f32 / span,
    );
    let hue = if r == max {
        bc - gc
    } else if g == max {
        2.0 + rc - bc
    } else {
        4.0 + gc - rc
    } / 6.0;
    if hue < 0.0 { hue + 1.0 } else { hue }
}

/// The colour of an orbit of `n` turns: black past [`MAX_STEPS`]; scheme 1 a hue from ln n,
/// scheme 2 a hue from n / 6.333333, schemes 0 and 3 channels from n modulo 91, 123 and 17.
fn orbit_rgb(n: i64, scheme: i64) -> [i32; 3] {
    if n == MAX_STEPS + 1 {
        return [0; 3];
    }
    let hue = |z: f32| hsb_to_rgb(z - f64::from(z).floor() as f32, 0.85, 1.0);
    match scheme {
        1 => hue((n as f64).ln() as f32),
        2 => hue((n as f64 / 6.333333) as f32),
        _ => {
            let byte = |v: f32| (v * 255.0 + 0.5) as i32;
            [
                byte((n % 91) as f32 / 90.0),
                byte((n % 123) as f32 / 122.0),
                byte((n % 17) as f32 / 16.0),
            ]
        }
    }
}

/// Red, green and blue bytes packed in one value.
fn pack([r, g, b]: [i32; 3]) -> f64 {
    f64::from(r * 65536 + g * 256 + b)
}

/// The bytes of [`pack`].
fn unpack(c: f64) -> [f64; 3] {
    let c = c as i64;
    [(c >> 16) & 255, (c >> 8) & 255, c & 255].map(|b| b as f64)
}

/// mandala's pixels in drawing order: (x, y, colour) with x and y from 0 to `width` − 1; the
/// colour is the hue of the orbit's colour (`color id` 1) or its bytes packed (0).
fn mandala_pixels(q: &[f64], _: &[String]) -> Vec<f64> {
    let [width, _, num, denom, minsky, wobble, wrap, hskew, color_id] = params_of(q);
    let show = -(width as i64) / 2;
    let mut out = Vec::new();
    walk(
        [width, num, denom, minsky, wobble, wrap, hskew],
        false,
        |x, y, n| {
            let rgb = orbit_rgb(n, 1);
            let c = if color_id == 0.0 {
                pack(rgb)
            } else {
                f64::from(rgb_hue(rgb))
            };
            out.extend_from_slice(&[(x - show) as f64, (y - show) as f64, c]);
        },
    );
    out
}

/// mandala: a random point of a random pixel's square (`size` pixels wide, drawn as
/// FractalDesire's nBlur fills a square), the square centred and scaled by 1/100, with the
/// pixel's colour (hue or direct colour).
fn mandala(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [width, size, _, _, _, _, _, _, color_id] = v.params();
    let px = v.data();
    let count = px.len() / 3;
    if count == 0 {
        return [0.0; 3];
    }
    let i = ((rng.f01() * count as f64) as usize).min(count - 1);
    let (x, y, c) = (px[3 * i], px[3 * i + 1], px[3 * i + 2]);
    let (ox, oy) = nblur_point(rng, 4, 0.0);
    let half = (width as i64 / 2) as f64;
    if color_id == 0.0 {
        acc.rgb = Some(unpack(c));
    } else {
        acc.color = c;
    }
    [
        0.01 * v.w * (ox * size + x - half),
        0.01 * v.w * (oy * size + y - half),
        0.0,
    ]
}

/// mandala2's square, pixel by pixel (column major): the hue of the pixel's colour (`color
/// id` 0) or its bytes packed.
fn mandala2_pixels(q: &[f64], _: &[String]) -> Vec<f64> {
    let [width, num, denom, minsky, wobble, wrap, hskew, color_id] = params_of(q);
    let w = width as i64;
    let show = -w / 2;
    let scheme = color_id as i64;
    let black = if scheme == 0 { 0.0 } else { pack([0; 3]) };
    let mut out = vec![black; (w * w) as usize];
    walk(
        [width, num, denom, minsky, wobble, wrap, hskew],
        true,
        |x, y, n| {
            let rgb = orbit_rgb(n, scheme);
            out[((x - show) * w + (y - show)) as usize] = if scheme == 0 {
                f64::from(rgb_hue(rgb))
            } else {
                pack(rgb)
            };
        },
    );
    out
}

/// mandala2: a random pixel of the square, mapped to [−½, ½)², with its colour (hue, or direct
/// colour for `color id` 1 to 3).
fn mandala2(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [width, _, _, _, _, _, _, color_id] = v.params();
    let px = v.data();
    let w = width as usize;
    if px.len() < w * w || w == 0 {
        return [0.0; 3];
    }
    let x = ((rng.f01() * width) as usize).min(w - 1);
    let y = ((rng.f01() * width) as usize).min(w - 1);
    let c = px[x * w + y];
    if color_id == 0.0 {
        acc.color = c;
    } else {
        acc.rgb = Some(unpack(c));
    }
    [
        v.w * (x as f64 / width - 0.5),
        v.w * (y as f64 / width - 0.5),
        0.0,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn java_colour_conversions() {
        // Color.getHSBColor(0.25f, 0.85f, 1f) is (147, 255, 38); its hue back is 0.25 to f32.
        assert_eq!(hsb_to_rgb(0.25, 0.85, 1.0), [147, 255, 38]);
        assert!((rgb_hue([147, 255, 38]) - 0.25).abs() < 2e-3);
        assert_eq!(rgb_hue([10, 10, 10]), 0.0);
        assert_eq!(java_round(0.49999999999999994), 0);
        assert_eq!(java_round(-2.5), -2);
    }

    #[test]
    fn default_square_is_covered() {
        // Every pixel of the square lies on some orbit and is marked exactly once.
        let mut count = vec![0u8; 100 * 100];
        walk([100.0, 1.0, 3.0, 0.0, 0.0, 0.0, 0.0], false, |x, y, n| {
            assert!((1..=MAX_STEPS + 1).contains(&n));
            count[((x + 50) * 100 + y + 50) as usize] += 1;
        });
        assert!(count.iter().all(|&c| c == 1));
    }
}
