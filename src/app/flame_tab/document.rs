//! The open document (the flames of a file or batch, the selected one, its path) and the
//! undo/redo history.

use std::path::PathBuf;

use crate::flame::Flame;

/// Undo steps kept.
pub const UNDO_LIMIT: usize = 200;

/// One undoable change: the state it replaced, and what it was (for the History window).
#[derive(Clone, Debug)]
enum Step {
    /// An edit of one flame.
    Flame {
        index: usize,
        before: Box<Flame>,
        label: String,
    },
    /// A change of the set of flames (add, delete, new file, batch).
    Document {
        before: Vec<Flame>,
        current: usize,
        label: String,
    },
}

impl Step {
    fn label(&self) -> &str {
        match self {
            Step::Flame { label, .. } | Step::Document { label, .. } => label,
        }
    }
}

/// The flames being edited.
#[derive(Clone, Debug)]
pub struct Document {
    pub flames: Vec<Flame>,
    pub current: usize,
    pub path: Option<PathBuf>,
    /// Name of the `<flames>` root when saved.
    pub name: String,
    pub dirty: bool,
    undo: Vec<Step>,
    redo: Vec<Step>,
    /// A change in progress while a control is dragged: which flame, and how it was before.
    live: Option<(usize, Flame)>,
    /// Undos and redos so far: a flame that changed by one was restored, not edited.
    restores: u64,
}

impl Document {
    pub fn new(flames: Vec<Flame>, path: Option<PathBuf>) -> Document {
        assert!(!flames.is_empty(), "a document holds at least one flame");
        let name = path
            .as_ref()
            .and_then(|p| p.file_stem())
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "untitled".into());
        Document {
            flames,
            current: 0,
            path,
            name,
            dirty: false,
            undo: Vec::new(),
            redo: Vec::new(),
            live: None,
            restores: 0,
        }
    }

    pub fn flame(&self) -> &Flame {
        &self.flames[self.current]
    }

    /// Edit the current flame as one undo step (no step if nothing changed).
    pub fn edit(&mut self, f: impl FnOnce(&mut Flame)) {
        self.commit_live();
        let before = self.flames[self.current].clone();
        f(&mut self.flames[self.current]);
        if self.flames[self.current] != before {
            self.push_flame(self.current, before);
        }
    }

    /// An edit of flame `index` that replaced `before`, labelled by what changed.
    fn push_flame(&mut self, index: usize, before: Flame) {
        let label = super::history::describe(&before, &self.flames[index]);
        self.push(Step::Flame {
            index,
            before: Box::new(before),
            label,
        });
    }

    /// Edit the current flame from a control; while `dragging` (a pointer is held on a slider
    /// or number) every change is part of one undo step, made when the drag ends
    /// ([`Document::commit_live`], or the first edit without `dragging`).
    pub fn edit_while(&mut self, dragging: bool, f: impl FnOnce(&mut Flame)) {
        if !dragging && self.live.is_none() {
            self.edit(f);
            return;
        }
        if self.live.as_ref().is_some_and(|(i, _)| *i != self.current) {
            self.commit_live();
        }
        if self.live.is_none() {
            self.live = Some((self.current, self.flames[self.current].clone()));
        }
        f(&mut self.flames[self.current]);
        if !dragging {
            self.commit_live();
        }
    }

    /// End a drag of a control: its changes become one undo step.
    pub fn commit_live(&mut self) {
        if let Some((i, before)) = self.live.take()
            && i < self.flames.len()
            && self.flames[i] != before
        {
            self.push_flame(i, before);
        }
    }

    /// Begin a continuous edit (a drag): returns the state to push when it ends.
    pub fn begin_gesture(&self) -> Flame {
        self.flames[self.current].clone()
    }

    /// Mutable access during a gesture (no undo step; call [`Document::end_gesture`]).
    pub fn flame_mut_in_gesture(&mut self) -> &mut Flame {
        &mut self.flames[self.current]
    }

    /// End a continuous edit: one undo step for the whole gesture.
    pub fn end_gesture(&mut self, before: Flame) {
        if self.flames[self.current] != before {
            self.push_flame(self.current, before);
        }
    }

    /// Change the set of flames as one undo step.
    pub fn edit_document(&mut self, f: impl FnOnce(&mut Vec<Flame>, &mut usize)) {
        self.commit_live();
        let before = self.flames.clone();
        let cur = self.current;
        f(&mut self.flames, &mut self.current);
        if self.flames.is_empty() {
            self.flames = before;
            self.current = cur;
            return;
        }
        self.current = self.current.min(self.flames.len() - 1);
        let label = super::history::describe_document(&before, &self.flames);
        self.push(Step::Document {
            before,
            current: cur,
            label,
        });
    }

    fn push(&mut self, s: Step) {
        self.undo.push(s);
        if self.undo.len() > UNDO_LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
        self.dirty = true;
    }

    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty() || self.live.is_some()
    }

    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    fn swap(&mut self, s: Step) -> Step {
        match s {
            Step::Flame {
                index,
                before,
                label,
            } => {
                let i = index.min(self.flames.len() - 1);
                let now = std::mem::replace(&mut self.flames[i], *before);
                self.current = i;
                Step::Flame {
                    index: i,
                    before: Box::new(now),
                    label,
                }
            }
            Step::Document {
                before,
                current,
                label,
            } => {
                let now = std::mem::replace(&mut self.flames, before);
                let cur = std::mem::replace(&mut self.current, current.min(self.flames.len() - 1));
                Step::Document {
                    before: now,
                    current: cur,
                    label,
                }
            }
        }
    }

    pub fn undo(&mut self) -> bool {
        self.commit_live();
        let Some(s) = self.undo.pop() else {
            return false;
        };
        let r = self.swap(s);
        self.redo.push(r);
        self.restores += 1;
        self.dirty = true;
        true
    }

    pub fn redo(&mut self) -> bool {
        self.commit_live();
        let Some(s) = self.redo.pop() else {
            return false;
        };
        let r = self.swap(s);
        self.undo.push(r);
        self.restores += 1;
        self.dirty = true;
        true
    }

    pub fn undo_len(&self) -> usize {
        self.undo.len()
    }

    /// What the steps were: those that can be undone, oldest first, and those that can be
    /// redone, next first.
    pub fn history(&self) -> (Vec<&str>, Vec<&str>) {
        (
            self.undo.iter().map(Step::label).collect(),
            self.redo.iter().rev().map(Step::label).collect(),
        )
    }

    /// Undo or redo until `position` steps of the history are applied (0: the oldest state
    /// kept); false when nothing changed.
    pub fn go_to(&mut self, position: usize) -> bool {
        self.commit_live();
        let mut moved = false;
        while self.undo.len() > position && self.undo() {
            moved = true;
        }
        while self.undo.len() < position && self.redo() {
            moved = true;
        }
        moved
    }

    /// How many undos and redos were made: a change of the flame that comes with a change of
    /// this count is a restored state, not an edit.
    pub fn restores(&self) -> u64 {
        self.restores
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::{Affine, Xform};

    fn doc() -> Document {
        let f = Flame {
            name: "a".into(),
            xforms: vec![Xform::default(), Xform::default()],
            ..Flame::default()
        };
        Document::new(
            vec![
                f.clone(),
                Flame {
                    name: "b".into(),
                    ..f
                },
            ],
            None,
        )
    }

    #[test]
    fn undo_redo_restores_exact_states() {
        let mut d = doc();
        let orig = d.flame().clone();
        d.edit(|f| f.xforms[0].coefs = Affine::new(0.3, 0.1, 0.2, 0.9, 0.5, -0.5));
        let edited = d.flame().clone();
        assert!(d.dirty);
        assert!(d.undo());
        assert_eq!(d.flame(), &orig);
        assert!(d.redo());
        assert_eq!(d.flame(), &edited);
        assert!(!d.redo());
        // No-op edits leave no step.
        let n = d.undo_len();
        d.edit(|_| {});
        assert_eq!(d.undo_len(), n);
    }

    #[test]
    fn a_dragged_control_is_one_step() {
        let mut d = doc();
        let orig = d.flame().clone();
        for k in 1..=8 {
            d.edit_while(true, |f| f.xforms[0].color = k as f64 / 10.0);
        }
        assert_eq!(d.undo_len(), 0, "nothing is pushed during the drag");
        // The release frame's change joins the drag.
        d.edit_while(false, |f| f.xforms[0].color = 0.9);
        assert_eq!(d.undo_len(), 1);
        assert_eq!(d.flame().xforms[0].color, 0.9);
        d.undo();
        assert_eq!(d.flame(), &orig);
        // A drag that ends without another change is committed explicitly.
        d.edit_while(true, |f| f.xforms[1].color = 0.3);
        d.commit_live();
        assert_eq!(d.undo_len(), 1);
        // Plain edits stay one step each.
        d.edit_while(false, |f| f.zoom = 1.0);
        d.edit_while(false, |f| f.zoom = 2.0);
        assert_eq!(d.undo_len(), 3);
    }

    #[test]
    fn gestures_are_one_step_and_documents_undo() {
        let mut d = doc();
        let g = d.begin_gesture();
        for i in 0..50 {
            d.flame_mut_in_gesture().xforms[0].coefs.e = i as f64;
        }
        d.end_gesture(g.clone());
        assert_eq!(d.undo_len(), 1);
        d.undo();
        assert_eq!(d.flame(), &g);
        d.edit_document(|fl, cur| {
            fl.remove(0);
            *cur = 0;
        });
        assert_eq!(d.flames.len(), 1);
        assert_eq!(d.flame().name, "b");
        d.undo();
        assert_eq!(d.flames.len(), 2);
        // The steps say what they were, and the history can be walked.
        assert_eq!(d.history(), (vec![], vec!["Delete flame"]));
        assert!(d.go_to(1));
        assert_eq!(d.flames.len(), 1);
        d.edit(|f| f.gamma = 3.0);
        assert_eq!(d.history(), (vec!["Delete flame", "Tone"], vec![]));
        assert!(d.go_to(0));
        assert_eq!(d.flames.len(), 2);
        assert_eq!(d.history(), (vec![], vec!["Delete flame", "Tone"]));
        assert!(!d.go_to(0));
        assert!(d.go_to(2));
        assert_eq!(d.flame().gamma, 3.0);
        d.go_to(0);
        // At least 100 steps are kept.
        for i in 0..150 {
            d.edit(|f| f.zoom = i as f64 + 1.0);
        }
        let mut n = 0;
        while d.undo() {
            n += 1;
        }
        assert!(n >= 100);
    }
}
