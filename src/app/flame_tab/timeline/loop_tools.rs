//! Loop tools: a rotation loop made as keys (every transform turns N × 360° over M frames, a
//! seamless loop to edit further), and flam3-genome's morphs and loops (`sequence=`) played
//! on the timeline as flam3 sequences and exported as such.

use eframe::egui;

use super::super::FlameTab;
use super::{Mode, Sequence};
use crate::flame::Flame;
use crate::flame::interpolate::check_times;
use crate::flame::keyframes::{Interp, Key, Keyframes, MAX_FRAMES, Target, XformParam, XformRef};
use crate::flame::loops::sequence;

/// The loop tools' settings.
#[derive(Clone, Debug, PartialEq)]
pub struct LoopDialog {
    /// Frames of a loop, and of a morph.
    pub frames: u32,
    /// Whole turns of every transform per loop (and during a morph).
    pub turns: f64,
    /// Turns during a morph (flam3-genome turns once; 0 blends only).
    pub morph_turns: f64,
}

impl Default for LoopDialog {
    fn default() -> Self {
        LoopDialog {
            frames: 100,
            turns: 1.0,
            morph_turns: 0.0,
        }
    }
}

/// Most frames a loop tool makes per loop or morph.
pub const MAX_LOOP_FRAMES: u32 = 100_000;

/// The keys of a rotation loop of `f`: every transform that takes part in animations
/// (`animate` ≠ 0, not the final one) turns `turns` × 360° about the origin over `frames`
/// frames, linearly; the timeline is `frames` long and wraps, so the loop is seamless for
/// whole turns. Other curves stay; earlier turn curves of the transforms are replaced. This
/// is flam3-genome's loop (`sheep_loop`) without the `<motion>` elements.
pub fn rotation_loop(f: &Flame, turns: f64, frames: u32) -> Keyframes {
    let mut k = f.keys.clone();
    k.frames = frames.clamp(1, MAX_FRAMES);
    let end = k.frames as f64;
    k.wrap = true;
    k.curves.retain(|c| {
        !matches!(
            c.target,
            Target::Xform(XformRef::Index(_), XformParam::Rotate)
        )
    });
    for (i, x) in f.xforms.iter().enumerate() {
        if x.animate == 0.0 {
            continue;
        }
        let c = k.curve_mut(Target::Xform(XformRef::Index(i), XformParam::Rotate));
        for (frame, v) in [(0.0, 0.0), (end, 360.0 * turns)] {
            let key = Key {
                interp: Interp::Linear,
                ..Key::new(frame, v)
            };
            // Both keys are finite and two is far below the limit.
            let _ = c.insert(key);
        }
    }
    k
}

/// What the loop tools' window asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Ask {
    RotationLoop,
    Morph,
    FileLoop,
    FileSequence,
}

impl FlameTab {
    /// Make the current flame a rotation loop (one undo step) and show it on the timeline.
    pub fn make_rotation_loop(&mut self, turns: f64, frames: u32) {
        if !turns.is_finite() || turns == 0.0 {
            self.notices
                .status("A rotation loop needs a number of turns other than 0");
            return;
        }
        let f = self.doc().flame();
        if f.xforms.iter().all(|x| x.animate == 0.0) {
            self.notices
                .status("No transform takes part in animations (all have animate 0)");
            return;
        }
        let motion = f.xforms.iter().any(|x| !x.motion.is_empty());
        let keys = rotation_loop(f, turns, frames);
        self.doc_mut().edit(|f| f.keys = keys);
        let t = &mut self.timeline;
        t.mode = Mode::Keys;
        t.open = true;
        t.frame = 0.0;
        t.target = Some(Target::Xform(XformRef::Index(0), XformParam::Rotate));
        t.selected_key = None;
        let mut note = format!("Rotation loop: {turns} turn(s) over {frames} frames, seamless");
        if motion {
            note.push_str(
                " (the transforms' <motion> elements are not keyed: Loop through the file plays them)",
            );
        }
        self.notices.status(note);
    }

    /// Play a flam3 sequence on the timeline.
    fn play_sequence(&mut self, cps: Vec<Flame>, label: String) {
        if let Err(i) = check_times(&cps) {
            self.notices.message(
                "Not a sequence",
                format!(
                    "flame {} ('{}') has time {}: the times of a sequence must increase",
                    i + 1,
                    cps[i].name,
                    cps[i].anim.time
                ),
            );
            return;
        }
        let s = Sequence::new(cps, label.clone(), self.doc());
        let t = &mut self.timeline;
        t.mode = Mode::Sequence(Box::new(s));
        t.open = true;
        t.frame = 0.0;
        t.stop();
        self.notices.status(format!("Timeline: {label}"));
    }

    /// The file's flames as flam3-genome's `sequence=` makes them: `loops` (each flame turns
    /// in `frames` frames) and transitions of `frames` frames to the next one.
    pub fn play_file_loop(&mut self, frames: u32, turns: f64, loops: bool) {
        let flames = self.doc().flames.clone();
        if flames.len() < 2 && !loops {
            self.notices
                .status("A morph needs a file with two or more flames");
            return;
        }
        let frames = frames.clamp(1, MAX_LOOP_FRAMES);
        if flames.len() as u64 * 2 * frames as u64 > MAX_FRAMES as u64 {
            self.notices.status(format!(
                "The sequence would have more than {MAX_FRAMES} frames"
            ));
            return;
        }
        let cps = sequence(&flames, frames as usize, loops, turns);
        let label = format!(
            "{} through the {} flames, {frames} frames each",
            if loops { "loops and morphs" } else { "morphs" },
            flames.len()
        );
        self.play_sequence(cps, label);
    }

    /// A morph from the current flame to the next one of the file over `frames` frames
    /// (flam3-genome's transition, turning `turns` times on the way).
    pub fn play_morph(&mut self, frames: u32, turns: f64) {
        let doc = self.doc();
        let n = doc.flames.len();
        if n < 2 {
            self.notices
                .status("Morphing needs a file with two or more flames");
            return;
        }
        let (a, b) = (
            doc.flame().clone(),
            doc.flames[(doc.current + 1) % n].clone(),
        );
        let frames = frames.clamp(1, MAX_LOOP_FRAMES);
        let cps = sequence(&[a.clone(), b.clone()], frames as usize, false, turns);
        let name = |f: &Flame| {
            if f.name.is_empty() {
                "(unnamed)".to_string()
            } else {
                f.name.clone()
            }
        };
        let label = format!("morph {} -> {}, {frames} frames", name(&a), name(&b));
        self.play_sequence(cps, label);
    }

    /// The file's flames as the flam3 sequence their times make.
    pub fn play_file_sequence(&mut self) {
        let flames = self.doc().flames.clone();
        if flames.len() < 2 || flames.iter().all(|f| f.anim.time == 0.0) {
            self.notices
                .status("The file is no sequence: its flames carry no times");
            return;
        }
        let label = format!("the file's sequence of {} flames", flames.len());
        self.play_sequence(flames, label);
    }

    /// The loop tools' window.
    pub(crate) fn loop_window(&mut self, ctx: &egui::Context) {
        let sequence_file = self.file_is_sequence();
        let Some(d) = &mut self.timeline.loop_dialog else {
            return;
        };
        let mut open = true;
        let mut ask = None;
        egui::Window::new("Loop tools")
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .pivot(egui::Align2::CENTER_CENTER)
            .default_pos(ctx.content_rect().center())
            .show(ctx, |ui| ask = loop_dialog(ui, d, sequence_file));
        let d = d.clone();
        if !open {
            self.timeline.loop_dialog = None;
        }
        match ask {
            Some(Ask::RotationLoop) => self.make_rotation_loop(d.turns, d.frames),
            Some(Ask::Morph) => self.play_morph(d.frames, d.morph_turns),
            Some(Ask::FileLoop) => self.play_file_loop(d.frames, d.turns, true),
            Some(Ask::FileSequence) => self.play_file_sequence(),
            None => {}
        }
    }

    /// The document's flames carry times (a flam3 sequence).
    pub fn file_is_sequence(&self) -> bool {
        let f = &self.doc().flames;
        f.len() > 1 && f.iter().any(|f| f.anim.time != 0.0)
    }
}

/// The window's contents.
fn loop_dialog(ui: &mut egui::Ui, d: &mut LoopDialog, sequence_file: bool) -> Option<Ask> {
    let mut ask = None;
    egui::Grid::new("loop-grid").num_columns(2).show(ui, |ui| {
        let l = ui.label("Frames");
        ui.add(egui::DragValue::new(&mut d.frames).range(1..=MAX_LOOP_FRAMES))
            .labelled_by(l.id)
            .on_hover_text("frames of one loop, and of one morph");
        ui.end_row();
        let l = ui.label("Turns per loop");
        ui.add(
            egui::DragValue::new(&mut d.turns)
                .range(-100.0..=100.0)
                .speed(0.1),
        )
        .labelled_by(l.id)
        .on_hover_text("whole turns make a seamless loop");
        ui.end_row();
        let l = ui.label("Turns per morph");
        ui.add(
            egui::DragValue::new(&mut d.morph_turns)
                .range(-100.0..=100.0)
                .speed(0.1),
        )
        .labelled_by(l.id)
        .on_hover_text("0: the flames blend without turning; flam3-genome's sequences turn once");
        ui.end_row();
    });
    ui.separator();
    if ui
        .button("Make rotation loop")
        .on_hover_text(
            "keys on this flame: every transform turns about the origin over the frames, \
             and the timeline wraps (seamless); edit the keys further as you like",
        )
        .clicked()
    {
        ask = Some(Ask::RotationLoop);
    }
    if ui
        .button("Play morph to the next flame")
        .on_hover_text("flam3-genome's transition from this flame to the next of the file")
        .clicked()
    {
        ask = Some(Ask::Morph);
    }
    if ui
        .button("Play loops through the file")
        .on_hover_text(
            "flam3-genome's sequence: each flame of the file loops, then morphs into the next",
        )
        .clicked()
    {
        ask = Some(Ask::FileLoop);
    }
    if ui
        .add_enabled(sequence_file, egui::Button::new("Play the file's sequence"))
        .on_hover_text("the file's flames carry times: frame t is their blend at time t")
        .on_disabled_hover_text("the file's flames carry no times")
        .clicked()
    {
        ask = Some(Ask::FileSequence);
    }
    ask
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::loops::loop_frame;
    use crate::flame::{Affine, Xform};

    /// The keys turn the maps exactly as flam3-genome's loop does, and the loop is seamless.
    #[test]
    fn a_rotation_loop_as_keys_is_flam3_genomes_loop() {
        let mut f = Flame {
            xforms: vec![
                Xform::linear(Affine::new(0.5, 0.2, -0.1, 0.6, 0.3, -0.2), 1.0, 0.0),
                Xform::linear(Affine::new(0.4, -0.3, 0.2, 0.5, -0.4, 0.1), 1.0, 1.0),
                Xform::linear(Affine::new(-0.5, 0.0, 0.0, 0.5, 0.0, 0.0), 1.0, 0.5),
            ],
            ..Flame::default()
        };
        f.xforms[2].animate = 0.0;
        let (turns, frames) = (2.0, 24);
        f.keys = rotation_loop(&f, turns, frames);
        assert!(f.keys.wrap && f.keys.frames == 24);
        assert_eq!(f.keys.curves.len(), 2, "symmetry transforms stay");
        for k in [0, 1, 7, 12, 23] {
            let ours = f.keys.apply(&f, k as f64);
            let flam3 = loop_frame(&f, k as f64 / frames as f64, turns);
            for (a, b) in ours.xforms.iter().zip(&flam3.xforms) {
                let (p, q) = (a.coefs, b.coefs);
                for (x, y) in [(p.a, q.a), (p.b, q.b), (p.c, q.c), (p.d, q.d), (p.e, q.e)] {
                    assert!((x - y).abs() < 1e-12, "frame {k}: {p:?} vs {q:?}");
                }
            }
        }
        // The frame after the last is the first.
        let (a, b) = (f.keys.apply(&f, 24.0), f.keys.apply(&f, 0.0));
        for (x, y) in a.xforms.iter().zip(&b.xforms) {
            assert!((x.coefs.a - y.coefs.a).abs() < 1e-12);
            assert!((x.coefs.c - y.coefs.c).abs() < 1e-12);
        }
    }
}
