//! Checks of `sunvoroni`'s geometry against properties that hold for any correct convex hull,
//! Voronoi diagram and triangulation.

use super::super::jwf_sv_quickhull::hull_faces;
use super::*;

/// Points from a small linear congruential generator, in [-1, 1).
fn scatter(n: usize, seed: u64) -> Vec<[f64; 3]> {
    let mut s = seed;
    let mut next = || {
        s = s
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..n).map(|_| [next(), next(), next()]).collect()
}

fn sub3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A closed convex polyhedron: every point on or below every face, the faces listed
/// clockwise from outside, every edge between exactly two faces, V − E + F = 2.
fn check_hull(points: &[[f64; 3]], faces: &[Vec<usize>]) {
    let k = points.len() as f64;
    let inner = points.iter().fold([0.0; 3], |a, p| {
        [a[0] + p[0] / k, a[1] + p[1] / k, a[2] + p[2] / k]
    });
    let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
    let mut vertices = std::collections::BTreeSet::new();
    for f in faces {
        assert!(f.len() >= 3, "face {f:?}");
        let p0 = points[f[0]];
        // Clockwise from outside: the fan's normal points inwards.
        let mut n = [0.0; 3];
        for w in 1..f.len() - 1 {
            let c = cross3(sub3(points[f[w]], p0), sub3(points[f[w + 1]], p0));
            n = [n[0] + c[0], n[1] + c[1], n[2] + c[2]];
        }
        let len = dot3(n, n).sqrt();
        assert!(dot3(n, sub3(inner, p0)) > 0.0, "face {f:?} turned outwards");
        for (i, p) in points.iter().enumerate() {
            let above = -dot3(n, sub3(*p, p0)) / len;
            assert!(above < 1e-9, "point {i} {above} above face {f:?}");
        }
        for i in 0..f.len() {
            let (a, b) = (f[i], f[(i + 1) % f.len()]);
            *edges.entry((a.min(b), a.max(b))).or_default() += 1;
            vertices.insert(a);
        }
    }
    assert!(
        edges.values().all(|&c| c == 2),
        "an edge not between two faces"
    );
    let euler = vertices.len() as i64 - edges.len() as i64 + faces.len() as i64;
    assert_eq!(euler, 2);
}

#[test]
fn hull_of_scattered_points_is_closed_and_convex() {
    for (n, seed) in [(4, 1), (10, 2), (200, 3), (1000, 4)] {
        let points = scatter(n, seed);
        let faces = hull_faces(&points).expect("a hull");
        check_hull(&points, &faces);
    }
    // Points on a sphere are all corners.
    let sphere: Vec<[f64; 3]> = scatter(300, 5)
        .into_iter()
        .map(|p| {
            let r = dot3(p, p).sqrt();
            [p[0] / r, p[1] / r, p[2] / r]
        })
        .collect();
    let faces = hull_faces(&sphere).expect("a hull");
    check_hull(&sphere, &faces);
    let used: std::collections::BTreeSet<usize> = faces.iter().flatten().copied().collect();
    assert_eq!(used.len(), 300);
}

#[test]
fn hull_refuses_flat_or_broken_input() {
    let flat: Vec<[f64; 3]> = scatter(20, 6)
        .into_iter()
        .map(|p| [p[0], p[1], 0.5])
        .collect();
    assert!(hull_faces(&flat).is_none());
    assert!(hull_faces(&scatter(3, 7)).is_none());
    let mut nan = scatter(20, 8);
    nan[5][1] = f64::NAN;
    assert!(hull_faces(&nan).is_none());
}

/// Every seed's cell: a convex polygon round its seed, each corner the centre of a circle
/// through the seed and at least two other sites with no site inside it; the cells' ear
/// clipping covers each cell once.
#[test]
fn sunflower_cells_are_voronoi_cells() {
    for (n, angle) in [
        (10, 180.0),
        (50, 180.0),
        (51, 144.3),
        (300, 270.7),
        (1000, 100.0),
    ] {
        let seeds = sunflower_seeds(n, angle);
        let d = voronoi(&seeds).expect("a diagram");
        assert_eq!(d.regions.len(), n);
        let mut sites: Vec<P2> = seeds
            .iter()
            .map(|&[x, y]| [f64::from(x), f64::from(y)])
            .collect();
        sites.extend(FAR.iter().map(|f| [f[0], f[1]]));
        let dist = |a: P2, b: P2| (a[0] - b[0]).hypot(a[1] - b[1]);
        for (k, cell) in d.regions.iter().enumerate() {
            assert!(cell.len() >= 3, "seed {k} of {n}: {cell:?}");
            let c: Vec<P2> = cell.iter().map(|&[x, y]| [x.into(), y.into()]).collect();
            for &corner in &c {
                let r = dist(corner, sites[k]);
                // Single precision corners: a relative error of a few 1e-7.
                let tol = 1e-5 * r.max(1.0);
                let nearest = sites
                    .iter()
                    .map(|&s| dist(corner, s))
                    .fold(f64::MAX, f64::min);
                assert!(
                    nearest > r - tol,
                    "seed {k}: a site inside circle {corner:?}"
                );
                let on = sites.iter().filter(|&&s| (dist(corner, s) - r).abs() < tol);
                assert!(on.count() >= 3, "seed {k}: {corner:?} no circumcentre");
            }
            // Convex, one way round, about the seed.
            let area = signed_area(&c);
            let m = c.len();
            for i in 0..m {
                let (a, b) = (c[i], c[(i + 1) % m]);
                let turn =
                    (b[0] - a[0]) * (sites[k][1] - a[1]) - (b[1] - a[1]) * (sites[k][0] - a[0]);
                assert!(turn * area > 0.0, "seed {k} of {n} outside its cell");
            }
            let tris = ear_clip(&c);
            assert_eq!(tris.len(), m - 2);
            let covered: f64 = tris
                .iter()
                .map(|t| signed_area(&[c[t[0]], c[t[1]], c[t[2]]]).abs())
                .sum();
            assert!(
                (covered - area.abs()).abs() <= 1e-9 * area.abs(),
                "seed {k}"
            );
        }
        // Each edge joins the corners of two neighbouring faces: its ends are equidistant
        // from two sites (those on both circles).
        assert!(!d.edges.is_empty());
    }
}

#[test]
fn ear_clip_keeps_concave_polygons_inside() {
    // An L shape, listed clockwise: four triangles covering its area exactly.
    let l: Vec<P2> = vec![
        [0.0, 0.0],
        [0.0, 2.0],
        [1.0, 2.0],
        [1.0, 1.0],
        [2.0, 1.0],
        [2.0, 0.0],
    ];
    assert_eq!(signed_area(&l), -3.0);
    let tris = ear_clip(&l);
    assert_eq!(tris.len(), 4);
    let total: f64 = tris
        .iter()
        .map(|t| signed_area(&[l[t[0]], l[t[1]], l[t[2]]]))
        .sum();
    // Counter-clockwise triangles (the polygon's order reversed).
    assert_eq!(total, 3.0);
    assert!(ear_clip(&l[..2]).is_empty());
}

/// The lifted seeds with megamu's far points.
fn lifted(seeds: &[[f32; 2]]) -> Vec<[f64; 3]> {
    let mut q: Vec<[f64; 3]> = seeds
        .iter()
        .map(|&[x, y]| [f64::from(x), f64::from(y), f64::from(-(x * x + y * y))])
        .collect();
    q.extend_from_slice(&FAR);
    q
}

/// The hull in QuickHull3D 1.4's order (the release JWildfire 9.00 ships, run on the same
/// points): the default sunflower's 102 faces begin with these, the artifact first; 1000
/// seeds at 100° give 2002 faces ending with these.
#[test]
fn hull_follows_quickhull3d_order() {
    let faces = hull_faces(&lifted(&sunflower_seeds(50, 180.0))).expect("a hull");
    assert_eq!(faces.len(), 102);
    let first: [[usize; 3]; 8] = [
        [52, 51, 50],
        [48, 52, 50],
        [47, 50, 51],
        [46, 51, 52],
        [44, 51, 49],
        [39, 51, 44],
        [39, 47, 51],
        [26, 47, 39],
    ];
    for (f, want) in faces.iter().zip(first) {
        assert_eq!(f[..], want[..]);
    }
    let faces = hull_faces(&lifted(&sunflower_seeds(1000, 100.0))).expect("a hull");
    assert_eq!(faces.len(), 2002);
    assert_eq!(faces[2000], [245, 278, 292]);
    assert_eq!(faces[2001], [245, 231, 278]);
}

/// The default figures begin with the first cell's three triangles, coloured by its area
/// (JWildfire 9.00 makes the same list).
#[test]
fn default_figures_begin_with_the_first_cell() {
    let t = sunvoroni_figures(&[50.0, 3.0, 180.0, 0.0, 0.0, 1.0, 0.5], &[]);
    assert_eq!(t.len() % FIG, 0);
    assert_eq!(t.len() / FIG, 184);
    let (a, b, c) = (
        [-0.25242260098457336, 0.09860515594482422],
        [-0.10613216459751129, -0.07743389159440994],
        [0.07861099392175674, -0.0011175702093169093],
    );
    let (d, e) = (
        [-0.0027305642142891884, 0.20730364322662354],
        [-0.2243036925792694, 0.22060717642307281],
    );
    let want = [[a, b, c], [c, d, e], [e, a, c]];
    for (k, tri) in want.iter().enumerate() {
        let f = &t[k * FIG..(k + 1) * FIG];
        assert_eq!(f[0], 3.0);
        assert_eq!(
            f[1..7],
            [
                tri[0][0], tri[0][1], tri[1][0], tri[1][1], tri[2][0], tri[2][1]
            ]
        );
        assert!((f[7] - 0.06598781470556037).abs() < 1e-12, "{}", f[7]);
    }
}
