//! The Options dialog's settings, persisted as TOML in the platform config directory
//! (`$XDG_CONFIG_HOME/ugnis/options.toml`, `~/.config/ugnis/…`). The defaults are those of
//! the Options dialog of Fraktalai (Urbonavičius 2006): main density 15, gamma 2, brightness 4,
//! contrast 1; preview density 5; animation density 1; 2–6 transforms; each of the seven
//! variations 1/7.

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use crate::flame::NewFlame;
use crate::flame::random::{RandomOptions, SymmetryMode, VariationMode};
use crate::flame::variations::{self, Form, VarId};
use crate::gradient::{self, Gradient};

/// All persisted options.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Options {
    // Display
    /// Quality (samples per pixel) of new flames.
    pub main_quality: f64,
    /// Gamma of new flames.
    pub main_gamma: f64,
    /// Brightness of new flames.
    pub main_brightness: f64,
    /// Contrast of new flames.
    pub main_contrast: f64,
    /// Quality of the preview's first pass, and of the whole preview while dragging.
    pub preview_quality: f64,
    /// Gamma of the preview, as set in the Options dialog.
    pub preview_gamma: f64,
    /// Quality of the preview while an animation or morph runs.
    pub animation_quality: f64,
    /// The preview refines until its estimated noise is at most this many 8-bit levels (root
    /// mean square over the flame's pixels), whatever the file's quality.
    pub preview_noise: f64,
    /// The fewest samples per pixel the preview refines to before its noise may stop it
    /// (density estimation keeps sharpening a picture whose grain is gone).
    pub preview_least_quality: f64,
    /// The most samples per pixel the preview refines to.
    pub preview_max_quality: f64,
    // Random
    /// Fewest xforms of a random flame.
    pub min_xforms: usize,
    /// Most xforms of a random flame.
    pub max_xforms: usize,
    /// Random flames get a random gradient.
    pub random_gradient: bool,
    /// Probabilities of Fraktalai's seven variations in random flames.
    pub probabilities: [f64; 7],
    /// Symmetry of random flames: none, flam3's random order, or a fixed order.
    #[serde(with = "symmetry_text")]
    pub symmetry: SymmetryMode,
    /// Chance of a random post transform per transform, and of a final transform.
    pub post_probability: f64,
    /// Chance of a final transform in a random flame.
    pub final_probability: f64,
    // General
    /// Name of the built-in gradient of new flames.
    pub default_gradient: String,
    /// Largest side of the live preview, pixels.
    pub preview_size: u32,
    /// Render threads, 0 = all cores.
    pub threads: usize,
    /// Set xform weights by the determinant rule after triangle edits.
    pub auto_weights: bool,
    /// Width of new flames, pixels.
    pub width: u32,
    /// Height of new flames, pixels.
    pub height: u32,
    /// The variations filter: the names (NAME, pre_NAME, post_NAME) random flames may use.
    pub variation_filter: Vec<String>,
    /// Random flames draw their variations from the filter.
    pub use_variation_filter: bool,
    /// Files opened or saved lately, newest first.
    pub recent_files: Vec<PathBuf>,
    /// JWildfire's jar or resource folders (separated as in `PATH`), where JWildfire's own
    /// resources are read from; empty: none (the environment variable `UGNIS_JWILDFIRE`,
    /// when set, wins).
    pub jwildfire: String,
}

/// The preview's noise target by default (8-bit levels of grain): a little less grain than
/// the example flames have at quality 100.
pub const DEFAULT_PREVIEW_NOISE: f64 = 2.5;
/// The range of the preview's noise target.
pub const PREVIEW_NOISE_RANGE: std::ops::RangeInclusive<f64> = 0.2..=20.0;

/// Most recent files kept.
pub const RECENT_FILES: usize = 10;
/// Most names the variations filter keeps (every name with its forms is about 1,400).
pub const MAX_FILTER_NAMES: usize = 5000;

impl Default for Options {
    fn default() -> Self {
        Options {
            main_quality: 15.0,
            main_gamma: 2.0,
            main_brightness: 4.0,
            main_contrast: 1.0,
            preview_quality: 5.0,
            preview_gamma: 2.0,
            animation_quality: 1.0,
            preview_noise: DEFAULT_PREVIEW_NOISE,
            preview_least_quality: 100.0,
            preview_max_quality: 2000.0,
            min_xforms: 2,
            max_xforms: 6,
            random_gradient: true,
            probabilities: [1.0 / 7.0; 7],
            symmetry: SymmetryMode::None,
            post_probability: 0.0,
            final_probability: 0.0,
            default_gradient: "ember".into(),
            preview_size: 1280,
            threads: 0,
            auto_weights: true,
            width: 640,
            height: 480,
            variation_filter: Vec::new(),
            use_variation_filter: false,
            recent_files: Vec::new(),
            jwildfire: String::new(),
        }
    }
}

impl Options {
    /// Problems that make the options invalid, empty when valid: densities, gamma,
    /// brightness and contrast above 0; 2 ≤ minimum ≤ maximum ≤ 100 transforms.
    pub fn problems(&self) -> Vec<String> {
        let mut p = Vec::new();
        for (name, v) in [
            ("main density", self.main_quality),
            ("preview density", self.preview_quality),
            ("animation density", self.animation_quality),
            ("gamma", self.main_gamma),
            ("preview gamma", self.preview_gamma),
            ("brightness", self.main_brightness),
            ("contrast", self.main_contrast),
        ] {
            if !(v > 0.0 && v.is_finite()) {
                p.push(format!("{name} must be greater than 0"));
            }
        }
        if !(2 <= self.min_xforms && self.min_xforms <= self.max_xforms && self.max_xforms <= 100) {
            p.push("transforms: need 2 ≤ minimum ≤ maximum ≤ 100".into());
        }
        if self.probabilities.iter().any(|v| *v < 0.0)
            || self.probabilities.iter().sum::<f64>() <= 0.0
        {
            p.push("variation probabilities must be ≥ 0 and not all 0".into());
        }
        if !(0.0..=1.0).contains(&self.post_probability)
            || !(0.0..=1.0).contains(&self.final_probability)
        {
            p.push("post and final chances must be between 0 and 1".into());
        }
        if let SymmetryMode::Order(k) = self.symmetry
            && !(-100..=100).contains(&k)
        {
            p.push("symmetry order must be between −100 and 100".into());
        }
        if !PREVIEW_NOISE_RANGE.contains(&self.preview_noise) {
            p.push(format!(
                "preview noise target must be between {} and {} levels",
                PREVIEW_NOISE_RANGE.start(),
                PREVIEW_NOISE_RANGE.end()
            ));
        }
        if !(1.0..=crate::flame::render::MAX_QUALITY).contains(&self.preview_max_quality) {
            p.push(format!(
                "preview's most quality must be between 1 and {}",
                crate::flame::render::MAX_QUALITY
            ));
        }
        if !(0.0..=self.preview_max_quality).contains(&self.preview_least_quality) {
            p.push("preview's least quality must be between 0 and its most quality".into());
        }
        if !(64..=4096).contains(&self.preview_size) {
            p.push("preview size must be between 64 and 4096 pixels".into());
        }
        if self.width == 0 || self.height == 0 || self.width > 20000 || self.height > 20000 {
            p.push("new flame size must be between 1 and 20000 pixels".into());
        }
        if self.variation_filter.len() > MAX_FILTER_NAMES {
            p.push(format!(
                "the variations filter holds at most {MAX_FILTER_NAMES} names"
            ));
        }
        if self.recent_files.len() > 100 {
            p.push("at most 100 recent files".into());
        }
        p
    }

    /// The variations filter as variations (unknown names are left out).
    pub fn filter_list(&self) -> Vec<(VarId, Form)> {
        self.variation_filter
            .iter()
            .filter_map(|n| variations::parse_name(n))
            .collect()
    }

    /// How random flames choose variations at start: the filter when it is in use, otherwise
    /// one of the seven variations of Fraktalai per transform.
    pub fn variation_mode(&self) -> VariationMode {
        if self.use_variation_filter {
            VariationMode::FromList(self.filter_list())
        } else {
            VariationMode::Random(self.probabilities)
        }
    }

    /// Put `path` first in the recent files.
    pub fn remember(&mut self, path: &std::path::Path) {
        // The options file is text: a name that is not Unicode is not kept.
        if path.to_str().is_none() {
            return;
        }
        let p = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
        self.recent_files.retain(|q| q != &p);
        self.recent_files.insert(0, p);
        self.recent_files.truncate(RECENT_FILES);
    }

    /// The gradient of new flames (the default gradient if the name is unknown).
    pub fn gradient(&self) -> Gradient {
        gradient::builtin_named(&self.default_gradient).unwrap_or_else(gradient::default_gradient)
    }

    /// Settings for new, random and imported flames.
    pub fn new_flame(&self) -> NewFlame {
        NewFlame {
            width: self.width,
            height: self.height,
            quality: self.main_quality,
            gamma: self.main_gamma,
            brightness: self.main_brightness,
            contrast: self.main_contrast,
            gradient: self.gradient(),
        }
    }

    /// The options of random flames, with these variations.
    pub fn random_options(&self, variations: VariationMode) -> RandomOptions {
        RandomOptions {
            min_xforms: self.min_xforms,
            max_xforms: self.max_xforms,
            random_gradient: self.random_gradient,
            symmetry: self.symmetry,
            post_probability: self.post_probability,
            final_probability: self.final_probability,
            variations: match variations {
                VariationMode::Random(_) => VariationMode::Random(self.probabilities),
                v => v,
            },
            ..RandomOptions::default()
        }
    }

    /// The options as TOML.
    pub fn to_text(&self) -> String {
        let body = toml::to_string(self).expect("options always serialise");
        format!("# ugnis options\n{body}")
    }

    /// Read options from TOML; absent keys keep their defaults, unknown keys are ignored.
    /// Errors name the line and what was expected; options that break a rule are refused.
    pub fn from_text(text: &str) -> Result<Options, String> {
        let o: Options = toml::from_str(text).map_err(|e| {
            let line = e
                .span()
                .map(|s| text[..s.start.min(text.len())].lines().count().max(1));
            match line {
                Some(l) => format!("line {l}: {}", e.message()),
                None => e.message().to_string(),
            }
        })?;
        let p = o.problems();
        if p.is_empty() {
            Ok(o)
        } else {
            Err(format!("invalid options: {}", p.join("; ")))
        }
    }

    /// `$XDG_CONFIG_HOME/ugnis/options.toml` (or `~/.config/ugnis/options.toml`).
    pub fn path() -> Option<PathBuf> {
        config_dir().map(|d| d.join("options.toml"))
    }

    /// Read JWildfire's resources from the installation these options name, unless the
    /// environment names one; a message when it cannot be opened.
    pub fn apply_jwildfire(&self) -> Option<String> {
        use crate::io::jwf_install;
        if jwf_install::paths_from_env().is_some() {
            return None;
        }
        let paths: Vec<PathBuf> = std::env::split_paths(self.jwildfire.trim())
            .filter(|p| !p.as_os_str().is_empty())
            .collect();
        if paths.is_empty() {
            crate::flame::variations::resources::set_jwildfire_reader(None);
            return None;
        }
        jwf_install::install(&paths)
            .err()
            .map(|e| format!("JWildfire installation: {e}; JWildfire's own resources are not read"))
    }

    /// The saved options, or the defaults when there are none. A file that cannot be used
    /// gives the defaults and a message naming it.
    pub fn load() -> (Options, Option<String>) {
        let Some(p) = Self::path() else {
            return (Options::default(), None);
        };
        match std::fs::read_to_string(&p) {
            Ok(t) => match Options::from_text(&t) {
                Ok(o) => (o, None),
                Err(e) => (
                    Options::default(),
                    Some(format!("{}: {e}; using the defaults", p.display())),
                ),
            },
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => (Options::default(), None),
            Err(e) => (
                Options::default(),
                Some(format!("{}: {e}; using the defaults", p.display())),
            ),
        }
    }

    /// Write the options to the configuration file.
    pub fn save(&self) -> Result<(), String> {
        let p = Self::path().ok_or("no configuration directory (HOME is not set)")?;
        if let Some(d) = p.parent() {
            std::fs::create_dir_all(d)
                .map_err(|e| format!("cannot create {}: {e}", d.display()))?;
        }
        crate::io::atomic::write_atomic(&p, self.to_text().as_bytes())
            .map_err(|e| format!("cannot save options: {e}"))
    }
}

/// Symmetry as TOML: "none", "random" or the order as a number.
mod symmetry_text {
    use serde::{Deserialize, Deserializer, Serializer, de};

    use crate::flame::random::SymmetryMode;

    pub fn serialize<S: Serializer>(m: &SymmetryMode, s: S) -> Result<S::Ok, S::Error> {
        match m {
            SymmetryMode::None => s.serialize_str("none"),
            SymmetryMode::Random => s.serialize_str("random"),
            SymmetryMode::Order(k) => s.serialize_i32(*k),
        }
    }

    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Text {
        Word(String),
        Order(i32),
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<SymmetryMode, D::Error> {
        match Text::deserialize(d)? {
            Text::Order(k) => Ok(SymmetryMode::Order(k)),
            Text::Word(w) => match w.as_str() {
                "none" => Ok(SymmetryMode::None),
                "random" => Ok(SymmetryMode::Random),
                _ => Err(de::Error::custom(format!(
                    "symmetry '{w}': expected \"none\", \"random\" or an order"
                ))),
            },
        }
    }
}

/// The ugnis configuration directory.
pub fn config_dir() -> Option<PathBuf> {
    std::env::var_os("XDG_CONFIG_HOME")
        .map(PathBuf::from)
        .filter(|p| p.is_absolute())
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".config")))
        .map(|d| d.join("ugnis"))
}

/// The ugnis data directory (the last random batch lives here).
pub fn data_dir() -> Option<PathBuf> {
    std::env::var_os("XDG_DATA_HOME")
        .map(PathBuf::from)
        .filter(|p| p.is_absolute())
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".local/share")))
        .map(|d| d.join("ugnis"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thesis_defaults_and_round_trip() {
        let o = Options::default();
        assert_eq!(
            (
                o.main_quality,
                o.main_gamma,
                o.main_brightness,
                o.main_contrast
            ),
            (15.0, 2.0, 4.0, 1.0)
        );
        assert_eq!(
            (o.preview_quality, o.preview_gamma, o.animation_quality),
            (5.0, 2.0, 1.0)
        );
        assert_eq!(
            (o.min_xforms, o.max_xforms, o.random_gradient),
            (2, 6, true)
        );
        let mut p = o.clone();
        p.main_quality = 50.0;
        p.default_gradient = "lagoon".into();
        p.probabilities[3] = 0.5;
        p.symmetry = SymmetryMode::Order(-3);
        p.post_probability = 0.25;
        p.variation_filter = vec!["julia".into(), "pre_blur".into()];
        p.use_variation_filter = true;
        p.remember(std::path::Path::new("/tmp/a.flame"));
        assert_eq!(Options::from_text(&p.to_text()), Ok(p.clone()));
        assert_eq!(
            p.filter_list(),
            vec![
                variations::parse_name("julia").unwrap(),
                variations::parse_name("pre_blur").unwrap()
            ]
        );
        assert!(matches!(p.variation_mode(), VariationMode::FromList(l) if l.len() == 2));
        p.symmetry = SymmetryMode::Random;
        assert_eq!(Options::from_text(&p.to_text()), Ok(p));
        // Absent keys keep their defaults.
        assert_eq!(Options::from_text("threads = 3\n").unwrap().threads, 3);
        assert_eq!(Options::from_text("").unwrap(), Options::default());
    }

    #[test]
    fn recent_files_are_newest_first_without_repeats() {
        let mut o = Options::default();
        for k in 0..15 {
            o.remember(std::path::Path::new(&format!("/tmp/f{k}.fla")));
        }
        o.remember(std::path::Path::new("/tmp/f10.fla"));
        assert_eq!(o.recent_files.len(), RECENT_FILES);
        assert_eq!(o.recent_files[0], std::path::Path::new("/tmp/f10.fla"));
        assert_eq!(o.recent_files[1], std::path::Path::new("/tmp/f14.fla"));
        assert_eq!(
            o.recent_files
                .iter()
                .filter(|p| p.ends_with("f10.fla"))
                .count(),
            1
        );
    }

    #[test]
    fn bad_values_name_the_line_and_broken_rules_are_refused() {
        let o = Options {
            min_xforms: 7,
            ..Options::default()
        };
        assert!(!o.problems().is_empty());
        let e = Options::from_text("threads = 2\nmain_gamma = \"x\"\n").unwrap_err();
        assert!(e.starts_with("line 2:"), "{e}");
        let e = Options::from_text("symmetry = \"sometimes\"\n").unwrap_err();
        assert!(
            e.contains("expected \"none\", \"random\" or an order"),
            "{e}"
        );
        let e = Options::from_text("min_xforms = 1\n").unwrap_err();
        assert!(e.contains("2 ≤ minimum"), "{e}");
    }
}
