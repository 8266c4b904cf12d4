//! The tables of a scene file as serde reads them (their names appear in serde's messages),
//! and the check for the non-finite numbers TOML allows and no scene setting does.

use serde::Deserialize;
use toml::Spanned;

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct ImageSpec {
    pub(super) size: Option<[u32; 2]>,
    pub(super) background: Option<[f64; 3]>,
    pub(super) supersample: Option<u32>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct CameraSpec {
    pub(super) target: Option<[f64; 3]>,
    pub(super) distance: Option<f64>,
    pub(super) azimuth: Option<f64>,
    pub(super) polar: Option<f64>,
    pub(super) projection: Option<String>,
    pub(super) scale: Option<f64>,
    /// Axonometric angles in degrees.
    pub(super) phi: Option<f64>,
    pub(super) theta: Option<f64>,
    /// Dimetric: the z foreshortening.
    pub(super) fz: Option<f64>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct LightingSpec {
    pub(super) ambient: Option<f64>,
    pub(super) attenuation: Option<f64>,
    pub(super) blinn: Option<bool>,
}

#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum Intensity {
    Grey(f64),
    Rgb([f64; 3]),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LightSpec {
    pub(super) position: [f64; 3],
    pub(super) intensity: Option<Intensity>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct TextureSpec {
    pub(super) name: String,
    pub(super) kind: String,
    pub(super) file: Option<String>,
    pub(super) size: Option<[u32; 2]>,
    pub(super) quality: Option<f64>,
    pub(super) colors: Option<Vec<[f64; 3]>>,
    pub(super) octaves: Option<u32>,
    pub(super) lacunarity: Option<f64>,
    pub(super) gain: Option<f64>,
    pub(super) frequency: Option<f64>,
    pub(super) seed: Option<u64>,
    pub(super) cells: Option<[u32; 2]>,
    pub(super) alpha: Option<f64>,
    pub(super) beta: Option<f64>,
    pub(super) delta: Option<f64>,
    pub(super) phi: Option<f64>,
    pub(super) omega: Option<f64>,
    pub(super) sweeps: Option<u32>,
    pub(super) gradient: Option<String>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct MaterialSpec {
    pub(super) ka: Option<f64>,
    pub(super) kd: Option<f64>,
    pub(super) ks: Option<f64>,
    pub(super) n: Option<f64>,
    pub(super) color: Option<[f64; 3]>,
    pub(super) two_sided: Option<bool>,
    pub(super) bump: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct Step {
    pub(super) translate: Option<[f64; 3]>,
    pub(super) scale: Option<ScaleSpec>,
    pub(super) rotate_x: Option<f64>,
    pub(super) rotate_y: Option<f64>,
    pub(super) rotate_z: Option<f64>,
    /// Rotation about an axis: [nx, ny, nz, degrees] (through the origin) or with `through`.
    pub(super) rotate_axis: Option<[f64; 4]>,
    pub(super) through: Option<[f64; 3]>,
    pub(super) shear: Option<[f64; 6]>,
    pub(super) reflect: Option<String>,
}

#[derive(Deserialize)]
#[serde(untagged)]
pub(super) enum ScaleSpec {
    Uniform(f64),
    Axes([f64; 3]),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ObjectSpec {
    pub(super) kind: String,
    pub(super) name: Option<String>,
    pub(super) texture: Option<String>,
    pub(super) bump_texture: Option<String>,
    pub(super) material: Option<MaterialSpec>,
    pub(super) transform: Option<Vec<Step>>,
    /// revolve: 3k + 1 profile points [r, y].
    pub(super) profile: Option<Vec<[f64; 2]>>,
    /// tube: 4 spine points.
    pub(super) spine: Option<Vec<[f64; 3]>>,
    pub(super) radius: Option<f64>,
    /// bezier: degrees [n, m] and the (n + 1)(m + 1) net, rows along u.
    pub(super) degree: Option<[usize; 2]>,
    pub(super) net: Option<Vec<[f64; 3]>>,
    /// bilinear: p00, p01, p10, p11.
    pub(super) corners: Option<Vec<[f64; 3]>>,
    /// mountain.
    pub(super) levels: Option<u32>,
    pub(super) size: Option<f64>,
    pub(super) sigma: Option<f64>,
    pub(super) h: Option<f64>,
    pub(super) seed: Option<u64>,
    /// quaternion_julia: c = [c₀, c₁, c₂, c₃] (or [re, im]), the fixed component and its
    /// value, iterations.
    pub(super) c: Option<Vec<f64>>,
    pub(super) slice: Option<String>,
    pub(super) slice_value: Option<f64>,
    pub(super) iterations: Option<u32>,
    /// menger: construction step.
    pub(super) step: Option<u32>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneSpec {
    /// "zbuffer" (default) or "raycast".
    pub(super) render: Option<Spanned<String>>,
    /// Shadow rays (ray casting only; default on).
    pub(super) shadows: Option<Spanned<bool>>,
    pub(super) image: Option<ImageSpec>,
    pub(super) camera: Option<CameraSpec>,
    pub(super) lighting: Option<LightingSpec>,
    pub(super) light: Option<Vec<LightSpec>>,
    pub(super) texture: Option<Vec<Spanned<TextureSpec>>>,
    pub(super) object: Option<Vec<Spanned<ObjectSpec>>>,
}

/// The first bare `nan`/`inf` value of a TOML text (TOML allows them; no scene setting
/// does): its byte offset and spelling. Strings and comments are skipped.
pub(super) fn non_finite_value(text: &str) -> Option<(usize, &str)> {
    const BAD: [&str; 6] = ["nan", "+nan", "-nan", "inf", "+inf", "-inf"];
    let b = text.as_bytes();
    let mut i = 0;
    // After '=', '[' or ',' a value may start.
    let mut value_pos = false;
    while i < b.len() {
        match b[i] {
            b'#' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            q @ (b'"' | b'\'') => {
                i += 1;
                while i < b.len() && b[i] != q {
                    if q == b'"' && b[i] == b'\\' {
                        i += 1;
                    }
                    i += 1;
                }
                i += 1;
                value_pos = false;
            }
            b'=' | b'[' | b',' => {
                value_pos = true;
                i += 1;
            }
            b'{' | b'}' | b']' => {
                value_pos = false;
                i += 1;
            }
            c if c.is_ascii_whitespace() => i += 1,
            _ => {
                let start = i;
                while i < b.len()
                    && !b[i].is_ascii_whitespace()
                    && !matches!(b[i], b',' | b']' | b'}' | b'=' | b'[' | b'{' | b'#')
                {
                    i += 1;
                }
                let tok = &text[start..i];
                if value_pos && BAD.contains(&tok) {
                    return Some((start, tok));
                }
                value_pos = false;
            }
        }
    }
    None
}
