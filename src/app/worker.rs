//! Renders off the UI thread. The UI submits jobs; the worker always takes the newest one and
//! drops the ones it has not started (a dragged slider sends many), so the window never waits.

use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, TryRecvError, channel};

use pipeline::StageTimes;
use pipeline::capture::FrameCapture;
use pipeline::scene::{Camera, Projection, RenderSettings, Samples, Scene};

use crate::lesson::SceneSpec;

/// A render to do.
#[derive(Clone, Debug)]
pub struct Job {
    /// Which request this is; results of older ones are dropped.
    pub generation: u64,
    /// The scene and settings.
    pub spec: SceneSpec,
    /// The observer's camera (the same scene seen from outside).
    pub observer: Camera,
    /// Settings to render as well, for a side-by-side comparison, with their labels.
    pub variants: Vec<(String, RenderSettings)>,
}

/// What a job produced.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The capture of the viewing camera.
    pub capture: Arc<FrameCapture>,
    /// How long its stages took.
    pub times: StageTimes,
    /// The capture of the observer's camera, when it could be rendered.
    pub observer: Option<Arc<FrameCapture>>,
    /// The compared captures, with their labels (those that could be rendered).
    pub variants: Vec<(String, Arc<FrameCapture>)>,
    /// The buffers the capture holds (listed here, off the UI thread: finding whether a
    /// mirror shows scans every pixel).
    pub buffers: Vec<pipeline::capture::BufferKind>,
}

/// A finished job.
#[derive(Debug)]
pub struct Done {
    /// The job's generation.
    pub generation: u64,
    /// The captures, or why the scene cannot be rendered.
    pub result: Result<Rendered, String>,
}

impl Job {
    /// Renders the job on this thread.
    #[must_use]
    pub fn run(self) -> Done {
        let result = pipeline::render_timed(&self.spec.scene, &self.spec.settings)
            .map_err(|e| e.to_string())
            .map(|(capture, times)| {
                let observer = render_observer(&self.spec, self.observer).map(Arc::new);
                let variants = self
                    .variants
                    .iter()
                    .filter_map(|(label, settings)| {
                        let c = pipeline::render(&self.spec.scene, settings).ok()?;
                        Some((label.clone(), Arc::new(c)))
                    })
                    .collect();
                Rendered {
                    buffers: capture.buffers(),
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

/// The scene from the observer's camera: the same pipeline, one sample, no culling (so the
/// outside of everything is seen), a perspective lens wide enough for the viewing frustum.
pub fn render_observer(spec: &SceneSpec, camera: Camera) -> Option<FrameCapture> {
    let distance = (camera.eye - camera.at).length();
    let scene = Scene {
        objects: spec.scene.objects.clone(),
        camera,
        projection: Projection::Perspective {
            fovy_deg: 50.0,
            aspect: None,
            near: (distance * 0.02).max(1e-3),
            far: distance * 20.0,
        },
        figures: spec.scene.figures.clone(),
        shadow: spec.scene.shadow,
        lights: spec.scene.lights.clone(),
    };
    let settings = RenderSettings {
        samples: Samples::X1,
        ..spec.settings
    };
    pipeline::render(&scene, &settings).ok()
}

/// The render thread and its two channels.
pub struct RenderWorker {
    jobs: Sender<Job>,
    done: Receiver<Done>,
}

impl RenderWorker {
    /// Starts the thread; `wake` is called after each finished job (to repaint the window).
    ///
    /// # Errors
    /// When the operating system refuses a thread (the app then renders on its own thread).
    pub fn start(wake: impl Fn() + Send + 'static) -> std::io::Result<Self> {
        let (jobs, job_rx) = channel::<Job>();
        let (done_tx, done) = channel::<Done>();
        std::thread::Builder::new()
            .name("pipelens-render".into())
            .spawn(move || {
                while let Ok(mut job) = job_rx.recv() {
                    // Skip to the newest job: the ones behind it are stale.
                    loop {
                        match job_rx.try_recv() {
                            Ok(newer) => job = newer,
                            Err(TryRecvError::Empty) => break,
                            Err(TryRecvError::Disconnected) => return,
                        }
                    }
                    if done_tx.send(job.run()).is_err() {
                        return;
                    }
                    wake();
                }
            })?;
        Ok(Self { jobs, done })
    }

    /// Submits a job (never blocks).
    pub fn submit(&self, job: Job) {
        let _ = self.jobs.send(job);
    }

    /// The jobs finished since the last call.
    pub fn finished(&self) -> impl Iterator<Item = Done> + '_ {
        self.done.try_iter()
    }
}
