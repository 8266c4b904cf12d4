//! JWildfire's `lsystem3D_js` (JWildfire 9.00, `LSystem3DWFFunc` on `AbstractOBJMeshWFFunc`;
//! the behaviour written anew): a 3-D L-system in Laurens Lapre's LParser form, rewritten and
//! drawn once by a turtle into a mesh of blocks, cylinders and polygons
//! ([`super::jwf_ls_grammar`], [`super::jwf_ls_turtle`]); each call picks one of its
//! triangles uniformly (not by area: JWildfire prepares this mesh no further) and returns a
//! uniform random point of it, the corners scaled and moved first, times the weight.
//!
//! The grammar is the text `lsystem3D_js_grammar` (JWildfire writes it into the flame); an
//! empty text takes built-in preset `presetId` ([`super::jwf_ls_presets`]). A text JWildfire
//! cannot read leaves the preset's mesh, drawn without colours (in JWildfire's copy of the
//! variation the preset is drawn before `color_mode` is set and the text fails after).
//! `color_mode` 1 gives the point the palette position colour/100 of its triangle, 2 the
//! colour table's RGB. Productions are limited to JWildfire's 4 MiB − 50 characters and
//! meshes to [`MAX_FACES`] triangles; a grammar that passes them is drawn up to the limit and
//! the reader warns ([`grammar_problem`]).
//!
//! The subdivision, smoothing, colour-map and displacement parameters are kept for the file's
//! sake: JWildfire's `lsystem3D_js` does not apply them.

use super::jwf_h9b_meshes::{place, point_in_triangle};
use super::jwf_ls_grammar::{expand, read_grammar};
use super::jwf_ls_presets::preset;
use super::jwf_ls_turtle::{FaceColor, LsMesh, MAX_FACES, draw};
use super::*;

/// Values per triangle in the shared data: nine corner coordinates, then three colour values.
const PER_FACE: usize = 12;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("lsystem3D_js", lsystem3d_js)
    .params(&[
        p_int("lsystem3D_js_presetId", 19.0, -2147483648.0, 2147483647.0),
        p("lsystem3D_js_scale_x", 1.0),
        p("lsystem3D_js_scale_y", 1.0),
        p("lsystem3D_js_scale_z", 1.0),
        p("lsystem3D_js_offset_x", 0.0),
        p("lsystem3D_js_offset_y", 0.0),
        p("lsystem3D_js_offset_z", 0.0),
        // JWildfire's own bounds (its `limitIntVal`).
        p_int("lsystem3D_js_color_mode", 0.0, 0.0, 2.0).limited(),
        p_int("lsystem3D_js_subdiv_level", 0.0, 0.0, 6.0).limited(),
        p_int("lsystem3D_js_subdiv_smooth_passes", 12.0, 0.0, 24.0).limited(),
        p("lsystem3D_js_subdiv_smooth_lambda", 0.42),
        p("lsystem3D_js_subdiv_smooth_mu", -0.45),
        p_int("lsystem3D_js_blend_colormap", 1.0, 0.0, 1.0),
        p("lsystem3D_js_displ_amount", 0.1),
        p_int("lsystem3D_js_blend_displ_map", 1.0, 0.0, 1.0),
        p_int("lsystem3D_js_receive_only_shadows", 0.0, 0.0, 1.0),
    ])
    .texts(&[
        TextParam {
            name: "lsystem3D_js_grammar",
            default: "",
            max_len: 1 << 16,
        },
        TextParam {
            name: "lsystem3D_js_presetId_reference",
            default: "org.jwildfire.create.tina.variation.reference.ReferenceFile lsystem3D-presets.pdf",
            max_len: 1024,
        },
    ])
    .flags(flag::JWILDFIRE | flag::RANDOM | flag::WRITES_Z | flag::SETS_COLOR)
    .shared(&[0, 7], mesh_data)];

/// The mesh of a grammar text in colour mode `mode`; `None` where JWildfire's fails.
pub(super) fn build(text: &str, mode: u8) -> Option<LsMesh> {
    let g = read_grammar(text)?;
    let (s, cut) = expand(&g)?;
    let mut m = draw(&g, &s, mode)?;
    m.cut |= cut;
    Some(m)
}

/// The mesh the variation samples: the text's, else the preset's (see the module comment).
fn chosen_mesh(preset_id: f64, mode: u8, texts: &[String]) -> Option<LsMesh> {
    let text = texts.first().filter(|t| !t.is_empty());
    let of_preset = |mode: u8| preset(preset_id as i64).and_then(|t| build(t, mode));
    match text {
        None => of_preset(mode),
        Some(t) => build(t, mode).or_else(|| of_preset(0)),
    }
}

/// The shared data: the number n of triangles, the colour mode, then per triangle its three
/// corners and its colour (palette position, or red, green, blue).
fn mesh_data(p: &[f64], texts: &[String]) -> Vec<f64> {
    let mode = p.get(7).map_or(0, |&m| m.clamp(0.0, 2.0) as u8);
    let m = chosen_mesh(p.first().copied().unwrap_or(0.0), mode, texts).unwrap_or_default();
    let mut d = Vec::with_capacity(2 + PER_FACE * m.faces.len());
    d.push(m.faces.len() as f64);
    d.push(f64::from(mode));
    for (f, c) in &m.faces {
        for &i in f {
            d.extend(m.vertices[i as usize].map(f64::from));
        }
        d.extend(match *c {
            FaceColor::Plain => [0.0; 3],
            FaceColor::Index(x) => [x, 0.0, 0.0],
            FaceColor::Rgb(rgb) => rgb,
        });
    }
    d
}

/// The reader's warning for an `lsystem3D_js` whose grammar text JWildfire cannot read or
/// whose production or mesh passes the limits; `None` otherwise and for other variations.
pub fn grammar_problem(name: &str, params: &[f64], texts: &[String]) -> Option<String> {
    if name != "lsystem3D_js" {
        return None;
    }
    let text = texts.first().filter(|t| !t.is_empty())?;
    let mode = params.get(7).map_or(0, |&m| m.clamp(0.0, 2.0) as u8);
    match build(text, mode) {
        None => Some(format!(
            "{name}: the grammar cannot be read (JWildfire's LParser rules); the preset's mesh is used"
        )),
        Some(m) if m.cut => Some(format!(
            "{name}: the grammar's production or mesh is too large; it is drawn up to {} characters or {MAX_FACES} triangles",
            super::jwf_ls_grammar::MAX_PRODUCTION
        )),
        Some(_) => None,
    }
}

/// lsystem3D_js: a random point of a random triangle of the mesh, scaled, moved, times the
/// weight; the triangle's colour as the point's (colour modes 1 and 2).
fn lsystem3d_js(v: &Prepared, _t: &VarIn, acc: &mut Acc, rng: &mut FastRng) -> V3 {
    let [_, sx, sy, sz, ox, oy, oz] = v.params();
    let d = v.data();
    let n = d.first().map_or(0, |&n| n as usize);
    if n == 0 || d.len() < 2 + PER_FACE * n {
        return [0.0; 3];
    }
    let k = rng.below(n as u64) as usize;
    let f = &d[2 + PER_FACE * k..2 + PER_FACE * (k + 1)];
    let corner = |i: usize| {
        place(
            [f[3 * i], f[3 * i + 1], f[3 * i + 2]],
            [sx, sy, sz],
            [ox, oy, oz],
        )
    };
    let p = point_in_triangle([corner(0), corner(1), corner(2)], rng);
    match d[1] as u8 {
        1 => acc.color = f[9],
        2 => acc.rgb = Some([f[9], f[10], f[11]]),
        _ => {}
    }
    p.map(|c| v.w * c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_presets_draw_and_bad_texts_fall_back() {
        for id in 1..=21 {
            let m = build(preset(id).unwrap(), 1).unwrap();
            assert!(!m.faces.is_empty(), "preset {id}");
            assert!(m.faces.len() <= MAX_FACES + 1000, "preset {id}");
        }
        // Preset 19 (Becker plant): cylinders of colour 2, all quads of steps.
        let m = chosen_mesh(19.0, 2, &[]).unwrap();
        let rgb = [204.0, 102.0, 102.0];
        assert!(m.faces.iter().all(|f| f.1 == FaceColor::Rgb(rgb)));
        // An unreadable text: the preset without colours.
        let m = chosen_mesh(19.0, 2, &["angle x".to_string()]).unwrap();
        assert!(m.faces.iter().all(|f| f.1 == FaceColor::Plain));
        assert!(grammar_problem("lsystem3D_js", &[19.0], &["angle x".to_string()]).is_some());
        assert!(grammar_problem("lsystem3D_js", &[19.0], &["axiom FF".to_string()]).is_none());
        // A text of its own: one block.
        let m = chosen_mesh(19.0, 0, &["shape 0\naxiom FF".to_string()]).unwrap();
        assert_eq!(m.faces.len(), 12);
        // A production past the limits is drawn up to them, with a warning.
        let big = "recursion 40\naxiom FF\nrule F = FF".to_string();
        let m = build(&big, 0).unwrap();
        assert!(m.cut && m.faces.len() <= MAX_FACES + 16);
        assert!(grammar_problem("lsystem3D_js", &[19.0], &[big]).is_some());
    }

    #[test]
    fn points_lie_on_the_scaled_block_with_its_colour() {
        // One block from (0, 0, 0) to (0, 0, 1), 0.2 wide, colour 5 (palette position 0.05),
        // scaled by 2 and moved by (1, 0, 0), at weight 0.5.
        let id = super::super::by_name("lsystem3D_js").unwrap();
        let mut p = DEFS[0].defaults();
        p[1] = 2.0;
        p[4] = 1.0;
        p[7] = 1.0;
        let texts = [
            "thickness 20\nshape 0\naxiom c(5)FF".to_string(),
            String::new(),
        ];
        let v = Prepared::with_texts(id, Form::Regular, 0.5, &p, &texts, Default::default(), true);
        let mut rng = FastRng::new(11);
        for _ in 0..2000 {
            let mut acc = Acc::default();
            let o = lsystem3d_js(&v, &VarIn::default(), &mut acc, &mut rng);
            assert_eq!(acc.color, 0.05);
            assert!((0.3999..=0.6001).contains(&o[0]), "{o:?}");
            assert!((-0.0501..=0.0501).contains(&o[1]), "{o:?}");
            assert!((-1e-6..=0.5001).contains(&o[2]), "{o:?}");
        }
    }
}
