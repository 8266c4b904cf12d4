//! The flame / IFS data model.

pub use crate::flame::affine::Affine;
pub use crate::flame::filter::FilterShape;
use crate::flame::keyframes::Keyframes;
pub use crate::flame::palette_rule::{PaletteIndex, PaletteMode};
use crate::flame::sequence::{Animation, MotionFunction};
use crate::flame::variations::{self, Form, VarId};
use crate::gradient::Gradient;

/// One variation term of an xform: which variation, in which form (regular, `pre_`, `post_`),
/// its weight and its parameters (in the order of [`variations::VarDef::params`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Var {
    /// The variation's registry id.
    pub id: VarId,
    /// Regular, `pre_` or `post_`.
    pub form: Form,
    /// The weight its output is multiplied by.
    pub weight: f64,
    /// Parameter values, in [`variations::VarDef::params`] order.
    pub params: Vec<f64>,
    /// Text parameters in [`variations::VarDef::texts`] order (empty for most variations).
    pub texts: Vec<String>,
    /// A regular variation JWildfire's priority (`NAME_fx_priority`) moved before or after the
    /// others (`form` says which): it adds its output to the point there instead of replacing
    /// it, and is written back as the plain name with its priority. With `form` regular: a
    /// variation JWildfire runs after the others by default (`flatten`) that the file's
    /// priority 0 keeps among the regular ones, in its place.
    pub moved: bool,
}

impl Var {
    /// A regular variation with its default parameters.
    pub fn new(id: VarId, weight: f64) -> Self {
        Self::with_form(id, Form::Regular, weight)
    }

    /// A variation used in `form`, with its default parameters.
    pub fn with_form(id: VarId, form: Form, weight: f64) -> Self {
        Self {
            id,
            form,
            weight,
            params: variations::param_defaults(id),
            texts: variations::info(id)
                .texts
                .iter()
                .map(|t| t.default.to_string())
                .collect(),
            moved: false,
        }
    }

    /// The variation's canonical name (without a `pre_`/`post_` prefix).
    pub fn name(&self) -> &'static str {
        variations::info(self.id).name
    }

    /// The attribute name in a flame file (`pre_`/`post_` prefix included).
    pub fn attr_name(&self) -> String {
        variations::attr_name(self.id, self.form)
    }

    /// A parameter by its full name (`julian_power`), case-insensitive.
    pub fn param(&self, name: &str) -> Option<f64> {
        let info = variations::info(self.id);
        info.params
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name))
            .map(|i| self.params[i])
    }
}

/// One transform of the IFS.
#[derive(Clone, Debug, PartialEq)]
pub struct Xform {
    /// Relative probability of choosing this xform (≥ 0).
    pub weight: f64,
    /// The colour coordinate the xform moves points towards (0–1).
    pub color: f64,
    /// How far a step moves the colour coordinate towards `color`: c′ = speed·color +
    /// (1 − speed)·c.
    pub color_speed: f64,
    /// How visible the xform's points are (0: not plotted, 1: fully); the orbit goes on
    /// either way.
    pub opacity: f64,
    /// The affine map applied before the variations.
    pub coefs: Affine,
    /// The affine map applied after the variations (identity: none).
    pub post: Affine,
    /// How much of a colour set by a "direct colour" variation is kept (Fractorium's
    /// `direct_color`; 1 = all of it).
    pub direct_color: f64,
    /// Variation terms in file order; their outputs are summed. A variation appears once,
    /// except in JWildfire's files, which may use one twice (`log` and `log#1#`).
    pub vars: Vec<Var>,
    /// Xaos multipliers towards xforms 0, 1, …; missing entries are 1.
    pub chaos: Vec<f64>,
    /// Whether the xform turns when a loop rotates the flame (flam3's `animate`; 0: it stays,
    /// as symmetry xforms do).
    pub animate: f64,
    /// flam3's `<motion>` elements: periodic changes over a loop.
    pub motion: Vec<Motion>,
    /// Attributes this version of ugnis does not interpret, kept in file order for round trip
    /// (this includes variations that are known to flam3 but not implemented here).
    pub extra_attrs: Vec<(String, String)>,
    /// Raw XML of child elements that are preserved verbatim (e.g. `<motion>`).
    pub extra_children: Vec<String>,
}

impl Default for Xform {
    fn default() -> Self {
        Self {
            weight: 0.5,
            color: 0.0,
            color_speed: 0.5,
            opacity: 1.0,
            coefs: Affine::IDENTITY,
            post: Affine::IDENTITY,
            direct_color: 1.0,
            vars: vec![Var::new(variations::LINEAR, 1.0)],
            chaos: Vec::new(),
            animate: 1.0,
            motion: Vec::new(),
            extra_attrs: Vec::new(),
            extra_children: Vec::new(),
        }
    }
}

/// An xform's `<motion>` element: over a loop (blend 0 → 1) the xform's values move by
/// `delta · function(frequency · blend)`. Every number of `delta` is an amount of change (zero
/// where the element names nothing); its variations carry the changes of the xform's
/// variation weights and parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// Whole periods per loop (`motion_frequency`).
    pub frequency: i32,
    /// The periodic function (`motion_function`).
    pub function: MotionFunction,
    /// The change at full swing of the function: an xform of amounts (zero where nothing moves).
    pub delta: Xform,
}

impl Motion {
    /// A motion element that changes nothing yet.
    pub fn new(frequency: i32, function: MotionFunction) -> Motion {
        Motion {
            frequency,
            function,
            delta: Xform {
                weight: 0.0,
                color: 0.0,
                color_speed: 0.0,
                opacity: 0.0,
                coefs: Affine::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
                post: Affine::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
                direct_color: 0.0,
                vars: Vec::new(),
                animate: 0.0,
                ..Xform::default()
            },
        }
    }
}

impl Xform {
    /// A linear xform with the given affine map and weight.
    pub fn linear(coefs: Affine, weight: f64, color: f64) -> Self {
        Self {
            weight,
            color,
            coefs,
            ..Self::default()
        }
    }

    /// The regular use of variation `id`, if any.
    pub fn var(&self, id: VarId) -> Option<&Var> {
        self.vars
            .iter()
            .find(|v| v.id == id && v.form == Form::Regular)
    }

    /// The weight of the regular use of variation `id` (0 if absent).
    pub fn var_weight(&self, id: VarId) -> f64 {
        self.var(id).map_or(0.0, |v| v.weight)
    }

    /// Set a variation's weight (adding it with default parameters if absent; weight 0 removes it).
    pub fn set_var(&mut self, id: VarId, weight: f64) {
        if let Some(v) = self
            .vars
            .iter_mut()
            .find(|v| v.id == id && v.form == Form::Regular)
        {
            v.weight = weight;
        } else if weight != 0.0 {
            self.vars.push(Var::new(id, weight));
        }
        self.vars.retain(|v| v.weight != 0.0);
    }

    /// Names and weights of variations kept for round trip but not rendered.
    pub fn unsupported_vars(&self) -> Vec<(String, f64)> {
        self.extra_attrs
            .iter()
            .filter(|(k, _)| variations::is_foreign_variation_name(k))
            .map(|(k, v)| (k.clone(), v.trim().parse().unwrap_or(0.0)))
            .collect()
    }

    /// Xaos multiplier towards xform `j`.
    pub fn chaos_to(&self, j: usize) -> f64 {
        self.chaos.get(j).copied().unwrap_or(1.0)
    }
}

/// A 3-D Fractint IFS shown through a fixed view: rows
/// a b c d e f g h i j k l p with x′ = a x + b y + c z + j, y′ = d x + e y + f z + k,
/// z′ = g x + h y + i z + l.
#[derive(Clone, Debug, PartialEq)]
pub struct Ifs3d {
    /// The maps, one row `a b c d e f g h i j k l p` each (p: the probability).
    pub rows: Vec<[f64; 13]>,
    /// Rotations about the x, y and z axes, degrees (applied in that order), then an
    /// orthographic projection onto the screen plane.
    pub view_degrees: [f64; 3],
}

impl Ifs3d {
    /// Fractint's suggested 3-D view: 30°/30°/30°.
    pub const FRACTINT_VIEW: [f64; 3] = [30.0, 30.0, 30.0];
}

/// Settings for new, random and imported flames (the Options dialog's "main" values).
#[derive(Clone, Debug, PartialEq)]
pub struct NewFlame {
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// Samples per pixel.
    pub quality: f64,
    /// Gamma of the tone map.
    pub gamma: f64,
    /// Brightness of the tone map.
    pub brightness: f64,
    /// Contrast of the tone map.
    pub contrast: f64,
    /// The gradient of new flames.
    pub gradient: Gradient,
}

impl Default for NewFlame {
    fn default() -> Self {
        NewFlame {
            width: 640,
            height: 480,
            quality: 15.0,
            gamma: 2.0,
            brightness: 4.0,
            contrast: 1.0,
            gradient: crate::gradient::default_gradient(),
        }
    }
}

impl NewFlame {
    /// An empty flame with these settings and the remaining default render
    /// settings.
    pub fn flame(&self) -> Flame {
        Flame {
            width: self.width,
            height: self.height,
            quality: self.quality,
            gamma: self.gamma,
            brightness: self.brightness,
            contrast: self.contrast,
            palette: self.gradient.clone(),
            ..Flame::default()
        }
    }
}

/// What a flame was made from (`ugnis_kind`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FlameKind {
    /// An ordinary flame (the default).
    #[default]
    Flame,
    /// Created from (and exportable to) a Fractint `.ifs` entry.
    Ifs,
}

impl FlameKind {
    /// The kind's name in flame files (`ugnis_kind`).
    pub fn name(self) -> &'static str {
        match self {
            FlameKind::Flame => "flame",
            FlameKind::Ifs => "ifs",
        }
    }
}

/// The 3-D camera of Apophysis 7X, Fractorium and JWildfire: points carry z through the chaos
/// game and are turned (yaw about z, then pitch about x), seen in perspective and blurred by
/// depth before they are plotted. All zero: the flat flam3 view.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Camera3d {
    /// Radians (`cam_pitch`).
    pub pitch: f64,
    /// Radians (`cam_yaw`).
    pub yaw: f64,
    /// Perspective strength (`cam_perspective` / `cam_persp`): 1/distance of the eye.
    pub perspective: f64,
    /// Height of the focal plane (`cam_zpos`).
    pub zpos: f64,
    /// Depth-of-field blur (`cam_dof`).
    pub dof: f64,
    /// How the blur grows away from the centre (Fractorium's `blur_curve`; 0: uniform).
    pub blur_curve: f64,
}

impl Camera3d {
    /// No 3-D projection at all.
    pub fn is_flat(&self) -> bool {
        self.pitch == 0.0
            && self.yaw == 0.0
            && self.perspective == 0.0
            && self.zpos == 0.0
            && self.dof == 0.0
    }
}

/// A fractal flame: camera, render settings, palette and transforms.
#[derive(Clone, Debug, PartialEq)]
pub struct Flame {
    /// The flame's name.
    pub name: String,
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// The point of the plane at the picture's centre.
    pub center: [f64; 2],
    /// Pixels per world unit at zoom 0.
    pub scale: f64,
    /// Magnification as a power of two: the scale is multiplied by 2^zoom.
    pub zoom: f64,
    /// JWildfire's `cam_zoom`: a further factor on the scale (1 = none).
    pub cam_zoom: f64,
    /// The 3-D camera (flat by default).
    pub cam: Camera3d,
    /// Degrees; positive turns the picture clockwise on screen.
    pub rotate: f64,
    /// Samples per pixel.
    pub quality: f64,
    /// Oversampling per axis (1: none).
    pub supersample: u32,
    /// Radius of the spatial filter, in pixels.
    pub filter: f64,
    /// Kernel of the spatial filter.
    pub filter_shape: FilterShape,
    /// Largest radius of the density-estimation filter (0: no density estimation).
    pub estimator_radius: f64,
    /// Smallest radius of the density-estimation filter.
    pub estimator_minimum: f64,
    /// How fast the density-estimation radius shrinks as the density grows.
    pub estimator_curve: f64,
    /// Brightness of the tone map.
    pub brightness: f64,
    /// Contrast of the tone map (positive; 1: none).
    pub contrast: f64,
    /// Gamma of the tone map.
    pub gamma: f64,
    /// Density below which gamma is applied linearly (keeps sparse areas from noise).
    pub gamma_threshold: f64,
    /// Mix of the two gamma rules (0–1): 1 scales the colour by the gamma-corrected density,
    /// 0 applies gamma to each colour channel.
    pub vibrancy: f64,
    /// How bright areas move towards white (negative: off, the default).
    pub highlight_power: f64,
    /// Background colour (RGB, 0–1).
    pub background: [f64; 3],
    /// How the colour coordinate indexes the palette.
    pub palette_mode: PaletteMode,
    /// Whose rule indexes the palette (the program that wrote the file).
    pub palette_index: PaletteIndex,
    /// JWildfire's "preserve Z": in a flame JWildfire wrote, its 2-D variations carry the
    /// weighted input z along (else their z is 0).
    pub preserve_z: bool,
    /// The gradient (256 entries).
    pub palette: Gradient,
    /// The file's palette when it has more than 256 entries (Fractorium writes such palettes):
    /// `palette` then holds it resampled to 256 for the editor. It renders and is saved only as
    /// long as `palette` is still that resampling — editing the gradient drops it.
    pub palette_hires: Option<Vec<[f64; 4]>>,
    /// Colour curves applied to the final picture (Fractorium's; identity by default).
    pub curves: crate::flame::curves::Curves,
    /// JWildfire's picture settings, used when JWildfire's renderer draws the flame (see
    /// [`Flame::renders_as_jwildfire`]).
    pub jwf: crate::flame::jwf_render::JwfLook,
    /// The control point's time and how it animates (flam3's sequence settings).
    pub anim: Animation,
    /// ugnis' own keyframe animation of this flame's settings.
    pub keys: Keyframes,
    /// The transforms.
    pub xforms: Vec<Xform>,
    /// The final xform, applied to every point before it is plotted (the orbit goes on from
    /// the point before it).
    pub final_xform: Option<Xform>,
    /// Further final xforms, applied in order after `final_xform` (and only with it): JWildfire
    /// allows several `<finalxform>` and chains them. The editor shows the first only.
    pub more_finals: Vec<Xform>,
    /// The settings of the layer the flame's xforms, final xforms and gradient make (JWildfire's
    /// first `<layer>`; plain for other flames).
    pub layer: crate::flame::layers::LayerSettings,
    /// JWildfire's further layers, drawn into the same picture (none for other flames).
    pub more_layers: Vec<crate::flame::layers::Layer>,
    /// Render only this xform (flam3 `soloxform`); others get opacity 0.
    pub solo_xform: Option<usize>,
    /// False when the flame came without a camera (e.g. from an IFS file) and must be framed
    /// automatically before rendering.
    pub has_camera: bool,
    /// Generator seed (`ugnis_seed`).
    pub seed: Option<u64>,
    /// What the flame was made from.
    pub kind: FlameKind,
    /// A 3-D IFS iterated instead of the xforms (from a Fractint `(3D)` entry).
    pub ifs3d: Option<Ifs3d>,
    /// Determinant-rule weights after triangle edits (`ugnis_auto_weights`); `None`: the
    /// Options value.
    pub auto_weights: Option<bool>,
    /// Unknown flame attributes, kept in file order for round trip.
    pub extra_attrs: Vec<(String, String)>,
    /// Child elements preserved verbatim (e.g. `<edit>`).
    pub extra_children: Vec<String>,
}

impl Default for Flame {
    fn default() -> Self {
        Self {
            name: String::new(),
            width: 640,
            height: 480,
            center: [0.0, 0.0],
            scale: 100.0,
            zoom: 0.0,
            cam_zoom: 1.0,
            cam: Camera3d::default(),
            rotate: 0.0,
            quality: 15.0,
            supersample: 1,
            filter: 0.5,
            filter_shape: FilterShape::Gaussian,
            estimator_radius: 9.0,
            estimator_minimum: 0.0,
            estimator_curve: 0.4,
            brightness: 4.0,
            contrast: 1.0,
            gamma: 2.0,
            gamma_threshold: 0.01,
            vibrancy: 1.0,
            highlight_power: -1.0,
            background: [0.0, 0.0, 0.0],
            palette_mode: PaletteMode::Step,
            palette_index: PaletteIndex::Flam3,
            preserve_z: false,
            palette: Gradient::default(),
            palette_hires: None,
            curves: crate::flame::curves::Curves::default(),
            jwf: crate::flame::jwf_render::JwfLook::default(),
            anim: Animation::default(),
            keys: Keyframes::default(),
            xforms: Vec::new(),
            final_xform: None,
            more_finals: Vec::new(),
            layer: crate::flame::layers::LayerSettings::default(),
            more_layers: Vec::new(),
            solo_xform: None,
            has_camera: true,
            seed: None,
            kind: FlameKind::Flame,
            ifs3d: None,
            auto_weights: None,
            extra_attrs: Vec::new(),
            extra_children: Vec::new(),
        }
    }
}

impl Flame {
    /// The palette entries that colour the picture: the file's own palette of more than 256
    /// entries while the gradient is unedited, else the 256-entry gradient.
    pub fn render_colors(&self) -> &[[f64; 4]] {
        match &self.palette_hires {
            Some(h)
                if crate::gradient::resample_colors(h, Gradient::LEN) == self.palette.colors =>
            {
                h
            }
            _ => &self.palette.colors,
        }
    }

    /// The program whose formulas the flame's variations follow where programs differ: the
    /// one that wrote it, as its palette rule names it (flam3's for Apophysis and ugnis).
    pub fn dialect(&self) -> variations::Dialect {
        match self.palette_index {
            PaletteIndex::Fractorium => variations::Dialect::Fractorium,
            PaletteIndex::JWildfire => variations::Dialect::JWildfire,
            PaletteIndex::Flam3 | PaletteIndex::Apophysis => variations::Dialect::Flam3,
        }
    }

    /// Whether JWildfire's solid rendering (`sld_render_enabled`) draws this flame: its
    /// depth buffers are kept in memory only, so it has no render state.
    pub fn draws_solid(&self) -> bool {
        self.renders_as_jwildfire() && self.jwf.solid.enabled
    }

    /// Whether JWildfire's renderer draws the flame (its filters, tone map and plotting): for
    /// the flames JWildfire wrote, as the palette rule names the writer.
    pub fn renders_as_jwildfire(&self) -> bool {
        self.palette_index == PaletteIndex::JWildfire
    }

    /// How the variations of this flame run: as the program that wrote it runs them.
    pub fn rules(&self) -> variations::Rules {
        variations::Rules {
            compat: true,
            dialect: self.dialect(),
            preserve_z: self.preserve_z,
        }
    }

    /// Pixels per world unit: scale·2^zoom·cam_zoom.
    pub fn ppu(&self) -> f64 {
        self.scale * self.zoom.exp2() * self.cam_zoom
    }

    /// Chaos-game samples per unit of quality: 4^zoom·W·H (JWildfire: 4^zoom times its
    /// raster of the picture and the filter's border, divided by the oversampling).
    pub fn samples_per_quality(&self) -> f64 {
        let (w, h) = (self.width as f64, self.height as f64);
        let area = if self.renders_as_jwildfire() {
            let os = self.supersample.max(1) as usize;
            let border =
                crate::flame::jwf_render::JwfRaster::new(&self.jwf, self.filter, os).border as f64;
            let os = os as f64;
            (os * w + 2.0 * border) * (os * h + 2.0 * border) / os
        } else {
            w * h
        };
        (4f64).powf(self.zoom) * area
    }

    /// Total chaos-game samples: quality·[`Flame::samples_per_quality`].
    pub fn total_samples(&self) -> u64 {
        let n = self.quality * self.samples_per_quality();
        if n.is_finite() && n > 0.0 {
            n.ceil() as u64
        } else {
            0
        }
    }

    /// The final xforms in the order they apply: `final_xform`, then `more_finals` (none
    /// without a `final_xform`).
    pub fn finals(&self) -> impl Iterator<Item = &Xform> {
        let more = if self.final_xform.is_some() {
            &self.more_finals[..]
        } else {
            &[]
        };
        self.final_xform.iter().chain(more)
    }

    /// Every xform and final xform of the flame, those of its further layers too.
    fn every_xform(&self) -> impl Iterator<Item = &Xform> {
        let layers = self
            .more_layers
            .iter()
            .flat_map(|l| l.xforms.iter().chain(&l.finals));
        self.xforms.iter().chain(self.finals()).chain(layers)
    }

    /// Names of every variation that has nonzero weight somewhere (supported or not).
    pub fn variations_used(&self) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for x in self.every_xform() {
            for v in &x.vars {
                let n = v.attr_name();
                if !out.contains(&n) {
                    out.push(n);
                }
            }
            for (n, _) in x.unsupported_vars() {
                if !out.contains(&n) {
                    out.push(n);
                }
            }
        }
        out
    }

    /// Warnings for variations that are kept but not rendered:
    /// "variation 'x' (weight w) not supported; ignored", once per name.
    pub fn unsupported_variation_warnings(&self) -> Vec<String> {
        let mut seen: Vec<String> = Vec::new();
        let mut out = Vec::new();
        for x in self.every_xform() {
            for (n, w) in x.unsupported_vars() {
                if w != 0.0 && !seen.contains(&n) {
                    out.push(format!(
                        "variation '{n}' (weight {w}) not supported; ignored"
                    ));
                    seen.push(n);
                }
            }
        }
        out
    }

    /// Resize the image keeping the framing: pixels per unit scale with the width (flam3 `ss`).
    pub fn resize_keep_framing(&mut self, width: u32, height: u32) {
        if self.width > 0 {
            self.scale *= width as f64 / self.width as f64;
        }
        self.width = width;
        self.height = height;
    }

    /// Determinant-rule weights for the given maps.
    pub fn determinant_weights(maps: &[Affine]) -> Vec<f64> {
        let n = maps.len();
        if n == 0 {
            return Vec::new();
        }
        let dets: Vec<f64> = maps.iter().map(|m| m.det().abs()).collect();
        let s: f64 = dets.iter().sum();
        if s == 0.0 || !s.is_finite() {
            return vec![1.0 / n as f64; n];
        }
        let p: Vec<f64> = dets.iter().map(|d| (d / s).max(0.001)).collect();
        let t: f64 = p.iter().sum();
        p.iter().map(|v| v / t).collect()
    }

    /// Set every standard xform's weight by the determinant rule.
    pub fn set_determinant_weights(&mut self) {
        let maps: Vec<Affine> = self.xforms.iter().map(|x| x.coefs).collect();
        for (x, w) in self.xforms.iter_mut().zip(Self::determinant_weights(&maps)) {
            x.weight = w;
        }
    }

    /// w_i = 1/n.
    pub fn set_equal_weights(&mut self) {
        let n = self.xforms.len().max(1) as f64;
        for x in &mut self.xforms {
            x.weight = 1.0 / n;
        }
    }
}

#[cfg(test)]
#[path = "model_tests.rs"]
mod tests;
#[cfg(test)]
pub(crate) use tests::test_sierpinski;
