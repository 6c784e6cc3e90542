//! Renders off the UI thread. The UI submits jobs; the worker always takes the newest one and
//! drops the ones it has not started (a dragged slider sends many), so the window never waits.

use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, TryRecvError, channel};

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
    /// The buffer shown, to render at the view's resolution as well (`display`), and the size.
    pub display: Option<(BufferKind, (u32, u32))>,
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
    pub display: Option<Arc<FrameCapture>>,
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
    pub result: Result<Rendered, String>,
}

/// Captures no longer shown, whose storage the next renders write into (a capture is tens of
/// megabytes: reusing it spares the system's page faults and zeroing, and the UI thread the
/// freeing).
#[derive(Default)]
pub struct Spares {
    /// For the viewing camera's capture.
    pub capture: Option<FrameCapture>,
    /// For the observer's.
    pub observer: Option<FrameCapture>,
}

impl Spares {
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

impl Job {
    /// Renders the job on this thread, into the storage of `spares` when it has some.
    #[must_use]
    pub fn run(self, spares: &mut Spares) -> Done {
        let result =
            pipeline::render_reusing(&self.spec.scene, &self.spec.settings, spares.capture.take())
                .map_err(|e| e.to_string())
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
                    let display = self.display.and_then(|(buffer, size)| {
                        crate::app::display::render(&self.spec, buffer, size).map(Arc::new)
                    });
                    Rendered {
                        reference,
                        display,
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

/// The render thread and its two channels.
pub struct RenderWorker {
    jobs: Sender<Message>,
    done: Receiver<Done>,
}

impl RenderWorker {
    /// Starts the thread; `wake` is called after each finished job (to repaint the window).
    ///
    /// # Errors
    /// When the operating system refuses a thread (the app then renders on its own thread).
    pub fn start(wake: impl Fn() + Send + 'static) -> std::io::Result<Self> {
        let (jobs, job_rx) = channel::<Message>();
        let (done_tx, done) = channel::<Done>();
        std::thread::Builder::new()
            .name("pipelens-render".into())
            .spawn(move || {
                let mut spares = Spares::default();
                while let Ok(first) = job_rx.recv() {
                    // Skip to the newest job: the ones behind it are stale.
                    let mut job = None;
                    let mut next = Ok(first);
                    loop {
                        match next {
                            Ok(Message::Job(newer)) => job = Some(newer),
                            Ok(Message::Spare(old, observer)) => spares.keep(old, observer),
                            Err(TryRecvError::Empty) => break,
                            Err(TryRecvError::Disconnected) => return,
                        }
                        next = job_rx.try_recv();
                    }
                    let Some(job) = job else { continue };
                    if done_tx.send(job.run(&mut spares)).is_err() {
                        return;
                    }
                    wake();
                }
            })?;
        Ok(Self { jobs, done })
    }

    /// Submits a job (never blocks).
    pub fn submit(&self, job: Job) {
        let _ = self.jobs.send(Message::Job(Box::new(job)));
    }

    /// Hands back a capture no longer shown (`observer`: the observer's), so that the render
    /// thread reuses its storage, or frees it there rather than on the UI thread.
    pub fn recycle(&self, old: Arc<FrameCapture>, observer: bool) {
        let _ = self.jobs.send(Message::Spare(old, observer));
    }

    /// The jobs finished since the last call.
    pub fn finished(&self) -> impl Iterator<Item = Done> + '_ {
        self.done.try_iter()
    }
}
