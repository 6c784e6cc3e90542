//! The app's state with no egui in it: the scene being taught, the latest capture, what is
//! selected. Panels read it and return [`Command`](crate::app::command::Command)s; the app applies them once per frame.

use std::path::PathBuf;
use std::sync::Arc;

use pipeline::StageTimes;
use pipeline::buffers::BufferKind;
use pipeline::buffers::Capture;
use pipeline::capture::FrameCapture;
use pipeline::overlay::OverlayKind;

use super::reference::Comparison as ExerciseComparison;
use crate::app::player::LessonPlayer;
use crate::app::selection::{DepthView, Selection};
use crate::app::view_resolution::ViewResolution;
use crate::app::worker::{Job, RenderWorker, Rendered};
use crate::lesson::script::{Layout, Overlay};
use crate::lesson::{Document, SceneSpec};
use crate::observer::{Orbit, default_orbit};
use crate::vocabulary::{Lang, Stage};
/// The state of the app.
pub struct Session {
    /// The scene and settings being shown.
    pub spec: SceneSpec,
    /// Where the scene came from, for messages.
    pub source: String,
    /// The latest capture of the viewing camera.
    pub capture: Option<Arc<FrameCapture>>,
    /// The buffers the latest capture holds.
    pub buffers: Vec<BufferKind>,
    /// The latest capture of the observer's camera.
    pub observer: Option<Arc<FrameCapture>>,
    /// The captures of the compared settings, with their labels.
    pub variants: Vec<(String, Arc<FrameCapture>)>,
    /// Stage times of the latest capture.
    pub times: Option<StageTimes>,
    /// Why the latest render failed, if it did (the last good capture stays on screen).
    pub error: Option<String>,
    /// The observer's orbit.
    pub orbit: Orbit,
    /// The width/height the observer is rendered at (its panel's).
    pub observer_aspect: Option<f32>,
    /// Whether the orbit is still the one that frames the step's subject (not turned or zoomed
    /// by hand since): it is framed again when the observer's panel changes shape, as it does
    /// on the first frame that shows it.
    pub orbit_framed: bool,
    /// Where the step's subject reaches while its animation plays ([`crate::observer::reached`],
    /// world coordinates), with the [`Self::step_entered`] it is for; empty for a step that
    /// does not animate.
    pub subject_reach: (u64, Vec<glam::Vec3>),
    /// The physical pixels the pixel view draws the image over.
    pub view_pixels: Option<[u32; 2]>,
    /// The buffer shown rendered at that resolution (`view_resolution`).
    pub view_resolution: ViewResolution,
    /// What is selected.
    pub selection: Selection,
    /// The interface language.
    pub lang: Lang,
    /// Whether the screen is touched, not typed and clicked on (a phone, a tablet): the
    /// lessons' words about keys and clicks are then said with taps and swipes
    /// (`vocabulary::touch`).
    pub touch: bool,
    /// Bumped by every change that needs a new capture; stale results are dropped.
    pub generation: u64,
    /// The generation of the capture on screen.
    pub shown_generation: u64,
    /// Whether the latest render asked for the observer (it is not asked again when it could
    /// not be rendered).
    observer_asked: bool,
    /// The lesson being played, if a lesson was opened.
    pub lesson: Option<LessonPlayer>,
    /// Why the file on disk no longer loads (the last good version keeps running).
    pub reload_error: Option<String>,
    /// Why a file dropped on the window (or page) did not open: shown until it is closed, a
    /// step is entered or something else opens.
    pub dropped_error: Option<String>,
    /// The meshes dropped on the page, by name: where a lesson opened in a page finds the
    /// meshes it names (a page cannot read a path).
    pub given: crate::lesson::Given,
    /// Where the results come from: a worker thread, or (tests) this thread.
    worker: Option<RenderWorker>,
    /// Counts the steps entered: a view that frames or opens something per step resets when it
    /// changes.
    pub step_entered: u64,
    /// The generation of the first render asked for on the step on screen: a render older than
    /// it was drawn for the step before, and its frame is not judged by this step's exercise
    /// (nor its reference kept as this step's).
    step_generation: u64,
    /// A parameter is being dragged: each render is a draft (one sample per pixel, shaded once
    /// per 2×2 block but the inspected pixel, the observer at a quarter of its pixels) so
    /// that the picture keeps up with the hand; letting go renders the full frame.
    pub drafting: bool,
    /// The scene as it was when the drag under way (or the last one) began: the lesson editor
    /// records a drag as an animation from it.
    pub drag_from: Option<SceneSpec>,
    /// Whether the capture on screen is a draft.
    pub shown_draft: bool,
    /// What the student has done, kept across runs by the app's storage.
    pub progress: crate::app::progress::Progress,
    /// An exercise step's reference (pipelens' own stages) and how the student's frame
    /// compares with it.
    pub exercise: ExerciseComparison,
    /// Why the watch last asked for was dropped (the code changed and it no longer compiles).
    pub watch_error: Option<String>,
}

impl Session {
    /// A session on `spec`. With a worker, renders run off the UI thread; without, they run
    /// at once (deterministic, for tests).
    #[must_use]
    pub fn new(spec: SceneSpec, source: &str, worker: Option<RenderWorker>) -> Self {
        Self::starting_at(spec, source, worker, 0)
    }

    /// [`Self::new`] with its generations counted from `generation` (a session that replaces
    /// another on the same worker drops the old one's results still under way).
    fn starting_at(
        spec: SceneSpec,
        source: &str,
        worker: Option<RenderWorker>,
        generation: u64,
    ) -> Self {
        let orbit = default_orbit(&spec);
        let mut s = Self {
            spec,
            source: source.to_owned(),
            capture: None,
            buffers: Vec::new(),
            observer: None,
            variants: Vec::new(),
            times: None,
            error: None,
            orbit,
            orbit_framed: true,
            subject_reach: (0, Vec::new()),
            observer_aspect: None,
            view_pixels: None,
            view_resolution: ViewResolution::default(),
            selection: Selection::default(),
            lang: Lang::default(),
            touch: false,
            generation,
            shown_generation: generation,
            observer_asked: false,
            lesson: None,
            reload_error: None,
            dropped_error: None,
            given: crate::lesson::Given::new(),
            worker,
            step_entered: 0,
            step_generation: generation,
            drafting: false,
            drag_from: None,
            shown_draft: false,
            progress: crate::app::progress::Progress::default(),
            exercise: ExerciseComparison::default(),
            watch_error: None,
        };
        s.request_render();
        s
    }

    /// A session on a scene file or a lesson (then on its first step).
    #[must_use]
    pub fn with_document(doc: Document, source: &str, worker: Option<RenderWorker>) -> Self {
        Self::document_at(doc, source, worker, 0)
    }

    /// Opens another lesson or scene (`source` names it) in place of this one, on the same
    /// render worker and in the same language.
    pub fn open(&mut self, doc: Document, source: &str) {
        let worker = self.worker.take();
        let lang = self.lang;
        let progress = std::mem::take(&mut self.progress);
        // The meshes a page was given stay for the next lesson that names them.
        let given = std::mem::take(&mut self.given);
        *self = Self::document_at(doc, source, worker, self.generation + 1);
        self.lang = lang;
        self.progress = progress;
        self.given = given;
    }

    fn document_at(
        doc: Document,
        source: &str,
        worker: Option<RenderWorker>,
        generation: u64,
    ) -> Self {
        let mut s = Self::starting_at(doc.first_spec(), source, worker, generation);
        if let Document::Lesson(lesson) = doc {
            s.lesson = Some(LessonPlayer::new(Arc::from(lesson), 0));
            s.enter_step(0);
        }
        s
    }

    /// Points the observer at the subject of the step playing (its `focus`, from its `orbit`
    /// direction; the whole scene `spec` without a lesson), framed for the observer's panel
    /// and for every pose the step's animations take (nine, across the longest): a limb
    /// swinging out stays in the picture.
    pub(super) fn frame_observer(&mut self, spec: &SceneSpec, poses: &[SceneSpec]) {
        self.orbit = self.observer_framing(spec, poses);
        self.orbit_framed = true;
    }

    /// The orbit [`Self::frame_observer`] sets: framing the step's `poses`
    /// ([`Self::animation_poses`]), or `spec` for a step that does not animate.
    pub(super) fn observer_framing(&self, spec: &SceneSpec, poses: &[SceneSpec]) -> Orbit {
        let step = self.lesson.as_ref().map(LessonPlayer::current);
        crate::observer::orbit_for_poses(
            if poses.is_empty() {
                std::slice::from_ref(spec)
            } else {
                poses
            },
            step.and_then(|s| s.focus.as_deref()).unwrap_or_default(),
            step.and_then(|s| s.orbit),
            self.observer_aspect,
        )
    }

    /// The step's scene at nine moments of its longest animation; none for a step that does
    /// not animate (or outside a lesson).
    pub(super) fn animation_poses(&self) -> Vec<SceneSpec> {
        let step = self.lesson.as_ref().map(LessonPlayer::current);
        match (&self.lesson, step) {
            (Some(p), Some(s)) if !s.animate.is_empty() => {
                let longest = s.animate.iter().map(|a| a.seconds).fold(0.0, f32::max);
                (0..=8)
                    .map(|i| p.lesson.spec_playing(p.step, longest * i as f32 / 8.0))
                    .collect()
            }
            _ => Vec::new(),
        }
    }

    /// Goes to step `k` (clamped): its scene, stage, layout, buffer, overlays and highlights.
    pub(super) fn enter_step(&mut self, k: usize) {
        let Some(player) = &mut self.lesson else {
            return;
        };
        let k = k.min(player.lesson.steps.len().saturating_sub(1));
        player.step = k;
        player.time = 0.0;
        player.show_answer = false;
        player.verdict = None;
        let step = player.current().clone();
        player.playing = !step.animate.is_empty() && !step.predicts();
        let spec = player.lesson.spec_playing(k, 0.0);
        let (stage, buffer) = (player.lesson.stage_at(k), player.lesson.buffer_at(k));
        self.go_to(stage);
        let sel = &mut self.selection;
        match step.layout {
            Layout::Single => {
                sel.show_observer = false;
                sel.comparison = None;
            }
            Layout::Observer => {
                sel.show_observer = true;
                sel.comparison = None;
            }
            Layout::Compare => sel.comparison = step.compare,
        }
        // What a step does not say is predictable: without `buffer` it shows the default
        // buffer of the stage on screen (whatever the viewer looked at before), and the pixel,
        // vertex, focus and profile are the step's (none when it names none).
        sel.buffer = buffer;
        // The overlays are the step's own too: none when it names none.
        let overlays = step.overlays.as_deref().unwrap_or_default();
        sel.overlays = overlays
            .iter()
            .filter_map(|o| match o {
                Overlay::Edges => Some(OverlayKind::TriangleEdges),
                Overlay::BoundingBoxes => Some(OverlayKind::BoundingBoxes),
                Overlay::Samples | Overlay::Normals => None,
            })
            .collect();
        sel.show_samples = overlays.contains(&Overlay::Samples);
        sel.show_normals = overlays.contains(&Overlay::Normals);
        sel.pixel = step.pixel;
        sel.vertex = step.vertex;
        sel.watch.clone_from(&step.watch);
        sel.focus.clone_from(&step.focus);
        sel.depth_view = DepthView {
            linear: false,
            range: step.depth_range,
        };
        sel.profile = step.profile_line(spec.settings.width, spec.settings.height);
        // The observer frames the step's subject, as the geometry views do.
        let poses = self.animation_poses();
        self.frame_observer(&spec, &poses);
        self.step_entered += 1;
        let focus = step.focus.as_deref().unwrap_or_default();
        let reach = crate::observer::reached(&poses, focus);
        self.subject_reach = (self.step_entered, reach);
        // A dropped file's trouble is about what was on screen when it was dropped.
        self.dropped_error = None;
        let mut spec = spec;
        self.restore_code(&mut spec);
        self.spec = spec;
        self.step_generation = self.generation + 1;
        self.request_render();
    }

    /// Moves the step's animations on by `dt` seconds.
    pub(super) fn tick(&mut self, dt: f32) {
        let Some(player) = &mut self.lesson else {
            return;
        };
        if !player.playing {
            return;
        }
        player.time += dt;
        let (k, t) = (player.step, player.time);
        if player.current().animate.iter().all(|a| a.finished(t)) {
            player.playing = false;
        }
        let spec = player.lesson.spec_playing(k, t);
        if spec != self.spec {
            self.spec = spec;
            self.request_render();
        }
    }

    /// Whether a render is under way.
    #[must_use]
    pub fn rendering(&self) -> bool {
        self.shown_generation != self.generation
    }

    /// What the current view needs a capture to keep: the buffer a pixel stage shows, and every
    /// term while a pixel is inspected (the inspector lists them all and draws the lighting
    /// vectors, and another pixel clicked is explained at once). A draft keeps the inspected
    /// pixel's terms only: writing every buffer would cost it a quarter of its time. Where
    /// objects run shaders, the inspected pixel is named in the full capture too: the shaders'
    /// runs are traced at that pixel only, so another pixel clicked renders again.
    #[must_use]
    pub fn capture_needed(&self) -> Capture {
        let shown = Capture::showing([self.selection.buffer]);
        let shaders = self.spec.scene.has_shaders();
        let needed = match self.selection.pixel {
            Some(_) if self.drafting => shown.with_pixel(self.selection.pixel),
            Some(_) if shaders => Capture::FULL.with_pixel(self.selection.pixel),
            Some(_) => Capture::FULL,
            None => shown,
        };
        Capture {
            cost: self.selection.cost && shaders,
            ..needed
        }
    }

    /// Whether the view shows the observer: beside a space, or beside a pixel stage that
    /// compares nothing.
    #[must_use]
    pub fn observer_shown(&self) -> bool {
        let sel = &self.selection;
        sel.show_observer && (sel.stage.space().is_some() || sel.comparison.is_none())
    }

    /// Asks for a new capture when the view needs a buffer the latest one did not keep, or the
    /// observer it did not render.
    pub fn ensure_captured(&mut self) {
        if self.view_resolution_job().is_none() {
            // The finer render is not for this view (another stage, a comparison, a drag).
            self.view_resolution = ViewResolution::default();
        }
        let Some(kept) = self.capture.as_ref().map(|c| c.settings.capture) else {
            return;
        };
        let needed = self.capture_needed();
        // Shaders are traced at the captured pixel only: another pixel needs another run.
        let shaders = self.spec.scene.has_shaders();
        let missing = !kept.covers(needed)
            || (shaders && needed.pixel.is_some() && kept.pixel != needed.pixel)
            || self.watch_missing()
            || (self.observer_shown() && !self.observer_asked)
            || self.view_resolution_missing()
            || self.reference_stale();
        if !self.rendering() && missing {
            self.request_render();
        }
    }

    /// Whether the frame on screen lacks the watch the selection asks for, or keeps one it no
    /// longer asks for.
    fn watch_missing(&self) -> bool {
        let kept = self
            .capture
            .as_ref()
            .and_then(|c| c.shaders.as_ref())
            .and_then(|r| r.watch.as_ref())
            .map(|w| (w.from_vertex, w.line, w.expression.as_str()));
        let asked = self
            .selection
            .watch
            .as_ref()
            .filter(|_| self.spec.scene.has_shaders())
            .map(|w| {
                (
                    w.stage == pipeline::shader::Stage::Vertex,
                    w.line,
                    w.expression.as_str(),
                )
            });
        kept != asked
    }

    /// The render the current view needs: the scene keeping what the view shows, the observer,
    /// the compared settings.
    #[must_use]
    pub fn job(&self) -> Job {
        let mut spec = self.spec.clone();
        spec.settings.capture = self.capture_needed();
        if self.drafting {
            spec.settings.samples = pipeline::raster::Samples::X1;
            // Shaded once per 2×2 block, but the inspected pixel by itself: its explanation
            // derives its colour from its own records and must agree with it (the capture
            // keeps that pixel, see `capture_needed`).
            spec.settings.coarse_shading = true;
        }
        Job {
            draft: self.drafting,
            generation: self.generation,
            variants: self
                .selection
                .comparison
                .map(|c| c.variants(&spec.settings))
                .unwrap_or_default(),
            observer: self
                .observer_shown()
                .then(|| (self.orbit.camera(), self.observer_aspect)),
            reference: self.exercise_reference(&spec),
            view_resolution: self.view_resolution_job(),
            spec,
        }
    }

    /// Starts or ends a drag of a parameter (see [`Self::drafting`]); ending it renders the
    /// full frame in place of the draft on screen or under way.
    pub fn set_drafting(&mut self, on: bool) {
        let was = std::mem::replace(&mut self.drafting, on);
        if on && !was {
            // Called before the drag's first change is applied.
            self.drag_from = Some(self.spec.clone());
        }
        if was && !on && (self.shown_draft || self.shown_generation < self.generation) {
            self.request_render();
        }
    }

    /// Asks for a new capture of the current scene, keeping what the view shows.
    pub fn request_render(&mut self) {
        self.generation += 1;
        let mut job = self.job();
        // The watch the selection asks for, drawn into the same frame; one that no longer
        // compiles (the code changed under it) is dropped, with why.
        if let Some(watch) = self.selection.watch.clone()
            && job.spec.scene.has_shaders()
        {
            match job.spec.scene.watching(&watch) {
                Ok(watched) => job.spec.scene = watched,
                Err(e) => {
                    self.watch_error = Some(e.to_string());
                    self.selection.watch = None;
                }
            }
        }
        self.observer_asked = job.observer.is_some();
        self.view_resolution.asked = job.view_resolution;
        match &self.worker {
            Some(w) => w.submit(job),
            None => {
                let done = job.run(&mut crate::app::worker::RecycledCaptures::default());
                self.receive(done.generation, done.result);
            }
        }
    }

    /// Takes any finished render from the worker; returns whether something new arrived.
    pub fn poll(&mut self) -> bool {
        let mut got = false;
        if let Some(w) = &self.worker {
            let results: Vec<_> = w.finished().collect();
            for done in results {
                got |= self.receive(done.generation, done.result);
            }
        }
        got
    }

    fn receive(
        &mut self,
        generation: u64,
        result: Result<Rendered, pipeline::RenderError>,
    ) -> bool {
        if generation < self.shown_generation {
            return false;
        }
        self.shown_generation = generation;
        match result {
            Ok(r) => {
                let old = (
                    self.capture.replace(r.capture),
                    std::mem::replace(&mut self.observer, r.observer),
                );
                if let Some(w) = &self.worker {
                    // Their storage serves the next renders, and is freed off this thread.
                    old.0.into_iter().for_each(|c| w.recycle(c, false));
                    old.1.into_iter().for_each(|c| w.recycle(c, true));
                }
                self.shown_draft = r.draft;
                self.receive_reference(r.reference, generation >= self.step_generation);
                self.view_resolution.capture = r.view_resolution;
                self.buffers = r.buffers;
                self.variants = r.variants;
                self.times = Some(r.times);
                self.error = None;
                if let (Some((x, y)), Some(c)) = (self.selection.pixel, &self.capture)
                    && (x >= c.width() || y >= c.height())
                {
                    self.selection.pixel = None;
                }
            }
            Err(e) => self.error = Some(crate::vocabulary::run::render_error(&e, self.lang)),
        }
        true
    }

    pub(super) fn go_to(&mut self, stage: Stage) {
        let sel = &mut self.selection;
        if stage != sel.stage {
            let animate =
                stage.space().is_some() && sel.stage.space().is_some() && stage == sel.stage.next();
            sel.stage = stage;
            sel.transition = if animate { 0.0 } else { 1.0 };
            if stage.space().is_none() {
                sel.buffer = stage.default_buffer();
            }
        }
    }
}

/// Where a scene file was loaded from, for the title.
#[must_use]
pub fn source_name(path: Option<&PathBuf>) -> String {
    path.map_or_else(
        || crate::lesson::DEFAULT_LESSON_NAME.to_owned(),
        |p| p.display().to_string(),
    )
}
