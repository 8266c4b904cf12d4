//! The hide flag of the crops (and of `bsplit` and `dinis_surface_wf`) against the `hide_out`
//! column JWildfire's own classes printed for the 24 points of the variation vectors.

use crate::flame::rng::FastRng;
use crate::flame::variations::jwf_testing::make;
use crate::flame::variations::{Acc, eval_prepared};

/// The affine images t of the 24 vector points (x, y; z is not read by these).
const T: [[f64; 2]; 24] = [
    [-0.1125, 0.3975],
    [0.625, 0.125],
    [0.125, 1.625],
    [-0.875, 0.625],
    [-0.375, -0.875],
    [0.5821067811865476, 1.0821067811865475],
    [-0.28349364905389035, 1.5825317547305482],
    [-0.899519052838329, -0.03349364905389035],
    [0.03349364905389035, -0.8325317547305482],
    [0.675, -0.825],
    [-1.6, 1.4],
    [-0.6499999999999999, 0.15],
    [-0.12499999999999994, -1.225],
    [-0.124999975, 0.374999725],
    [2.875, -4.625],
    [-0.125, 0.375],
    [0.0, 0.0],
    [7.499999998827889e-08, -2.500000001459668e-08],
    [0.0, 1.0],
    [-1.0, 0.0],
    [0.3, 1.3],
    [-3.45, -1.45],
    [0.375, 0.875],
    [1.9500000000000002, 1.95],
];

/// Parameters by full name.
type Params = &'static [(&'static str, f64)];

/// (variation, parameters, JWildfire's hide flags for the 24 points).
const CASES: &[(&str, Params, &str)] = &[
    ("crop_box", &[], "011111111111101000111111"),
    (
        "crop_box",
        &[
            ("crop_box_width", 0.7),
            ("crop_box_height", 0.7),
            ("crop_box_invert", 1.0),
        ],
        "110000000001010111000000",
    ),
    (
        "crop_box",
        &[
            ("crop_box_width", 1.45),
            ("crop_box_height", 1.45),
            ("crop_box_invert", 1.0),
        ],
        "110111011101110111111010",
    ),
    ("crop_polygon", &[], "011111111111101000111111"),
    (
        "crop_polygon",
        &[("crop_polygon_radius", 0.58), ("crop_polygon_invert", 1.0)],
        "110000001001010111100000",
    ),
    (
        "crop_polygon",
        &[("crop_polygon_radius", 1.225), ("crop_polygon_invert", 1.0)],
        "111111111101110111111010",
    ),
    ("crop_trapezoid", &[], "011111111111101000111111"),
    (
        "crop_trapezoid",
        &[
            ("crop_trapezoid_Base Sup.", 0.7),
            ("crop_trapezoid_Base Inf.", 0.46),
            ("crop_trapezoid_height", 0.7),
            ("crop_trapezoid_invert", 1.0),
        ],
        "100000000000010111000000",
    ),
    (
        "crop_trapezoid",
        &[
            ("crop_trapezoid_Base Sup.", 1.45),
            ("crop_trapezoid_Base Inf.", 1.0),
            ("crop_trapezoid_height", 1.45),
            ("crop_trapezoid_invert", 1.0),
        ],
        "110111011101110111111010",
    ),
    // Only the points near the centre (16, 17) lie inside the default X.
    ("crop_x", &[], "111111111111111100111111"),
    ("bsplit", &[], "000000000000000010100000"),
    ("dinis_surface_wf", &[], "000000000000000010010000"),
];

#[test]
fn hidden_points_are_jwildfires() {
    let mut rng = FastRng::new(1);
    for (name, params, want) in CASES {
        let v = make(name, params, 0.7);
        let got: String = T
            .iter()
            .map(|t| {
                let a = eval_prepared(&v, [t[0], t[1], 0.0], Acc::default(), false, &mut rng);
                if a.hide { '1' } else { '0' }
            })
            .collect();
        assert_eq!(&got, want, "{name} {params:?}");
    }
}
