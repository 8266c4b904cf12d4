//! The turtle of JWildfire's `lsystem3D_js` (JWildfire 9.00, `LSystem3DWFFunc`, after Laurens
//! Lapre's LParser; the behaviour written anew): it reads the production character by
//! character (all but the last, as JWildfire's loop does) and builds a mesh of triangles.
//!
//! The turtle starts at the origin heading +z, its left +y and its up +x, with colour 2, step
//! 1, half step 0.5, the grammar's angle and thickness and tropism 0.2. A command followed by
//! `(v)` takes v for that command (an angle in degrees, times 0.017453); the characters of
//! `(v)` are then read as commands too (a `.` in `(0.5)` adds a polygon vertex, as in
//! JWildfire). Commands:
//! * `+`/`-` turn about up by −/+ the angle, `&`/`^` pitch about left by +/−, `<`/`>` roll
//!   about forward by −/+, `|` turns about up and `%` rolls by π, `~` turns about up, left and
//!   forward by random angles in ±v (default ±6 radians), `t` bends towards −z by the
//!   tropism times forward·(−forward_xy), `$` turns left horizontal;
//! * `F` (`Z`) draws a step (half step) forward, `f` (`z`) moves and adds a polygon vertex,
//!   `g` moves, `.` adds a vertex;
//! * `!`/`?` thickness ×0.7 / ÷0.7 (× v), `:`/`;` angle ×0.9 / ÷0.9, `'`/`"` both steps
//!   ×0.9 / ÷0.9, `c` next colour (colour v);
//! * `[`/`]` push/pop the turtle, `{`/`}` open/close a polygon (a fan of triangles from its
//!   first vertex; an open polygon is put aside while a nested one is drawn — JWildfire's
//!   store of put-aside polygons only grows, and a close takes back the entry at the current
//!   depth, which after a close and a new open is an older one; that is kept).
//!
//! A drawn step is a block (eight corners, six quads) or, with `shape 1`, an octagonal
//! cylinder (sixteen corners, eight quads) whose start ring snaps to the end ring of the
//! previous cylinder of the same colour when that ended less than 1 away. The width is the
//! step's length times the thickness, at least the minimum thickness. A quad becomes two
//! triangles (its first diagonal). Vertices at the same place (to 10⁻⁴) are merged.
//!
//! Colour modes: 0 none, 1 the palette position colour/100, 2 the colour table's RGB (0–255
//! for the quads of steps, 0–1 for polygon triangles: JWildfire's own inconsistency, kept).

use std::collections::HashMap;

use super::jwf_ls_grammar::{Grammar, MAX_COLORS, PI, parse_double};

/// Most triangles of a mesh: the drawing stops after the command that passes them.
pub(super) const MAX_FACES: usize = 500_000;
/// Depth of the `[` stack (JWildfire's).
const MAX_STACK: usize = 1024;
/// LParser's 1/√2, four decimals (a block's half diagonal, a cylinder's octagon corners): not
/// `std`'s.
#[allow(clippy::approx_constant)]
const HALF_DIAGONAL: f64 = 0.7071;
/// Vertex slots of a polygon, and of its triangle table (JWildfire's).
const MAX_POLY: usize = 400;
/// Most polygon vertices put aside in all (JWildfire's store has no limit).
const MAX_ASIDE: usize = 1 << 22;

type P3 = [f32; 3];

/// A triangle's colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum FaceColor {
    /// None (colour mode 0).
    Plain,
    /// A palette position.
    Index(f64),
    /// Red, green, blue.
    Rgb([f64; 3]),
}

/// The mesh a production draws.
#[derive(Default, Debug)]
pub(super) struct LsMesh {
    pub vertices: Vec<P3>,
    pub faces: Vec<([u32; 3], FaceColor)>,
    /// A limit cut the production or the drawing short.
    pub cut: bool,
    index: HashMap<[i32; 3], u32>,
}

/// JWildfire's `Tools.FTOI`: rounded half away from zero, saturating, NaN to 0.
fn ftoi(v: f64) -> i32 {
    if v > 0.0 {
        (v + 0.5) as i32
    } else if v < 0.0 {
        (0.0 - (v.abs() + 0.5)) as i32
    } else {
        0
    }
}

impl LsMesh {
    /// The index of vertex `v`, merged with an earlier one whose coordinates round alike.
    fn add_vertex(&mut self, v: P3) -> u32 {
        let key = v.map(|c| ftoi(f64::from(c) * 10000.0));
        let n = self.vertices.len() as u32;
        let i = *self.index.entry(key).or_insert(n);
        if i == n {
            self.vertices.push(v);
        }
        i
    }
}

fn add(a: P3, b: P3) -> P3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: P3, b: P3) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Length, in `float` as JWildfire computes it.
fn len(a: P3) -> f32 {
    f64::from(dot(a, a)).sqrt() as f32
}

/// Divided by its length (the turtle's normalisation).
fn unit_div(a: P3) -> P3 {
    let l = len(a);
    a.map(|c| c / l)
}

/// Times the reciprocal of its length (the shapes' normalisation).
fn unit_mul(a: P3) -> P3 {
    let k = 1.0f32 / len(a);
    a.map(|c| c * k)
}

/// a + t·b, each coordinate rounded to a `float`.
fn plus(a: P3, b: P3, t: f64) -> P3 {
    std::array::from_fn(|k| (f64::from(a[k]) + t * f64::from(b[k])) as f32)
}

/// p + s·u + r·w, rounded once.
fn plus2(p: P3, u: P3, s: f64, w: P3, r: f64) -> P3 {
    std::array::from_fn(|k| (f64::from(p[k]) + s * f64::from(u[k]) + r * f64::from(w[k])) as f32)
}

/// The rotation by `a` about the unit axis `n` (rows), in `float`.
fn rotation(a: f32, n: P3) -> [P3; 3] {
    let (c, s) = (f64::from(a).cos() as f32, f64::from(a).sin() as f32);
    let (n11, n22, n33) = (n[0] * n[0], n[1] * n[1], n[2] * n[2]);
    let (nxy, nxz, nyz) = (n[0] * n[1], n[0] * n[2], n[1] * n[2]);
    let k = 1.0f32 - c;
    [
        [
            n11 + (1.0 - n11) * c,
            nxy * k - n[2] * s,
            nxz * k + n[1] * s,
        ],
        [
            nxy * k + n[2] * s,
            n22 + (1.0 - n22) * c,
            nyz * k - n[0] * s,
        ],
        [
            nxz * k - n[1] * s,
            nyz * k + n[0] * s,
            n33 + (1.0 - n33) * c,
        ],
    ]
}

/// Turns `u` and `w` by `a` about `axis`, each normalised after.
fn turn(a: f64, axis: P3, u: &mut P3, w: &mut P3) {
    let m = rotation(a as f32, axis);
    let apply = |v: P3| [dot(m[0], v), dot(m[1], v), dot(m[2], v)];
    *u = unit_div(apply(*u));
    *w = unit_div(apply(*w));
}

/// The number in `(…)` after the command at `i`; `None` where JWildfire's fails (no `)`, not
/// a number).
fn value(s: &[char], i: usize) -> Option<f64> {
    let rest = s.get(i + 2..)?;
    let end = rest.iter().position(|&c| c == ')')?;
    parse_double(&rest[..end].iter().collect::<String>())
}

/// Adds `p` as the next vertex of the open polygon; `None` past the table's end.
fn record(p: P3, vcount: &mut usize, ver: &mut [P3; MAX_POLY]) -> Option<()> {
    *ver.get_mut(*vcount)? = p;
    *vcount += 1;
    Some(())
}

/// The turtle's saved state.
#[derive(Clone, Copy)]
struct Saved {
    pos: P3,
    fow: P3,
    lef: P3,
    upp: P3,
    col: i32,
    dis: f64,
    dis2: f64,
    ang: f64,
    thick: f64,
    tr: f64,
    last: P3,
    last_col: i32,
    last_v: [P3; 9],
}

/// What the shapes share: thickness, the last cylinder's end, the vertex and polygon tables
/// (shared by steps and polygons, as in JWildfire), the mesh.
struct Builder<'a> {
    g: &'a Grammar,
    mode: u8,
    thick: f64,
    last: P3,
    last_col: i32,
    last_v: [P3; 9],
    ver: [P3; MAX_POLY],
    poly: [[i32; 4]; MAX_POLY + 1],
    mesh: LsMesh,
}

impl Builder<'_> {
    /// Adds vertices 1..=`vertices` of the vertex table and polygons 1..=`polygons` of the
    /// polygon table (a polygon whose last two indices agree is a triangle, else a quad).
    fn save(&mut self, vertices: usize, polygons: usize, color: i32) -> Option<()> {
        let mut nvert = [0u32; MAX_POLY];
        for t in 1..=vertices {
            nvert[t - 1] = self.mesh.add_vertex(*self.ver.get(t)?);
        }
        for t in 1..=polygons {
            let p = *self.poly.get(t)?;
            let at =
                |k: usize| -> Option<u32> { nvert.get(usize::try_from(p[k] - 1).ok()?).copied() };
            let tri = p[2] == p[3];
            let colour = match self.mode {
                0 => FaceColor::Plain,
                1 => FaceColor::Index(f64::from(color) / MAX_COLORS as f64),
                _ => {
                    let c = usize::try_from(color.min(MAX_COLORS as i32 - 1)).ok()?;
                    let rgb = self.g.colors[c].map(f64::from);
                    if tri {
                        FaceColor::Rgb(rgb)
                    } else {
                        FaceColor::Rgb(rgb.map(|x| (x * 256.0).floor()))
                    }
                }
            };
            let (a, b, c) = (at(0)?, at(1)?, at(2)?);
            self.mesh.faces.push(([a, b, c], colour));
            if !tri {
                self.mesh.faces.push(([a, c, at(3)?], colour));
            }
        }
        Some(())
    }

    /// The half width of a step of length `d`.
    fn width(&self, d: f64) -> f64 {
        let s = d * self.thick;
        let m = f64::from(self.g.min_thickness);
        if s < m { m } else { s }
    }

    /// A block from `p1` to `p2`, its sides facing `up`.
    fn block(&mut self, p1: P3, p2: P3, up: P3, c: i32) -> Option<()> {
        let dis = sub(p2, p1);
        let d = f64::from(len(dis));
        if d == 0.0 {
            return Some(());
        }
        let s = self.width(d) * HALF_DIAGONAL;
        let d1 = unit_mul(dis);
        let d2 = unit_mul(up);
        let d3 = unit_mul(cross(d1, d2));
        let b = unit_mul(add(d2, d3));
        self.ver[1] = plus(p1, b, s);
        self.ver[3] = plus(p1, b, -s);
        let b = unit_mul(sub(d2, d3));
        self.ver[2] = plus(p1, b, s);
        self.ver[4] = plus(p1, b, -s);
        for i in 1..=4 {
            self.ver[i + 4] = add(self.ver[i], dis);
        }
        let quads = [
            [1, 5, 6, 2],
            [2, 6, 7, 3],
            [3, 7, 8, 4],
            [4, 8, 5, 1],
            [1, 2, 3, 4],
            [8, 7, 6, 5],
        ];
        self.poly[1..=6].copy_from_slice(&quads);
        self.save(8, 6, c)
    }

    /// An octagonal cylinder from `p1` to `p2`, attached to the previous one of its colour.
    fn cylinder(&mut self, p1: P3, p2: P3, up: P3, c: i32) -> Option<()> {
        let dis = sub(p2, p1);
        let d = f64::from(len(dis));
        if d == 0.0 {
            return Some(());
        }
        let mut s = self.width(d) * 0.5;
        let d1 = unit_mul(dis);
        let d2 = unit_mul(up);
        let d3 = unit_mul(cross(d1, d2));
        let t1 = unit_mul(add(d2, d3));
        let t2 = unit_mul(sub(d2, d3));
        self.ver[1] = plus(p1, t1, s);
        self.ver[5] = plus(p1, t1, -s);
        self.ver[3] = plus(p1, t2, s);
        self.ver[7] = plus(p1, t2, -s);
        s *= f64::from(HALF_DIAGONAL as f32);
        self.ver[2] = plus2(p1, t1, s, t2, s);
        self.ver[4] = plus2(p1, t1, -s, t2, s);
        self.ver[6] = plus2(p1, t1, -s, t2, -s);
        self.ver[8] = plus2(p1, t1, s, t2, -s);
        for i in 1..=8 {
            self.ver[i + 8] = add(self.ver[i], dis);
        }
        if self.last_col == c && len(sub(p1, self.last)) < 1.0 {
            // Start from the previous end ring, beginning at its corner nearest corner 1.
            let mut best = f64::from(1e30f32);
            let mut ii = 0;
            for i in 1..=8 {
                let d = f64::from(len(sub(self.ver[1], self.last_v[i])));
                if d < best {
                    best = d;
                    ii = i;
                }
            }
            for i in 1..=8 {
                self.ver[i] = self.last_v[ii];
                ii = (ii + 1) % 9;
                if ii == 0 {
                    ii = 1;
                }
            }
        }
        for i in 1..=7 {
            let i4 = i as i32;
            self.poly[i] = [i4, i4 + 8, i4 + 9, i4 + 1];
        }
        self.poly[8] = [8, 16, 9, 1];
        self.save(16, 8, c)?;
        self.last_col = c;
        self.last = p2;
        for i in 1..=8 {
            self.last_v[i] = self.ver[i + 8];
        }
        Some(())
    }

    fn step(&mut self, p1: P3, p2: P3, up: P3, c: i32) -> Option<()> {
        if self.g.cylinders {
            self.cylinder(p1, p2, up, c)
        } else {
            self.block(p1, p2, up, c)
        }
    }
}

/// A small generator for `~` (JWildfire draws from `Math.random()`, different on every
/// run; a fixed sequence keeps ugnis' meshes reproducible): SplitMix64 (Steele, Lea and
/// Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014).
struct Mix(u64);

impl Mix {
    fn f01(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// Draws production `s` of grammar `g` in colour mode `mode` (0–2); `None` where
/// JWildfire's drawing fails (a `(v)` without `)` or number, a `]` without `[`, deeper than
/// 1024 `[`, a polygon of more than 399 vertices, a negative colour in mode 2).
pub(super) fn draw(g: &Grammar, s: &[char], mode: u8) -> Option<LsMesh> {
    let mut b = Builder {
        g,
        mode,
        thick: g.thickness,
        last: [0.0; 3],
        last_col: 0,
        last_v: [[0.0; 3]; 9],
        ver: [[0.0; 3]; MAX_POLY],
        poly: [[0; 4]; MAX_POLY + 1],
        mesh: LsMesh::default(),
    };
    let mut pos: P3 = [0.0, 0.0, 0.0];
    let mut fow: P3 = [0.0, 0.0, 1.0];
    let mut lef: P3 = [0.0, 1.0, 0.0];
    let mut upp: P3 = [1.0, 0.0, 0.0];
    let sky: P3 = [0.0, 0.0, 1.0];
    let (mut col, mut dis, mut dis2, mut ang, mut tr) = (2i32, 1.0f64, 0.5f64, g.angle, 0.2f64);
    let mut stack: Vec<Saved> = Vec::new();
    let mut aside: Vec<Vec<P3>> = Vec::new();
    let (mut aside_depth, mut aside_total) = (0usize, 0usize);
    let (mut poly_on, mut vcount, mut pcount) = (false, 0usize, 0usize);
    let mut rng = Mix(0x4c50_6172_7365_7233);
    let pi = PI as f32;
    for i in 0..s.len().saturating_sub(1) {
        if g.poly_limit.is_some_and(|l| l < 0) {
            break;
        }
        if b.mesh.faces.len() > MAX_FACES {
            b.mesh.cut = true;
            break;
        }
        let arg = s[i + 1] == '(';
        let val = || if arg { value(s, i) } else { None };
        let angle = || -> Option<f64> { Some(if arg { 0.017453 * value(s, i)? } else { ang }) };
        match s[i] {
            '+' => turn(-angle()?, upp, &mut fow, &mut lef),
            '-' => turn(angle()?, upp, &mut fow, &mut lef),
            '&' => turn(angle()?, lef, &mut fow, &mut upp),
            '^' => turn(-angle()?, lef, &mut fow, &mut upp),
            '<' => turn(-angle()?, fow, &mut lef, &mut upp),
            '>' => turn(angle()?, fow, &mut lef, &mut upp),
            '%' => turn(f64::from(pi), fow, &mut lef, &mut upp),
            '|' => turn(f64::from(pi), upp, &mut fow, &mut lef),
            '~' => {
                let r = if arg { 0.017453 * value(s, i)? } else { 6.0 };
                let a = rng.f01() * r * 2.0 - r;
                turn(a, upp, &mut fow, &mut lef);
                let a = rng.f01() * r * 2.0 - r;
                turn(a, lef, &mut fow, &mut upp);
                let a = rng.f01() * r * 2.0 - r;
                turn(a, fow, &mut lef, &mut upp);
            }
            't' => {
                if fow[0] == 0.0 && fow[1] == 0.0 {
                    continue;
                }
                let k = if arg { value(s, i)? } else { tr };
                let trope = unit_div([-fow[0], -fow[1], 0.0]);
                let r = k * f64::from(dot(fow, trope));
                turn(-r, lef, &mut fow, &mut upp);
            }
            '$' => {
                if len(sub(fow, sky)) == 0.0 {
                    continue;
                }
                lef = cross(fow, sky);
                upp = cross(fow, lef);
                if upp[2] < 0.0 {
                    upp = upp.map(|c| -c);
                    lef = lef.map(|c| -c);
                }
            }
            '!' => b.thick *= if arg { val()? } else { 0.7 },
            '?' => {
                if arg {
                    b.thick *= val()?;
                } else {
                    b.thick /= 0.7;
                }
            }
            ':' => ang *= if arg { val()? } else { 0.9 },
            ';' => {
                if arg {
                    ang *= val()?;
                } else {
                    ang /= 0.9;
                }
            }
            '\'' | '"' => {
                if arg {
                    let r = val()?;
                    dis *= r;
                    dis2 *= r;
                } else if s[i] == '\'' {
                    dis *= 0.9;
                    dis2 *= 0.9;
                } else {
                    dis /= 0.9;
                    dis2 /= 0.9;
                }
            }
            'F' | 'Z' => {
                let d = match (arg, s[i]) {
                    (true, _) => val()?,
                    (false, 'F') => dis,
                    _ => dis2,
                };
                let end = plus(pos, fow, d);
                b.step(pos, end, upp, col)?;
                pos = end;
            }
            'f' | 'z' | 'g' => {
                let d = match (arg, s[i]) {
                    (true, _) => val()?,
                    (false, 'z') => dis2,
                    _ => dis,
                };
                pos = plus(pos, fow, d);
                if poly_on && s[i] != 'g' {
                    record(pos, &mut vcount, &mut b.ver)?;
                }
            }
            '.' if poly_on => record(pos, &mut vcount, &mut b.ver)?,
            '[' => {
                if stack.len() >= MAX_STACK {
                    return None;
                }
                stack.push(Saved {
                    pos,
                    fow,
                    lef,
                    upp,
                    col,
                    dis,
                    dis2,
                    ang,
                    thick: b.thick,
                    tr,
                    last: b.last,
                    last_col: b.last_col,
                    last_v: b.last_v,
                });
            }
            ']' => {
                let t = stack.pop()?;
                (pos, fow, lef, upp, col) = (t.pos, t.fow, t.lef, t.upp, t.col);
                (dis, dis2, ang, b.thick, tr) = (t.dis, t.dis2, t.ang, t.thick, t.tr);
                (b.last, b.last_col, b.last_v) = (t.last, t.last_col, t.last_v);
            }
            '{' => {
                if poly_on {
                    aside_total += vcount;
                    if aside_total > MAX_ASIDE {
                        b.mesh.cut = true;
                        break;
                    }
                    aside.push(b.ver[..vcount].to_vec());
                    aside_depth += 1;
                }
                poly_on = true;
                vcount = 1;
                pcount = 1;
            }
            '}' => {
                if vcount > 3 {
                    for j in 1..vcount - 2 {
                        let j = j as i32;
                        *b.poly.get_mut(pcount)? = [1, j + 1, j + 2, j + 2];
                        pcount += 1;
                    }
                    b.save(vcount - 1, pcount - 1, col)?;
                }
                poly_on = false;
                if aside_depth > 0 {
                    aside_depth -= 1;
                    let kept = &aside[aside_depth];
                    b.ver[..kept.len()].copy_from_slice(kept);
                    vcount = kept.len();
                    poly_on = true;
                }
            }
            'c' => {
                col = if arg {
                    val()? as i32
                } else {
                    col.wrapping_add(1)
                }
            }
            _ => {}
        }
    }
    Some(b.mesh)
}

#[cfg(test)]
mod tests {
    use super::super::jwf_ls_grammar::{expand, read_grammar};
    use super::*;

    fn mesh(text: &str, mode: u8) -> LsMesh {
        let g = read_grammar(text).unwrap();
        let (s, _) = expand(&g).unwrap();
        draw(&g, &s, mode).unwrap()
    }

    fn bounds(m: &LsMesh) -> [[f32; 2]; 3] {
        let mut b = [[f32::MAX, f32::MIN]; 3];
        for v in &m.vertices {
            for k in 0..3 {
                b[k] = [b[k][0].min(v[k]), b[k][1].max(v[k])];
            }
        }
        b
    }

    #[test]
    fn one_step_is_one_block_or_one_cylinder() {
        // `F_`: the last character is not read, `F` draws one step of length 1 along +z.
        // A block of thickness 0.2: half diagonal 0.2 · 0.7071 from the axis along
        // up ± left, i.e. corners at (±0.1, ±0.1) after normalising.
        let m = mesh("thickness 20\nshape 0\naxiom F_", 0);
        assert_eq!((m.vertices.len(), m.faces.len()), (8, 12));
        let b = bounds(&m);
        for (k, want) in [[-0.1, 0.1], [-0.1, 0.1], [0.0, 1.0]].iter().enumerate() {
            assert!((b[k][0] - want[0]).abs() < 1e-4 && (b[k][1] - want[1]).abs() < 1e-4);
        }
        // The cylinder: 16 corners, 8 quads, radius 0.1 (its corners on the x and y axes
        // at 45° to up and left, i.e. the octagon's extent is 0.1 on both).
        let m = mesh("thickness 20\naxiom F_", 1);
        assert_eq!((m.vertices.len(), m.faces.len()), (16, 16));
        let b = bounds(&m);
        assert!((b[0][1] - 0.1).abs() < 1e-4 && (b[1][0] + 0.1).abs() < 1e-4);
        assert!(b[2][0].abs() < 1e-6 && (b[2][1] - 1.0).abs() < 1e-6);
        assert!(m.faces.iter().all(|f| f.1 == FaceColor::Index(0.02)));
        // Two steps of one colour share the ring between them.
        let m = mesh("thickness 20\naxiom FF_", 0);
        assert_eq!((m.vertices.len(), m.faces.len()), (24, 32));
    }

    #[test]
    fn a_polygon_is_a_fan_coloured_from_the_table() {
        // A unit square in the plane x = 0: four vertices, two triangles.
        let m = mesh("angle 90\naxiom {.f+f+f}_", 2);
        assert_eq!(m.faces.len(), 2);
        assert_eq!(m.vertices.len(), 4);
        // Triangles take the table's colour as 0–1 (colour 2: 0.8, 0.4, 0.4).
        let c = [0.8f32, 0.4, 0.4].map(f64::from);
        assert!(m.faces.iter().all(|f| f.1 == FaceColor::Rgb(c)));
        let b = bounds(&m);
        assert!((b[2][1] - 1.0).abs() < 1e-6 && (b[1][1] - 1.0).abs() < 1e-5);
    }

    #[test]
    fn broken_productions_fail_as_jwildfires() {
        let g = read_grammar("axiom F(1_").unwrap();
        assert!(draw(&g, &g.axiom, 0).is_none());
        let g = read_grammar("axiom ]F_").unwrap();
        assert!(draw(&g, &g.axiom, 0).is_none());
        let g = read_grammar("axiom c(-3)FF").unwrap();
        assert!(draw(&g, &g.axiom, 2).is_none());
        assert!(draw(&g, &g.axiom, 1).is_some());
    }
}
