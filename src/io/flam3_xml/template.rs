//! flam3's template files: a `<flame>` of render settings, usually without any xform (flam3's
//! own `vidres.flam3` holds a size, a quality, a filter …), that flam3-genome's `template=`
//! applies to other flames. Which settings it applies, and how, is flam3's
//! `flam3_apply_template`: the size (the scale follows the new height), zoom, oversampling,
//! filter radius and shape, quality, passes, background, density estimator, gamma threshold,
//! highlight power, palette mode, and the animation settings — never the camera's centre,
//! rotation or scale, nor brightness, gamma, vibrancy or contrast.

use quick_xml::events::Event;

use super::context::R;
use super::{ReadOptions, read};
use crate::flame::model::{FilterShape, Flame};
use crate::io::diag::{Diagnostic, Parsed, Pos};
use crate::io::xml::{XmlCursor, scan_attrs_jwf};

/// The settings of a template file's first flame.
#[derive(Clone, Debug, PartialEq)]
pub struct Template {
    /// The template flame as read (ugnis' defaults where the file says nothing).
    pub flame: Flame,
    /// The names of the attributes its `<flame>` element sets.
    pub attrs: Vec<String>,
}

/// A setting flam3 applies from a template, by the attribute that sets it (aliases after the
/// first), and how it moves into a flame.
struct Setting {
    names: &'static [&'static str],
    apply: fn(&Flame, &mut Flame),
}

/// flam3's `flam3_apply_template`, one entry per attribute it reads; a setting applies only
/// when flam3 counts the template's value as given (e.g. a filter shape other than gaussian,
/// a highlight power of 0 or more).
const SETTINGS: &[Setting] = &[
    Setting {
        names: &["size"],
        // flam3 keeps the framing of the height: pixels per unit scale with it.
        apply: |t, f| {
            f.scale *= t.height as f64 / f.height.max(1) as f64;
            (f.width, f.height) = (t.width, t.height);
        },
    },
    Setting {
        names: &["zoom"],
        apply: |t, f| f.zoom = t.zoom,
    },
    Setting {
        names: &["supersample", "oversample"],
        apply: |t, f| f.supersample = t.supersample,
    },
    Setting {
        names: &["filter"],
        apply: |t, f| f.filter = t.filter,
    },
    Setting {
        names: &["filter_shape"],
        // flam3 takes the template's kernel only when it is not gaussian (its number 0).
        apply: |t, f| {
            if t.filter_shape != FilterShape::Gaussian {
                f.filter_shape = t.filter_shape;
            }
        },
    },
    Setting {
        names: &["quality"],
        apply: |t, f| f.quality = t.quality,
    },
    Setting {
        names: &["passes"],
        apply: |t, f| {
            if let Some((_, v)) = t.extra_attrs.iter().find(|(k, _)| k == "passes")
                && v.trim().parse::<f64>().is_ok_and(|n| n > 0.0)
            {
                f.extra_attrs.retain(|(k, _)| k != "passes");
                f.extra_attrs.push(("passes".into(), v.clone()));
            }
        },
    },
    Setting {
        names: &["background"],
        // Channel by channel, those not negative; flam3 checks green for blue.
        apply: |t, f| {
            for (k, check) in [(0, 0), (1, 1), (2, 1)] {
                if t.background[check] >= 0.0 {
                    f.background[k] = t.background[k];
                }
            }
        },
    },
    Setting {
        names: &["estimator_radius"],
        apply: |t, f| f.estimator_radius = t.estimator_radius,
    },
    Setting {
        names: &["estimator_minimum"],
        apply: |t, f| f.estimator_minimum = t.estimator_minimum,
    },
    Setting {
        names: &["estimator_curve"],
        apply: |t, f| f.estimator_curve = t.estimator_curve,
    },
    Setting {
        names: &["gamma_threshold"],
        apply: |t, f| {
            if t.gamma_threshold >= 0.0 {
                f.gamma_threshold = t.gamma_threshold
            }
        },
    },
    Setting {
        names: &["highlight_power"],
        apply: |t, f| {
            if t.highlight_power >= 0.0 {
                f.highlight_power = t.highlight_power
            }
        },
    },
    Setting {
        names: &["palette_mode"],
        apply: |t, f| f.palette_mode = t.palette_mode,
    },
    Setting {
        names: &["temporal_samples"],
        apply: |t, f| f.anim.temporal_samples = t.anim.temporal_samples,
    },
    Setting {
        names: &["interpolation_type", "interpolation_space"],
        apply: |t, f| f.anim.interpolation_type = t.anim.interpolation_type,
    },
    Setting {
        names: &["temporal_filter_type"],
        apply: |t, f| f.anim.temporal_filter_type = t.anim.temporal_filter_type,
    },
    Setting {
        names: &["temporal_filter_width"],
        apply: |t, f| {
            if t.anim.temporal_filter_width > 0.0 {
                f.anim.temporal_filter_width = t.anim.temporal_filter_width
            }
        },
    },
    Setting {
        names: &["temporal_filter_exp"],
        apply: |t, f| {
            if t.anim.temporal_filter_exp > -900.0 {
                f.anim.temporal_filter_exp = t.anim.temporal_filter_exp
            }
        },
    },
];

/// Settings flam3 copies from every template, given or not (its template reader starts them
/// at their defaults): the interpolation between control points and of palettes.
const ALWAYS: &[Setting] = &[Setting {
    names: &[
        "interpolation",
        "palette_interpolation",
        "hsv_rgb_palette_blend",
    ],
    apply: |t, f| {
        f.anim.interpolation = t.anim.interpolation;
        f.anim.palette_interpolation = t.anim.palette_interpolation;
        f.anim.hsv_rgb_palette_blend = t.anim.hsv_rgb_palette_blend;
    },
}];

/// Attributes of a flame that are neither applied by a template nor without meaning in one:
/// named by [`Template::not_applied`] so that a user sees what the template leaves alone.
const NOT_APPLIED: &[&str] = &[
    "center",
    "scale",
    "rotate",
    "angle",
    "brightness",
    "gamma",
    "vibrancy",
    "contrast",
    "palette",
    "hue",
    "cam_zoom",
    "cam_pitch",
    "cam_yaw",
    "cam_perspective",
    "cam_zpos",
    "cam_dof",
];

impl Template {
    /// The settings it applies, as `name="value"` of its file, in flam3's order.
    pub fn applied(&self) -> Vec<String> {
        SETTINGS
            .iter()
            .chain(ALWAYS)
            .flat_map(|s| s.names.iter())
            .filter(|n| self.attrs.iter().any(|a| a == *n))
            .map(|n| n.to_string())
            .collect()
    }

    /// The settings of its file that flam3 does not apply from a template (the camera's
    /// centre and scale, brightness, gamma, vibrancy …).
    pub fn not_applied(&self) -> Vec<String> {
        self.attrs
            .iter()
            .filter(|a| NOT_APPLIED.contains(&a.as_str()))
            .cloned()
            .collect()
    }

    /// Apply the template's render settings to `f` as flam3-genome's `template=` does.
    pub fn apply(&self, f: &mut Flame) {
        for s in SETTINGS {
            if s.names.iter().any(|n| self.attrs.iter().any(|a| a == n)) {
                (s.apply)(&self.flame, f);
            }
        }
        for s in ALWAYS {
            (s.apply)(&self.flame, f);
        }
    }
}

/// Read a template: the first `<flame>` of the document (xforms or not; more flames are
/// ignored with a warning, as flam3-genome does).
pub fn read_template(text: &str, opts: &ReadOptions) -> R<Parsed<Template>> {
    let opts = ReadOptions {
        templates: true,
        ..opts.clone()
    };
    let mut p = read(text, &opts)?;
    if p.value.flames.len() > 1 {
        p.warnings.push(Diagnostic::warning(
            &opts.file,
            Pos::File,
            "XML025",
            format!(
                "the template holds {} flames; only the first is used, as in flam3-genome",
                p.value.flames.len()
            ),
        ));
    }
    let flame = p.value.flames.swap_remove(0);
    Ok(Parsed {
        value: Template {
            flame,
            attrs: first_flame_attrs(text),
        },
        warnings: p.warnings,
    })
}

/// The attribute names of the first `<flame>` element (already read without error).
fn first_flame_attrs(text: &str) -> Vec<String> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut cur = XmlCursor::new(text);
    while let Ok(p) = cur.next_event() {
        match &p.event {
            Event::Start(e) | Event::Empty(e) if e.name().as_ref() == "flame" => {
                let mut notes = Vec::new();
                return scan_attrs_jwf(e, p.start + 1, &mut notes)
                    .map(|a| a.iter().map(|a| a.name.to_string()).collect())
                    .unwrap_or_default();
            }
            Event::Eof => break,
            _ => {}
        }
    }
    Vec::new()
}
