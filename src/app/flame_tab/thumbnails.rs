//! Small pictures of flames (the file contents, the random batch, the mutation grid), rendered
//! one after the other in the background. Each list slot remembers the flame it shows; a
//! picture is rendered again only when that flame changes.

use std::collections::HashMap;

use eframe::egui;

use super::preview::to_color_image;
use crate::app::worker::{JobContext, Worker};
use crate::flame::Flame;
use crate::flame::render::{RenderOptions, render};

/// A slot: which list (the shell's numbering) and the index in it.
pub type Slot = (u8, usize);

type ThumbWorker = Worker<Vec<(u64, Flame)>, (u64, Result<egui::ColorImage, String>)>;

/// Thumbnails of one size, with their background renderer.
pub struct Thumbnails {
    worker: Option<ThumbWorker>,
    /// What each slot shows: its flame and the key of its picture.
    slots: HashMap<Slot, (Flame, u64)>,
    textures: HashMap<u64, egui::TextureHandle>,
    /// Pictures asked for this frame that are not ready.
    wanted: Vec<(u64, Flame)>,
    /// Keys of the last list handed to the worker.
    queued: Vec<u64>,
    next_key: u64,
}

impl Thumbnails {
    /// `ctx`: the context whose repaint the worker requests; none (tests): no pictures.
    pub fn new(ctx: Option<&egui::Context>, width: u32, height: u32, quality: f64) -> Thumbnails {
        let worker = ctx.map(|c| {
            let c = c.clone();
            ThumbWorker::new(
                "ugnis-thumbnails",
                move || c.request_repaint(),
                move |list: Vec<(u64, Flame)>, cx: &JobContext<_>| {
                    for (key, mut f) in list {
                        // Stop between pictures when a newer list waits.
                        if cx.is_stale() {
                            return;
                        }
                        f.resize_keep_framing(width, height);
                        f.quality = quality;
                        let o = RenderOptions {
                            seed: 1,
                            threads: 1,
                            ..RenderOptions::default()
                        };
                        let r = render(&f, &o)
                            .map(|img| to_color_image(&img))
                            .map_err(|e| e.to_string());
                        cx.send((key, r));
                    }
                },
            )
        });
        Thumbnails {
            worker,
            slots: HashMap::new(),
            textures: HashMap::new(),
            wanted: Vec::new(),
            queued: Vec::new(),
            next_key: 1,
        }
    }

    /// The picture of `flame` in `slot`, when ready; otherwise it is asked for.
    pub fn get(&mut self, slot: Slot, flame: &Flame) -> Option<egui::TextureId> {
        self.worker.as_ref()?;
        let key = match self.slots.get(&slot) {
            Some((f, k)) if f == flame => *k,
            old => {
                if let Some((_, k)) = old {
                    self.textures.remove(k);
                }
                let k = self.next_key;
                self.next_key += 1;
                self.slots.insert(slot, (flame.clone(), k));
                k
            }
        };
        match self.textures.get(&key) {
            Some(t) => Some(t.id()),
            None => {
                if !self.wanted.iter().any(|(k, _)| *k == key) {
                    self.wanted.push((key, flame.clone()));
                }
                None
            }
        }
    }

    /// Forget every slot of list `list` from index `from` on (the list got shorter).
    pub fn truncate(&mut self, list: u8, from: usize) {
        let gone: Vec<Slot> = self
            .slots
            .keys()
            .filter(|(l, i)| *l == list && *i >= from)
            .copied()
            .collect();
        for s in gone {
            if let Some((_, k)) = self.slots.remove(&s) {
                self.textures.remove(&k);
            }
        }
    }

    /// Take the finished pictures and hand the missing ones of this frame to the worker.
    pub fn end_frame(&mut self, ctx: &egui::Context) {
        let Some(w) = &self.worker else {
            return;
        };
        for (key, r) in w.poll() {
            if let Ok(img) = r {
                let t = ctx.load_texture(format!("thumb-{key}"), img, egui::TextureOptions::LINEAR);
                self.textures.insert(key, t);
            }
        }
        let wanted = std::mem::take(&mut self.wanted);
        // Only a picture that is not already on its way makes a new list: finished ones
        // leave the list without restarting it.
        let fresh = wanted
            .iter()
            .any(|(k, _)| !self.queued.contains(k) && !self.textures.contains_key(k));
        if fresh {
            let list: Vec<(u64, Flame)> = wanted
                .into_iter()
                .filter(|(k, _)| !self.textures.contains_key(k))
                .collect();
            self.queued = list.iter().map(|(k, _)| *k).collect();
            w.queue(list);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    fn flame() -> Flame {
        crate::io::read_flames(
            std::path::Path::new(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/examples/orchid.flame"
            )),
            &Default::default(),
        )
        .unwrap()
        .value
        .remove(0)
    }

    #[test]
    fn pictures_arrive_and_are_rendered_again_only_when_the_flame_changes() {
        let ctx = egui::Context::default();
        let mut t = Thumbnails::new(Some(&ctx), 32, 24, 5.0);
        let f = flame();
        assert!(t.get((0, 0), &f).is_none());
        t.end_frame(&ctx);
        let start = Instant::now();
        while t.get((0, 0), &f).is_none() {
            assert!(start.elapsed() < Duration::from_secs(30));
            std::thread::sleep(Duration::from_millis(5));
            t.end_frame(&ctx);
        }
        let id = t.get((0, 0), &f).unwrap();
        assert_eq!(ctx.tex_manager().read().meta(id).unwrap().size, [32, 24]);
        // The same flame: the same picture, nothing new asked for.
        t.end_frame(&ctx);
        assert_eq!(t.get((0, 0), &f), Some(id));
        assert!(t.wanted.is_empty());
        // Another flame in the slot: a new picture is needed.
        let mut g = f.clone();
        g.xforms[0].color = 0.9;
        assert!(t.get((0, 0), &g).is_none());
        assert_eq!(t.wanted.len(), 1);
    }
}
