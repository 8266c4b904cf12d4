//! The textbook IFS tables (Kovács, Fractint's `fractint.ifs`, the Su Xiaohong slides T1–T11,
//! the Urbonavičius thesis) as rows `a b c d e f p`, one function per table, and all of them in
//! teaching order.

use super::Ifs;

const SQRT3_2: f64 = 0.866_025_403_784_438_6;

fn ifs(name: &str, rows: &[[f64; 7]]) -> Ifs {
    Ifs::from_rows(name, rows).expect("preset tables are valid")
}

/// Kovács: three maps of ratio ½ towards the corners (0, 0), (1, 0), (½, √3/2).
pub fn kovacs_sierpinski() -> Ifs {
    let t = 1.0 / 3.0;
    ifs(
        "Sierpinski triangle",
        &[
            [0.5, 0.0, 0.0, 0.5, 0.0, 0.0, t],
            [0.5, 0.0, 0.0, 0.5, 0.5, 0.0, t],
            [0.5, 0.0, 0.0, 0.5, 0.25, SQRT3_2 / 2.0, t],
        ],
    )
}

/// Kovács: eight maps of ratio ⅓ (the unit square without its middle ninth).
pub fn kovacs_carpet() -> Ifs {
    let t = 1.0 / 3.0;
    let rows: Vec<[f64; 7]> = (0..9)
        .filter(|&i| i != 4)
        .map(|i| {
            [
                t,
                0.0,
                0.0,
                t,
                (i % 3) as f64 * t,
                (i / 3) as f64 * t,
                0.125,
            ]
        })
        .collect();
    ifs("Sierpinski carpet", &rows)
}

/// Kovács: two maps of ratio ⅓ (the Cantor set on the unit segment of the x axis).
pub fn kovacs_cantor() -> Ifs {
    let t = 1.0 / 3.0;
    ifs(
        "Cantor set",
        &[
            [t, 0.0, 0.0, t, 0.0, 0.0, 0.5],
            [t, 0.0, 0.0, t, 2.0 * t, 0.0, 0.5],
        ],
    )
}

/// The Koch curve from (0, 0) to (1, 0): four maps of ratio ⅓, the middle two turned by
/// ±60°.
pub fn koch_curve() -> Ifs {
    let t = 1.0 / 3.0;
    let (c, s) = (0.5 * t, SQRT3_2 * t);
    ifs(
        "Koch curve",
        &[
            [t, 0.0, 0.0, t, 0.0, 0.0, 0.25],
            [c, -s, s, c, t, 0.0, 0.25],
            [c, s, -s, c, 0.5, SQRT3_2 * t, 0.25],
            [t, 0.0, 0.0, t, 2.0 * t, 0.0, 0.25],
        ],
    )
}

/// Fractint's `fern` (Barnsley's fern; `fractint.ifs`).
pub fn fractint_fern() -> Ifs {
    ifs(
        "fern",
        &[
            [0.0, 0.0, 0.0, 0.16, 0.0, 0.0, 0.01],
            [0.85, 0.04, -0.04, 0.85, 0.0, 1.6, 0.85],
            [0.2, -0.26, 0.23, 0.22, 0.0, 1.6, 0.07],
            [-0.15, 0.28, 0.26, 0.24, 0.0, 0.44, 0.07],
        ],
    )
}

/// Fractint's `triangle`: corners (0, 0), (0, 2), (2, 2).
pub fn fractint_triangle() -> Ifs {
    ifs(
        "triangle",
        &[
            [0.5, 0.0, 0.0, 0.5, 0.0, 0.0, 0.33],
            [0.5, 0.0, 0.0, 0.5, 0.0, 1.0, 0.33],
            [0.5, 0.0, 0.0, 0.5, 1.0, 1.0, 0.34],
        ],
    )
}

/// T1: Sierpinski in pixel coordinates (y down; Σp = 0.99 as printed).
pub fn t1_sierpinski_pixels() -> Ifs {
    ifs(
        "T1 Sierpinski (pixels)",
        &[
            [0.5, 0.0, 0.0, 0.5, 25.0, 1.0, 0.33],
            [0.5, 0.0, 0.0, 0.5, 1.0, 50.0, 0.33],
            [0.5, 0.0, 0.0, 0.5, 50.0, 50.0, 0.33],
        ],
    )
}

/// T3: a fern leaflet, four maps.
pub fn t3_fern_leaflet() -> Ifs {
    ifs(
        "T3 fern leaflet",
        &[
            [0.0, 0.0, 0.0, 0.25, 0.0, -0.14, 0.02],
            [0.85, 0.02, -0.02, 0.83, 0.0, 1.0, 0.84],
            [0.09, -0.28, 0.3, 0.11, 0.0, 0.6, 0.07],
            [-0.09, 0.25, 0.3, 0.09, 0.0, 0.7, 0.07],
        ],
    )
}

/// T4: a tree crown, four maps.
pub fn t4_tree_crown() -> Ifs {
    ifs(
        "T4 tree crown",
        &[
            [0.01, 0.0, 0.0, 0.45, 0.0, 0.0, 0.05],
            [-0.01, 0.0, 0.0, -0.45, 0.0, 0.4, 0.15],
            [0.42, -0.42, 0.42, 0.42, 0.0, 0.4, 0.4],
            [0.42, 0.42, -0.42, 0.42, 0.0, 0.4, 0.4],
        ],
    )
}

/// T5: a hexagonal maple leaf, four maps.
pub fn t5_maple_hexagonal() -> Ifs {
    ifs(
        "T5 hexagonal maple leaf",
        &[
            [0.01, 0.0, 0.0, 0.45, 0.0, 0.0, 0.05],
            [-0.01, 0.0, 0.0, -0.45, 0.0, 0.2, 0.15],
            [0.12, -0.82, 0.42, 0.42, 0.0, 0.2, 0.4],
            [0.12, 0.82, -0.42, 0.42, 0.0, 0.2, 0.4],
        ],
    )
}

/// T6: a maple-type leaf, four maps of ratio 0.6 and 0.5.
pub fn t6_maple() -> Ifs {
    ifs(
        "T6 maple-type leaf",
        &[
            [0.6, 0.0, 0.0, 0.6, 0.18, 0.36, 0.25],
            [0.6, 0.0, 0.0, 0.6, 0.18, 0.12, 0.25],
            [0.4, 0.3, -0.3, 0.4, 0.27, 0.36, 0.25],
            [0.4, -0.3, 0.3, 0.4, 0.27, 0.09, 0.25],
        ],
    )
}

/// T7: a fractal tree, six maps.
pub fn t7_tree() -> Ifs {
    ifs(
        "T7 fractal tree",
        &[
            [0.05, 0.0, 0.0, 0.6, 0.0, 0.0, 0.1],
            [0.05, 0.0, 0.0, -0.5, 0.0, 1.0, 0.1],
            [0.46, 0.32, -0.386, 0.383, 0.0, 0.6, 0.2],
            [0.47, -0.154, 0.171, 0.423, 0.0, 1.0, 0.2],
            [0.43, 0.275, -0.26, 0.476, 0.0, 1.0, 0.2],
            [0.421, -0.357, 0.354, 0.307, 0.0, 0.7, 0.2],
        ],
    )
}

/// T8: five maps.
pub fn t8_five_maps() -> Ifs {
    ifs(
        "T8 five maps",
        &[
            [0.25, 0.0, 0.0, 0.5, 0.0, 0.0, 0.154],
            [0.5, 0.0, 0.0, 0.5, -0.25, 0.5, 0.307],
            [-0.25, 0.0, 0.0, -0.25, 0.25, 1.0, 0.078],
            [0.5, 0.0, 0.0, 0.5, 0.0, 0.75, 0.307],
            [0.5, 0.0, 0.0, -0.25, 0.5, 1.25, 0.154],
        ],
    )
}

/// T9: Dürer's pentagon, five maps of ratio 0.382 (1/φ²).
pub fn t9_durer_pentagon() -> Ifs {
    let ef = [
        (0.3072, 0.619),
        (0.6033, 0.4044),
        (0.0139, 0.4044),
        (0.1253, 0.0595),
        (0.492, 0.0595),
    ];
    let rows: Vec<[f64; 7]> = ef
        .iter()
        .map(|&(e, f)| [0.382, 0.0, 0.0, 0.382, e, f, 0.2])
        .collect();
    ifs("T9 Dürer pentagon", &rows)
}

/// T10: z → (1 + i)z/2 and z → (1 − i)z/2 + (1 + i)/2.
pub fn t10_levy_c() -> Ifs {
    ifs(
        "T10 Lévy C curve",
        &[
            [0.5, -0.5, 0.5, 0.5, 0.0, 0.0, 0.5],
            [0.5, 0.5, -0.5, 0.5, 0.5, 0.5, 0.5],
        ],
    )
}

/// T11: Fractint's `dragon` with p = 0.8 / 0.2 (Fractint: 0.787473 / 0.212527).
pub fn t11_dragon() -> Ifs {
    ifs(
        "T11 Fractint dragon",
        &[
            [
                0.824074, 0.281482, -0.212346, 0.864198, -1.882290, -0.110607, 0.8,
            ],
            [
                0.088272, 0.520988, -0.463889, -0.377778, 0.785360, 8.095795, 0.2,
            ],
        ],
    )
}

/// The first test IFS of the Urbonavičius thesis (Σp = 0.99 as printed).
pub fn thesis_a() -> Ifs {
    ifs(
        "Urbonavičius (a)",
        &[
            [0.48, 0.01, -0.01, 0.47, 0.80, -0.34, 0.26],
            [0.47, 0.01, -0.01, 0.47, -1.01, -0.28, 0.25],
            [-0.28, 0.38, -0.96, -0.19, 0.03, -0.06, 0.48],
        ],
    )
}

/// The second test IFS of the Urbonavičius thesis.
pub fn thesis_b() -> Ifs {
    ifs(
        "Urbonavičius (b)",
        &[
            [-0.46, -0.50, 0.58, -0.58, 0.46, -0.24, 0.60],
            [0.52, -0.45, 0.45, 0.32, -0.85, 0.43, 0.40],
        ],
    )
}

/// Every preset, in teaching order.
pub fn all() -> Vec<Ifs> {
    vec![
        kovacs_sierpinski(),
        kovacs_carpet(),
        kovacs_cantor(),
        koch_curve(),
        fractint_fern(),
        fractint_triangle(),
        t1_sierpinski_pixels(),
        t3_fern_leaflet(),
        t4_tree_crown(),
        t5_maple_hexagonal(),
        t6_maple(),
        t7_tree(),
        t8_five_maps(),
        t9_durer_pentagon(),
        t10_levy_c(),
        t11_dragon(),
        thesis_a(),
        thesis_b(),
    ]
}
