//! The running animation export: the engine's animation job on its own thread, its progress
//! (frames done, skipped, the frame being rendered), Cancel, and how it ended. A video that
//! needs ffmpeg when ffmpeg is not on PATH is not attempted: the frames are written and kept,
//! and the end says what to install.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use crate::app::worker::{TaskWorker, task_worker};
use crate::io::animation::{AnimError, Job, Progress, Summary};
use crate::io::video::{VideoError, ffmpeg_available};

/// How an animation export ended.
#[derive(Clone, Debug, PartialEq)]
pub struct Ended {
    pub summary: Summary,
    /// Where the frames are.
    pub dir: PathBuf,
    /// The video that could not be made, and why (the frames are kept).
    pub no_video: Option<String>,
}

/// A running animation export.
pub struct AnimJob {
    /// Where the frames go, and the video if any.
    pub dir: PathBuf,
    pub video: Option<PathBuf>,
    pub total: usize,
    worker: TaskWorker<Result<Ended, String>>,
    progress: Arc<Mutex<Progress>>,
}

impl AnimJob {
    /// Start `job` in the background.
    pub fn start(mut job: Job, repaint: impl Fn() + Send + 'static) -> AnimJob {
        let dir = job.dir.clone();
        let video = job.video.as_ref().map(|(p, _)| p.clone());
        // Without ffmpeg the frames are still worth making; the video is left out and the end
        // says why.
        let no_video = match job.video.take() {
            Some((p, o))
                if matches!(
                    crate::io::video::VideoKind::of(&p),
                    Some(crate::io::video::VideoKind::Ffmpeg(_))
                ) && !ffmpeg_available(&o.ffmpeg) =>
            {
                let what = format!(
                    "a .{} video",
                    p.extension().unwrap_or_default().to_string_lossy()
                );
                Some(VideoError::FfmpegMissing { path: p, what }.to_string())
            }
            v => {
                job.video = v;
                None
            }
        };
        let total = job.frames.len();
        let progress = Arc::new(Mutex::new(Progress {
            done: 0,
            total,
            fraction: 0.0,
            skipped: 0,
        }));
        let shared = progress.clone();
        let worker = task_worker("ugnis-animation", repaint);
        let frames_dir = dir.clone();
        worker.submit(Box::new(move |cancel, report| {
            let summary = job
                .run(cancel, |p| {
                    if let Ok(mut s) = shared.lock() {
                        *s = p;
                    }
                    report((p.done as f64 + p.fraction.min(1.0)) / p.total.max(1) as f64);
                })
                .map_err(|e| message(e, &frames_dir))?;
            Ok(Ended {
                summary,
                dir: frames_dir,
                no_video,
            })
        }));
        AnimJob {
            dir,
            video,
            total,
            worker,
            progress,
        }
    }

    /// Frames done (rendered or found on disk), of the total, and the fraction of the whole.
    pub fn progress(&self) -> Progress {
        self.progress.lock().map(|p| *p).unwrap_or(Progress {
            done: 0,
            total: self.total,
            fraction: 0.0,
            skipped: 0,
        })
    }

    pub fn fraction(&self) -> f64 {
        self.worker.progress()
    }

    /// Stop at once; the frames written so far stay (a new export of the same frames
    /// resumes).
    pub fn cancel(&self) {
        self.worker.cancel();
    }

    /// The result once the job has finished.
    pub fn poll(&mut self) -> Option<Result<Ended, String>> {
        self.worker.poll().pop()
    }
}

/// What a failed export says in the editor.
fn message(e: AnimError, dir: &std::path::Path) -> String {
    match e {
        AnimError::Interrupted => format!(
            "Animation export cancelled; the frames written so far are kept in {} (export \
             again to resume: frames on disk are not rendered again)",
            dir.display()
        ),
        AnimError::Video { source, frames } => format!(
            "{source}\nThe frames written so far are kept in '{}'; export again to encode them \
             (frames already on disk are not rendered again).",
            frames.display()
        ),
        e => e.to_string(),
    }
}
