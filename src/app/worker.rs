//! The one background worker every job of the application uses: a thread that runs the newest
//! job it was given (older queued jobs are dropped), can be cancelled, reports progress and
//! results over a channel, wakes the UI when it sends, and is joined when dropped.
//!
//! The UI thread never renders: previews, thumbnails, exports, random batches, escape-time
//! and scene renders all run in a [`Worker`].

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::thread::JoinHandle;
use std::time::Duration;

/// Wakes the UI from a background thread.
pub type Repaint = Arc<dyn Fn() + Send + Sync>;

/// A [`Repaint`] for `ctx` (none, in tests: does nothing).
pub fn repaint_of(ctx: Option<&eframe::egui::Context>) -> Repaint {
    let c = ctx.cloned();
    Arc::new(move || {
        if let Some(c) = &c {
            c.request_repaint();
        }
    })
}

/// State shared by the UI side and the thread.
struct Shared {
    /// Set to stop the running job as soon as possible.
    cancel: AtomicBool,
    /// Jobs handed to the worker so far.
    submitted: AtomicU64,
    /// Number of the last job the thread finished (or dropped as superseded).
    done: AtomicU64,
    /// Progress of the running job in millionths.
    progress: AtomicU64,
}

/// What a running job sees: its cancel flag, a way to send results and report progress.
pub struct JobContext<'a, E> {
    shared: &'a Shared,
    number: u64,
    events: &'a Sender<E>,
    repaint: &'a (dyn Fn() + Send),
}

impl<E> JobContext<'_, E> {
    /// The flag engine loops poll to stop early (set by [`Worker::submit`] and
    /// [`Worker::cancel`]).
    pub fn cancel_flag(&self) -> &AtomicBool {
        &self.shared.cancel
    }

    /// True when the job was cancelled or a newer job is waiting: stop at the next
    /// convenient point.
    pub fn is_stale(&self) -> bool {
        self.shared.cancel.load(Ordering::SeqCst)
            || self.shared.submitted.load(Ordering::SeqCst) != self.number
    }

    /// Send a result to the UI and wake it.
    pub fn send(&self, event: E) {
        let _ = self.events.send(event);
        (self.repaint)();
    }

    /// Report progress in `[0, 1]` (read with [`Worker::progress`]).
    pub fn set_progress(&self, fraction: f64) {
        let v = (fraction.clamp(0.0, 1.0) * 1e6) as u64;
        self.shared.progress.store(v, Ordering::Relaxed);
    }
}

/// A background thread running jobs of type `J` and sending events of type `E`.
pub struct Worker<J: Send + 'static, E: Send + 'static> {
    jobs: Sender<Option<J>>,
    events: Receiver<E>,
    shared: Arc<Shared>,
    handle: Option<JoinHandle<()>>,
}

impl<J: Send + 'static, E: Send + 'static> Worker<J, E> {
    /// Start a worker thread called `name`. `run` is called with each job (it may keep state
    /// between jobs); `repaint` wakes the UI whenever the job sends something.
    pub fn new<F>(name: &str, repaint: impl Fn() + Send + 'static, mut run: F) -> Self
    where
        F: FnMut(J, &JobContext<E>) + Send + 'static,
    {
        let (jobs, job_rx) = mpsc::channel::<Option<J>>();
        let (event_tx, events) = mpsc::channel::<E>();
        let shared = Arc::new(Shared {
            cancel: AtomicBool::new(false),
            submitted: AtomicU64::new(0),
            done: AtomicU64::new(0),
            progress: AtomicU64::new(0),
        });
        let sh = shared.clone();
        let handle = std::thread::Builder::new()
            .name(name.to_string())
            .spawn(move || {
                let mut taken = 0u64;
                'outer: loop {
                    let mut job = match job_rx.recv() {
                        Ok(Some(j)) => j,
                        _ => return,
                    };
                    taken += 1;
                    // The newest job wins.
                    loop {
                        match job_rx.try_recv() {
                            Ok(Some(j)) => {
                                job = j;
                                taken += 1;
                            }
                            Ok(None) | Err(TryRecvError::Disconnected) => return,
                            Err(TryRecvError::Empty) => break,
                        }
                    }
                    sh.cancel.store(false, Ordering::SeqCst);
                    // A submit between the drain and the reset: its job is on its way.
                    if sh.submitted.load(Ordering::SeqCst) != taken {
                        sh.done.store(taken, Ordering::SeqCst);
                        continue 'outer;
                    }
                    sh.progress.store(0, Ordering::Relaxed);
                    let cx = JobContext {
                        shared: &sh,
                        number: taken,
                        events: &event_tx,
                        repaint: &repaint,
                    };
                    run(job, &cx);
                    sh.done.store(taken, Ordering::SeqCst);
                    repaint();
                }
            })
            .expect("cannot start a worker thread");
        Worker {
            jobs,
            events,
            shared,
            handle: Some(handle),
        }
    }

    /// Replace whatever runs or waits by `job`; the running job is cancelled.
    pub fn submit(&self, job: J) {
        self.shared.submitted.fetch_add(1, Ordering::SeqCst);
        self.shared.cancel.store(true, Ordering::SeqCst);
        let _ = self.jobs.send(Some(job));
    }

    /// Replace whatever waits by `job`; the running job is not cancelled but sees
    /// [`JobContext::is_stale`] and stops at its next convenient point.
    pub fn queue(&self, job: J) {
        self.shared.submitted.fetch_add(1, Ordering::SeqCst);
        let _ = self.jobs.send(Some(job));
    }

    /// Stop the running job.
    pub fn cancel(&self) {
        self.shared.cancel.store(true, Ordering::SeqCst);
    }

    /// Everything the worker sent since the last poll.
    pub fn poll(&self) -> Vec<E> {
        self.events.try_iter().collect()
    }

    /// Block until the next event (tests and benchmarks).
    pub fn wait(&self, timeout: Duration) -> Option<E> {
        self.events.recv_timeout(timeout).ok()
    }

    /// Progress of the running job in `[0, 1]`.
    pub fn progress(&self) -> f64 {
        self.shared.progress.load(Ordering::Relaxed) as f64 / 1e6
    }

    /// Let the thread finish on its own instead of joining it when dropped (for a job that
    /// cannot be cancelled, such as the platform's file dialog).
    pub fn detach(mut self) {
        self.handle.take();
    }

    /// True while a job is queued or running.
    pub fn is_busy(&self) -> bool {
        self.shared.submitted.load(Ordering::SeqCst) != self.shared.done.load(Ordering::SeqCst)
    }
}

impl<J: Send + 'static, E: Send + 'static> Drop for Worker<J, E> {
    fn drop(&mut self) {
        self.shared.cancel.store(true, Ordering::SeqCst);
        let _ = self.jobs.send(None);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

/// A one-off job for a [`TaskWorker`]: gets the cancel flag and a progress callback.
pub type Task<R> = Box<dyn FnOnce(&AtomicBool, &dyn Fn(f64)) -> R + Send>;

/// A worker for one-off jobs (exports, batches, textures): each job is a closure and its
/// return value is the event.
pub type TaskWorker<R> = Worker<Task<R>, R>;

/// Start a [`TaskWorker`].
pub fn task_worker<R: Send + 'static>(
    name: &str,
    repaint: impl Fn() + Send + 'static,
) -> TaskWorker<R> {
    Worker::new(name, repaint, |task: Task<R>, cx: &JobContext<R>| {
        let r = task(cx.cancel_flag(), &|f| cx.set_progress(f));
        cx.send(r);
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicUsize;

    #[test]
    fn the_newest_job_wins_and_cancels_the_running_one() {
        let started = Arc::new(AtomicUsize::new(0));
        let s = started.clone();
        let w: Worker<u32, (u32, bool)> = Worker::new(
            "test",
            || {},
            move |j, cx| {
                s.fetch_add(1, Ordering::SeqCst);
                // A long job that stops when cancelled.
                for _ in 0..2000 {
                    if cx.is_stale() {
                        cx.send((j, false));
                        return;
                    }
                    std::thread::sleep(Duration::from_millis(1));
                }
                cx.send((j, true));
            },
        );
        w.submit(1);
        // Let job 1 start, then queue three more at once: only the last one runs.
        while started.load(Ordering::SeqCst) == 0 {
            std::thread::sleep(Duration::from_millis(1));
        }
        w.submit(2);
        w.submit(3);
        w.submit(4);
        let first = w.wait(Duration::from_secs(10)).unwrap();
        assert_eq!(first, (1, false), "job 1 is cancelled");
        assert!(w.is_busy());
        let next = w.wait(Duration::from_secs(10)).unwrap();
        assert_eq!(next, (4, true), "jobs 2 and 3 are dropped");
        assert_eq!(started.load(Ordering::SeqCst), 2);
        let t = std::time::Instant::now();
        while w.is_busy() {
            assert!(t.elapsed() < Duration::from_secs(10));
            std::thread::sleep(Duration::from_millis(1));
        }
    }

    #[test]
    fn queued_jobs_let_the_running_step_finish_and_progress_is_reported() {
        let w = task_worker::<u32>("test", || {});
        w.submit(Box::new(|_, progress| {
            progress(0.5);
            std::thread::sleep(Duration::from_millis(30));
            7
        }));
        // The progress of the running task becomes visible.
        let t = std::time::Instant::now();
        while w.progress() < 0.5 {
            assert!(t.elapsed() < Duration::from_secs(10));
            std::thread::sleep(Duration::from_millis(1));
        }
        w.queue(Box::new(|_, _| 8));
        assert_eq!(w.wait(Duration::from_secs(10)), Some(7));
        assert_eq!(w.wait(Duration::from_secs(10)), Some(8));
    }

    #[test]
    fn dropping_joins_a_running_job() {
        let started = Arc::new(AtomicBool::new(false));
        let finished = Arc::new(AtomicBool::new(false));
        let (s, f) = (started.clone(), finished.clone());
        let w = task_worker::<()>("test", || {});
        w.submit(Box::new(move |cancel, _| {
            s.store(true, Ordering::SeqCst);
            while !cancel.load(Ordering::SeqCst) {
                std::thread::sleep(Duration::from_millis(1));
            }
            f.store(true, Ordering::SeqCst);
        }));
        while !started.load(Ordering::SeqCst) {
            std::thread::sleep(Duration::from_millis(1));
        }
        drop(w);
        assert!(finished.load(Ordering::SeqCst), "drop cancels and waits");
    }
}
