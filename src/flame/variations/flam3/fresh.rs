//! The parameter values of a variation an xform does not use, as flam3 blends them: an
//! in-between of two control points where only one uses a variation blends its parameters
//! against these (flam3's fresh-xform values, `initialize_xforms`).

use super::FLAM3_COUNT;
use crate::flame::variations::{VarId, info};

/// The parameters a control point's xform blends with when it lacks the variation: flam3's
/// values for a fresh xform (`initialize_xforms`) where they differ from the defaults a new
/// variation gets in the editor, the defaults otherwise.
pub fn absent_params(id: VarId) -> Vec<f64> {
    /// flam3's fresh-xform values that differ from ugnis's defaults.
    const FLAM3_BLANK: [(&str, f64); 30] = [
        ("fan2_x", 0.0),
        ("fan2_y", 0.0),
        ("rings2_val", 0.0),
        ("pie_rotation", 0.0),
        ("escher_beta", 0.0),
        ("lazysusan_spin", 0.0),
        ("modulus_x", 0.0),
        ("modulus_y", 0.0),
        ("popcorn2_x", 0.0),
        ("popcorn2_y", 0.0),
        ("popcorn2_c", 0.0),
        ("separation_x", 0.0),
        ("separation_y", 0.0),
        ("split_xsize", 0.0),
        ("split_ysize", 0.0),
        ("stripes_space", 0.0),
        ("wedge_angle", 0.0),
        ("wedge_count", 1.0),
        ("wedge_sph_angle", 0.0),
        ("wedge_sph_count", 1.0),
        ("whorl_inside", 0.0),
        ("whorl_outside", 0.0),
        ("waves2_freqx", 0.0),
        ("waves2_freqy", 0.0),
        ("auger_freq", 1.0),
        ("auger_scale", 1.0),
        ("mobius_re_a", 0.0),
        ("mobius_re_d", 0.0),
        ("waves2_freqz", 0.0),
        ("waves2_scalez", 0.0),
    ];
    let def = info(id);
    def.params
        .iter()
        .map(|p| {
            let blank = (usize::from(id) < FLAM3_COUNT)
                .then(|| FLAM3_BLANK.iter().find(|(n, _)| *n == p.name))
                .flatten();
            blank.map_or(p.default, |&(_, v)| v)
        })
        .collect()
}
