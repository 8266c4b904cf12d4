//! The open document (the flames of a file or batch, the selected one, its path) and the
//! undo/redo history.

use std::path::PathBuf;

use crate::flame::Flame;

/// Undo steps kept.
pub const UNDO_LIMIT: usize = 200;

/// One undoable change: the state it replaced.
#[derive(Clone, Debug)]
enum Step {
    /// An edit of one flame.
    Flame { index: usize, before: Box<Flame> },
    /// A change of the set of flames (add, delete, new file, batch).
    Document { before: Vec<Flame>, current: usize },
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
        }
    }

    pub fn flame(&self) -> &Flame {
        &self.flames[self.current]
    }

    /// Edit the current flame as one undo step (no step if nothing changed).
    pub fn edit(&mut self, f: impl FnOnce(&mut Flame)) {
        let before = self.flames[self.current].clone();
        f(&mut self.flames[self.current]);
        if self.flames[self.current] != before {
            self.push(Step::Flame {
                index: self.current,
                before: Box::new(before),
            });
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
            self.push(Step::Flame {
                index: self.current,
                before: Box::new(before),
            });
        }
    }

    /// Change the set of flames as one undo step.
    pub fn edit_document(&mut self, f: impl FnOnce(&mut Vec<Flame>, &mut usize)) {
        let before = self.flames.clone();
        let cur = self.current;
        f(&mut self.flames, &mut self.current);
        if self.flames.is_empty() {
            self.flames = before;
            self.current = cur;
            return;
        }
        self.current = self.current.min(self.flames.len() - 1);
        self.push(Step::Document {
            before,
            current: cur,
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
        !self.undo.is_empty()
    }

    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    fn swap(&mut self, s: Step) -> Step {
        match s {
            Step::Flame { index, before } => {
                let i = index.min(self.flames.len() - 1);
                let now = std::mem::replace(&mut self.flames[i], *before);
                self.current = i;
                Step::Flame {
                    index: i,
                    before: Box::new(now),
                }
            }
            Step::Document { before, current } => {
                let now = std::mem::replace(&mut self.flames, before);
                let cur = std::mem::replace(&mut self.current, current.min(self.flames.len() - 1));
                Step::Document {
                    before: now,
                    current: cur,
                }
            }
        }
    }

    pub fn undo(&mut self) -> bool {
        let Some(s) = self.undo.pop() else {
            return false;
        };
        let r = self.swap(s);
        self.redo.push(r);
        self.dirty = true;
        true
    }

    pub fn redo(&mut self) -> bool {
        let Some(s) = self.redo.pop() else {
            return false;
        };
        let r = self.swap(s);
        self.undo.push(r);
        self.dirty = true;
        true
    }

    pub fn undo_len(&self) -> usize {
        self.undo.len()
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
