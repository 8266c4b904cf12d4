//! The timeline under the preview: the frames of the flame's keyframe animation (or of a flam3
//! sequence), the current frame shown in the preview, the keys of one parameter, playback at
//! preview quality, and the curve of that parameter.
//!
//! While the timeline is shown, the flame's numbers in the editor are those of the current
//! frame: every animated value (not the turns, scales and palette offsets, which move the
//! flame rather than replace a value) is held at its curve's value there. With Auto-key on,
//! changing an animated value in any panel keys it at the current frame, as Chaotica and
//! JWildfire do; the key joins the edit's undo step.
//!
//! | file | what |
//! |---|---|
//! | `mod.rs` | the timeline's state, the flame at the current frame, holding and auto-key, playback |
//! | `panel.rs`, `icons.rs` | the panel: transport, parameter and key rows, the ruler, the curve |
//! | `ruler.rs` | the frame ruler: scrub, key markers, dragging keys |
//! | `keys.rs` | undoable key edits and the animatable parameters of a flame |
//! | `curve_editor.rs` | value against frame of the chosen parameter, keys and Bézier handles |
//! | `loop_tools.rs` | a rotation loop as keys; morphs and loops as flam3 sequences |
//! | `sound.rs` | a sound file's loudness as the curve of the chosen parameter |

pub mod curve_editor;
mod icons;
pub mod keys;
pub mod loop_tools;
mod panel;
pub mod ruler;
pub mod sound;

use std::collections::VecDeque;
use std::time::Instant;

use eframe::egui;

use super::document::Document;
use super::{FlameTab, Showing};
use crate::flame::Flame;
use crate::flame::interpolate::interpolate_at;
use crate::flame::keyframes::Target;
use crate::io::animation::Source;

pub use loop_tools::{LoopDialog, rotation_loop};
pub use sound::{SoundAsk, SoundDialog, SoundJob};

/// What the timeline plays.
#[derive(Clone, Debug, Default)]
pub enum Mode {
    /// The current flame's keyframes (editable).
    #[default]
    Keys,
    /// A flam3 sequence: the file's own, or a morph or loop made by the loop tools.
    Sequence(Box<Sequence>),
}

/// A flam3 sequence the timeline plays: frame t is the blend of its flames at time t.
#[derive(Clone, Debug)]
pub struct Sequence {
    /// Control points, their times increasing.
    pub cps: Vec<Flame>,
    /// What it is, for people ("morph orchid -> ember, 100 frames").
    pub label: String,
    /// The document's flames it was made from: any edit ends it.
    made_from: Vec<Flame>,
}

impl Sequence {
    /// A sequence made from the flames of `doc` (dropped when they change).
    pub fn new(cps: Vec<Flame>, label: String, doc: &Document) -> Sequence {
        Sequence {
            cps,
            label,
            made_from: doc.flames.clone(),
        }
    }

    /// Frames of the sequence: times from the first flame's up to one before the last's.
    pub fn frames(&self) -> u32 {
        let first = self.cps[0].anim.time;
        let last = self.cps[self.cps.len() - 1].anim.time;
        ((last - first).trunc().max(1.0) as u32).min(crate::flame::keyframes::MAX_FRAMES)
    }
}

/// A running playback.
#[derive(Clone, Debug)]
struct Play {
    clock: Instant,
    /// The frame at `clock`.
    from: f64,
    /// Generation of the preview frame that must be shown before the next frame is asked.
    waiting_for: u64,
    /// The flame when playback started: an edit (the flame differs) pauses it.
    flame: Flame,
}

/// What [`Timeline::sync`] saw last: the flame as held, where it was, and its frame.
#[derive(Clone, Debug)]
struct Seen {
    showing: Showing,
    current: usize,
    restores: u64,
    frame: f64,
    flame: Flame,
}

/// A key being dragged (on the ruler or in the curve editor).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KeyDrag {
    /// The key at this frame, moving in frame (ruler) or in frame and value (curve).
    Key(f64),
    /// A Bézier handle of the key at this frame: 0 the one before it, 1 the one after.
    Handle(f64, usize),
}

/// The timeline's state.
#[derive(Clone, Debug)]
pub struct Timeline {
    pub open: bool,
    /// The current frame (whole frames, from 0).
    pub frame: f64,
    pub mode: Mode,
    /// The parameter whose keys are shown.
    pub target: Option<Target>,
    /// The selected key, by its frame (a curve has at most one key per frame).
    pub selected_key: Option<f64>,
    /// Changing an animated value keys it at the current frame.
    pub auto_key: bool,
    /// Playback starts again at the first frame after the last.
    pub repeat: bool,
    /// The curve editor is shown.
    pub show_curve: bool,
    pub(super) drag: Option<KeyDrag>,
    /// The ruler is being dragged (the preview renders quick frames).
    pub scrubbing: bool,
    /// Where the ruler was drawn last frame (tests and the pointer use it).
    pub ruler: Option<ruler::Geometry>,
    /// Where the curve editor was drawn last frame.
    pub curve: Option<curve_editor::Geometry>,
    /// The loop tools' dialog, when open.
    pub loop_dialog: Option<LoopDialog>,
    /// The sound window's settings, when open.
    pub sound_dialog: Option<SoundDialog>,
    /// The sound being decoded for the sound window.
    pub sound_job: Option<std::rc::Rc<SoundJob>>,
    play: Option<Play>,
    /// When the last frames were shown during playback (frames per second).
    shown_at: VecDeque<Instant>,
    seen: Option<Seen>,
}

impl Default for Timeline {
    fn default() -> Self {
        Timeline {
            open: false,
            frame: 0.0,
            mode: Mode::Keys,
            target: None,
            selected_key: None,
            auto_key: true,
            repeat: true,
            show_curve: false,
            drag: None,
            scrubbing: false,
            ruler: None,
            curve: None,
            loop_dialog: None,
            sound_dialog: None,
            sound_job: None,
            play: None,
            shown_at: VecDeque::new(),
            seen: None,
        }
    }
}

impl Timeline {
    pub fn playing(&self) -> bool {
        self.play.is_some()
    }

    /// The timeline is shown and plays a sequence (the flame itself is not what is shown).
    pub fn plays_sequence(&self) -> bool {
        self.open && matches!(self.mode, Mode::Sequence(_))
    }

    /// Frames of what the timeline plays.
    pub fn frames(&self, f: &Flame) -> u32 {
        match &self.mode {
            Mode::Keys => f.keys.frames.max(1),
            Mode::Sequence(s) => s.frames(),
        }
    }

    /// The time of frame `frame` (a sequence's frames start at its first flame's time).
    fn time_of(&self, frame: f64) -> f64 {
        match &self.mode {
            Mode::Keys => frame,
            Mode::Sequence(s) => s.cps[0].anim.time.trunc() + frame,
        }
    }

    /// The selected key of the chosen parameter: the one clicked, or else the one at the
    /// current frame.
    pub fn selection(&self, f: &Flame) -> Option<f64> {
        let t = self.target?;
        self.selected_key
            .filter(|k| keys::index_at(f, &t, *k).is_some())
            .or_else(|| keys::index_at(f, &t, self.frame).map(|_| self.frame))
    }

    /// The flame the preview shows at the current frame, or None for the flame itself (the
    /// timeline hidden, or no keys).
    pub fn flame_at(&self, base: &Flame) -> Option<Flame> {
        if !self.open {
            return None;
        }
        match &self.mode {
            Mode::Keys if base.keys.is_empty() => None,
            Mode::Keys => Some(base.keys.apply(base, self.frame)),
            Mode::Sequence(s) => Some(interpolate_at(&s.cps, self.time_of(self.frame))),
        }
    }

    /// What the preview's frame is blurred from: the animation and the current frame's time
    /// (None when the preview shows the flame itself).
    pub fn motion_source(&self, base: &Flame) -> Option<(Source, f64)> {
        if !self.open {
            return None;
        }
        match &self.mode {
            Mode::Keys if base.keys.is_empty() => None,
            Mode::Keys => Some((Source::Keys(base.clone()), self.frame)),
            Mode::Sequence(s) => Some((Source::Sequence(s.cps.clone()), self.time_of(self.frame))),
        }
    }

    /// The frame the triangle editor shows and keys, while the timeline shows the flame's
    /// keys.
    pub fn keyed_view(&self, base: &Flame) -> Option<crate::app::flame_tab::triangles::KeyedView> {
        (self.open && matches!(self.mode, Mode::Keys) && !base.keys.is_empty()).then_some(
            crate::app::flame_tab::triangles::KeyedView {
                frame: self.frame,
                auto_key: self.auto_key,
            },
        )
    }

    /// Go to a frame (clamped to the timeline).
    pub fn go_to(&mut self, frame: f64, f: &Flame) {
        let last = self.frames(f).saturating_sub(1) as f64;
        self.frame = frame.round().clamp(0.0, last);
        if let Some(p) = &mut self.play {
            p.clock = Instant::now();
            p.from = self.frame;
        }
    }

    /// One frame on or back; past either end the timeline wraps round.
    pub fn step(&mut self, by: f64, f: &Flame) {
        let n = self.frames(f) as f64;
        self.go_to((self.frame + by).rem_euclid(n), f);
    }

    /// Start or stop playing.
    pub fn toggle_play(&mut self, f: &Flame) {
        if self.play.take().is_none() {
            let last = self.frames(f).saturating_sub(1) as f64;
            if self.frame >= last && !self.repeat {
                self.frame = 0.0;
            }
            self.play = Some(Play {
                clock: Instant::now(),
                from: self.frame,
                waiting_for: 0,
                flame: f.clone(),
            });
            self.shown_at.clear();
        }
    }

    pub fn stop(&mut self) {
        self.play = None;
    }

    /// Frames per second shown during the last second of playback.
    pub fn shown_fps(&self) -> f64 {
        match (self.shown_at.front(), self.shown_at.back()) {
            (Some(a), Some(b)) if self.shown_at.len() > 1 => {
                let dt = b.duration_since(*a).as_secs_f64();
                if dt > 0.0 {
                    (self.shown_at.len() - 1) as f64 / dt
                } else {
                    0.0
                }
            }
            _ => 0.0,
        }
    }

    /// Advance a playback: the frame the clock says, at `fps`, once the preview has shown the
    /// last frame asked (`preview`: the newest and the shown generation; None without a
    /// preview). Frames the preview cannot keep up with are skipped, as a video player does.
    fn advance(&mut self, fps: f64, frames: u32, preview: Option<(u64, u64)>) {
        let Some(p) = &mut self.play else {
            return;
        };
        if let Some((_, shown)) = preview
            && shown < p.waiting_for
        {
            return;
        }
        let n = frames.max(1) as f64;
        let mut next = (p.from + p.clock.elapsed().as_secs_f64() * fps).floor();
        if next >= n {
            if self.repeat {
                next = next.rem_euclid(n);
            } else {
                next = n - 1.0;
                self.play = None;
            }
        }
        if next != self.frame {
            self.frame = next;
            let now = Instant::now();
            self.shown_at.push_back(now);
            while self
                .shown_at
                .front()
                .is_some_and(|t| now.duration_since(*t).as_secs_f64() > 1.0)
            {
                self.shown_at.pop_front();
            }
            if let (Some(p), Some((generation, _))) = (&mut self.play, preview) {
                p.waiting_for = generation + 1;
            }
        }
    }

    /// Hold the flame's animated values at the current frame and, with Auto-key, key the ones
    /// an edit changed. Changes the flame without an undo step: holding is no edit, and an
    /// automatic key joins the undo step of the edit that made it.
    fn sync(&mut self, doc: &mut Document, showing: Showing) {
        let base = doc.flame();
        // Not while the frames run by (playing, scrubbing): the flame would change every
        // frame, and with it the thumbnails; the frame it stops at is held.
        let moving = self.playing() || self.scrubbing;
        if !self.open || !matches!(self.mode, Mode::Keys) || base.keys.is_empty() || moving {
            self.seen = None;
            return;
        }
        let (current, restores) = (doc.current, doc.restores());
        let same = self.seen.as_ref().filter(|s| {
            s.showing == showing
                && s.current == current
                && s.restores == restores
                && s.frame == self.frame
        });
        if same.is_some_and(|s| &s.flame == base) {
            return;
        }
        let mut f = base.clone();
        if self.auto_key
            && let Some(s) = same
            && s.flame.keys == base.keys
        {
            for c in base.keys.curves.iter().filter(|c| !c.target.is_offset()) {
                if c.target.get(&s.flame) != c.target.get(base) {
                    // The value exists in the flame (it was read just now).
                    let _ = f.keys.key_current(base, c.target, self.frame);
                }
            }
        }
        let keys = f.keys.clone();
        keys.hold_at(&mut f, self.frame);
        if &f != doc.flame() {
            *doc.flame_mut_in_gesture() = f.clone();
        }
        self.seen = Some(Seen {
            showing,
            current,
            restores,
            frame: self.frame,
            flame: f,
        });
    }
}

impl FlameTab {
    /// Show or hide the timeline.
    pub fn toggle_timeline(&mut self) {
        self.timeline.open = !self.timeline.open;
        if !self.timeline.open {
            self.timeline.stop();
            self.timeline.scrubbing = false;
        } else if self.timeline.target.is_none() {
            // The first animated parameter, if any.
            self.timeline.target = self.doc().flame().keys.curves.first().map(|c| c.target);
        }
    }

    /// Start or stop playing (showing the timeline if it is hidden).
    pub fn toggle_play(&mut self) {
        if !self.timeline.open {
            self.toggle_timeline();
        }
        if !self.timeline.playing() {
            // One moving picture at a time.
            self.morph = None;
            if self.animation.is_some() {
                self.toggle_animation();
            }
        }
        let f = self.doc().flame().clone();
        self.timeline.toggle_play(&f);
    }

    /// One frame on or back on the timeline.
    pub fn timeline_step(&mut self, by: f64) {
        let f = self.doc().flame().clone();
        self.timeline.step(by, &f);
    }

    /// Go to a frame of the timeline (clamped: infinity is the last frame).
    pub fn timeline_go(&mut self, frame: f64) {
        let f = self.doc().flame().clone();
        let last = self.timeline.frames(&f).saturating_sub(1) as f64;
        self.timeline.go_to(frame.min(last), &f);
    }

    /// An edit while playing pauses playback at the frame shown, as the edit is made there:
    /// with Auto-key its animated values are keyed at that frame (the flame from before the
    /// edit is what the next hold compares with).
    fn pause_on_edit(&mut self) {
        let Some(p) = &self.timeline.play else {
            return;
        };
        if &p.flame == self.doc().flame() {
            return;
        }
        let before = p.flame.clone();
        self.timeline.stop();
        let (current, restores) = (self.doc().current, self.doc().restores());
        self.timeline.seen = Some(Seen {
            showing: self.showing,
            current,
            restores,
            frame: self.timeline.frame,
            flame: before,
        });
        self.notices.status(format!(
            "Paused at frame {}: edits are made at the frame shown",
            self.timeline.frame
        ));
    }

    /// Keep the timeline in step with the document: a sequence made from flames that have
    /// changed ends, the frame stays on the timeline, animated values are held at it.
    pub(super) fn timeline_frame(&mut self, ctx: &egui::Context) {
        if let Mode::Sequence(s) = &self.timeline.mode
            && s.made_from != self.doc().flames
        {
            self.timeline.mode = Mode::Keys;
            self.timeline.stop();
            self.notices
                .status("Back to the keys: the flames of the sequence changed");
        }
        let frames = self.timeline.frames(self.doc().flame());
        if self.timeline.frame > (frames - 1) as f64 {
            self.timeline.frame = (frames - 1) as f64;
        }
        self.pause_on_edit();
        if self.timeline.playing() {
            let fps = match &self.timeline.mode {
                Mode::Keys => self.doc().flame().keys.fps,
                Mode::Sequence(_) => 25.0,
            };
            let preview = self
                .preview
                .as_ref()
                .map(|p| (p.generation, p.shown_generation));
            self.timeline
                .advance(fps.clamp(0.01, 1000.0), frames, preview);
            ctx.request_repaint();
        }
        let showing = self.showing;
        let doc = super::pick(showing, &mut self.batch, &mut self.file);
        self.timeline.sync(doc, showing);
    }
}
