//! The textures of a scene file: each `[[texture]]` table checked and turned into the engine's
//! description of what to make (files it names are read here, nothing is rendered), and the
//! memory each will take once made.

use std::path::{Path, PathBuf};

use glam::Vec3;

use super::MAX_TEXTURE_SIDE;
use super::format::TextureSpec as TextureTable;
use crate::noise::Fbm;
use crate::surface::texture::{MAX_MRF_SIDE, MrfParams};
use crate::surface::{TextureKind, TextureSpec};

pub(super) fn c3(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

/// Bytes a texture of w×h texels takes with its mipmaps (4/3 of the base level).
pub fn texture_bytes(w: usize, h: usize) -> u64 {
    (w as u64 * h as u64 * std::mem::size_of::<Vec3>() as u64) * 4 / 3
}

/// Bytes a texture will take once made (with the buffers used while making it).
pub(super) fn texture_need(t: &TextureTable) -> u64 {
    let [w, h] = t.size.unwrap_or([512, 512]);
    let (w, h) = (w as usize, h as usize);
    match t.kind.as_str() {
        "solid" => 16,
        "gradient" => texture_bytes(4, 256),
        "mrf" => {
            let (w, h) = (w.min(MAX_MRF_SIDE), h.min(MAX_MRF_SIDE));
            texture_bytes(w, h) + (w * h * 8) as u64
        }
        // Flame and escape renders check their own memory; an image is checked by size when
        // it is decoded. Their textures are the size of the picture.
        _ => texture_bytes(w, h) + (w * h * 4) as u64,
    }
}

/// What to make for a texture table; `base` resolves relative files, which are read here.
/// Values changed to fit are reported in `warn`.
pub(super) fn texture_spec(
    t: &TextureTable,
    base: &Path,
    warn: &mut Vec<String>,
) -> Result<TextureSpec, String> {
    let [w, h] = t.size.unwrap_or([512, 512]);
    if w == 0 || h == 0 || w > MAX_TEXTURE_SIDE || h > MAX_TEXTURE_SIDE {
        return Err(format!(
            "size {w}x{h} must be between 1x1 and {MAX_TEXTURE_SIDE}x{MAX_TEXTURE_SIDE}"
        ));
    }
    let (w, h) = (w as usize, h as usize);
    let colors = t
        .colors
        .clone()
        .unwrap_or_else(|| vec![[0.1, 0.1, 0.12], [0.95, 0.9, 0.8]]);
    let Some(&first) = colors.first() else {
        return Err("colors needs at least one colour [r, g, b]".into());
    };
    let colors = [c3(first), c3(*colors.get(1).unwrap_or(&first))];
    let octaves = t.octaves.unwrap_or(6);
    if !(1..=16).contains(&octaves) {
        warn.push(format!(
            "octaves {octaves} is outside 1..16; using {}",
            octaves.clamp(1, 16)
        ));
    }
    let cells = |what: &str, warn: &mut Vec<String>| {
        let [n, m] = t.cells.unwrap_or([8, 8]);
        if n == 0 || m == 0 {
            warn.push(format!(
                "{what} cells {n}x{m}: at least 1 each; using {}x{}",
                n.max(1),
                m.max(1)
            ));
        }
        [n.max(1) as usize, m.max(1) as usize]
    };
    let kind = match t.kind.as_str() {
        "image" | "flame" | "escape" => read_source(t, base)?,
        "fbm" => TextureKind::Fbm {
            fbm: Fbm {
                octaves: octaves.clamp(1, 16),
                lacunarity: t.lacunarity.unwrap_or(2.0),
                gain: t.gain.unwrap_or(0.5),
                frequency: t.frequency.unwrap_or(4.0),
                seed: t.seed.unwrap_or(1),
            },
            colors,
        },
        "value" => TextureKind::Value {
            seed: t.seed.unwrap_or(1),
            cells: cells("value", warn)[0] as u32,
            colors,
        },
        "mrf" => TextureKind::Mrf {
            params: mrf_params(t, w, h, warn),
            colors,
        },
        "checker" => TextureKind::Checker {
            cells: cells("checker", warn),
            colors,
        },
        "grid" => TextureKind::Grid {
            cells: cells("grid", warn),
            colors,
        },
        "solid" => TextureKind::Solid(colors[0]),
        "gradient" => {
            let name = t.gradient.as_deref().unwrap_or("ember");
            let g = crate::io::escape_view::resolve_gradient_parsed(name, Some(base))?;
            warn.extend(g.warnings.iter().map(|w| w.to_string()));
            TextureKind::Gradient(Box::new(g.value))
        }
        other => {
            return Err(format!(
                "unknown texture kind '{other}': expected image, flame, escape, fbm, value, mrf, checker, grid, solid or gradient"
            ));
        }
    };
    Ok(TextureSpec {
        width: w,
        height: h,
        kind,
    })
}

/// The picture, flame or escape-time view a texture is made from, read from its file.
fn read_source(t: &TextureTable, base: &Path) -> Result<TextureKind, String> {
    let f = t.file.as_ref().ok_or("needs file = \"…\"")?;
    let p: PathBuf = base.join(f);
    if !p.exists() {
        return Err(format!("file '{}' does not exist", p.display()));
    }
    Ok(match t.kind.as_str() {
        "image" => {
            let img = crate::io::image_in::read_rgb(&p).map_err(|e| e.to_string())?;
            TextureKind::Image(img)
        }
        "flame" => {
            let f = crate::io::read_flames(&p, &Default::default())
                .map_err(|e| e.to_string())?
                .value
                .into_iter()
                .next()
                .ok_or_else(|| format!("{}: no flame", p.display()))?;
            TextureKind::Flame {
                flame: Box::new(f),
                quality: t.quality,
            }
        }
        _ => {
            let d = crate::io::escape_view::read(&p)
                .map_err(|e| e.to_string())?
                .value;
            TextureKind::Escape(Box::new(d))
        }
    })
}

/// The Markov random field's parameters, the sweeps and size clamped with a warning.
fn mrf_params(t: &TextureTable, w: usize, h: usize, warn: &mut Vec<String>) -> MrfParams {
    let d = MrfParams::default();
    let sweeps = t.sweeps.unwrap_or(d.sweeps);
    if sweeps > 1000 {
        warn.push(format!("sweeps {sweeps} is more than 1000; using 1000"));
    }
    if w > MAX_MRF_SIDE || h > MAX_MRF_SIDE {
        warn.push(format!(
            "a Markov random field texture is at most 1024x1024; using {}x{}",
            w.min(MAX_MRF_SIDE),
            h.min(MAX_MRF_SIDE)
        ));
    }
    MrfParams {
        alpha: t.alpha.unwrap_or(d.alpha),
        beta: t.beta.unwrap_or(d.beta),
        delta: t.delta.unwrap_or(d.delta),
        phi: t.phi.unwrap_or(d.phi),
        omega: t.omega.unwrap_or(d.omega),
        sweeps: sweeps.min(1000),
        seed: t.seed.unwrap_or(1),
    }
}
