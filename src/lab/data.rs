//! Which measured data a scene shows, and the groove they were measured in. Data
//! belong to their groove where it is known: a preset's to the preset's, a file's to
//! the one its `# scene` lines state. (A file without them is in the groove the user
//! gives, by the options or in the app: the student's own claim, which moves with
//! their edits.) Data stay through every edit of the scene (so a student can fit by
//! hand, and the RMS follows), and wherever the model's groove is not theirs,
//! [`OtherGroove`] says so on every screen that shows them, the same whether the
//! scene was reached by options or by keys. Once the user drops their own data, the
//! preset's come back only while the model's groove is the preset's: in any other the
//! scene shows no data ([`in_use`]).

use super::origin::Origin;
use super::settings::Layers;
use crate::physics::scene::Scene;
use crate::settings::params::Key;
use crate::settings::spec::{SceneError, SceneSpec};
use crate::settings::units::{Dimension, show, show_below};
use std::sync::Arc;

use crate::study::measured::{Measured, Series};
use crate::study::preset::Preset;

/// A measured series of the user's own (`--data`), kept when another preset is
/// picked for the model, until the user drops it.
#[derive(Clone, Debug)]
pub struct OwnData {
    /// The file(s) it was read from, as the user named them.
    pub name: String,
    pub series: Series,
    /// The groove it was measured in, where the file says so (its `# scene` lines);
    /// `None`: the data are in the groove the user sets (by the options or in the
    /// app), which moves with it.
    pub groove: Option<Groove>,
}

impl OwnData {
    /// Said wherever the data are named when the file was read turned: mirrored (its
    /// ball approaches the other toward −x: "x runs toward −x in FILE: read
    /// mirrored"), its v_t signed the other way round ("… read turned"), one line each.
    pub fn reading_notes(&self) -> Option<String> {
        let mirrored = self.series.mirrored().then(|| {
            format!(
                "x runs toward −x in {}: read mirrored (x → −x, the ball approaching toward +x as in the model)",
                self.name
            )
        });
        let turned = self.series.spin_turned().then(|| {
            format!(
                "v_t runs opposite to v_cm in {} while the ball rolls before the impact (where v_t = v_cm): read turned (v_t → −v_t)",
                self.name
            )
        });
        match (mirrored, turned) {
            (Some(a), Some(b)) => Some(format!("{a}\n{b}")),
            (a, b) => a.or(b),
        }
    }
}

/// The user's data that can be read and shown but not fitted (no impact found, too
/// few frames on a side of it, a unit in doubt): the app opens with them rather than
/// refusing, shows what it can (the table, the centre's v_cm in the file's own time)
/// and says why there is no fit and what to give.
#[derive(Clone, Debug)]
pub struct Unfit {
    /// The file(s), as the user named them.
    pub name: String,
    /// Why there is no fit, with what to give: the line the fit's refusal says.
    pub why: String,
    /// The centre's velocities in the file's own time (`measured::in_file_time`);
    /// `None` where the file's lengths are not known to be metres, or it is too short.
    pub in_file_time: Option<Arc<Measured>>,
}

/// A groove's geometry, m: the balls' radius R and the groove's width b (what a
/// measured series depends on beyond the run itself: b sets the contact radius r, R
/// turns a track's spin into v_t).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Groove {
    pub radius: f64,
    pub width: f64,
    /// Whether R and b were stated (a data file's `# scene` lines may give one of
    /// them; the other is then the preset's, and no measurement of the data's).
    #[serde(skip)]
    pub stated: [bool; 2],
}

impl Groove {
    pub fn of(scene: &Scene) -> Groove {
        Groove {
            radius: scene.radius,
            width: scene.width,
            stated: [true; 2],
        }
    }

    /// The same groove: R and b agree to far below any measurement (a value typed
    /// in another unit, 4.9 cm or 49 mm, rounds differently in its last bits), where
    /// both state them.
    pub fn same(&self, other: &Groove) -> bool {
        self.differing(other).next().is_none()
    }

    /// The values both state that differ: (name, this one's, the other's).
    fn differing<'a>(
        &'a self,
        other: &'a Groove,
    ) -> impl Iterator<Item = (&'static str, f64, f64)> + 'a {
        [
            ("R", self.radius, other.radius, 0),
            ("b", self.width, other.width, 1),
        ]
        .into_iter()
        .filter(move |&(_, a, b, i)| {
            self.stated.get(i).copied().unwrap_or(true)
                && other.stated.get(i).copied().unwrap_or(true)
                && !Groove::near(a, b)
        })
        .map(|(name, a, b, _)| (name, a, b))
    }

    fn near(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-9 * a.abs().max(b.abs())
    }

    /// "R = 2.75 cm, b = 4.9 cm".
    pub fn describe(&self) -> String {
        format!(
            "R = {}, b = {}",
            show(self.radius, Dimension::Length),
            show(self.width, Dimension::Length)
        )
    }

    /// The preset's own groove (`None` if its values make no valid scene).
    pub fn of_preset(preset: &Preset) -> Option<Groove> {
        preset
            .spec
            .resolve()
            .ok()
            .map(|(scene, _)| Groove::of(&scene))
    }
}

/// Whose measured data a scene shows.
#[derive(Clone, Debug, PartialEq)]
pub enum Whose {
    /// The user's own, read from the file(s) named.
    Own(String),
    /// A preset's, by its name.
    Preset(String),
}

/// The measured series a scene shows, whose it is and the groove it was measured in.
#[derive(Clone, Debug)]
pub struct InUse {
    pub series: Series,
    pub whose: Whose,
    /// `None`: not known (data read without a scene named).
    pub groove: Option<Groove>,
}

/// The data shown were measured in another groove than the model's: what every
/// screen showing them says (see [`OtherGroove::describe`]).
#[derive(Clone, Debug, PartialEq)]
pub struct OtherGroove {
    pub whose: Whose,
    pub data: Groove,
    pub model: Groove,
}

impl OtherGroove {
    /// The note for data `in_use` against a model in `model`; `None` when they were
    /// measured in this groove, or in one not known.
    pub fn of(in_use: &InUse, model: Groove) -> Option<OtherGroove> {
        let data = in_use.groove?;
        (!data.same(&model)).then(|| OtherGroove {
            whose: in_use.whose.clone(),
            data,
            model,
        })
    }

    /// One sentence naming the values that differ, e.g. "paper-b4.9's data were
    /// measured at b = 4.9 cm; the model uses b = 2 cm".
    pub fn describe(&self) -> String {
        let (d, m) = (&self.data, &self.model);
        let len = |v: f64| show(v, Dimension::Length);
        let mut data = Vec::new();
        let mut model = Vec::new();
        // Only what the data state: a value their file leaves out is the preset's,
        // and the data were never "measured at" it.
        // A width just under 2R keeps the digits that tell it from 2R.
        let shown = |name: &str, v: f64, g: &Groove| match name {
            "b" => show_below(v, 2.0 * g.radius, Dimension::Length),
            _ => len(v).to_string(),
        };
        for (name, a, b) in d.differing(m) {
            data.push(format!("{name} = {}", shown(name, a, d)));
            model.push(format!("{name} = {}", shown(name, b, m)));
        }
        let whose = match &self.whose {
            Whose::Preset(name) => format!("{name}'s data were"),
            Whose::Own(_) => "the data were".to_string(),
        };
        format!(
            "{whose} measured at {}; the model uses {}",
            data.join(", "),
            model.join(", ")
        )
    }
}

/// The data a scene in groove `model` shows: the user's own while they are loaded and
/// not dropped; else the preset's, except after a drop in a groove not the preset's
/// (someone else's points against the student's groove would read as a fit of it).
pub(super) fn in_use(
    own: Option<&OwnData>,
    dropped: bool,
    preset: &Preset,
    model: Groove,
) -> Option<InUse> {
    if let Some(own) = own.filter(|_| !dropped) {
        return Some(InUse {
            series: own.series.clone(),
            whose: Whose::Own(own.name.clone()),
            groove: own.groove,
        });
    }
    let groove = Groove::of_preset(preset);
    let fits = groove.is_some_and(|g| g.same(&model));
    if dropped && own.is_some() && !fits {
        return None;
    }
    let measured = preset.measured.clone()?;
    Some(InUse {
        series: Series::Velocities(std::sync::Arc::new(measured)),
        whose: Whose::Preset(preset.name.clone()),
        groove,
    })
}

/// The same data as before an edit: the analyses of a series are kept while it is in
/// use (a preset's is made anew each time, so it is compared by value; the user's own
/// never change within a lab).
pub(super) fn same_data(a: Option<&InUse>, b: Option<&InUse>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => {
            a.whose == b.whose
                && a.groove == b.groove
                && (matches!(a.whose, Whose::Own(_)) || a.series == b.series)
        }
        _ => false,
    }
}

/// The approach speed of `series` (the scene's v0 it measures): a track's line through
/// the frames before the first impact, a velocity series' mean v_cm over them
/// ([`crate::study::fit::of_velocities`]); `None` where the data do not show it.
pub fn approach(series: &Series) -> Option<crate::study::fit::Approach> {
    use crate::study::fit::{Approach, of_velocities};
    match series {
        Series::Track(_, found) => Approach::of_track(
            found.approach_speed,
            found.approach_speed_se,
            found.frames_before,
        ),
        Series::Velocities(m) => of_velocities(m.t(), m.v_cm()),
    }
}

/// The scene values a series measures itself: both balls' v0 from the left ball's
/// approach ([`approach`]; the right ball is not tracked, and the lab's scenes are
/// symmetric); none where the data do not show the approach.
pub fn measured_values(series: &Series) -> SceneSpec {
    match approach(series) {
        Some(a) => SceneSpec::default().with(Key::V0, a.speed),
        None => SceneSpec::default(),
    }
}

/// A value given (an option, the data file's `# scene` line, an edit in the app)
/// that the data contradict: the left ball's v0 farther from their approach speed
/// than its ± 2σ and [`V0_AGREES`] of it (the given value is used: a flag wins over
/// the data).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contradiction {
    /// The left ball's v0 given, m/s.
    pub value: f64,
    /// Who gave it.
    pub origin: Origin,
    /// What the data measure.
    pub approach: crate::study::fit::Approach,
}

impl Contradiction {
    /// The contradiction of `scene`'s v0, set as `settings` say, by the data `series`.
    pub fn of(settings: &Layers, series: Option<&Series>, scene: &Scene) -> Option<Contradiction> {
        let approach = approach(series?)?;
        let origin = settings.origin(Key::V0Left);
        let value = scene.left.v0;
        (matches!(origin, Origin::Flag | Origin::File | Origin::Edited)
            && (value - approach.speed).abs()
                > 2.0 * approach.se + V0_AGREES * approach.speed.abs())
        .then_some(Contradiction {
            value,
            origin,
            approach,
        })
    }

    /// "the left ball's v0 = 0.79 m/s (BY) contradicts the data: they approach at
    /// 0.448 ± 0.002 m/s (± 2σ, 25 frames before the impact); the value given is used".
    pub fn describe(&self, by: &str) -> String {
        let a = &self.approach;
        let (speed, pm) = crate::settings::units::with_uncertainty(a.speed, 2.0 * a.se, 3);
        format!(
            "the left ball's v0 = {} ({by}) contradicts the data: they approach at {speed} ± {pm} m/s (± 2σ, {} frames before the impact); the value given is used",
            show(self.value, Dimension::Speed),
            a.frames
        )
    }
}

/// How far a given v0 may lie from the data's approach speed, beyond its ± 2σ, as a
/// share of it, and still agree: a tenth of a percent. A value is written to a few
/// digits (the app's export writes its scene to 6, so its exact run read back said
/// "v0 = 0.6101 m/s contradicts the data: they approach at 0.610143 ± < 1e-6 m/s"),
/// and no fit moves by that.
pub const V0_AGREES: f64 = 1e-3;

/// The scene's R must leave a tracked rim mark on the ball
/// ([`crate::study::measured::Found::least_radius`]): an R edited below it would turn
/// the mark's spin into a v_t wrong by their ratio, so the edit is refused, naming
/// the least R allowed.
pub(super) fn mark_on_the_ball(in_use: Option<&InUse>, scene: &Scene) -> Result<(), SceneError> {
    let Some(found) = in_use.and_then(|d| d.series.found()) else {
        return Ok(());
    };
    match (found.mark_radius, found.least_radius()) {
        (Some(mark), Some(least)) if scene.radius < least => Err(SceneError::MarkOffTheBall {
            radius: scene.radius,
            least,
            mark,
        }),
        _ => Ok(()),
    }
}
