//! Moving pictures in the preview: Fraktalai's animation (every triangle turns about
//! its centroid, one undo step for the whole run) and morphs (flam3-style in-betweens from the
//! current flame to the next one of the file, played forth and back without editing).

use eframe::egui;

use super::FlameTab;
use crate::flame::Flame;
use crate::flame::animate::{RotationAnimation, interpolation_frames};

/// A running rotation animation.
pub struct Animation {
    before: Flame,
    anim: RotationAnimation,
    waiting_for: u64,
}

/// In-betweens from one flame of the file to the next, played forth and back in the preview;
/// the document is not changed.
pub struct Morph {
    /// The flame being edited when the morph started (any edit stops the morph).
    source: Flame,
    pub frames: Vec<Flame>,
    pub index: usize,
    forward: bool,
    waiting_for: u64,
    pub label: String,
}

/// Frames in one direction of a morph (about 4 s at the animation density).
pub const MORPH_FRAMES: usize = 60;

impl FlameTab {
    /// Start or stop the morph to the next flame of the file.
    pub fn toggle_morph(&mut self) {
        if self.morph.take().is_some() {
            self.notices.status("Morph stopped");
            return;
        }
        let n = self.doc().flames.len();
        if n < 2 {
            self.notices
                .status("Morphing needs a file with two or more flames");
            return;
        }
        if let Some(a) = self.animation.take() {
            self.doc_mut().end_gesture(a.before);
        }
        self.timeline.stop();
        let doc = self.doc();
        let a = doc.flame().clone();
        let b = &doc.flames[(doc.current + 1) % n];
        let name = |f: &Flame| {
            if f.name.is_empty() {
                "(unnamed)".to_string()
            } else {
                f.name.clone()
            }
        };
        let label = format!("{} -> {}", name(&a), name(b));
        self.morph = Some(Morph {
            frames: interpolation_frames(&[a.clone(), b.clone()], MORPH_FRAMES),
            source: a,
            index: 0,
            forward: true,
            waiting_for: 0,
            label: label.clone(),
        });
        self.notices.status(format!("Morphing {label}"));
    }

    fn morph_step(&mut self) {
        let shown = self
            .preview
            .as_ref()
            .map(|p| (p.generation, p.shown_generation));
        let source_changed = self
            .morph
            .as_ref()
            .is_some_and(|m| self.doc().flame() != &m.source);
        if source_changed {
            self.morph = None;
            self.notices.status("Morph stopped (the flame changed)");
            return;
        }
        let Some(m) = self.morph.as_mut() else {
            return;
        };
        if let Some((_, shown)) = shown
            && shown < m.waiting_for
        {
            return;
        }
        let last = m.frames.len() - 1;
        if m.forward && m.index == last {
            m.forward = false;
        } else if !m.forward && m.index == 0 {
            m.forward = true;
        }
        m.index = if m.forward { m.index + 1 } else { m.index - 1 }.min(last);
        if let Some((generation, _)) = shown {
            m.waiting_for = generation + 1;
        }
    }

    /// Start or stop the rotation animation (stops a morph).
    pub fn toggle_animation(&mut self) {
        self.morph = None;
        if let Some(a) = self.animation.take() {
            // Stopping keeps the coefficients; one undo step returns to the start.
            self.doc_mut().end_gesture(a.before);
            self.notices.status("Animation stopped");
        } else {
            self.timeline.stop();
            let seed = self.rng.u64();
            self.animation = Some(Animation {
                before: self.doc().begin_gesture(),
                anim: RotationAnimation::new(seed),
                waiting_for: 0,
            });
            self.notices.status("Animating");
        }
    }

    fn animate_step(&mut self) {
        let shown = self
            .preview
            .as_ref()
            .map(|p| (p.generation, p.shown_generation));
        let Some(a) = self.animation.as_mut() else {
            return;
        };
        // Wait for the preview of the previous step (so the renderer keeps up).
        if let Some((_, shown)) = shown
            && shown < a.waiting_for
        {
            return;
        }
        let doc = super::pick(self.showing, &mut self.batch, &mut self.file);
        a.anim.step(doc.flame_mut_in_gesture());
        if let Some((generation, _)) = shown {
            a.waiting_for = generation + 1;
        }
    }

    /// Advance a running animation or morph by one frame.
    pub(super) fn step_animations(&mut self, ctx: &egui::Context) {
        if self.animation.is_some() {
            self.animate_step();
            ctx.request_repaint();
        }
        if self.morph.is_some() {
            self.morph_step();
            ctx.request_repaint();
        }
    }

    /// The flame the preview shows: a morph frame, the timeline's current frame, or the
    /// current flame.
    pub fn shown_flame(&self) -> Flame {
        match &self.morph {
            Some(m) => m.frames[m.index].clone(),
            None => {
                let base = self.doc().flame();
                self.timeline.flame_at(base).unwrap_or_else(|| base.clone())
            }
        }
    }
}
