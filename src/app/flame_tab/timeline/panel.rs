//! The timeline panel: the transport row (first, back, play, on, last; the frame; the
//! timeline's length, rate, wrap and repeat; auto-key), the parameter row (the chosen
//! parameter, Key and Delete, the selected key's frame, value, interpolation and easing), the
//! ruler and the curve editor.

use eframe::egui;

use super::super::FlameTab;
use super::super::editor_state::Selected;
use super::icons::{self, Icon};
use super::{KeyDrag, Mode, curve_editor, keys, ruler};
use crate::app::a11y::named;
use crate::flame::keyframes::{Ease, Interp, Key, XformRef};

/// A key edit asked for by the panel's widgets, applied once they are drawn.
enum Edit {
    Add,
    AddValue(f64, f64),
    Delete(f64),
    Change {
        frame: f64,
        dragging: bool,
        change: Box<dyn FnOnce(&mut Key)>,
    },
}

impl FlameTab {
    /// The timeline panel (under the preview).
    pub(in super::super) fn timeline_panel(&mut self, ui: &mut egui::Ui) {
        self.transport_row(ui);
        if let Mode::Sequence(s) = &self.timeline.mode {
            let label = s.label.clone();
            ui.horizontal(|ui| {
                ui.label(format!("Sequence: {label}"));
                if ui
                    .button("Back to the keys")
                    .on_hover_text("the timeline plays this flame's keyframes again")
                    .clicked()
                {
                    self.timeline.mode = Mode::Keys;
                    self.timeline.stop();
                    self.timeline.frame = 0.0;
                }
            });
            self.sequence_ruler(ui);
            return;
        }
        let mut edits = Vec::new();
        self.parameter_row(ui, &mut edits);
        self.keys_ruler(ui, &mut edits);
        if self.timeline.show_curve {
            self.curve(ui, &mut edits);
        }
        self.apply_edits(edits);
    }

    /// First, back, play, on, last, the frame, and the timeline's settings.
    fn transport_row(&mut self, ui: &mut egui::Ui) {
        let f = self.doc().flame().clone();
        let keys_mode = matches!(self.timeline.mode, Mode::Keys);
        let mut timeline = (f.keys.frames, f.keys.fps, f.keys.wrap);
        // Groups that wrap as a whole on a narrow panel.
        ui.horizontal_wrapped(|ui| {
            let t = &mut self.timeline;
            ui.horizontal(|ui| transport(ui, t, &f));
            ui.separator();
            if keys_mode {
                timeline_settings(ui, &mut timeline, &mut t.repeat, &mut t.auto_key);
            } else {
                ui.checkbox(&mut t.repeat, "Repeat")
                    .on_hover_text("playback starts again after the last frame");
            }
            if t.playing() {
                ui.label(format!("{:.1} fps", t.shown_fps()))
                    .on_hover_text("frames per second shown during the last second");
            }
            ui.separator();
            if ui
                .button("Loop tools…")
                .on_hover_text("rotation loops, morphs and flam3-genome loops")
                .clicked()
            {
                t.loop_dialog = Some(t.loop_dialog.clone().unwrap_or_default());
            }
            if ui
                .button("Sound…")
                .on_hover_text("move the chosen parameter with the loudness of a sound file")
                .clicked()
            {
                t.sound_dialog = Some(t.sound_dialog.clone().unwrap_or_default());
            }
        });
        if keys_mode && timeline != (f.keys.frames, f.keys.fps, f.keys.wrap) {
            let doc = super::super::pick(self.showing, &mut self.batch, &mut self.file);
            keys::set_timeline(doc, timeline.0, timeline.1, timeline.2);
        }
    }

    /// The parameter chooser, Key and Delete, and the selected key's settings.
    fn parameter_row(&mut self, ui: &mut egui::Ui, edits: &mut Vec<Edit>) {
        let f = self.doc().flame().clone();
        let xform = match self.editor.selected {
            Selected::Xform(i) => XformRef::Index(i),
            Selected::Final => XformRef::Final,
        };
        let t = &mut self.timeline;
        let mut sel = None;
        ui.horizontal_wrapped(|ui| {
            let before = t.target;
            ui.horizontal(|ui| {
                let shown = t.target.as_ref().map_or("choose…".to_string(), keys::label);
                let l = ui.label("Parameter");
                egui::ComboBox::from_id_salt("timeline-parameter")
                    .selected_text(shown)
                    .width(200.0)
                    .height(420.0)
                    .show_ui(ui, |ui| {
                        for g in keys::groups(&f, xform) {
                            ui.label(egui::RichText::new(g.title).strong());
                            for target in g.targets {
                                let n = keys::curve(&f, &target).map_or(0, |c| c.keys().len());
                                let mut text = keys::label(&target);
                                if n > 0 {
                                    text.push_str(&format!("  ({n} keys)"));
                                }
                                ui.selectable_value(&mut t.target, Some(target), text);
                            }
                        }
                    })
                    .response
                    .labelled_by(l.id)
                    .on_hover_text(
                        "the parameter whose keys the ruler shows: the flame's, the selected \
                         transform's and its variations', the palette's",
                    );
            });
            if t.target != before {
                t.selected_key = None;
            }
            if t.target.is_none() {
                return;
            }
            sel = t.selection(&f);
            ui.horizontal(|ui| {
                if ui
                    .button("Key")
                    .on_hover_text("key the parameter at the current frame (K)")
                    .clicked()
                {
                    edits.push(Edit::Add);
                }
                if ui
                    .add_enabled(sel.is_some(), egui::Button::new("Delete key"))
                    .on_hover_text("delete the selected key (Delete)")
                    .clicked()
                    && let Some(k) = sel
                {
                    edits.push(Edit::Delete(k));
                }
                ui.toggle_value(&mut t.show_curve, "Curve")
                    .on_hover_text("show the parameter's curve: drag keys and Bézier handles");
            });
        });
        // The selected key on a line of its own (always there, so the panel keeps its
        // layout).
        let target = t.target;
        let key = target.zip(sel).and_then(|(tg, k)| {
            let c = keys::curve(&f, &tg)?;
            c.keys().iter().find(|q| q.frame == k).copied()
        });
        ui.horizontal_wrapped(|ui| match (key, target) {
            (Some(k), Some(tg)) => key_inspector(ui, &k, keys::unit(&tg), edits),
            _ => {
                ui.weak("No key selected: press Key (K), or click a key on the ruler");
            }
        });
    }

    /// The ruler of the keys mode: the chosen parameter's keys, the others' as ticks.
    fn keys_ruler(&mut self, ui: &mut egui::Ui, edits: &mut Vec<Edit>) {
        let f = self.doc().flame().clone();
        let t = &mut self.timeline;
        let target = t.target;
        let keys: Vec<Key> = target
            .and_then(|tg| keys::curve(&f, &tg))
            .map_or_else(Vec::new, |c| c.keys().to_vec());
        let others: Vec<f64> = f
            .keys
            .curves
            .iter()
            .filter(|c| Some(c.target) != target)
            .flat_map(|c| c.keys().iter().map(|k| k.frame))
            .collect();
        let input = ruler::Input {
            frames: t.frames(&f),
            frame: t.frame,
            keys: &keys,
            selected: t.selection(&f),
            others: &others,
            wrap: f.keys.wrap,
        };
        let mut menu_key = ui.data(|d| d.get_temp(egui::Id::unique("timeline-menu-key")));
        let (g, events, scrubbing) = ruler::show(ui, &input, &mut t.drag, &mut menu_key);
        ui.data_mut(|d| d.insert_temp(egui::Id::unique("timeline-menu-key"), menu_key));
        t.ruler = Some(g);
        t.scrubbing = scrubbing;
        for e in events {
            match e {
                ruler::Event::Scrub(fr) => t.go_to(fr, &f),
                ruler::Event::Select(k) => t.selected_key = k,
                ruler::Event::Move { from, to } => edits.push(Edit::Change {
                    frame: from,
                    dragging: true,
                    change: Box::new(move |k| k.frame = to),
                }),
                ruler::Event::DragEnd => {}
                ruler::Event::Delete(k) => edits.push(Edit::Delete(k)),
                ruler::Event::Interp(k, i) => edits.push(interp_edit(k, i)),
                ruler::Event::Ease(k, e) => edits.push(ease_edit(k, e)),
            }
        }
    }

    /// The ruler of a sequence: frames only.
    fn sequence_ruler(&mut self, ui: &mut egui::Ui) {
        let f = self.doc().flame().clone();
        let t = &mut self.timeline;
        let input = ruler::Input {
            frames: t.frames(&f),
            frame: t.frame,
            keys: &[],
            selected: None,
            others: &[],
            wrap: false,
        };
        let (g, events, scrubbing) = ruler::show(ui, &input, &mut None, &mut None);
        t.ruler = Some(g);
        t.scrubbing = scrubbing;
        for e in events {
            if let ruler::Event::Scrub(fr) = e {
                t.go_to(fr, &f);
            }
        }
    }

    /// The curve editor of the chosen parameter.
    fn curve(&mut self, ui: &mut egui::Ui, edits: &mut Vec<Edit>) {
        let f = self.doc().flame().clone();
        let t = &mut self.timeline;
        let Some(c) = t.target.and_then(|tg| keys::curve(&f, &tg)) else {
            ui.weak("No keys yet: press Key (K) to key the parameter at the current frame.");
            return;
        };
        let input = curve_editor::Input {
            curve: c,
            frames: t.frames(&f),
            frame: t.frame,
            selected: t.selection(&f),
            wrap: f.keys.wrap,
            keep: t.curve.map(|g| (g.lo, g.hi)),
        };
        let height = ui.available_height().clamp(80.0, 220.0);
        let (g, events) = curve_editor::show(ui, &input, height, &mut t.drag);
        t.curve = Some(g);
        for e in events {
            match e {
                curve_editor::Event::Select(k) => t.selected_key = k,
                curve_editor::Event::Move { from, frame, value } => edits.push(Edit::Change {
                    frame: from,
                    dragging: true,
                    change: Box::new(move |k| {
                        k.frame = frame;
                        k.value = value;
                    }),
                }),
                curve_editor::Event::Handles { frame, handles } => edits.push(Edit::Change {
                    frame,
                    dragging: true,
                    change: Box::new(move |k| k.handles = Some(handles)),
                }),
                curve_editor::Event::DragEnd => {}
                curve_editor::Event::Add { frame, value } => {
                    edits.push(Edit::AddValue(frame, value));
                    t.selected_key = Some(frame);
                }
                curve_editor::Event::Scrub(fr) => t.go_to(fr, &f),
            }
        }
    }

    /// Carry out the panel's key edits on the document, each an undo step (a drag: one for
    /// the whole drag).
    fn apply_edits(&mut self, edits: Vec<Edit>) {
        let Some(target) = self.timeline.target else {
            return;
        };
        let frame = self.timeline.frame;
        let doc = super::super::pick(self.showing, &mut self.batch, &mut self.file);
        for e in edits {
            let r = match e {
                Edit::Add => keys::add(doc, target, frame).map(|()| {
                    self.timeline.selected_key = Some(frame);
                }),
                Edit::AddValue(fr, v) => keys::add_value(doc, target, fr, v),
                Edit::Delete(k) => {
                    keys::delete(doc, target, k);
                    if self.timeline.selected_key == Some(k) {
                        self.timeline.selected_key = None;
                    }
                    Ok(())
                }
                Edit::Change {
                    frame: k,
                    dragging,
                    change,
                } => keys::change(doc, target, k, dragging, change).map(|now| {
                    if self.timeline.selected_key == Some(k) {
                        self.timeline.selected_key = Some(now);
                    }
                    match &mut self.timeline.drag {
                        Some(KeyDrag::Key(d) | KeyDrag::Handle(d, _)) if *d == k => *d = now,
                        _ => {}
                    }
                }),
            };
            if let Err(e) = r {
                self.notices.status(e);
            }
        }
    }

    /// Key the chosen parameter at the current frame (K).
    pub fn key_here(&mut self) {
        let Some(target) = self.timeline.target else {
            self.notices
                .status("Choose a parameter on the timeline first");
            return;
        };
        self.apply_edits(vec![Edit::Add]);
        if keys::index_at(self.doc().flame(), &target, self.timeline.frame).is_some() {
            self.notices.status(format!(
                "Key: {} at frame {}",
                keys::label(&target),
                self.timeline.frame
            ));
        }
    }

    /// Delete the selected key, or the one at the current frame (Delete).
    pub fn delete_key_here(&mut self) {
        if let Some(k) = self.timeline.selection(self.doc().flame()) {
            self.apply_edits(vec![Edit::Delete(k)]);
        }
    }
}

/// First, back, play or pause, on, last, and the current frame.
fn transport(ui: &mut egui::Ui, t: &mut super::Timeline, f: &crate::flame::Flame) {
    let frames = t.frames(f);
    let (play, play_name) = if t.playing() {
        (Icon::Pause, "Pause")
    } else {
        (Icon::Play, "Play")
    };
    let buttons = [
        (Icon::First, "First frame", "first frame (Home)"),
        (Icon::Previous, "Previous frame", "one frame back (Left)"),
        (play, play_name, "play or pause at preview quality (Space)"),
        (Icon::Next, "Next frame", "one frame on (Right)"),
        (Icon::Last, "Last frame", "last frame (End)"),
    ];
    for (icon, name, tip) in buttons {
        if icons::button(ui, icon, name).on_hover_text(tip).clicked() {
            match icon {
                Icon::First => t.go_to(0.0, f),
                Icon::Previous => t.step(-1.0, f),
                Icon::Play | Icon::Pause => t.toggle_play(f),
                Icon::Next => t.step(1.0, f),
                Icon::Last => t.go_to(frames as f64, f),
            }
        }
    }
    let mut frame = t.frame;
    let r = named(
        ui.add(
            egui::DragValue::new(&mut frame)
                .range(0.0..=(frames - 1) as f64)
                .speed(0.25)
                .max_decimals(0),
        ),
        "Frame",
    )
    .on_hover_text("the current frame");
    if r.changed() {
        t.go_to(frame, f);
    }
    ui.label(format!("of {frames}"));
}

/// The timeline's length, rate, wrap, and the playback's repeat and auto-key.
fn timeline_settings(
    ui: &mut egui::Ui,
    (frames, fps, wrap): &mut (u32, f64, bool),
    repeat: &mut bool,
    auto_key: &mut bool,
) {
    ui.horizontal(|ui| {
        let l = ui.label("Frames");
        ui.add(egui::DragValue::new(frames).range(1..=keys::MAX_TIMELINE_FRAMES))
            .labelled_by(l.id)
            .on_hover_text("frames of the animation");
        let l = ui.label("fps");
        ui.add(
            egui::DragValue::new(fps)
                .range(crate::io::video::MIN_FPS..=crate::io::video::MAX_FPS)
                .speed(0.5)
                .max_decimals(2),
        )
        .labelled_by(l.id)
        .on_hover_text("frames per second of playback and of the video");
    });
    ui.horizontal(|ui| {
        ui.checkbox(wrap, "Seamless").on_hover_text(
            "the frame after the last equals the first: curves run on into their first key",
        );
        ui.checkbox(repeat, "Repeat")
            .on_hover_text("playback starts again after the last frame");
        ui.checkbox(auto_key, "Auto-key")
            .on_hover_text("changing an animated value in the editor keys it at the current frame");
    });
}

fn interp_edit(frame: f64, i: Interp) -> Edit {
    Edit::Change {
        frame,
        dragging: false,
        change: Box::new(move |k| k.interp = i),
    }
}

fn ease_edit(frame: f64, e: Ease) -> Edit {
    Edit::Change {
        frame,
        dragging: false,
        change: Box::new(move |k| k.ease = e),
    }
}

/// The selected key's frame, value, interpolation and easing.
fn key_inspector(ui: &mut egui::Ui, k: &Key, unit: &str, edits: &mut Vec<Edit>) {
    let held = ui.input(|i| i.pointer.any_down());
    let (mut frame, mut value) = (k.frame, k.value);
    ui.label("Key");
    if named(
        ui.add(
            egui::DragValue::new(&mut frame)
                .speed(0.25)
                .max_decimals(0)
                .prefix("frame "),
        ),
        "Key frame",
    )
    .on_hover_text("the key's frame")
    .changed()
    {
        let to = frame.round();
        edits.push(Edit::Change {
            frame: k.frame,
            dragging: held,
            change: Box::new(move |k| k.frame = to),
        });
    }
    if named(
        ui.add(
            egui::DragValue::new(&mut value)
                .speed(0.01)
                .max_decimals(6)
                .prefix("value ")
                .suffix(unit),
        ),
        "Key value",
    )
    .on_hover_text("the key's value")
    .changed()
    {
        edits.push(Edit::Change {
            frame: k.frame,
            dragging: held,
            change: Box::new(move |k| k.value = value),
        });
    }
    let r = egui::ComboBox::from_id_salt("key-interp")
        .selected_text(k.interp.name())
        .show_ui(ui, |ui| {
            for i in Interp::ALL {
                if ui.selectable_label(k.interp == i, i.name()).clicked() {
                    edits.push(interp_edit(k.frame, i));
                }
            }
        })
        .response;
    named(r, "Interpolation").on_hover_text(
        "how the curve runs to the next key: linear, smooth (Catmull-Rom), Bézier (drag its \
         handles in the curve editor) or step",
    );
    let r = egui::ComboBox::from_id_salt("key-ease")
        .selected_text(k.ease.name())
        .show_ui(ui, |ui| {
            for e in Ease::ALL {
                if ui.selectable_label(k.ease == e, e.name()).clicked() {
                    edits.push(ease_edit(k.frame, e));
                }
            }
        })
        .response;
    named(r, "Easing")
        .on_hover_text("how the time to the next key is spent: slow start, end, both");
}
