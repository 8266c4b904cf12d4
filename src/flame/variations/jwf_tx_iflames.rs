//! `iflames_wf`, JWildfire's "IFlames": an image whose structure places small embedded
//! flames, mixed with points sampled from the image itself (JWildfire 9.00,
//! `iflames/IFlamesFunc` and its package, LGPL-2.1; written anew).
//!
//! Each call, JWildfire takes the flames' branch when `image_brightness` is below 1e-8 or a
//! uniform draw falls below `iflame_density`, and the image's branch otherwise:
//! * flames' branch: a point of one of the shapes JWildfire built from the image (an edge
//!   detection of the image, thresholded and thinned at random, each kept pixel carrying one
//!   of six embedded flame files chosen by its hue, animated as a particle). ugnis builds no
//!   shapes: this branch adds nothing, as it does in JWildfire when no shape was built, which
//!   is the case for the default image (a smooth gradient has no edge above the default
//!   threshold; JWildfire 9.00 reports "0 flames" for the default parameters). With an image
//!   of the user's, or a lower `structure_threshold`, JWildfire draws flames ugnis does not.
//! * image's branch: a uniformly random position (x, y) in the image, each a pixel index
//!   plus a uniform offset in (−½, ½], placed at (x·scale_x/(W−1) + offset_x,
//!   y·scale_y/(H−1) + offset_y, offset_z) for the image's width W and height H and added to
//!   the point (the weight does not scale it), with the colour of the image there, blended
//!   bilinearly from the four pixels around (the truncated position and its right and lower
//!   neighbours; outside the image a pixel is black) and scaled by `image_brightness`.
//!   Where the pixel at the truncated position is black the sample is hidden.
//!
//! The image is the one named by `image_filename` (read by the flame readers, see
//! [`super::resources`]); without one, JWildfire's default: 128 × 128 pixels of its corner
//! gradient (`GradientCreator`).

use super::*;

/// Java's `int` range, for the integer parameters.
const IMIN: f64 = -2_147_483_648.0;
const IMAX: f64 = 2_147_483_647.0;

/// JWildfire's `EPSILON`.
const EPS: f64 = 1e-8;

/// Most bytes of an image file's name.
const MAX_NAME: usize = 4096;

macro_rules! iflames_params {
    ($(($k:literal, $flame_min_val:expr, $flame_max_val:expr, $preview_r:expr, $preview_g:expr, $preview_b:expr)),* $(,)?) => {
        &[
            p("iflames_wf_structure_threshold", 0.12),
            p("iflames_wf_structure_density", 0.03),
            p("iflames_wf_iflame_density", 0.666),
            p("iflames_wf_iflame_brightness", 1.24),
            p("iflames_wf_image_brightness", 0.42),
            p_int("iflames_wf_shape_distribution", 1.0, IMIN, IMAX),
            p_int("iflames_wf_erode", 0.0, IMIN, IMAX),
            p_int("iflames_wf_erode_size", 5.0, IMIN, IMAX),
            p_int("iflames_wf_conv_north", 1.0, IMIN, IMAX),
            p_int("iflames_wf_conv_east", 1.0, IMIN, IMAX),
            p_int("iflames_wf_conv_south", 0.0, IMIN, IMAX),
            p_int("iflames_wf_conv_west", 0.0, IMIN, IMAX),
            p("iflames_wf_scale_x", 19.2),
            p("iflames_wf_scale_y", 10.8),
            p("iflames_wf_scale_z", 0.3),
            p("iflames_wf_offset_x", -9.6),
            p("iflames_wf_offset_y", -5.7),
            p("iflames_wf_offset_z", 0.0),
            p_int("iflames_wf_max_img_width", 800.0, 16.0, 64000.0),
            p_int("iflames_wf_id", 1.0, IMIN, IMAX),
            p_int("iflames_wf_render_id", 0.0, IMIN, IMAX),
            p_int("iflames_wf_seed", 666.0, IMIN, IMAX),
            p("iflames_wf_color_chg_red", 0.0),
            p("iflames_wf_color_chg_green", 0.0),
            p("iflames_wf_color_chg_blue", 0.0),
            p("iflames_wf_color_chg_hue", 0.0),
            p("iflames_wf_color_chg_saturation", 0.0),
            p("iflames_wf_color_chg_lightness", 0.0),
            p("iflames_wf_time", 0.0),
            p_int("iflames_wf_preview", 0.0, IMIN, IMAX),
            p("iflames_wf_life", 600.0),
            p("iflames_wf_life_var", 0.0),
            p("iflames_wf_force_x0", 0.0),
            p("iflames_wf_force_y0", 0.1),
            p("iflames_wf_force_z0", 0.0),
            p("iflames_wf_force_centre_x", 0.0),
            p("iflames_wf_force_centre_y", 0.0),
            p("iflames_wf_force_centre_z", 0.0),
            p("iflames_wf_force_wavelen_x", 0.5),
            p("iflames_wf_force_wavelen_y", 0.5),
            p("iflames_wf_force_wavelen_z", 0.5),
            $(
                p(concat!("iflames_wf_flame_size", $k), 2.0),
                p(concat!("iflames_wf_flame_size_var", $k), 200.0),
                p(concat!("iflames_wf_flame_rotate_alpha", $k), 25.0),
                p(concat!("iflames_wf_flame_rotate_alpha_var", $k), 100.0),
                p(concat!("iflames_wf_flame_rotate_alpha_speed", $k), 16.0),
                p(concat!("iflames_wf_flame_rotate_alpha_speed_var", $k), 50.0),
                p(concat!("iflames_wf_flame_rotate_beta", $k), 0.0),
                p(concat!("iflames_wf_flame_rotate_beta_var", $k), 0.0),
                p(concat!("iflames_wf_flame_rotate_beta_speed", $k), 0.0),
                p(concat!("iflames_wf_flame_rotate_beta_speed_var", $k), 0.0),
                p(concat!("iflames_wf_flame_rotate_gamma", $k), 0.0),
                p(concat!("iflames_wf_flame_rotate_gamma_var", $k), 0.0),
                p(concat!("iflames_wf_flame_rotate_gamma_speed", $k), 0.0),
                p(concat!("iflames_wf_flame_rotate_gamma_speed_var", $k), 0.0),
                p(concat!("iflames_wf_flame_speed_x", $k), 0.0),
                p(concat!("iflames_wf_flame_speed_x_var", $k), 0.0),
                p(concat!("iflames_wf_flame_speed_y", $k), 0.0),
                p(concat!("iflames_wf_flame_speed_y_var", $k), 0.0),
                p(concat!("iflames_wf_flame_speed_z", $k), 0.0),
                p(concat!("iflames_wf_flame_speed_z_var", $k), 0.0),
                p(concat!("iflames_wf_flame_radial_accel", $k), 0.0),
                p(concat!("iflames_wf_flame_radial_accel_var", $k), 0.0),
                p(concat!("iflames_wf_flame_tangential_accel", $k), 0.0),
                p(concat!("iflames_wf_flame_tangential_accel_var", $k), 0.0),
                p(concat!("iflames_wf_flame_centre_x", $k), 0.0),
                p(concat!("iflames_wf_flame_centre_y", $k), 0.0),
                p(concat!("iflames_wf_flame_min_val", $k), $flame_min_val),
                p(concat!("iflames_wf_flame_max_val", $k), $flame_max_val),
                p(concat!("iflames_wf_flame_weight", $k), 1.0),
                p(concat!("iflames_wf_flame_param1_min", $k), 0.0),
                p(concat!("iflames_wf_flame_param1_max", $k), 1.0),
                p(concat!("iflames_wf_flame_param2_min", $k), 0.0),
                p(concat!("iflames_wf_flame_param2_max", $k), 1.0),
                p(concat!("iflames_wf_flame_param3_min", $k), 0.0),
                p(concat!("iflames_wf_flame_param3_max", $k), 1.0),
                p_int(concat!("iflames_wf_preview_r", $k), $preview_r, IMIN, IMAX),
                p_int(concat!("iflames_wf_preview_g", $k), $preview_g, IMIN, IMAX),
                p_int(concat!("iflames_wf_preview_b", $k), $preview_b, IMIN, IMAX),
                p_int(concat!("iflames_wf_grid_x_offset", $k), 0.0, IMIN, IMAX),
                p_int(concat!("iflames_wf_grid_y_offset", $k), 0.0, IMIN, IMAX),
                p_int(concat!("iflames_wf_grid_x_size", $k), 20.0, IMIN, IMAX),
                p_int(concat!("iflames_wf_grid_y_size", $k), 16.0, IMIN, IMAX),
                p(concat!("iflames_wf_brightness_min", $k), 1.0),
                p(concat!("iflames_wf_brightness_max", $k), 1.0),
                p(concat!("iflames_wf_brightness_change", $k), 0.0),
                p_int(concat!("iflames_wf_instancing", $k), 0.0, IMIN, IMAX),
            )*
        ]
    };
}

/// The parameters: the image's, the motion's, then those of the six embedded flames
/// (`001` to `006`), in JWildfire's order and with its defaults.
const PARAMS: &[Param] = iflames_params![
    ("001", 0.0, 0.15, 255.0, 128.0, 31.0),
    ("002", 0.15, 0.3, 255.0, 0.0, 0.0),
    ("003", 0.3, 0.44999999999999996, 0.0, 255.0, 0.0),
    ("004", 0.44999999999999996, 0.6, 0.0, 255.0, 255.0),
    ("005", 0.6, 0.75, 255.0, 180.0, 32.0),
    ("006", 0.75, 0.9, 255.0, 128.0, 31.0),
];

pub(super) static DEFS: &[VarDef] = &[VarDef::new("iflames_wf", iflames_wf)
    .params(PARAMS)
    .texts(&[TextParam {
        name: "iflames_wf_image_filename",
        default: "",
        max_len: MAX_NAME,
    }])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR | flag::HIDES)
    .sum()
    .shared(&[], image)];

/// The shared image: the one handed over under `image_filename`, else the default gradient.
fn image(_p: &[f64], texts: &[String]) -> Vec<f64> {
    jwf_h9b_images::gradient_map_of_size(texts, 128, 128)
}

/// iflames_wf: a sample of the image, or nothing (the flames' branch, see the module
/// documentation).
fn iflames_wf(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [
        _,
        _,
        iflame_density,
        _,
        image_brightness,
        _,
        _,
        _,
        _,
        _,
        _,
        _,
        scale_x,
        scale_y,
        _,
        offset_x,
        offset_y,
        offset_z,
    ] = v.params();
    // `||` as in JWildfire: the draw is made only when the brightness is not below 1e-8.
    if image_brightness < EPS || rng.f01() < iflame_density {
        return [0.0; 3];
    }
    let img = jwf_h9b_images::View::of(v.data());
    let (w, h) = (img.w, img.h);
    if w < 1 || h < 1 {
        return [0.0; 3];
    }
    let x = rng.below(w as u64) as f64 + (0.5 - rng.f01());
    let y = rng.below(h as u64) as f64 + (0.5 - rng.f01());
    let out = [
        x * scale_x / f64::from(w - 1) + offset_x,
        y * scale_y / f64::from(h - 1) + offset_y,
        offset_z,
    ];
    // Java's (int) truncates toward zero; positions just below 0 read column or row 0.
    let (ix, iy) = (x as i32, y as i32);
    let pixel = |px: i32, py: i32| {
        if (0..w).contains(&px) && (0..h).contains(&py) {
            let [r, g, b, _] = img.at(px, py);
            [r, g, b].map(f64::from)
        } else {
            [0.0; 3]
        }
    };
    let lu = pixel(ix, iy);
    acc.hide = lu == [0.0; 3];
    if acc.hide {
        return out;
    }
    let (ru, lb, rb) = (pixel(ix + 1, iy), pixel(ix, iy + 1), pixel(ix + 1, iy + 1));
    // MathLib.frac: the part after the truncated integer (negative below 0).
    let (fx, fy) = (x - x.trunc(), y - y.trunc());
    let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
    let rgb: [f64; 3] = std::array::from_fn(|k| {
        lerp(lerp(lu[k], ru[k], fx), lerp(lb[k], rb[k], fx), fy) * image_brightness
    });
    acc.rgb = Some(rgb);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn prepared(params: &[(usize, f64)]) -> Prepared {
        let mut p = DEFS[0].defaults();
        for &(i, x) in params {
            p[i] = x;
        }
        Prepared::with_texts(
            by_name("iflames_wf").unwrap(),
            Form::Regular,
            0.7,
            &p,
            &[String::new()],
            Affine::default(),
            true,
        )
    }

    /// JWildfire's default image: pixels of the 128 × 128 corner gradient as JWildfire 9.00
    /// draws it (read back from its `ImageParams` colour map).
    #[test]
    fn default_image_is_jwildfires_gradient() {
        let v = prepared(&[]);
        let img = jwf_h9b_images::View::of(v.data());
        assert_eq!((img.w, img.h), (128, 128));
        for (x, y, rgb) in [
            (0, 0, [0xff, 0x00, 0x00]),
            (37, 0, [0xff, 0x4a, 0x00]),
            (111, 0, [0xff, 0xde, 0x00]),
            (37, 37, [0xb4, 0x68, 0x4a]),
            (111, 74, [0x6a, 0x6f, 0x94]),
            (74, 111, [0x20, 0x6f, 0xde]),
        ] {
            let [r, g, b, _] = img.at(x, y);
            assert_eq!([r, g, b], rgb, "({x}, {y})");
        }
    }

    /// With density 0 every sample comes from the image: inside its rectangle, coloured by
    /// it (0.42 of its bytes), never hidden (the gradient has no black pixel); with
    /// density above 1 nothing is added.
    #[test]
    fn samples_of_the_image_and_of_no_flame() {
        let v = prepared(&[(2, 0.0), (17, 0.25)]);
        let mut rng = FastRng::new(5);
        let t = VarIn::default();
        for _ in 0..2000 {
            let mut acc = Acc::default();
            let o = v.eval(&t, &mut acc, &mut rng);
            assert!((-9.6 - 0.08..=9.6 + 0.08).contains(&o[0]), "{o:?}");
            assert!((-5.7 - 0.05..=5.1 + 0.05).contains(&o[1]), "{o:?}");
            assert_eq!(o[2], 0.25);
            let rgb = acc.rgb.expect("a colour");
            // Blended within the image; extrapolated as in JWildfire left of or above its
            // first pixel centres (a negative fraction).
            if o[0] >= -9.6 && o[1] >= -5.7 {
                assert!(rgb.iter().all(|c| (0.0..=255.0 * 0.42 + 1e-9).contains(c)));
            }
            assert!(!acc.hide);
        }
        let v = prepared(&[(2, 1.5)]);
        let mut acc = Acc::default();
        assert_eq!(v.eval(&t, &mut acc, &mut rng), [0.0; 3]);
        assert_eq!(acc.rgb, None);
    }
}
