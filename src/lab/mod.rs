//! One scene under study, for every front end: its settings layers (`settings`: the
//! preset, the command line, the app's edits), the one immutable snapshot built from
//! them (`resolved`: the scene, its exact solution and derived values, the measured
//! series derived for it), and the analyses that take longer than a frame (methods
//! rows, the overlay run, the fits) as work for jobs on a worker pool. An edit sets a
//! layer and builds a new snapshot; `Lab` derefs to it, so a view reads `lab.scene`,
//! `lab.solution`, `lab.story` from the one snapshot. The lab holds no job and knows
//! no view: whoever shows an analysis requests it (`jobs`), keyed by the snapshot's
//! [`Lab::generation`]; the analyses' work is in `analyses` and `work`, the span rule
//! in `span`; what depends on the terminal's size is cached by the app, not here.

pub mod analyses;
mod data;
pub mod jobs;
mod origin;
mod resolved;
mod settings;
mod span;
mod work;

use std::ops::Deref;
use std::sync::Arc;

use crate::settings::params::Key;
use crate::settings::spec::{SceneError, SceneSpec};
use crate::study::measured::Series;
use crate::study::preset::Preset;

pub use data::{
    Contradiction, Groove, InUse, OtherGroove, OwnData, Unfit, Whose, approach, measured_values,
};
pub use origin::Origin;
pub use resolved::{ChartPoint, MeasuredPoints, Pinned, Resolved, Story, differences, value_range};
pub use settings::{Edit, Layers};
pub use span::SpanEnd;
pub use work::{
    ExportResult, Exported, FitWindowError, METHOD_VIEW_LEVELS, OVERLAY_LEVELS, Overlay,
    level_settings,
};

use span::solve_shown;

/// The scene a job belongs to: it counts up with every new solve, so a request made
/// for an earlier scene never matches a newer one.
pub type Generation = u64;

/// The line fit's window, s: from, to (`None`: the sliding phase's end).
pub type FitWindow = (Option<f64>, Option<f64>);

/// One scene under study.
#[derive(Clone, Debug)]
pub struct Lab {
    settings: Layers,
    /// The user's own series, used instead of the preset's until dropped.
    own_data: Option<OwnData>,
    /// The data in use by the rule of `data::in_use`, shared by every snapshot built
    /// from it.
    in_use: Option<InUse>,
    /// The user's data that could be read but not fitted, shown without a fit.
    unfit: Option<Unfit>,
    /// The user's own data on their way, by name (a `--data` video tracked on a
    /// worker): the preset's series is not shown meanwhile, nor after the tracking
    /// fails, until dropped.
    awaiting: Option<String>,
    /// The run pinned for an A/B comparison.
    pub pinned: Option<Pinned>,
    /// The current snapshot, built from the layers by [`Resolved::build`].
    now: Arc<Resolved>,
    /// The scene the current snapshot solves: counts up when its scene, span or data
    /// change (not for a pin), so an analysis asked for an earlier one is stale.
    generation: Generation,
}

/// The lab reads as its current snapshot: `lab.scene`, `lab.solution`, `lab.story`.
impl Deref for Lab {
    type Target = Resolved;

    fn deref(&self) -> &Resolved {
        &self.now
    }
}

impl Lab {
    /// The lab on its settings, with the user's own series (`--data`) in place of the
    /// preset's, if any.
    pub fn new(settings: Layers, own_data: Option<OwnData>) -> Result<Lab, SceneError> {
        let in_use = choose(&settings, own_data.as_ref(), false)?;
        let now = Arc::new(Resolved::build(&settings, in_use.as_ref(), None)?);
        Ok(Lab {
            settings,
            own_data,
            in_use,
            unfit: None,
            awaiting: None,
            pinned: None,
            now,
            generation: 0,
        })
    }

    /// The lab on a preset as it is (no flags, no data of the user's).
    pub fn of_preset(preset: Preset) -> Result<Lab, SceneError> {
        Lab::new(Layers::new(preset, SceneSpec::default()), None)
    }

    /// The lab with the user's data that could be read but not fitted (`--data` of a
    /// track with no impact): shown in the file's own time, with no fit.
    pub fn with_unfit(mut self, unfit: Unfit) -> Lab {
        // They are the user's data: the preset's are not shown beside them.
        self.set_unfit(unfit);
        self
    }

    /// The lab awaiting the user's own data, `name` (a `--data` video tracked on a
    /// worker): until they arrive, and if they never do (the tracking refused), no
    /// series is shown: the preset's points would read as the user's. Dropping the
    /// data (`Lab::drop_data`) brings the preset's back.
    pub fn awaiting_own_data(mut self, name: String) -> Lab {
        self.awaiting = Some(name);
        self.no_values_from_data();
        self
    }

    /// Names no value the scene takes the data's (the preset's series gave v0 'd')
    /// and assumes the masses, as for the user's data; where the preset's v0 comes
    /// from its series alone (a preset file without one), its series' values stay.
    fn no_values_from_data(&mut self) {
        let before = self.settings.from_data.replace(SceneSpec::default());
        if self.rebuild().is_err() {
            self.settings.from_data = before;
            self.rebuild()
                .expect("the values from the data before were valid");
        }
    }

    /// The user's data without a fit arriving after the lab opened (a video tracked
    /// on a worker whose clip shows no impact): as [`Lab::with_unfit`].
    pub fn set_unfit(&mut self, unfit: Unfit) {
        self.unfit = Some(unfit);
        // The user's data are in use and measure nothing the scene takes.
        self.no_values_from_data();
    }

    /// The name of the user's data still awaited (or refused), unless they came or
    /// were dropped.
    fn awaited(&self) -> Option<&String> {
        self.awaiting
            .as_ref()
            .filter(|_| self.own_data.is_none() && !self.settings.data_dropped())
    }

    /// The user's data shown without a fit, unless dropped or replaced by data of
    /// their own that can be fitted.
    pub fn unfit(&self) -> Option<&Unfit> {
        self.unfit
            .as_ref()
            .filter(|_| self.own_data.is_none() && !self.settings.data_dropped())
    }

    /// The current snapshot, shared (a job or a view cache keeps it whole).
    pub fn resolved(&self) -> &Arc<Resolved> {
        &self.now
    }

    /// Which solve the current snapshot is: an analysis is keyed by it (a pin keeps
    /// it, an edit of the scene, its span or its data moves it on).
    pub fn generation(&self) -> Generation {
        self.generation
    }

    /// The preset the scene starts from.
    pub fn preset(&self) -> &Preset {
        self.settings.preset()
    }

    /// The name a file of this scene is suggested under: the preset's, or for the
    /// user's own scene (their data, in the scene their file's `# scene` lines or the
    /// options give) the data file's, without its extension.
    pub fn scene_name(&self) -> String {
        let own_scene = self
            .settings
            .flags_in_force()
            .is_some_and(|f| f.given().next().is_some());
        match self.own_data() {
            Some(own) if own_scene => {
                let first = own.name.split(" + ").next().unwrap_or(&own.name);
                std::path::Path::new(first)
                    .file_stem()
                    .map_or(first.into(), |s| s.to_string_lossy().into_owned())
            }
            _ => self.preset().name.clone(),
        }
    }

    /// The settings layers.
    pub fn settings(&self) -> &Layers {
        &self.settings
    }

    /// The user's own measured series, if one is loaded and not dropped.
    pub fn own_data(&self) -> Option<&OwnData> {
        self.own_data
            .as_ref()
            .filter(|_| !self.settings.data_dropped())
    }

    /// The measured series in use, as loaded, before any scene: the user's own, else
    /// the preset's (what a position track's derivation found is in it).
    pub fn series(&self) -> Option<&Series> {
        self.in_use.as_ref().map(|d| &d.series)
    }

    /// The data in use, whose they are and the groove they were measured in.
    pub fn data_in_use(&self) -> Option<&InUse> {
        self.in_use.as_ref()
    }

    /// Sets a parameter if the scene stays valid (an edit: `undo` takes it back).
    /// Setting `t_end` fixes the span's end; any other value of the scene ends a
    /// preset's `t_end` (the span follows the physics again).
    pub fn set(&mut self, key: Key, value: f64) -> Result<(), SceneError> {
        self.set_all(&[(key, value)])
    }

    /// Sets several parameters at once, all or none: the scene is checked with every
    /// change in it, and solved once.
    pub fn set_all(&mut self, changes: &[(Key, f64)]) -> Result<(), SceneError> {
        self.edit(Edit::Values(changes.to_vec()))
    }

    /// As [`Lab::set_all`], the values a fit gave ([`Edit::Fitted`]): one the data
    /// in use measure (v0) stays the data's.
    pub fn set_fitted(&mut self, changes: &[(Key, f64)]) -> Result<(), SceneError> {
        self.edit(Edit::Fitted(changes.to_vec()))
    }

    /// Chooses how the span ends (the span key), keeping the scene.
    pub fn set_span_end(&mut self, end: SpanEnd) -> Result<(), SceneError> {
        self.edit(Edit::SpanEnd(end))
    }

    /// Puts `edit` on the app's layer if the scene stays valid. Values or a span end
    /// that leave the scene, its start and how its span ends as they are add no layer
    /// entry (a repeated key is not a change for undo to take back; the shown end
    /// follows from these).
    fn edit(&mut self, edit: Edit) -> Result<(), SceneError> {
        let may_repeat = matches!(edit, Edit::Values(_) | Edit::Fitted(_) | Edit::SpanEnd(_));
        self.settings.push(edit);
        if may_repeat
            && let Ok((scene, span, end)) = self.settings.settle()
            && (scene, span.t_start, end)
                == (self.now.scene, self.now.span.t_start, self.now.span_end)
        {
            self.settings.undo();
            return Ok(());
        }
        let built = self.rebuild();
        if built.is_err() {
            self.settings.undo();
        }
        built
    }

    /// Takes back the newest edit; `None` when there is none. A preset picked or
    /// the data dropped is taken back with its data choice: the series in use is the
    /// one before it again.
    pub fn undo(&mut self) -> Option<Edit> {
        let edit = self.settings.undo()?;
        // The layers below it made a valid scene before it was added.
        self.rebuild().expect("the scene before an edit was valid");
        Some(edit)
    }

    /// Sets aside every edit made in the app (the preset and the command line's
    /// values stay; [`Lab::undo`] brings them back); false if none was in force.
    pub fn reset(&mut self) -> bool {
        if !self.settings.reset() {
            return false;
        }
        self.rebuild().expect("the scene without edits was valid");
        true
    }

    /// Starts over from `preset` alone (its `t_end`, if any, holds until a parameter
    /// changes): an edit, so [`Lab::undo`] goes back to the preset before with its
    /// edits and data; the user's own series stays (see [`Lab::drop_data`]).
    pub fn load_preset(&mut self, preset: Preset) -> Result<(), SceneError> {
        self.edit(Edit::Preset(Box::new(preset)))
    }

    /// Drops the user's own series (an edit: [`Lab::undo`] brings it back): the
    /// preset's data are shown while the groove is the preset's, else none (see
    /// `data::in_use`). The dropped series' name, if there was one.
    pub fn drop_data(&mut self) -> Option<String> {
        let name = match (self.own_data(), self.unfit(), self.awaited()) {
            (Some(own), _, _) => own.name.clone(),
            (None, Some(unfit), _) => unfit.name.clone(),
            // A video still tracked, or refused: its place is given back.
            (None, None, Some(name)) => name.clone(),
            (None, None, None) => return None,
        };
        self.edit(Edit::DropData)
            .expect("dropping the data leaves a valid scene");
        Some(name)
    }

    /// The user's own series arriving after the lab opened (a video tracked on a
    /// worker), as if given at the start: in place of the preset's, the values they
    /// measure (`from_data`) and the file whose `# scene` lines are among the flags
    /// (`scene_file`); the app's edits stay. Nothing changes if the scene would not
    /// be valid with them (a rim mark off a ball of the scene's R).
    pub fn attach_data(
        &mut self,
        own: OwnData,
        from_data: Option<SceneSpec>,
        file_keys: Vec<Key>,
        scene_file: Option<String>,
    ) -> Result<(), SceneError> {
        let before = (
            self.own_data.replace(own),
            std::mem::replace(&mut self.settings.from_data, from_data),
            std::mem::replace(&mut self.settings.file_keys, file_keys),
            std::mem::replace(&mut self.settings.scene_file, scene_file),
        );
        let built = self.rebuild();
        if built.is_err() {
            (
                self.own_data,
                self.settings.from_data,
                self.settings.file_keys,
                self.settings.scene_file,
            ) = before;
            self.rebuild().expect("the scene before the data was valid");
        }
        built
    }

    /// Pins the current run for an A/B comparison, or unpins it; true if now pinned.
    pub fn toggle_pin(&mut self) -> bool {
        self.pinned = match self.pinned {
            Some(_) => None,
            None => Some(Pinned {
                scene: self.scene,
                solution: self.solution.clone(),
                label: self.settings.preset().name.clone(),
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
                derived: self.derived,
                summary: self.summary,
            }),
        };
        self.rebuild().expect("pinning does not change the scene");
        self.pinned.is_some()
    }

    /// Builds the snapshot of the layers, the series in use and the pin; its
    /// generation moves on only if the scene, its span or its data changed.
    fn rebuild(&mut self) -> Result<(), SceneError> {
        let stand_in = self.unfit().is_some() || self.awaited().is_some();
        let chosen = choose(&self.settings, self.own_data.as_ref(), stand_in)?;
        let same = data::same_data(chosen.as_ref(), self.in_use.as_ref());
        let in_use = if same {
            self.in_use.as_ref()
        } else {
            chosen.as_ref()
        };
        let mut now = Resolved::build(&self.settings, in_use, self.pinned.as_ref())?;
        now.show_in_file_time(self.unfit());
        let moved = now.scene != self.now.scene || now.span != self.now.span || !same;
        if !same {
            self.in_use = chosen;
        }
        self.now = Arc::new(now);
        if moved {
            // Every analysis asked for from now on belongs to this solve.
            self.generation += 1;
        }
        Ok(())
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
            &crate::physics::scene::Span {
                t_start: self.span.t_start,
                t_end,
            },
        )
    }
}

/// The data the layers' scene shows, by the rule of `data::in_use` (none where the
/// user's data stand in for the preset's: without a fit, or awaited); an error if its
/// R would put their rim mark off the ball.
fn choose(
    settings: &Layers,
    own: Option<&OwnData>,
    stand_in: bool,
) -> Result<Option<InUse>, SceneError> {
    let (scene, _, _) = settings.settle()?;
    // The user's data without a fit, or still to come, stand in for their own: not
    // the preset's.
    if stand_in {
        return Ok(None);
    }
    let in_use = data::in_use(
        own,
        settings.data_dropped(),
        settings.preset(),
        Groove::of(&scene),
    );
    data::mark_on_the_ball(in_use.as_ref(), &scene)?;
    Ok(in_use)
}
