//! The figures of Craig S. Kaplan's Taprats (as JWildfire 9.00 ships it in `csk.taprats.app`
//! for its `taprats` variation; GPL-3.0): the star [n/d]s and the rosette (n, q, s) drawn in a
//! regular n-gon whose edges' midpoints lie on the unit circle, and the design: each tile of a
//! tiling's translational unit gets its figure, and the unit is repeated over a window (Kaplan,
//! "Computer Generated Islamic Star Patterns", Bridges 2000). Written anew from the
//! algorithms, keeping the order of the floating operations.

use std::f64::consts::PI;

use super::jwf_tp_map::{
    Map, P, Tiling, Tr, add, angle, apply, compose, convex_sum, fill_region, intersection, invert,
    normalize, rotate, scale, sub, translate,
};

/// Most translational units a design repeats.
const MAX_UNITS: usize = 4096;

/// The point `frac` of the way round the unit circle.
fn arc(frac: f64) -> P {
    let a = frac * 2.0 * PI;
    [a.cos(), a.sin()]
}

/// The figure of one tile.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Figure {
    /// Nothing drawn.
    Empty,
    /// A rosette: n points, q the turn of its petals' tips, s the petals' sides.
    Rosette { n: usize, q: f64, s: i32 },
    /// A star [n/d]s: n points, d the hop between joined edge midpoints, s the segments.
    Star { n: usize, d: f64, s: i32 },
}

/// A map of one of `unit`'s edge chains: the chain through `points` and its mirror image in
/// the x axis, both from (1, 0).
fn chains(points: &[P]) -> Map {
    let mut from = Map::default();
    let tip = from.insert_vertex([1.0, 0.0]);
    let (mut top_prev, mut bot_prev) = (tip, tip);
    for &p in points {
        let top = from.insert_vertex(p);
        let bot = from.insert_vertex([p[0], -p[1]]);
        from.insert_edge(top_prev, top);
        from.insert_edge(bot_prev, bot);
        top_prev = top;
        bot_prev = bot;
    }
    from
}

/// The rosette's unit: the part between the directions of two neighbouring corners.
fn rosette_unit(n: usize, q: f64, s: i32) -> Map {
    let don = 1.0 / n as f64;
    let tip = [1.0, 0.0];
    let rtip = arc(don);
    let q = q.clamp(-0.99, 0.99);
    let s = s.min((n as i32 - 1) / 2);
    let r_outer = 1.0 / (PI * don).cos();
    let up_outer = scale(arc(0.5 * don), r_outer);
    let bisector = scale(sub(up_outer, [0.0, r_outer]), 0.5);
    let mut th = angle(sub(rtip, tip));
    let stable_isect = add(up_outer, scale(normalize(up_outer), -up_outer[1]));
    let stable_angle = angle(sub(stable_isect, tip));
    if q >= 0.0 {
        th = th * (1.0 - q) + (PI * 0.5) * q;
    } else {
        th = th * (1.0 + q) - stable_angle * q;
    }
    let qtip = [1.0 + th.cos(), th.sin()];
    let Some(key_point) = intersection(tip, qtip, up_outer, bisector) else {
        return Map::default();
    };
    let key_end = convex_sum(key_point, stable_isect, 10.0);
    let mut points = vec![key_point];
    let step = rotate(2.0 * PI * don);
    let (mut key_r_p, mut key_r_e) = ([key_point[0], -key_point[1]], [key_end[0], -key_end[1]]);
    for _ in 1..=s {
        key_r_p = apply(&step, key_r_p);
        key_r_e = apply(&step, key_r_e);
        // Near-parallel segments (e.g. n = 12, q = −0.8, s = 4) have no crossing: skipped.
        if let Some(mid) = intersection(key_point, key_end, key_r_p, key_r_e) {
            points.push(mid);
        }
    }
    chains(&points)
}

/// The star's unit.
fn star_unit(n: usize, d: f64, s: i32) -> Map {
    let (dn, don) = (n as f64, 1.0 / n as f64);
    let clamp_d = d.min(0.5 * dn - 0.01).max(1.0);
    let did = clamp_d.floor();
    let mut dfrac = clamp_d - did;
    let mut di = did as i32;
    let mut is_int = false;
    let clamp_s = s.min(di);
    let outer_s = s.min(di - 1);
    if dfrac < super::jwf_tp_map::TOL {
        dfrac = 0.0;
        is_int = true;
    } else if (1.0 - dfrac) < super::jwf_tp_map::TOL {
        dfrac = 0.0;
        di = did as i32 + 1;
        is_int = true;
    }
    let a = [1.0, 0.0];
    let b = arc(clamp_d * don);
    let mut points = Vec::new();
    for idx in 1..=outer_s {
        let ar = arc(f64::from(idx) * don);
        let br = arc((f64::from(idx) - clamp_d) * don);
        // Taprats takes the crossing as found; a missing one ends the chain here.
        match intersection(a, b, ar, br) {
            Some(mid) => points.push(mid),
            None => return Map::default(),
        }
    }
    let mut from = chains(&points);
    if clamp_s == di {
        let last = points.last().copied().unwrap_or(a);
        let top_prev = from.insert_vertex(last);
        let v4 = from.insert_vertex(apply(&rotate(2.0 * PI * don), last));
        if is_int {
            from.insert_edge(top_prev, v4);
        } else {
            let ar = arc(did * don);
            let br = arc(-dfrac * don);
            let c = arc(d * don);
            let Some(cent) = intersection(ar, br, a, c) else {
                return from;
            };
            let vcent = from.insert_vertex(cent);
            from.insert_edge(top_prev, vcent);
            from.insert_edge(vcent, v4);
        }
    }
    from
}

impl Figure {
    /// The figure's map: its unit turned n times by 2π/n.
    pub fn map(&self) -> Map {
        let (n, unit) = match *self {
            Figure::Empty => return Map::default(),
            Figure::Rosette { n, q, s } => (n, rosette_unit(n, q, s)),
            Figure::Star { n, d, s } => (n, star_unit(n, d, s)),
        };
        let step = rotate(2.0 * PI / n as f64);
        let mut turns = Vec::with_capacity(n);
        let mut base = step;
        for _ in 0..n {
            turns.push(base);
            base = compose(&base, &step);
        }
        let mut m = Map::default();
        m.merge_simple_many(&unit, &turns);
        m
    }
}

/// The window Taprats' view of JWildfire shows: x and y from −1.5 to 1.5, as the inverse of
/// its 200 × 200 pixel transform gives the corners.
pub(super) fn view_window() -> [P; 4] {
    // A square view: its height is its width.
    let (left, top, width, pixels) = (-1.5, 1.5, 3.0, 200.0);
    let height = width;
    let first = translate([-left, -(top - height)]);
    let second = [pixels / width, 0.0, 0.0, 0.0, -(pixels / height), 0.0];
    let third = translate([0.0, pixels]);
    let t = compose(&third, &compose(&second, &first));
    let inv = invert(&t).unwrap_or([1.0, 0.0, 0.0, 0.0, 1.0, 0.0]);
    [
        apply(&inv, [0.0, 0.0]),
        apply(&inv, [pixels, 0.0]),
        apply(&inv, [pixels, pixels]),
        apply(&inv, [0.0, pixels]),
    ]
}

/// The design: for each tile shape of `tiling` (with its figure in `figures`, one per entry
/// of `tiling.features`), the figure placed in every copy of the shape in every translational
/// unit meeting the window, the shapes' maps merged with their crossings split.
pub(super) fn construct(tiling: &Tiling, figures: &[Map]) -> Map {
    let cells = fill_region(&view_window(), tiling.t1, tiling.t2, MAX_UNITS);
    let locations: Vec<Tr> = cells
        .iter()
        .map(|&(i, j)| {
            translate(add(
                scale(tiling.t1, f64::from(i)),
                scale(tiling.t2, f64::from(j)),
            ))
        })
        .collect();
    let mut design = Map::default();
    for (feature, figure) in tiling.features.iter().zip(figures) {
        if figure.edges.is_empty() && figure.pos.is_empty() {
            continue;
        }
        let mut in_unit = Map::default();
        in_unit.merge_simple_many(figure, feature.placements);
        let mut everywhere = Map::default();
        everywhere.merge_simple_many(&in_unit, &locations);
        design.merge(everywhere);
    }
    design
}

#[cfg(test)]
mod tests {
    use super::super::jwf_tp_map::{dist, mag};
    use super::*;

    /// A rosette of n points: n-fold symmetric (turning it by 2π/n maps its vertices onto
    /// themselves), 2·(s + 1)·n edges, its tips at the edge midpoints (radius 1).
    #[test]
    fn rosette_is_symmetric() {
        for (n, q, s) in [(7, 0.0, 2), (8, 0.3, 2), (10, 0.7, 2)] {
            let m = Figure::Rosette { n, q, s }.map();
            let s_eff = s.min((n as i32 - 1) / 2) as usize;
            assert_eq!(m.edges.len(), 2 * (s_eff + 1) * n, "n {n}");
            let turn = rotate(2.0 * PI / n as f64);
            for &p in &m.pos {
                let q = apply(&turn, p);
                assert!(m.pos.iter().any(|&r| dist(q, r) < 1e-9), "n {n}: {p:?}");
            }
            let tips = m
                .pos
                .iter()
                .filter(|&&p| (mag(p) - 1.0).abs() < 1e-12)
                .count();
            assert_eq!(tips, n);
        }
    }

    /// The star [8/3]2 (Seal of Solomon): 8 tips, each joined to two crossing points, 32
    /// edges in all (two segments on each side of each tip).
    #[test]
    fn star_eight_three() {
        let m = Figure::Star { n: 8, d: 3.0, s: 2 }.map();
        assert_eq!(m.edges.len(), 32);
        let tips = m
            .pos
            .iter()
            .filter(|&&p| (mag(p) - 1.0).abs() < 1e-12)
            .count();
        assert_eq!(tips, 8);
        // Every vertex is a tip (degree 2), a crossing (degree 4) or an inner corner (2).
        for v in 0..m.pos.len() {
            let deg = m.edges.iter().flatten().filter(|&&w| w == v).count();
            assert!(deg == 2 || deg == 4, "degree {deg}");
        }
    }

    /// The view window is the square ±1.5.
    #[test]
    fn window_is_the_square() {
        let w = view_window();
        let want = [[-1.5, 1.5], [1.5, 1.5], [1.5, -1.5], [-1.5, -1.5]];
        for (a, b) in w.iter().zip(want) {
            assert!(dist(*a, b) < 1e-12, "{a:?}");
        }
    }
}
