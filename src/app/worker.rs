//! Renders off the UI thread. The UI submits jobs; the worker always takes the newest one and
//! drops the ones it has not started (a dragged slider sends many), so the window never waits.

use std::sync::mpsc::{Receiver, Sender, TryRecvError, channel};
use std::sync::{Arc, OnceLock};
use std::thread::Thread;
use std::time::Duration;

use pipeline::StageTimes;
use pipeline::buffers::BufferKind;
use pipeline::camera::Camera;
use pipeline::capture::FrameCapture;
use pipeline::settings::RenderSettings;

use crate::lesson::SceneSpec;
use crate::observer::render_observer;

/// A render to do.
#[derive(Clone, Debug)]
pub struct Job {
    /// Which request this is; results of older ones are dropped.
    pub generation: u64,
    /// A draft while a parameter is dragged: the observer at a quarter of its pixels.
    pub draft: bool,
    /// The scene and settings.
    pub spec: SceneSpec,
    /// The observer's camera (the same scene seen from outside) and the width/height of its
    /// panel, when the view shows it.
    pub observer: Option<(Camera, Option<f32>)>,
    /// Settings to render as well, for a side-by-side comparison, with their labels.
    pub variants: Vec<(String, RenderSettings)>,
    /// An exercise's reference: the same scene drawn by pipelens' own stages.
    pub reference: Option<(pipeline::scene::Scene, RenderSettings)>,
    /// The buffer shown, to render at the view's resolution as well (`view_resolution`), and the size.
    pub view_resolution: Option<(BufferKind, (u32, u32))>,
}

/// What a job produced.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The capture of the viewing camera.
    pub capture: Arc<FrameCapture>,
    /// Whether it is a draft (see [`Job::draft`]).
    pub draft: bool,
    /// How long its stages took.
    pub times: StageTimes,
    /// The capture of the observer's camera, when it could be rendered.
    pub observer: Option<Arc<FrameCapture>>,
    /// The compared captures, with their labels (those that could be rendered).
    pub variants: Vec<(String, Arc<FrameCapture>)>,
    /// The exercise's reference, when the job asked for one and it could be rendered.
    pub reference: Option<Arc<FrameCapture>>,
    /// The buffer shown at the view's resolution, when the job asked for it.
    pub view_resolution: Option<Arc<FrameCapture>>,
    /// The buffers the scene offers (the capture keeps those the view shows; choosing another
    /// renders again).
    pub buffers: Vec<BufferKind>,
}

/// A finished job.
#[derive(Debug)]
pub struct Done {
    /// The job's generation.
    pub generation: u64,
    /// The captures, or why the scene cannot be rendered.
    pub result: Result<Rendered, pipeline::RenderError>,
}

/// Captures no longer shown, whose storage the next renders write into (a capture is tens of
/// megabytes: reusing it spares the system's page faults and zeroing, and the UI thread the
/// freeing).
#[derive(Default)]
pub struct RecycledCaptures {
    /// For the viewing camera's capture.
    pub capture: Option<FrameCapture>,
    /// For the observer's.
    pub observer: Option<FrameCapture>,
}

impl RecycledCaptures {
    /// Keeps `old` for reuse when nothing else holds it (it is dropped here otherwise).
    fn keep(&mut self, old: Arc<FrameCapture>, observer: bool) {
        if let Ok(c) = Arc::try_unwrap(old) {
            *if observer {
                &mut self.observer
            } else {
                &mut self.capture
            } = Some(c);
        }
    }
}

impl RecycledCaptures {
    /// Keeps a finished job's captures for the next job to write into, as the app hands back
    /// the frames it no longer shows.
    pub fn reuse(&mut self, rendered: Rendered) {
        self.keep(rendered.capture, false);
        if let Some(o) = rendered.observer {
            self.keep(o, true);
        }
    }
}

impl Job {
    /// Renders the job on this thread, into the storage of `spares` when it has some.
    #[must_use]
    pub fn run(self, spares: &mut RecycledCaptures) -> Done {
        let result =
            pipeline::render_reusing(&self.spec.scene, &self.spec.settings, spares.capture.take())
                .map(|(capture, times)| {
                    let observer = self.observer.and_then(|(camera, aspect)| {
                        let draft;
                        let spec = if self.draft {
                            // A quarter of the pixels while dragging: the view shows it stretched.
                            let mut small = self.spec.clone();
                            small.settings.width = (small.settings.width / 2).max(16);
                            small.settings.height = (small.settings.height / 2).max(16);
                            draft = small;
                            &draft
                        } else {
                            &self.spec
                        };
                        render_observer(spec, camera, aspect, spares.observer.take()).map(Arc::new)
                    });
                    let variants = self
                        .variants
                        .iter()
                        .filter_map(|(label, settings)| {
                            let c = pipeline::render(&self.spec.scene, settings).ok()?;
                            Some((label.clone(), Arc::new(c)))
                        })
                        .collect();
                    let reference = self.reference.as_ref().and_then(|(scene, settings)| {
                        pipeline::render(scene, settings).ok().map(Arc::new)
                    });
                    let view_resolution = self.view_resolution.and_then(|(buffer, size)| {
                        crate::app::view_resolution::render(&self.spec, buffer, size).map(Arc::new)
                    });
                    Rendered {
                        reference,
                        view_resolution,
                        draft: self.draft,
                        buffers: BufferKind::ALL
                            .into_iter()
                            .filter(|&k| self.spec.scene.offers(&self.spec.settings, k))
                            .collect(),
                        capture: Arc::new(capture),
                        times,
                        observer,
                        variants,
                    }
                });
        Done {
            generation: self.generation,
            result,
        }
    }
}

/// What the UI thread sends the render thread.
enum Message {
    /// A render to do.
    Job(Box<Job>),
    /// A capture no longer shown (`true`: an observer's), to reuse or free off the UI thread.
    Spare(Arc<FrameCapture>, bool),
}

/// The render thread, its two channels, and the thread's handle to wake it by.
///
/// Neither side ever waits on the other's lock: the UI thread only sends and polls, and the
/// render thread polls its jobs and parks in between, woken by `unpark`. A page's UI thread
/// cannot wait for a lock at all (its render thread is a Web Worker over shared memory), and a
/// receiver blocked in `recv` would make every `send` take the channel's lock.
pub struct RenderWorker {
    jobs: Sender<Message>,
    done: Receiver<Done>,
    thread: Arc<OnceLock<Thread>>,
}

/// How long the render thread parks at most when no job has come: a wake lost before the
/// thread first parked costs no more than this.
const PARK: Duration = Duration::from_millis(100);

impl RenderWorker {
    /// Starts the thread; `wake` is called after each finished job (to repaint the window).
    ///
    /// # Errors
    /// When the operating system refuses a thread, or a page has no thread pool (the app then
    /// renders on its own thread).
    pub fn start(wake: impl Fn() + Send + 'static) -> std::io::Result<Self> {
        let (jobs, job_rx) = channel::<Message>();
        let (done_tx, done) = channel::<Done>();
        let thread = Arc::new(OnceLock::new());
        let handle = Arc::clone(&thread);
        spawn(move || {
            let _ = handle.set(std::thread::current());
            let mut spares = RecycledCaptures::default();
            loop {
                // Take every message waiting, keeping the newest job: the ones behind it are
                // stale.
                let mut job = None;
                loop {
                    match job_rx.try_recv() {
                        Ok(Message::Job(newer)) => job = Some(newer),
                        Ok(Message::Spare(old, observer)) => spares.keep(old, observer),
                        Err(TryRecvError::Empty) => break,
                        Err(TryRecvError::Disconnected) => return,
                    }
                }
                let Some(job) = job else {
                    std::thread::park_timeout(PARK);
                    continue;
                };
                if done_tx.send(job.run(&mut spares)).is_err() {
                    return;
                }
                wake();
            }
        })?;
        Ok(Self { jobs, done, thread })
    }

    fn send(&self, message: Message) {
        let _ = self.jobs.send(message);
        if let Some(t) = self.thread.get() {
            t.unpark();
        }
    }

    /// Submits a job (never blocks).
    pub fn submit(&self, job: Job) {
        self.send(Message::Job(Box::new(job)));
    }

    /// Hands back a capture no longer shown (`observer`: the observer's), so that the render
    /// thread reuses its storage, or frees it there rather than on the UI thread.
    pub fn recycle(&self, old: Arc<FrameCapture>, observer: bool) {
        self.send(Message::Spare(old, observer));
    }

    /// The jobs finished since the last call.
    pub fn finished(&self) -> impl Iterator<Item = Done> + '_ {
        self.done.try_iter()
    }
}

impl Drop for RenderWorker {
    /// Wakes the render thread to find its channel closed and end.
    fn drop(&mut self) {
        if let Some(t) = self.thread.get() {
            t.unpark();
        }
    }
}

/// Runs `body` as the render thread: a thread of its own on the desktop; in a page, one of the
/// rayon pool's Web Workers (a page cannot start threads any other way), which then also takes
/// its share of the frame's parallel work.
fn spawn(body: impl FnOnce() + Send + 'static) -> std::io::Result<()> {
    #[cfg(target_arch = "wasm32")]
    {
        if !super::platform::render_threads() {
            return Err(std::io::Error::from(std::io::ErrorKind::Unsupported));
        }
        rayon::spawn(body);
        Ok(())
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        std::thread::Builder::new()
            .name("pipelens-render".into())
            .spawn(body)
            .map(drop)
    }
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::{AtomicUsize, Ordering};

    use super::*;

    /// The tour's first step at a small size, as generation `generation`.
    fn job(generation: u64) -> Job {
        let tour = crate::lesson::default_lesson().expect("the built-in tour");
        let doc = crate::lesson::Document::Lesson(Box::new(tour));
        let session = crate::app::session::Session::with_document(doc, "test", None);
        let mut job = session.job();
        job.generation = generation;
        job.spec.settings.width = 64;
        job.spec.settings.height = 40;
        job
    }

    /// The jobs done, waited for until one of generation `last` comes (a minute at most).
    fn until_done(worker: &RenderWorker, last: u64) -> Vec<u64> {
        let mut done = Vec::new();
        for _ in 0..6000 {
            done.extend(worker.finished().map(|d| {
                assert!(d.result.is_ok(), "rendered: {:?}", d.result.err());
                d.generation
            }));
            if done.contains(&last) {
                return done;
            }
            std::thread::sleep(Duration::from_millis(10));
        }
        panic!("generation {last} was not rendered; done: {done:?}");
    }

    #[test]
    fn the_render_thread_wakes_for_each_job_and_skips_to_the_newest() {
        let woken = Arc::new(AtomicUsize::new(0));
        let count = Arc::clone(&woken);
        let worker = RenderWorker::start(move || {
            count.fetch_add(1, Ordering::SeqCst);
        })
        .expect("a thread");
        worker.submit(job(1));
        assert_eq!(until_done(&worker, 1), [1]);
        // Parked now, with nothing to do: a job sent later wakes it.
        std::thread::sleep(PARK * 3);
        worker.submit(job(2));
        assert_eq!(until_done(&worker, 2), [2]);
        // Three at once: the newest is rendered, and none after it; those it skipped never are.
        for g in 3..=5 {
            worker.submit(job(g));
        }
        let done = until_done(&worker, 5);
        assert_eq!(done.last(), Some(&5));
        assert!(done.iter().all(|g| (3..=5).contains(g)), "{done:?}");
        assert_eq!(woken.load(Ordering::SeqCst), 2 + done.len());
    }
}
