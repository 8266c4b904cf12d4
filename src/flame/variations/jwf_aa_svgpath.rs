//! SVG path data for `svg_wf`'s reader ([`super::jwf_aa_svgdoc`]): every command of SVG 1.1's
//! path grammar (moves, lines, cubic and quadratic Béziers with their smooth forms, elliptical
//! arcs, close), read into flattened polylines through an affine map, and the number lists of
//! other attributes.

use super::jwf_aa_raster::{Pt, ellipse_arc, flatten_cubic, flatten_quad};
use super::jwf_aa_svgdoc::{Doc, Mat};

/// A reader of path data and number lists.
pub(super) struct Cursor<'a> {
    b: &'a [u8],
    i: usize,
}

impl<'a> Cursor<'a> {
    pub(super) fn new(s: &'a str) -> Cursor<'a> {
        Cursor {
            b: s.as_bytes(),
            i: 0,
        }
    }

    fn skip(&mut self) {
        while self.i < self.b.len()
            && (self.b[self.i].is_ascii_whitespace() || self.b[self.i] == b',')
        {
            self.i += 1;
        }
    }

    /// The next number, if a number comes next.
    pub(super) fn number(&mut self) -> Option<f64> {
        self.skip();
        let s = self.i;
        let b = self.b;
        let mut j = s;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        let mut digits = false;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
            digits = true;
        }
        if j < b.len() && b[j] == b'.' {
            j += 1;
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
                digits = true;
            }
        }
        if !digits {
            return None;
        }
        if j < b.len() && (b[j] == b'e' || b[j] == b'E') {
            let mut k = j + 1;
            if k < b.len() && (b[k] == b'+' || b[k] == b'-') {
                k += 1;
            }
            if k < b.len() && b[k].is_ascii_digit() {
                while k < b.len() && b[k].is_ascii_digit() {
                    k += 1;
                }
                j = k;
            }
        }
        let x: f64 = std::str::from_utf8(&b[s..j]).ok()?.parse().ok()?;
        self.i = j;
        Some(x).filter(|x| x.is_finite())
    }

    /// An arc flag: a single 0 or 1.
    fn flag(&mut self) -> Option<bool> {
        self.skip();
        let c = *self.b.get(self.i)?;
        if c == b'0' || c == b'1' {
            self.i += 1;
            Some(c == b'1')
        } else {
            None
        }
    }

    /// The next command letter, if one comes next.
    fn command(&mut self) -> Option<u8> {
        self.skip();
        let c = *self.b.get(self.i)?;
        if c.is_ascii_alphabetic() && c != b'e' && c != b'E' {
            self.i += 1;
            Some(c)
        } else {
            None
        }
    }

    fn at_end(&mut self) -> bool {
        self.skip();
        self.i >= self.b.len()
    }
}

/// SVG path data as flattened subpaths in image pixels (through `mat`). Data after an error
/// is left out, as SVG's error handling asks.
pub(super) fn path_data(d: &str, mat: &Mat, budget: usize, doc: &mut Doc) -> Vec<(Vec<Pt>, bool)> {
    // The subpaths done, and how many points they hold.
    let mut out: Vec<(Vec<Pt>, bool)> = Vec::new();
    let mut done = 0usize;
    let mut c = Cursor::new(d);
    let mut cur: Vec<Pt> = Vec::new();
    let (mut p, mut start) = ((0.0, 0.0), (0.0, 0.0));
    // The last control point (for S and T) and the command that set it.
    let mut last_ctrl: Option<(Pt, u8)> = None;
    let mut cmd = 0u8;
    let tr = |q: Pt| mat.apply(q);
    fn flush(cur: &mut Vec<Pt>, out: &mut Vec<(Vec<Pt>, bool)>, closed: bool, done: &mut usize) {
        if cur.len() > 1 || (closed && !cur.is_empty()) {
            *done += cur.len();
            out.push((std::mem::take(cur), closed));
        } else {
            cur.clear();
        }
    }
    while !c.at_end() {
        if let Some(k) = c.command() {
            cmd = k;
        } else if cmd == 0 {
            doc.problem("path data not understood: the rest of the path is left out".into());
            break;
        }
        let rel = cmd.is_ascii_lowercase();
        let base = if rel { p } else { (0.0, 0.0) };
        let pt = |c: &mut Cursor, base: Pt| -> Option<Pt> {
            let x = c.number()?;
            let y = c.number()?;
            Some((base.0 + x, base.1 + y))
        };
        let ok = match cmd.to_ascii_uppercase() {
            b'M' => pt(&mut c, base).map(|q| {
                flush(&mut cur, &mut out, false, &mut done);
                p = q;
                start = q;
                cur.push(tr(q));
                // Further pairs are lines.
                cmd = if rel { b'l' } else { b'L' };
                last_ctrl = None;
            }),
            b'L' => pt(&mut c, base).map(|q| {
                p = q;
                cur.push(tr(q));
                last_ctrl = None;
            }),
            b'H' => c.number().map(|x| {
                p = (base.0 + x, p.1);
                cur.push(tr(p));
                last_ctrl = None;
            }),
            b'V' => c.number().map(|y| {
                p = (p.0, base.1 + y);
                cur.push(tr(p));
                last_ctrl = None;
            }),
            b'C' | b'S' => {
                let smooth = cmd.eq_ignore_ascii_case(&b'S');
                let c1 = if smooth {
                    match last_ctrl {
                        Some((q, b'C' | b'S')) => Some((2.0 * p.0 - q.0, 2.0 * p.1 - q.1)),
                        _ => Some(p),
                    }
                } else {
                    pt(&mut c, base)
                };
                let c2 = c1.and_then(|_| pt(&mut c, base));
                let e = c2.and_then(|_| pt(&mut c, base));
                match (c1, c2, e) {
                    (Some(c1), Some(c2), Some(e)) => {
                        if cur.is_empty() {
                            cur.push(tr(p));
                        }
                        flatten_cubic(&mut cur, tr(p), tr(c1), tr(c2), tr(e));
                        last_ctrl = Some((c2, b'C'));
                        p = e;
                        Some(())
                    }
                    _ => None,
                }
            }
            b'Q' | b'T' => {
                let smooth = cmd.eq_ignore_ascii_case(&b'T');
                let c1 = if smooth {
                    match last_ctrl {
                        Some((q, b'Q')) => Some((2.0 * p.0 - q.0, 2.0 * p.1 - q.1)),
                        _ => Some(p),
                    }
                } else {
                    pt(&mut c, base)
                };
                let e = c1.and_then(|_| pt(&mut c, base));
                match (c1, e) {
                    (Some(c1), Some(e)) => {
                        if cur.is_empty() {
                            cur.push(tr(p));
                        }
                        flatten_quad(&mut cur, tr(p), tr(c1), tr(e));
                        last_ctrl = Some((c1, b'Q'));
                        p = e;
                        Some(())
                    }
                    _ => None,
                }
            }
            b'A' => {
                let args = (|| {
                    let rx = c.number()?;
                    let ry = c.number()?;
                    let rot = c.number()?;
                    let large = c.flag()?;
                    let sweep = c.flag()?;
                    let e = pt(&mut c, base)?;
                    Some((rx, ry, rot, large, sweep, e))
                })();
                args.map(|(rx, ry, rot, large, sweep, e)| {
                    if cur.is_empty() {
                        cur.push(tr(p));
                    }
                    arc(&mut cur, mat, p, rx, ry, rot, large, sweep, e);
                    p = e;
                    last_ctrl = None;
                })
            }
            b'Z' => {
                flush(&mut cur, &mut out, true, &mut done);
                p = start;
                last_ctrl = None;
                // A command after Z starts at the subpath's start; a command letter must
                // follow.
                cur.push(tr(p));
                cmd = 0;
                Some(())
            }
            _ => None,
        };
        if ok.is_none() {
            doc.problem("path data not understood: the rest of the path is left out".into());
            break;
        }
        if done + cur.len() > budget {
            cur.clear();
            doc.problem("a path has too many points: the rest of it is left out".into());
            break;
        }
    }
    flush(&mut cur, &mut out, false, &mut done);
    out
}

/// Appends an elliptical arc from `p` to `e` (SVG's endpoint form, radii corrected as SVG
/// 1.1's implementation notes F.6 describe) in image pixels, after `p`.
#[allow(clippy::too_many_arguments)]
fn arc(
    out: &mut Vec<Pt>,
    mat: &Mat,
    p: Pt,
    rx: f64,
    ry: f64,
    rot: f64,
    large: bool,
    sweep: bool,
    e: Pt,
) {
    let (mut rx, mut ry) = (rx.abs(), ry.abs());
    if rx == 0.0 || ry == 0.0 || (p.0 == e.0 && p.1 == e.1) {
        out.push(mat.apply(e));
        return;
    }
    let (s, c) = rot.to_radians().sin_cos();
    let (dx, dy) = ((p.0 - e.0) / 2.0, (p.1 - e.1) / 2.0);
    let (x1, y1) = (c * dx + s * dy, -s * dx + c * dy);
    let lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
    if lambda > 1.0 {
        rx *= lambda.sqrt();
        ry *= lambda.sqrt();
    }
    let num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    let den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    let mut k = (num / den).max(0.0).sqrt();
    if large == sweep {
        k = -k;
    }
    let (cx1, cy1) = (k * rx * y1 / ry, -k * ry * x1 / rx);
    let (cx, cy) = (
        c * cx1 - s * cy1 + (p.0 + e.0) / 2.0,
        s * cx1 + c * cy1 + (p.1 + e.1) / 2.0,
    );
    let ang = |ux: f64, uy: f64| uy.atan2(ux);
    let t1 = ang((x1 - cx1) / rx, (y1 - cy1) / ry);
    let t2 = ang((-x1 - cx1) / rx, (-y1 - cy1) / ry);
    let mut dt = t2 - t1;
    let tau = std::f64::consts::TAU;
    if sweep && dt < 0.0 {
        dt += tau;
    } else if !sweep && dt > 0.0 {
        dt -= tau;
    }
    // Points of the unit-free arc, sized for the image.
    let sc = mat.scale().max(1e-9);
    let pts = ellipse_arc((0.0, 0.0), rx * sc, ry * sc, t1, dt);
    for &(ux, uy) in pts.iter().skip(1) {
        let (ex, ey) = (ux / sc, uy / sc);
        let q = (c * ex - s * ey + cx, s * ex + c * ey + cy);
        out.push(mat.apply(q));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn path_data_reads_every_command() {
        let mut doc = Doc::default();
        let d = "M10,10 h20 v20 H10 z m 40 0 l 10 10 10-10z M0 0 C 0 10 10 10 10 0 \
                 S 20 -10 20 0 Q 25 5 30 0 T 40 0 A 5 5 0 0 1 50 0 L1e1-5.5";
        let sub = path_data(d, &Mat::ID, 1000, &mut doc);
        assert!(doc.problems.is_empty(), "{:?}", doc.problems);
        assert_eq!(sub.len(), 3);
        assert!(sub[0].1 && sub[1].1 && !sub[2].1);
        assert_eq!(
            sub[0].0,
            vec![(10.0, 10.0), (30.0, 10.0), (30.0, 30.0), (10.0, 30.0)]
        );
        // The relative move after z starts from the first subpath's start.
        assert_eq!(sub[1].0[0], (50.0, 10.0));
        assert_eq!(sub[1].0[2], (70.0, 10.0));
        // Numbers run together: `1e1-5.5` is the point (10, −5.5).
        let last = sub[2].0.last().copied().unwrap();
        assert!(
            (last.0 - 10.0).abs() < 1e-12 && (last.1 + 5.5).abs() < 1e-12,
            "{last:?}"
        );
        // The half circle from (40, 0) to (50, 0) bulges to y = −5 (sweep 1: clockwise on
        // screen, through the top).
        let arc_min = sub[2].0[1..]
            .iter()
            .filter(|p| p.0 > 40.5 && p.0 < 49.5)
            .map(|p| p.1)
            .fold(f64::INFINITY, f64::min);
        assert!((arc_min + 5.0).abs() < 0.06, "{arc_min}");
        // A budget of points cuts the path, with a problem reported.
        let sub = path_data(d, &Mat::ID, 20, &mut doc);
        assert!(sub.iter().map(|p| p.0.len()).sum::<usize>() <= 20);
        assert_eq!(doc.problems.len(), 1);
    }
}
