//! One scene under study, for every front end: the preset it came from, its exact
//! solution and derived values, the measured series beside it, and the analyses that
//! take longer than a frame (methods rows, the overlay run, the fits), computed lazily
//! on worker threads and dropped when the scene changes. What the views draw from a
//! solution (curve samples, the regime grid, the ghost ball's track) is cached here
//! per scene and size, never recomputed per frame. `Lab` itself (the scene, its
//! parameters, the pin, what a saved preset holds) is here; the analyses' jobs are in `analyses`, the
//! span rule in `span`, the views' caches and the ghost track in `views`.

mod analyses;
pub mod jobs;
mod span;
mod views;

use std::cell::RefCell;
use std::sync::Arc;

use crate::methods::Method;
use crate::physics::derived::{Derived, Regime};
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{EnergySplit, Snapshot, Solution};
use crate::settings::params::{Key, SceneError, SceneSpec};
use crate::study::compare::Row;
use crate::study::fit::{FitError, Fits, ModelFit};
use crate::study::measured::{self, InScene, Measured, Series};
use crate::study::preset::Preset;
use analyses::Generation;
use jobs::{Job, Jobs};

pub use analyses::{
    ExportResult, Exported, METHOD_VIEW_LEVELS, OVERLAY_LEVELS, Overlay, level_settings,
};
pub use span::SpanEnd;
pub use views::Story;

use span::{preset_span_end, solve_shown};
use views::{Cached, data_rms, extent};

/// The line fit's window, s: from, to (`None`: the sliding phase's end).
pub type FitWindow = (Option<f64>, Option<f64>);

/// A scene pinned for comparison (A/B): drawn dimmed beside the current one.
#[derive(Clone, Debug)]
pub struct Pinned {
    pub scene: Scene,
    pub solution: Arc<Solution>,
    /// The preset it started from.
    pub label: String,
    /// Where its automatic span ends (the current automatic span reaches it too).
    pub auto_end: f64,
}

/// One scene under study.
#[derive(Clone, Debug)]
pub struct Lab {
    pub preset: Preset,
    pub scene: Scene,
    /// The span shown: `t_end` is always the shown end (see [`SpanEnd`]).
    pub span: Span,
    pub span_end: SpanEnd,
    /// The run pinned for an A/B comparison.
    pub pinned: Option<Pinned>,
    pub solution: Arc<Solution>,
    pub derived: Derived,
    /// The x range (m) the balls cover over the span.
    pub extent: (f64, f64),
    /// RMS residuals of v_cm and v_t against the measured points.
    /// (`None` for v_t when the series has none: a track without a rim mark).
    pub data_rms: Option<(f64, Option<f64>)>,
    /// The measured series' rest band (speeds within it cannot be told from rest).
    pub rest_band: Option<f64>,
    /// The run's headline, what follows the first impact, and the verdict.
    pub story: Story,
    /// The pinned run's parameters that differ from the current ones.
    pinned_changes: Vec<(&'static str, String, String)>,
    /// The measured series, ready for any scene (a preset's, or `--data`).
    series: Option<Series>,
    /// The measured series in this scene (`measured::for_scene`).
    data: Option<InScene>,
    /// Line-fit window (None: the sliding phase).
    pub fit_window: FitWindow,
    want_methods: bool,
    want_fits: bool,
    overlay_choice: Option<(Method, u8)>,
    /// The worker pool's jobs of this lab, and the scene they are asked for.
    jobs: Jobs,
    generation: Generation,
    methods: Job<Generation, Vec<Row>>,
    /// `None` only for a run that was cancelled before it finished.
    overlay: Job<(Generation, Method, u8), Option<Overlay>>,
    fits: Job<(Generation, FitWindow), Result<Fits, FitError>>,
    /// The model fitted to a position track's positions (none for a velocity file).
    position_fit: Job<Generation, Result<ModelFit, FitError>>,
    /// A file the app is writing (run CSV, chart SVG): the status message, or why not;
    /// each export its own request.
    export: Job<u64, ExportResult>,
    exports: u64,
    samples: Cached<usize, Snapshot>,
    energies: Cached<usize, (f64, EnergySplit)>,
    pinned_samples: Cached<usize, Snapshot>,
    pinned_kinetic: Cached<usize, (f64, f64)>,
    regimes: Cached<(usize, usize), Regime>,
}

impl Lab {
    /// The lab on `scene`; a `t_end` in `span` counts as the preset's (see [`SpanEnd`];
    /// [`Lab::set_span_end`] makes it explicit).
    pub fn new(preset: Preset, scene: Scene, span: Span) -> Lab {
        let series = preset_series(&preset);
        Lab::with_data(preset, scene, span, series)
    }

    /// The lab on `scene` with a measured series of the user's (`--data`) in place of
    /// the preset's.
    pub fn with_data(preset: Preset, scene: Scene, span: Span, series: Option<Series>) -> Lab {
        let span_end = preset_span_end(&span);
        let data = series.as_ref().map(|s| measured::for_scene(s, &scene));
        let solution = Arc::new(solve_shown(
            &scene,
            &span,
            span_end,
            data.as_ref().map(|d| &*d.measured),
            None,
        ));
        let span = Span {
            t_start: span.t_start,
            t_end: Some(solution.t_end),
        };
        let derived = Derived::of(&scene);
        // Placeholders: `cache` fills these from the finished lab.
        let story = Story::of(&solution, &derived, None);
        let mut lab = Lab {
            preset,
            scene,
            span,
            span_end,
            pinned: None,
            derived,
            solution,
            extent: (0.0, 0.0),
            data_rms: None,
            rest_band: None,
            story,
            pinned_changes: Vec::new(),
            series,
            data,
            fit_window: (None, None),
            want_methods: false,
            want_fits: false,
            overlay_choice: None,
            jobs: Jobs::default(),
            generation: 0,
            methods: Job::default(),
            overlay: Job::default(),
            fits: Job::default(),
            position_fit: Job::default(),
            export: Job::default(),
            exports: 0,
            samples: RefCell::default(),
            energies: RefCell::default(),
            pinned_samples: RefCell::default(),
            pinned_kinetic: RefCell::default(),
            regimes: RefCell::default(),
        };
        lab.cache();
        lab
    }

    /// The measured series in the scene shown (kept while parameters change, so a
    /// model can be tuned against it by hand; a track's v_t follows r).
    pub fn measured(&self) -> Option<&Measured> {
        self.data.as_ref().map(|d| &*d.measured)
    }

    /// [`Lab::measured`], shared (a job takes it without copying the series).
    fn measured_arc(&self) -> Option<Arc<Measured>> {
        self.data.as_ref().map(|d| Arc::clone(&d.measured))
    }

    /// The measured series as loaded, before any scene (what a position track's
    /// derivation found is in it).
    pub fn series(&self) -> Option<&Series> {
        self.series.as_ref()
    }

    /// The current value of a parameter, SI (`t_end`: the shown end).
    pub fn value(&self, key: Key) -> f64 {
        key.get(&self.scene, &self.span)
            .expect("the lab's span always has its shown end")
    }

    /// Sets a parameter if the scene stays valid. Setting `t_end` fixes the span's end;
    /// any other parameter ends a preset's `t_end` (the span follows the physics again).
    pub fn set(&mut self, key: Key, value: f64) -> Result<(), SceneError> {
        self.set_all(&[(key, value)])
    }

    /// Sets several parameters at once, all or none: the scene is checked with every
    /// change in it, and solved once.
    pub fn set_all(&mut self, changes: &[(Key, f64)]) -> Result<(), SceneError> {
        let fixed = match self.span_end {
            SpanEnd::Fixed { t_end, .. } => Some(t_end),
            _ => None,
        };
        let given = Span {
            t_start: self.span.t_start,
            t_end: fixed,
        };
        let mut spec = SceneSpec::of(&self.scene, &given);
        for &(key, value) in changes {
            spec.set(key, value);
        }
        let (scene, span) = spec.resolve()?;
        for &(key, value) in changes {
            self.span_end = match (key, self.span_end) {
                (Key::TEnd, _) => SpanEnd::Fixed {
                    t_end: value,
                    from_preset: false,
                },
                (Key::TStart, end) => end,
                (
                    _,
                    SpanEnd::Fixed {
                        from_preset: true, ..
                    },
                ) => SpanEnd::Auto,
                (_, end) => end,
            };
        }
        self.load(scene, span);
        Ok(())
    }

    /// Chooses how the span ends (the span key, or `--t-end`), keeping the scene.
    pub fn set_span_end(&mut self, end: SpanEnd) -> Result<(), SceneError> {
        if let SpanEnd::Fixed { t_end, .. } = end
            && !(t_end > self.span.t_start && t_end <= 1e6)
        {
            return Err(SceneError::OutOfRange {
                name: "t_end",
                value: format!("{t_end} s"),
                allowed: format!("t_start = {} s < t_end ≤ 1e6 s", self.span.t_start),
            });
        }
        self.span_end = end;
        self.load(self.scene, self.span);
        Ok(())
    }

    /// Starts over from `preset` (its `t_end`, if any, holds until a parameter changes).
    pub fn load_preset(&mut self, preset: Preset) -> Result<(), SceneError> {
        let (scene, span) = preset.spec.resolve()?;
        self.series = preset_series(&preset);
        self.preset = preset;
        self.fit_window = (None, None);
        self.span_end = preset_span_end(&span);
        self.load(scene, span);
        Ok(())
    }

    /// Pins the current run for an A/B comparison, or unpins it; true if now pinned.
    pub fn toggle_pin(&mut self) -> bool {
        self.pinned = match self.pinned {
            Some(_) => None,
            None => Some(Pinned {
                scene: self.scene,
                solution: self.solution.clone(),
                label: self.preset.name.clone(),
                // Its own automatic end, not the shown one: a scaled span must not
                // compound through the pin.
                auto_end: solve_shown(
                    &self.scene,
                    &self.span,
                    SpanEnd::Auto,
                    self.measured(),
                    None,
                )
                .t_end,
            }),
        };
        // The automatic span covers the pinned run too: re-solve only if that moves it.
        let sol = solve_shown(
            &self.scene,
            &self.span,
            self.span_end,
            self.measured(),
            self.pinned_end(),
        );
        if sol.t_end == self.solution.t_end {
            self.cache();
        } else {
            self.load(self.scene, self.span);
        }
        self.pinned.is_some()
    }

    /// Where the pinned run's span ends (the automatic span reaches it too).
    fn pinned_end(&self) -> Option<f64> {
        self.pinned.as_ref().map(|p| p.auto_end)
    }

    fn load(&mut self, scene: Scene, span: Span) {
        self.scene = scene;
        // The measured series for this scene: a track's v_t needs its r.
        self.data = self.series.as_ref().map(|s| measured::for_scene(s, &scene));
        let solution = solve_shown(
            &scene,
            &span,
            self.span_end,
            self.measured(),
            self.pinned_end(),
        );
        self.span = Span {
            t_start: span.t_start,
            t_end: Some(solution.t_end),
        };
        self.solution = Arc::new(solution);
        self.derived = Derived::of(&scene);
        self.cache();
        // Every analysis asked for from now on belongs to this solve.
        self.generation += 1;
        if !self.want_methods {
            self.methods.cancel();
        }
        self.restart();
    }

    /// What the views need from a solve that does not change from frame to frame.
    fn cache(&mut self) {
        self.extent = extent(&self.solution, self.scene.radius);
        if let Some(p) = &self.pinned {
            // The pinned balls are drawn too: the scene's scale covers both runs.
            let mut pinned = (*p.solution).clone();
            (pinned.t_start, pinned.t_end) = (self.solution.t_start, self.solution.t_end);
            let (lo, hi) = extent(&pinned, p.scene.radius);
            self.extent = (self.extent.0.min(lo), self.extent.1.max(hi));
        }
        self.data_rms = self.measured().map(|m| data_rms(&self.solution, m));
        self.rest_band = self.data.as_ref().map(|d| d.rest_band);
        self.story = Story::of(&self.solution, &self.derived, self.rest_band);
        self.pinned_changes = self.changes_from_pinned();
        self.samples.replace(None);
        self.energies.replace(None);
        self.pinned_samples.replace(None);
        self.pinned_kinetic.replace(None);
        self.regimes.replace(None);
    }

    /// The settings a saved preset holds: every value of the scene and the span's
    /// start, and its end only if it was set (not the automatic one).
    pub fn saved_spec(&self) -> SceneSpec {
        let t_end = match self.span_end {
            SpanEnd::Fixed { t_end, .. } => Some(t_end),
            _ => None,
        };
        SceneSpec::of(
            &self.scene,
            &Span {
                t_start: self.span.t_start,
                t_end,
            },
        )
    }
}

/// A preset's own measured series (velocities as the paper gives them).
fn preset_series(preset: &Preset) -> Option<Series> {
    preset
        .measured
        .clone()
        .map(|m| Series::Velocities(Arc::new(m)))
}
