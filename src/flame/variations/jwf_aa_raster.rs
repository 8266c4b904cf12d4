//! An anti-aliased rasteriser for the JWildfire variations that draw into a Java2D image and
//! sample its pixels (`svg_wf`, `msTruchet`): polygons filled by the non-zero or even-odd
//! rule with each pixel's covered share as its coverage, lines stroked into polygons, and
//! curves and arcs flattened into lines.
//!
//! Coverage: each pixel row is sampled on [`SUB_ROWS`] scanlines at the centres of equal
//! sub-rows, and on each scanline the inside spans count exactly along x. This is how Java2D's
//! anti-aliasing renderer (Marlin, OpenJDK 9 and later) estimates coverage, with 8 sub-rows
//! and 1/256-pixel steps along x; the edge pixels it produces may still differ from these by
//! a step of coverage, so an image drawn here matches JWildfire's up to its edges.

/// Scanlines per pixel row.
pub(super) const SUB_ROWS: usize = 8;

/// Most line segments one curve is cut into.
const MAX_PIECES: usize = 1024;

/// A point of the image plane: x to the right, y down, in pixels.
pub(super) type Pt = (f64, f64);

/// How the inside of a set of polygons is decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum FillRule {
    /// Inside where the winding number is not 0.
    NonZero,
    /// Inside where the winding number is odd.
    EvenOdd,
}

/// An edge with y0 < y1 and the winding it adds (+1 for an edge going down).
#[derive(Clone, Copy, Debug)]
struct Edge {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
    wind: i32,
}

impl Edge {
    fn x_at(&self, y: f64) -> f64 {
        self.x0 + (y - self.y0) / (self.y1 - self.y0) * (self.x1 - self.x0)
    }
}

/// Fills `polygons` (each closed implicitly) in a `w` × `h` image and calls
/// `paint(column, row, coverage)` for every pixel with a coverage above 0 (at most 1), row by
/// row. Without anti-aliasing (`aa` false) a pixel is covered wholly when its centre is
/// inside, else not at all. Non-finite points are dropped.
pub(super) fn fill(
    polygons: &[Vec<Pt>],
    rule: FillRule,
    aa: bool,
    w: usize,
    h: usize,
    mut paint: impl FnMut(usize, usize, f64),
) {
    let mut edges: Vec<Edge> = Vec::new();
    for poly in polygons {
        let pts: Vec<Pt> = poly
            .iter()
            .copied()
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .collect();
        for (i, &a) in pts.iter().enumerate() {
            let b = pts[(i + 1) % pts.len()];
            if a.1 == b.1 {
                continue;
            }
            let (p, q, wind) = if a.1 < b.1 { (a, b, 1) } else { (b, a, -1) };
            edges.push(Edge {
                x0: p.0,
                y0: p.1,
                x1: q.0,
                y1: q.1,
                wind,
            });
        }
    }
    if edges.is_empty() || w == 0 || h == 0 {
        return;
    }
    edges.sort_by(|a, b| a.y0.total_cmp(&b.y0));
    let y_lo = edges[0].y0.max(0.0).floor() as usize;
    let y_hi = edges
        .iter()
        .map(|e| e.y1)
        .fold(f64::NEG_INFINITY, f64::max)
        .min(h as f64)
        .ceil()
        .max(0.0) as usize;
    let sub_rows = if aa { SUB_ROWS } else { 1 };
    let sub = 1.0 / sub_rows as f64;
    // Coverage of each pixel of a row, and steps of the coverage of whole pixels (summed
    // along the row).
    let mut cov = vec![0.0f64; w + 1];
    let mut step = vec![0.0f64; w + 1];
    let mut next = 0;
    let mut active: Vec<Edge> = Vec::new();
    let mut cross: Vec<(f64, i32)> = Vec::new();
    for row in y_lo..y_hi.min(h) {
        let (mut lo, mut hi) = (w, 0usize);
        for k in 0..sub_rows {
            let ys = row as f64 + (k as f64 + 0.5) * sub;
            while next < edges.len() && edges[next].y0 <= ys {
                active.push(edges[next]);
                next += 1;
            }
            active.retain(|e| e.y1 > ys);
            cross.clear();
            cross.extend(
                active
                    .iter()
                    .filter(|e| e.y0 <= ys)
                    .map(|e| (e.x_at(ys), e.wind)),
            );
            cross.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut winding = 0;
            for pair in cross.windows(2) {
                winding += pair[0].1;
                let inside = match rule {
                    FillRule::NonZero => winding != 0,
                    FillRule::EvenOdd => winding % 2 != 0,
                };
                if !inside {
                    continue;
                }
                let (mut xa, mut xb) = (pair[0].0, pair[1].0);
                if !aa {
                    // The pixels whose centres lie in [xa, xb), wholly.
                    xa = (xa - 0.5).ceil();
                    xb = (xb - 0.5).ceil();
                }
                let xa = xa.clamp(0.0, w as f64);
                let xb = xb.clamp(0.0, w as f64);
                if xb <= xa {
                    continue;
                }
                let (ia, ib) = (xa.floor() as usize, (xb.floor() as usize).min(w));
                lo = lo.min(ia);
                hi = hi.max(ib + 1);
                if ia == ib {
                    cov[ia] += (xb - xa) * sub;
                } else {
                    cov[ia] += (ia as f64 + 1.0 - xa) * sub;
                    step[ia + 1] += sub;
                    step[ib] -= sub;
                    cov[ib] += (xb - ib as f64) * sub;
                }
            }
        }
        let mut run = 0.0;
        for x in lo..hi.min(w + 1) {
            run += step[x];
            let c = (cov[x] + run).clamp(0.0, 1.0);
            cov[x] = 0.0;
            step[x] = 0.0;
            if x < w && c > 1e-12 {
                paint(x, row, c);
            }
        }
    }
}

/// The signed area of a polygon (positive when it turns clockwise on screen, y down).
fn area(poly: &[Pt]) -> f64 {
    let n = poly.len();
    (0..n)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        / 2.0
}

/// `poly` turned so that its area is positive (pieces of a stroke then unite under the
/// non-zero rule).
fn oriented(mut poly: Vec<Pt>) -> Vec<Pt> {
    if area(&poly) < 0.0 {
        poly.reverse();
    }
    poly
}

/// A circle as a polygon fine enough for `radius` (in pixels).
pub(super) fn circle(c: Pt, radius: f64) -> Vec<Pt> {
    ellipse_arc(c, radius, radius, 0.0, std::f64::consts::TAU)
}

/// Points of the ellipse with centre `c` and radii `rx`, `ry` (axis-aligned) from angle `a0`
/// over `sweep` (radians; y down, so positive angles turn clockwise on screen), both ends
/// included, fine enough to stay within 0.05 pixel of the curve.
pub(super) fn ellipse_arc(c: Pt, rx: f64, ry: f64, a0: f64, sweep: f64) -> Vec<Pt> {
    let r = rx.abs().max(ry.abs());
    let n = pieces_for_arc(r, sweep);
    (0..=n)
        .map(|i| {
            let a = a0 + sweep * i as f64 / n as f64;
            (c.0 + rx * a.cos(), c.1 + ry * a.sin())
        })
        .collect()
}

/// Segments for an arc of radius `r` pixels and angle `sweep` within 0.05 pixel.
fn pieces_for_arc(r: f64, sweep: f64) -> usize {
    let tol = 0.05;
    let step = if r > tol {
        2.0 * (1.0 - tol / r).acos()
    } else {
        std::f64::consts::PI
    };
    let n = (sweep.abs() / step.max(1e-3)).ceil();
    if n.is_finite() {
        (n as usize).clamp(4, MAX_PIECES)
    } else {
        4
    }
}

/// Appends to `out` the points of a cubic Bézier curve after `p0` (its end included), within
/// about 0.05 pixel (Wang's bound on the number of segments).
pub(super) fn flatten_cubic(out: &mut Vec<Pt>, p0: Pt, p1: Pt, p2: Pt, p3: Pt) {
    let dd = |a: Pt, b: Pt, c: Pt| (a.0 - 2.0 * b.0 + c.0).hypot(a.1 - 2.0 * b.1 + c.1);
    let l = dd(p0, p1, p2).max(dd(p1, p2, p3));
    let n = (0.75 * l / 0.05).sqrt().ceil();
    let n = if n.is_finite() {
        (n as usize).clamp(1, MAX_PIECES)
    } else {
        1
    };
    for i in 1..=n {
        let t = i as f64 / n as f64;
        let u = 1.0 - t;
        let (a, b, c, d) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
        out.push((
            a * p0.0 + b * p1.0 + c * p2.0 + d * p3.0,
            a * p0.1 + b * p1.1 + c * p2.1 + d * p3.1,
        ));
    }
}

/// Appends to `out` the points of a quadratic Bézier curve after `p0` (its end included).
pub(super) fn flatten_quad(out: &mut Vec<Pt>, p0: Pt, p1: Pt, p2: Pt) {
    let c1 = (
        p0.0 + 2.0 / 3.0 * (p1.0 - p0.0),
        p0.1 + 2.0 / 3.0 * (p1.1 - p0.1),
    );
    let c2 = (
        p2.0 + 2.0 / 3.0 * (p1.0 - p2.0),
        p2.1 + 2.0 / 3.0 * (p1.1 - p2.1),
    );
    flatten_cubic(out, p0, c1, c2, p2);
}

/// How a stroke's open ends are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Cap {
    Butt,
    Round,
    Square,
}

/// How a stroke turns at a corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Join {
    /// Sharp, cut to a bevel where the miter is longer than the limit times the width.
    Miter(f64),
    Round,
    Bevel,
}

/// The polygons whose union (non-zero rule) is the stroke of width `width` along the
/// polyline `pts` (closed: its last point joins its first).
pub(super) fn stroke(pts: &[Pt], closed: bool, width: f64, cap: Cap, join: Join) -> Vec<Vec<Pt>> {
    let hw = width / 2.0;
    let mut out = Vec::new();
    if !(hw > 0.0 && hw.is_finite()) {
        return out;
    }
    // Drop repeated points.
    let mut p: Vec<Pt> = Vec::with_capacity(pts.len());
    for &q in pts {
        if !(q.0.is_finite() && q.1.is_finite()) {
            continue;
        }
        if p.last()
            .is_none_or(|l: &Pt| (l.0 - q.0).hypot(l.1 - q.1) > 1e-9)
        {
            p.push(q);
        }
    }
    if closed && p.len() > 2 && {
        let (a, b) = (p[0], p[p.len() - 1]);
        (a.0 - b.0).hypot(a.1 - b.1) <= 1e-9
    } {
        p.pop();
    }
    if p.len() < 2 {
        // A zero-length path: a dot where the caps are round or square.
        if let Some(&c) = p.first() {
            match cap {
                Cap::Round => out.push(oriented(circle(c, hw))),
                Cap::Square => out.push(oriented(vec![
                    (c.0 - hw, c.1 - hw),
                    (c.0 + hw, c.1 - hw),
                    (c.0 + hw, c.1 + hw),
                    (c.0 - hw, c.1 + hw),
                ])),
                Cap::Butt => {}
            }
        }
        return out;
    }
    let n = p.len();
    let segs = if closed { n } else { n - 1 };
    // Unit direction and left normal of each segment.
    let dir = |i: usize| {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let l = (b.0 - a.0).hypot(b.1 - a.1);
        ((b.0 - a.0) / l, (b.1 - a.1) / l)
    };
    for i in 0..segs {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let d = dir(i);
        let nrm = (-d.1 * hw, d.0 * hw);
        let (mut a, mut b) = (a, b);
        if !closed && cap == Cap::Square {
            if i == 0 {
                a = (a.0 - d.0 * hw, a.1 - d.1 * hw);
            }
            if i == segs - 1 {
                b = (b.0 + d.0 * hw, b.1 + d.1 * hw);
            }
        }
        out.push(oriented(vec![
            (a.0 + nrm.0, a.1 + nrm.1),
            (b.0 + nrm.0, b.1 + nrm.1),
            (b.0 - nrm.0, b.1 - nrm.1),
            (a.0 - nrm.0, a.1 - nrm.1),
        ]));
    }
    // Joins at the inner points (and, closed, at the first).
    let corners: Vec<usize> = if closed {
        (0..n).collect()
    } else {
        (1..n - 1).collect()
    };
    for k in corners {
        let (d1, d2) = (dir((k + n - 1) % n), dir(k));
        let v = p[k];
        let turn = d1.0 * d2.1 - d1.1 * d2.0;
        if turn.abs() < 1e-12 && d1.0 * d2.0 + d1.1 * d2.1 > 0.0 {
            continue;
        }
        // The outer side: right of the path (normal −n) when it turns left, else left.
        let s = if turn > 0.0 { -1.0 } else { 1.0 };
        let n1 = (-d1.1 * hw * s, d1.0 * hw * s);
        let n2 = (-d2.1 * hw * s, d2.0 * hw * s);
        let a = (v.0 + n1.0, v.1 + n1.1);
        let b = (v.0 + n2.0, v.1 + n2.1);
        match join {
            Join::Round => out.push(oriented(circle(v, hw))),
            Join::Bevel => out.push(oriented(vec![v, a, b])),
            Join::Miter(limit) => {
                // Half the angle between the segments' normals gives the miter's length.
                let cos_t = (d1.0 * d2.0 + d1.1 * d2.1).clamp(-1.0, 1.0);
                let half = ((1.0 + cos_t) / 2.0).sqrt(); // cos of half the turn
                let ratio = if half > 1e-12 {
                    1.0 / half
                } else {
                    f64::INFINITY
                };
                if ratio <= limit {
                    let m = ((n1.0 + n2.0) / 2.0, (n1.1 + n2.1) / 2.0);
                    let ml = m.0.hypot(m.1);
                    let reach = hw * ratio;
                    let tip = (v.0 + m.0 / ml * reach, v.1 + m.1 / ml * reach);
                    out.push(oriented(vec![v, a, tip, b]));
                } else {
                    out.push(oriented(vec![v, a, b]));
                }
            }
        }
    }
    if !closed && cap == Cap::Round {
        out.push(oriented(circle(p[0], hw)));
        out.push(oriented(circle(p[n - 1], hw)));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The summed coverage of polygons in a 200 × 200 image.
    fn covered(polys: &[Vec<Pt>], rule: FillRule) -> f64 {
        let mut sum = 0.0;
        fill(polys, rule, true, 200, 200, |_, _, c| sum += c);
        sum
    }

    #[test]
    fn a_square_on_sub_row_lines_covers_its_area_exactly() {
        // x edges anywhere, y edges on sub-row boundaries: exact.
        let sq = vec![(10.3, 20.25), (70.9, 20.25), (70.9, 81.5), (10.3, 81.5)];
        let want = 60.6 * 61.25;
        assert!((covered(&[sq], FillRule::NonZero) - want).abs() < 1e-9);
    }

    #[test]
    fn a_circle_and_a_tilted_square_cover_close_to_their_areas() {
        let c = circle((100.0, 100.0), 60.0);
        let want = std::f64::consts::PI * 3600.0;
        let got = covered(&[c], FillRule::NonZero);
        assert!((got - want).abs() < 3e-3 * want, "{got} vs {want}");
        // A square of side 80 turned by 30°.
        let (s, co) = (30f64.to_radians().sin(), 30f64.to_radians().cos());
        let sq: Vec<Pt> = [(-40.0, -40.0), (40.0, -40.0), (40.0, 40.0), (-40.0, 40.0)]
            .iter()
            .map(|&(x, y)| (100.0 + x * co - y * s, 100.0 + x * s + y * co))
            .collect();
        let got = covered(std::slice::from_ref(&sq), FillRule::NonZero);
        assert!((got - 6400.0).abs() < 1e-3 * 6400.0, "{got}");
        // Without anti-aliasing: whole pixels, about as many as the area.
        let mut n = 0.0;
        fill(&[sq], FillRule::NonZero, false, 200, 200, |_, _, c| {
            assert_eq!(c, 1.0);
            n += c
        });
        assert!((n - 6400.0).abs() < 80.0, "{n}");
    }

    #[test]
    fn every_pixel_is_covered_at_most_once_and_holes_follow_the_rule() {
        let outer = vec![(20.0, 20.0), (180.0, 20.0), (180.0, 180.0), (20.0, 180.0)];
        let same_way = vec![(50.0, 50.0), (150.0, 50.0), (150.0, 150.0), (50.0, 150.0)];
        let other_way: Vec<Pt> = same_way.iter().rev().copied().collect();
        let mut max: f64 = 0.0;
        fill(
            &[outer.clone(), same_way.clone()],
            FillRule::NonZero,
            true,
            200,
            200,
            |_, _, c| max = max.max(c),
        );
        assert!(max <= 1.0);
        let big = 160.0 * 160.0;
        let both = [outer.clone(), same_way.clone()];
        assert!((covered(&both, FillRule::NonZero) - big).abs() < 1e-6);
        assert!((covered(&both, FillRule::EvenOdd) - (big - 1e4)).abs() < 1e-6);
        let hole = [outer, other_way];
        assert!((covered(&hole, FillRule::NonZero) - (big - 1e4)).abs() < 1e-6);
    }

    #[test]
    fn strokes_cover_length_times_width() {
        // A bent line, butt caps, 4 wide: an L of 102 × 4 and 4 × 98 with its outer corner
        // square (2 × 2) drawn by the miter.
        let pts = [(20.0, 40.0), (120.0, 40.0), (120.0, 140.0)];
        let polys = stroke(&pts, false, 4.0, Cap::Butt, Join::Miter(4.0));
        let got = covered(&polys, FillRule::NonZero);
        assert!((got - 800.0).abs() < 1e-6, "{got}");
        // Beveled: half of that corner square.
        let polys = stroke(&pts, false, 4.0, Cap::Butt, Join::Bevel);
        let got = covered(&polys, FillRule::NonZero);
        assert!((got - 798.0).abs() < 1e-6, "{got}");
        // A closed square outline 2 wide: the ring between squares 102 and 98 wide.
        let sq = [(50.0, 50.0), (150.0, 50.0), (150.0, 150.0), (50.0, 150.0)];
        let polys = stroke(&sq, true, 2.0, Cap::Butt, Join::Miter(4.0));
        let got = covered(&polys, FillRule::NonZero);
        assert!((got - (102.0 * 102.0 - 98.0 * 98.0)).abs() < 1e-6, "{got}");
    }

    #[test]
    fn a_flattened_curve_stays_on_the_curve() {
        let mut pts = vec![(0.0, 0.0)];
        flatten_cubic(
            &mut pts,
            (0.0, 0.0),
            (0.0, 100.0),
            (100.0, 100.0),
            (100.0, 0.0),
        );
        assert!(pts.len() > 10 && pts.len() < 200);
        assert_eq!(*pts.last().unwrap(), (100.0, 0.0));
        // The curve's top is at t = 1/2: (50, 75); the polyline reaches it within 0.05.
        let top = pts.iter().map(|p| p.1).fold(0.0, f64::max);
        assert!((top - 75.0).abs() < 0.05, "{top}");
        // Nothing comes out of garbage.
        let mut junk = Vec::new();
        flatten_cubic(
            &mut junk,
            (f64::NAN, 0.0),
            (1e308, 0.0),
            (0.0, 0.0),
            (1.0, 1.0),
        );
        assert!(junk.len() <= MAX_PIECES);
        fill(&[junk], FillRule::NonZero, true, 10, 10, |_, _, c| {
            assert!(c <= 1.0)
        });
    }
}
