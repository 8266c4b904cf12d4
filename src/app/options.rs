//! The Options dialog's settings (flame.md §10), persisted as `key = value` lines in the
//! platform config directory (`$XDG_CONFIG_HOME/ugnis/options.txt`, `~/.config/ugnis/…`).

use std::path::PathBuf;

use eframe::egui;

use crate::flame::NewFlame;
use crate::flame::random::{RandomOptions, SymmetryMode, VariationMode};
use crate::gradient::{self, Gradient};

/// All persisted options.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    // Display
    pub main_quality: f64,
    pub main_gamma: f64,
    pub main_brightness: f64,
    pub main_contrast: f64,
    pub preview_quality: f64,
    pub preview_gamma: f64,
    pub animation_quality: f64,
    // Random
    pub min_xforms: usize,
    pub max_xforms: usize,
    pub random_gradient: bool,
    pub probabilities: [f64; 7],
    /// Symmetry of random flames: none, flam3's random order, or a fixed order.
    pub symmetry: SymmetryMode,
    /// Chance of a random post transform per transform, and of a final transform.
    pub post_probability: f64,
    pub final_probability: f64,
    // General
    pub default_gradient: String,
    /// Largest side of the live preview, pixels.
    pub preview_size: u32,
    /// Render threads, 0 = all cores.
    pub threads: usize,
    pub auto_weights: bool,
    /// Size of new flames.
    pub width: u32,
    pub height: u32,
}

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
            min_xforms: 2,
            max_xforms: 6,
            random_gradient: true,
            probabilities: [1.0 / 7.0; 7],
            symmetry: SymmetryMode::None,
            post_probability: 0.0,
            final_probability: 0.0,
            default_gradient: "ember".into(),
            preview_size: 640,
            threads: 0,
            auto_weights: true,
            width: 640,
            height: 480,
        }
    }
}

impl Options {
    /// Problems that make the options invalid (flame.md §10 rules), empty when valid.
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
        if !(64..=4096).contains(&self.preview_size) {
            p.push("preview size must be between 64 and 4096 pixels".into());
        }
        if self.width == 0 || self.height == 0 || self.width > 20000 || self.height > 20000 {
            p.push("new flame size must be between 1 and 20000 pixels".into());
        }
        p
    }

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

    /// The options as `key = value` lines.
    pub fn to_text(&self) -> String {
        let p: Vec<String> = self.probabilities.iter().map(|v| v.to_string()).collect();
        format!(
            "# ugnis options\nmain_quality = {}\nmain_gamma = {}\nmain_brightness = {}\nmain_contrast = {}\n\
             preview_quality = {}\npreview_gamma = {}\nanimation_quality = {}\nmin_xforms = {}\nmax_xforms = {}\n\
             random_gradient = {}\nprobabilities = {}\ndefault_gradient = {}\npreview_size = {}\nthreads = {}\n\
             auto_weights = {}\nwidth = {}\nheight = {}\nsymmetry = {}\npost_probability = {}\n\
             final_probability = {}\n",
            self.main_quality,
            self.main_gamma,
            self.main_brightness,
            self.main_contrast,
            self.preview_quality,
            self.preview_gamma,
            self.animation_quality,
            self.min_xforms,
            self.max_xforms,
            self.random_gradient,
            p.join(" "),
            self.default_gradient,
            self.preview_size,
            self.threads,
            self.auto_weights,
            self.width,
            self.height,
            match self.symmetry {
                SymmetryMode::None => "none".to_string(),
                SymmetryMode::Random => "random".to_string(),
                SymmetryMode::Order(k) => k.to_string(),
            },
            self.post_probability,
            self.final_probability,
        )
    }

    /// Parse `key = value` lines; unknown keys and bad values keep the defaults. Returns the
    /// options and messages about what was ignored.
    pub fn from_text(text: &str) -> (Options, Vec<String>) {
        let mut o = Options::default();
        let mut notes = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let Some((k, v)) = line.split_once('=') else {
                notes.push(format!("line {}: expected 'key = value'", n + 1));
                continue;
            };
            let (k, v) = (k.trim(), v.trim());
            let ok = match k {
                "main_quality" => v.parse().map(|x| o.main_quality = x).is_ok(),
                "main_gamma" => v.parse().map(|x| o.main_gamma = x).is_ok(),
                "main_brightness" => v.parse().map(|x| o.main_brightness = x).is_ok(),
                "main_contrast" => v.parse().map(|x| o.main_contrast = x).is_ok(),
                "preview_quality" => v.parse().map(|x| o.preview_quality = x).is_ok(),
                "preview_gamma" => v.parse().map(|x| o.preview_gamma = x).is_ok(),
                "animation_quality" => v.parse().map(|x| o.animation_quality = x).is_ok(),
                "min_xforms" => v.parse().map(|x| o.min_xforms = x).is_ok(),
                "max_xforms" => v.parse().map(|x| o.max_xforms = x).is_ok(),
                "random_gradient" => v.parse().map(|x| o.random_gradient = x).is_ok(),
                "probabilities" => {
                    let vals: Vec<f64> = v
                        .split_whitespace()
                        .filter_map(|t| t.parse().ok())
                        .collect();
                    match <[f64; 7]>::try_from(vals) {
                        Ok(a) => {
                            o.probabilities = a;
                            true
                        }
                        Err(_) => false,
                    }
                }
                "default_gradient" => {
                    o.default_gradient = v.to_string();
                    true
                }
                "preview_size" => v.parse().map(|x| o.preview_size = x).is_ok(),
                "threads" => v.parse().map(|x| o.threads = x).is_ok(),
                "auto_weights" => v.parse().map(|x| o.auto_weights = x).is_ok(),
                "width" => v.parse().map(|x| o.width = x).is_ok(),
                "height" => v.parse().map(|x| o.height = x).is_ok(),
                "symmetry" => match v {
                    "none" => {
                        o.symmetry = SymmetryMode::None;
                        true
                    }
                    "random" => {
                        o.symmetry = SymmetryMode::Random;
                        true
                    }
                    n => n
                        .parse()
                        .map(|k| o.symmetry = SymmetryMode::Order(k))
                        .is_ok(),
                },
                "post_probability" => v.parse().map(|x| o.post_probability = x).is_ok(),
                "final_probability" => v.parse().map(|x| o.final_probability = x).is_ok(),
                _ => {
                    notes.push(format!("line {}: unknown option '{k}'", n + 1));
                    true
                }
            };
            if !ok {
                notes.push(format!("line {}: bad value '{v}' for {k}", n + 1));
            }
        }
        if !o.problems().is_empty() {
            notes.push(format!(
                "invalid options ({}); using the defaults",
                o.problems().join("; ")
            ));
            o = Options::default();
        }
        (o, notes)
    }

    /// `$XDG_CONFIG_HOME/ugnis/options.txt` (or `~/.config/ugnis/options.txt`).
    pub fn path() -> Option<PathBuf> {
        config_dir().map(|d| d.join("options.txt"))
    }

    pub fn load() -> Options {
        Self::path()
            .and_then(|p| std::fs::read_to_string(p).ok())
            .map(|t| Options::from_text(&t).0)
            .unwrap_or_default()
    }

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

/// Tabs of the Options dialog.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum OptionsTab {
    #[default]
    Display,
    Random,
    General,
}

/// The Options dialog. Returns true when the user pressed OK with valid options.
pub fn dialog(ui: &mut egui::Ui, draft: &mut Options, tab: &mut OptionsTab) -> Option<bool> {
    let mut result = None;
    ui.horizontal(|ui| {
        ui.selectable_value(tab, OptionsTab::Display, "Display");
        ui.selectable_value(tab, OptionsTab::Random, "Random");
        ui.selectable_value(tab, OptionsTab::General, "General");
    });
    ui.separator();
    let num = |ui: &mut egui::Ui, label: &str, v: &mut f64, speed: f64| {
        ui.label(label);
        ui.add(egui::DragValue::new(v).speed(speed).range(0.0..=1e6));
        ui.end_row();
    };
    match tab {
        OptionsTab::Display => {
            egui::Grid::new("opt-display")
                .num_columns(2)
                .show(ui, |ui| {
                    ui.strong("Main render");
                    ui.end_row();
                    num(ui, "Density (quality)", &mut draft.main_quality, 0.5);
                    num(ui, "Gamma", &mut draft.main_gamma, 0.05);
                    num(ui, "Brightness", &mut draft.main_brightness, 0.05);
                    num(ui, "Contrast", &mut draft.main_contrast, 0.05);
                    ui.strong("Preview");
                    ui.end_row();
                    num(ui, "Density", &mut draft.preview_quality, 0.5);
                    num(ui, "Gamma", &mut draft.preview_gamma, 0.05);
                    ui.strong("Animation");
                    ui.end_row();
                    num(ui, "Density", &mut draft.animation_quality, 0.1);
                });
        }
        OptionsTab::Random => {
            egui::Grid::new("opt-random").num_columns(2).show(ui, |ui| {
                ui.label("Transforms, minimum");
                ui.add(egui::DragValue::new(&mut draft.min_xforms).range(2..=100));
                ui.end_row();
                ui.label("Transforms, maximum");
                ui.add(egui::DragValue::new(&mut draft.max_xforms).range(2..=100));
                ui.end_row();
                ui.label("Random gradient");
                ui.checkbox(&mut draft.random_gradient, "");
                ui.end_row();
                ui.label("Symmetry");
                ui.horizontal(|ui| {
                    let fixed = matches!(draft.symmetry, SymmetryMode::Order(_));
                    if ui
                        .selectable_label(draft.symmetry == SymmetryMode::None, "none")
                        .clicked()
                    {
                        draft.symmetry = SymmetryMode::None;
                    }
                    if ui
                        .selectable_label(draft.symmetry == SymmetryMode::Random, "random")
                        .clicked()
                    {
                        draft.symmetry = SymmetryMode::Random;
                    }
                    if ui.selectable_label(fixed, "order").clicked() && !fixed {
                        draft.symmetry = SymmetryMode::Order(4);
                    }
                    if let SymmetryMode::Order(k) = &mut draft.symmetry {
                        ui.add(egui::DragValue::new(k).range(-100..=100))
                            .on_hover_text("N: rotational; −N: rotational and mirror; −1: mirror");
                    }
                });
                ui.end_row();
                ui.label("Chance of post transforms");
                ui.add(egui::Slider::new(&mut draft.post_probability, 0.0..=1.0));
                ui.end_row();
                ui.label("Chance of a final transform");
                ui.add(egui::Slider::new(&mut draft.final_probability, 0.0..=1.0));
                ui.end_row();
                ui.strong("Variation probabilities");
                ui.end_row();
                for (i, id) in crate::flame::variations::THESIS_SEVEN.iter().enumerate() {
                    ui.label(crate::flame::variations::info(*id).name);
                    ui.add(
                        egui::DragValue::new(&mut draft.probabilities[i])
                            .speed(0.01)
                            .range(0.0..=1.0),
                    );
                    ui.end_row();
                }
            });
        }
        OptionsTab::General => {
            egui::Grid::new("opt-general")
                .num_columns(2)
                .show(ui, |ui| {
                    ui.label("Default gradient");
                    egui::ComboBox::from_id_salt("opt-gradient")
                        .selected_text(draft.default_gradient.clone())
                        .show_ui(ui, |ui| {
                            for g in gradient::builtin() {
                                ui.selectable_value(
                                    &mut draft.default_gradient,
                                    g.name.clone(),
                                    g.name,
                                );
                            }
                        });
                    ui.end_row();
                    ui.label("Preview size (pixels)");
                    ui.add(egui::DragValue::new(&mut draft.preview_size).range(64..=4096));
                    ui.end_row();
                    ui.label("New flame size");
                    ui.horizontal(|ui| {
                        ui.add(egui::DragValue::new(&mut draft.width).range(1..=20000));
                        ui.label("×");
                        ui.add(egui::DragValue::new(&mut draft.height).range(1..=20000));
                    });
                    ui.end_row();
                    ui.label("Render threads (0 = all)");
                    ui.add(egui::DragValue::new(&mut draft.threads).range(0..=256));
                    ui.end_row();
                    ui.label("Weights from triangle areas after edits");
                    ui.checkbox(&mut draft.auto_weights, "");
                    ui.end_row();
                });
        }
    }
    let problems = draft.problems();
    for p in &problems {
        ui.colored_label(egui::Color32::from_rgb(230, 90, 80), p);
    }
    ui.separator();
    ui.horizontal(|ui| {
        if ui
            .add_enabled(problems.is_empty(), egui::Button::new("OK"))
            .clicked()
        {
            result = Some(true);
        }
        if ui.button("Cancel").clicked() {
            result = Some(false);
        }
        if ui.button("Defaults").clicked() {
            *draft = Options::default();
        }
    });
    result
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
        let (q, notes) = Options::from_text(&p.to_text());
        assert!(notes.is_empty(), "{notes:?}");
        assert_eq!(q, p);
        p.symmetry = SymmetryMode::Random;
        assert_eq!(Options::from_text(&p.to_text()).0, p);
    }

    #[test]
    fn validation() {
        let o = Options {
            min_xforms: 7,
            ..Options::default()
        };
        assert!(!o.problems().is_empty());
        let (q, notes) = Options::from_text("min_xforms = 1\nfoo = 3\nmain_gamma = x\n");
        assert_eq!(q, Options::default());
        assert_eq!(notes.len(), 3, "{notes:?}");
    }
}
