//! The Settings section: everything of the whole flame that Apophysis' Adjust window and
//! Fractorium's flame tab hold — name and size; the camera, flat and 3-D (pitch, yaw,
//! perspective, focal height, depth of field and its blur curve); quality, oversampling,
//! the spatial filter and density estimation; the tone map, palette rule and background; and
//! the motion blur of animation frames.

use std::ops::RangeInclusive;

use eframe::egui;

use super::document::Document;
use crate::app::a11y::named;
use crate::flame::Flame;

/// One labelled number row of the grid.
fn row(
    ui: &mut egui::Ui,
    label: &str,
    tip: &str,
    v: &mut f64,
    speed: f64,
    range: RangeInclusive<f64>,
) {
    let l = ui.label(label);
    ui.add(
        egui::DragValue::new(v)
            .speed(speed)
            .range(range)
            // A file's value outside the range stays as it is until the user edits it.
            .clamp_existing_to_range(false)
            .max_decimals(5),
    )
    .labelled_by(l.id)
    .on_hover_text(tip);
    ui.end_row();
}

/// Flame-wide settings; `dragging`: a pointer is held (a drag is one undo step).
pub fn flame_settings(ui: &mut egui::Ui, doc: &mut Document, dragging: bool) {
    let mut f = doc.flame().clone();
    let before = f.clone();
    let grid = |ui: &mut egui::Ui, id: &str, rows: &mut dyn FnMut(&mut egui::Ui)| {
        egui::Grid::new(id)
            .num_columns(2)
            .min_col_width(120.0)
            .show(ui, |ui| rows(ui));
    };
    grid(ui, "flame-picture", &mut |ui| {
        name_and_size_rows(ui, &mut f)
    });
    ui.strong("Camera");
    grid(ui, "flame-camera", &mut |ui| camera_rows(ui, &mut f));
    egui::CollapsingHeader::new("3-D camera")
        .default_open(!f.cam.is_flat())
        .show(ui, |ui| {
            grid(ui, "flame-camera-3d", &mut |ui| camera3d_rows(ui, &mut f))
        });
    ui.strong("Render");
    grid(ui, "flame-render", &mut |ui| render_rows(ui, &mut f));
    ui.strong("Tone");
    grid(ui, "flame-tone", &mut |ui| {
        tone_rows(ui, &mut f);
        background_row(ui, &mut f);
    });
    ui.strong("Palette");
    grid(ui, "flame-palette", &mut |ui| palette_rows(ui, &mut f));
    ui.strong("Motion blur");
    grid(ui, "flame-motion-blur", &mut |ui| {
        motion_blur_rows(ui, &mut f)
    });
    if f.estimator_radius < f.estimator_minimum {
        f.estimator_minimum = f.estimator_radius;
    }
    if f != before {
        doc.edit_while(dragging, |g| *g = f);
    }
}

/// An angle in radians shown and typed in degrees.
fn degrees_row(ui: &mut egui::Ui, label: &str, tip: &str, radians: &mut f64) {
    let mut deg = radians.to_degrees();
    let old = deg;
    row(ui, label, tip, &mut deg, 0.5, -360.0..=360.0);
    if deg != old {
        *radians = deg.to_radians();
    }
}

/// The 3-D camera of Apophysis 7X, Fractorium and JWildfire.
fn camera3d_rows(ui: &mut egui::Ui, f: &mut Flame) {
    let c = &mut f.cam;
    degrees_row(
        ui,
        "Pitch (°)",
        "tilts the plane away from the viewer (about the horizontal axis)",
        &mut c.pitch,
    );
    degrees_row(
        ui,
        "Yaw (°)",
        "turns the plane about the vertical axis before the pitch",
        &mut c.yaw,
    );
    row(
        ui,
        "Perspective",
        "how strongly far parts shrink (1/distance of the eye; 0: parallel view)",
        &mut c.perspective,
        0.005,
        -100.0..=100.0,
    );
    row(
        ui,
        "Z position",
        "height of the focal plane: points there are sharp",
        &mut c.zpos,
        0.01,
        -1000.0..=1000.0,
    );
    row(
        ui,
        "Depth of field",
        "blur of points away from the focal plane (0: all sharp)",
        &mut c.dof,
        0.005,
        0.0..=100.0,
    );
    row(
        ui,
        "Blur curve",
        "how the blur grows away from the picture's centre (Fractorium; 0: the same everywhere)",
        &mut c.blur_curve,
        0.01,
        0.0..=100.0,
    );
}

/// Quality, oversampling, the spatial filter and density estimation.
fn render_rows(ui: &mut egui::Ui, f: &mut Flame) {
    row(
        ui,
        "Quality",
        "samples per pixel of the exported picture (the preview refines on its own, to the \
         noise target of Options › Display)",
        &mut f.quality,
        1.0,
        0.01..=1e6,
    );
    let l = ui.label("Supersample");
    ui.add(
        egui::DragValue::new(&mut f.supersample)
            .range(1..=16)
            .clamp_existing_to_range(false),
    )
    .labelled_by(l.id)
    .on_hover_text(
        "renders at this many times the size per side and filters down (smoother edges; \
         memory and time grow with its square)",
    );
    ui.end_row();
    row(
        ui,
        "Filter radius",
        "radius of the spatial filter in pixels (softens; 0: none)",
        &mut f.filter,
        0.01,
        0.0..=100.0,
    );
    let l = ui.label("Filter shape");
    let r = egui::ComboBox::from_id_salt("filter-shape")
        .selected_text(f.filter_shape.name())
        .show_ui(ui, |ui| {
            for s in crate::flame::FilterShape::ALL {
                ui.selectable_value(&mut f.filter_shape, s, s.name());
            }
        })
        .response;
    r.labelled_by(l.id)
        .on_hover_text("the spatial filter's kernel (flam3's filter_shape)");
    ui.end_row();
    row(
        ui,
        "DE radius",
        "density estimation: the largest blur radius, for the sparsest areas (0: off)",
        &mut f.estimator_radius,
        0.1,
        0.0..=50.0,
    );
    row(
        ui,
        "DE minimum",
        "density estimation: the smallest blur radius, for the densest areas",
        &mut f.estimator_minimum,
        0.05,
        0.0..=50.0,
    );
    row(
        ui,
        "DE curve",
        "density estimation: how fast the radius shrinks as the density grows",
        &mut f.estimator_curve,
        0.01,
        0.0..=10.0,
    );
}

/// The flame's name and picture size.
fn name_and_size_rows(ui: &mut egui::Ui, f: &mut Flame) {
    let l = ui.label("Name");
    ui.text_edit_singleline(&mut f.name)
        .labelled_by(l.id)
        .on_hover_text("the flame's name in the file");
    ui.end_row();
    ui.label("Size");
    ui.horizontal(|ui| {
        named(
            ui.add(
                egui::DragValue::new(&mut f.width)
                    .range(1..=20000)
                    .clamp_existing_to_range(false),
            ),
            "Width",
        )
        .on_hover_text("width of the picture in pixels");
        ui.label("×");
        named(
            ui.add(
                egui::DragValue::new(&mut f.height)
                    .range(1..=20000)
                    .clamp_existing_to_range(false),
            ),
            "Height",
        )
        .on_hover_text("height of the picture in pixels");
    });
    ui.end_row();
}

/// Where the picture looks: centre, scale, zoom and rotation.
fn camera_rows(ui: &mut egui::Ui, f: &mut Flame) {
    row(
        ui,
        "Centre x",
        "the world point in the middle of the picture",
        &mut f.center[0],
        0.01,
        -1e6..=1e6,
    );
    row(
        ui,
        "Centre y",
        "the world point in the middle of the picture (y down)",
        &mut f.center[1],
        0.01,
        -1e6..=1e6,
    );
    row(
        ui,
        "Scale",
        "pixels per world unit at zoom 0",
        &mut f.scale,
        0.5,
        0.001..=1e7,
    );
    row(
        ui,
        "Zoom",
        "magnification as a power of 2 (1 = twice as close)",
        &mut f.zoom,
        0.01,
        -20.0..=20.0,
    );
    row(
        ui,
        "Rotate (°)",
        "turns the picture (positive: clockwise)",
        &mut f.rotate,
        0.5,
        -3600.0..=3600.0,
    );
}

/// The tone map.
fn tone_rows(ui: &mut egui::Ui, f: &mut Flame) {
    row(
        ui,
        "Brightness",
        "overall brightness of the tone mapping",
        &mut f.brightness,
        0.05,
        0.01..=1000.0,
    );
    row(
        ui,
        "Gamma",
        "gamma of the tone mapping (higher: more detail in dark parts)",
        &mut f.gamma,
        0.05,
        0.01..=100.0,
    );
    row(
        ui,
        "Gamma threshold",
        "below this density gamma is linear (less noise)",
        &mut f.gamma_threshold,
        0.001,
        0.0..=10.0,
    );
    row(
        ui,
        "Vibrancy",
        "0: gamma per channel; 1: colours keep their saturation",
        &mut f.vibrancy,
        0.01,
        0.0..=10.0,
    );
    row(
        ui,
        "Highlight power",
        "how bright areas fade to white (−1: off)",
        &mut f.highlight_power,
        0.05,
        -1.0..=100.0,
    );
    row(
        ui,
        "Contrast",
        "contrast of the tone mapping",
        &mut f.contrast,
        0.01,
        0.01..=100.0,
    );
}

/// How colour coordinates pick gradient entries: the palette mode and whose rule, each a row
/// of its own with its label at the left.
fn palette_rows(ui: &mut egui::Ui, f: &mut Flame) {
    use crate::flame::{PaletteIndex, PaletteMode};
    let l = ui.label("Mode");
    egui::ComboBox::from_id_salt("palette-mode")
        .selected_text(f.palette_mode.name())
        .show_ui(ui, |ui| {
            for m in [PaletteMode::Step, PaletteMode::Linear] {
                ui.selectable_value(&mut f.palette_mode, m, m.name());
            }
        })
        .response
        .labelled_by(l.id)
        .on_hover_text(
            "step: each colour coordinate takes one gradient entry; \
             linear: blends the two nearest entries",
        );
    ui.end_row();
    let rule = |i: PaletteIndex| match i {
        PaletteIndex::Flam3 => "as flam3",
        PaletteIndex::Apophysis => "as Apophysis",
        PaletteIndex::Fractorium => "as Fractorium",
        PaletteIndex::JWildfire => "as JWildfire",
    };
    let l = ui.label("Rule");
    egui::ComboBox::from_id_salt("palette-rule")
        .selected_text(rule(f.palette_index))
        .show_ui(ui, |ui| {
            for i in PaletteIndex::ALL {
                ui.selectable_value(&mut f.palette_index, i, rule(i));
            }
        })
        .response
        .labelled_by(l.id)
        .on_hover_text(
            "whose rule turns a colour coordinate into a gradient position: the program \
             that wrote the file (they differ by up to one entry)",
        );
    ui.end_row();
}

/// The colour behind the flame.
fn background_row(ui: &mut egui::Ui, f: &mut Flame) {
    ui.label("Background");
    let mut bg = [
        f.background[0] as f32,
        f.background[1] as f32,
        f.background[2] as f32,
    ];
    if named(ui.color_edit_button_rgb(&mut bg), "Background colour")
        .on_hover_text("the colour behind the flame")
        .changed()
    {
        f.background = bg.map(|v| v as f64);
    }
    ui.end_row();
}

/// Motion blur of animation frames (flam3's temporal filter, Chaotica's exposure): how many
/// sub-frames, over how many frames, weighted how.
fn motion_blur_rows(ui: &mut egui::Ui, f: &mut Flame) {
    use crate::flame::sequence::{MAX_TEMPORAL_SAMPLES, TemporalFilterType};
    let a = &mut f.anim;
    let l = ui.label("Sub-frames");
    ui.add(
        egui::DragValue::new(&mut a.temporal_samples)
            .range(1..=MAX_TEMPORAL_SAMPLES)
            .clamp_existing_to_range(false),
    )
    .labelled_by(l.id)
    .on_hover_text(
        "temporal samples: each animation frame is drawn from this many instants of its \
         exposure, sharing the frame's samples (1: no blur)",
    );
    ui.end_row();
    row(
        ui,
        "Exposure (frames)",
        "how long the shutter is open, in frames (flam3's temporal filter width): the \
         sub-frames span the frame's time ± half of it",
        &mut a.temporal_filter_width,
        0.01,
        0.0..=1000.0,
    );
    let l = ui.label("Shape");
    let r = egui::ComboBox::from_id_salt("blur-shape")
        .selected_text(a.temporal_filter_type.name())
        .show_ui(ui, |ui| {
            for t in [
                TemporalFilterType::Box,
                TemporalFilterType::Gaussian,
                TemporalFilterType::Exp,
            ] {
                ui.selectable_value(&mut a.temporal_filter_type, t, t.name());
            }
        })
        .response;
    r.labelled_by(l.id).on_hover_text(
        "how the sub-frames weigh: box (all alike), gaussian (the middle most), exp (rising \
         towards the end of the exposure for a positive exponent, the start for a negative one)",
    );
    ui.end_row();
    if a.temporal_filter_type == TemporalFilterType::Exp {
        row(
            ui,
            "Exponent",
            "the exp shape's exponent (flam3's temporal_filter_exp)",
            &mut a.temporal_filter_exp,
            0.05,
            -100.0..=100.0,
        );
    }
}
