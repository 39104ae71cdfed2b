//! What the scene and data options open: the settings and scene they give, the data
//! file's own scene under them, the measured series read from `--data`, the one rule
//! for data without a scene, the lab on all of it and the app on the lab.

use std::path::Path;
use std::sync::Arc;

use super::args::{DataArgs, SceneArgs, TrackRole};
use super::error::{BadValue, CliError, Flag, video_scale};
use crate::input::data::Reading;
use crate::lab::{Groove, Lab, Layers, OwnData, Unfit};
use crate::physics::scene::{Scene, Span};
use crate::settings::params::Key;
use crate::settings::spec::SceneSpec;
use crate::settings::units::{Dimension, show};
use crate::study::measured::{Derive, Found, RawSeries, Series, in_file_time};
use crate::study::preset::{self, Preset};
use crate::tui::app::{App, Library, Status};

impl SceneArgs {
    /// The settings layers these options give: the preset, then the values given.
    pub fn settings(&self) -> Result<Layers, CliError> {
        let preset = crate::input::preset::load(self.preset.as_deref().unwrap_or(preset::DEFAULT))?;
        Ok(Layers::new(preset, self.values.clone()))
    }

    /// The preset these options start from, and the scene they make (by the lab's
    /// span rule: a preset's `t_end` holds unless a scene option is given).
    pub fn resolve(&self) -> Result<(Preset, Scene, Span), CliError> {
        let settings = self.settings()?;
        let (scene, span, _) = settings.settle()?;
        Ok((settings.preset().clone(), scene, span))
    }

    /// True if a preset or any scene option is given (a data file names no scene).
    pub fn names_a_scene(&self) -> bool {
        self.preset.is_some() || self.values.given().next().is_some()
    }
}

/// The scene options with the data file's own scene under them: a file that names
/// the scene it was taken in (`# scene NAME = VALUE` lines, as the app's CSV export
/// writes them) needs no `--preset`; an option given on the command line wins.
pub fn with_file_scene(scene: &SceneArgs, data: &DataArgs) -> Result<SceneArgs, CliError> {
    let Some(path) = data.data.first() else {
        return Ok(scene.clone());
    };
    // A video's tracks state the R their scale came from, known before tracking.
    let own = if super::video_data::is_video(path) {
        super::video_data::own_scene(scene, data)?
    } else {
        let text = crate::input::read_user_file(
            path,
            crate::input::FileRole::DataOption,
            crate::input::MAX_FILE_BYTES,
        )?;
        crate::input::data::scene_of(&text, &path.display().to_string())?
    };
    Ok(SceneArgs {
        values: own.over(&scene.values),
        ..scene.clone()
    })
}

/// The measured series that `--data` names (one file, or a centre and a mark track;
/// a video tracked for the scene `scene`), read with the data options, and the scene
/// values its (first) file's `# scene` lines give; `None` without `--data`.
pub fn load_series(
    args: &DataArgs,
    scene: &SceneArgs,
) -> Result<Option<(Series, SceneSpec)>, CliError> {
    let texts = match args.data.as_slice() {
        [] => return Ok(None),
        [_] | [_, _] => args
            .data
            .iter()
            .map(|path| {
                if super::video_data::is_video(path) {
                    return super::video_data::text(path, scene, args)
                        .map(|text| (path.display().to_string(), text));
                }
                crate::input::read_user_file(
                    path,
                    crate::input::FileRole::DataOption,
                    crate::input::MAX_FILE_BYTES,
                )
                .map(|text| (path.display().to_string(), text))
                .map_err(CliError::from)
            })
            .collect::<Result<Vec<_>, _>>()?,
        more => {
            return Err(BadValue::DataTooOften { count: more.len() }.into());
        }
    };
    series_of(&texts, args).map(Some)
}

/// The series of the data texts `(file, text)` (one, or a centre and a mark track)
/// read with the data options, and the first file's `# scene` values.
fn series_of(texts: &[(String, String)], args: &DataArgs) -> Result<(Series, SceneSpec), CliError> {
    // A video's --scale went into its tracking: its tracks are in metres.
    let video = args.data.iter().any(|p| super::video_data::is_video(p));
    let (mut reading, derive) = reading_of(args)?;
    if video {
        reading.scale = None;
    }
    let series = match texts {
        [(file, text)] => crate::input::data::load(text, file, &reading, &derive),
        [centre, mark] => crate::input::data::load_pair(centre, mark, &reading, &derive),
        _ => unreachable!("one or two files"),
    };
    let series = match (series, texts.first()) {
        (Err(e), Some((file, text))) if video => Err(video_scale(e, file, text)),
        (other, _) => other.map_err(CliError::from),
    }?;
    let file = texts[0].0.clone();
    let velocities = matches!(series, Series::Velocities(_));
    options_apply(args, &[(file.clone(), velocities)])?;
    let m = match &series {
        Series::Velocities(m) | Series::Track(m, _) => m,
    };
    m.check_magnitudes()
        .map_err(|source| CliError::Implausible { file, source })?;
    let (file, text) = &texts[0];
    // A video's tracks state the R they were scaled with, which came from an option
    // or the preset, not from a file: it is not the file's own scene.
    let own_scene = if video {
        SceneSpec::default()
    } else {
        crate::input::data::scene_of(text, file)?
    };
    Ok((series, own_scene))
}

/// `--length-unit` and `--time-unit` given with a video are refused: its tracks are
/// made in metres and seconds (`--scale` sets a pixel's length, `--fps` the frame
/// rate); read as another unit they would rescale μ_k a hundredfold. (`data` of
/// several files refuses them only where every file is a video, and reads a video's
/// tracks without them.)
pub fn units_of_a_video(args: &DataArgs, video: &std::path::Path) -> Result<(), CliError> {
    const VIDEO: &str = "a video, tracked in metres and seconds (--scale sets a pixel's length, --fps its frame rate)";
    let given = [
        ("length_unit", args.length_unit.is_some()),
        ("time_unit", args.time_unit.is_some()),
    ];
    match given.iter().find(|(_, g)| *g) {
        Some((id, _)) => Err(CliError::from(super::error::Usage::NotForFile {
            flag: Flag(id),
            file: video.display().to_string(),
            holds: VIDEO,
        })),
        None => Ok(()),
    }
}

/// The data options for what none of the files holds are refused: `files` are each
/// file's name and whether it holds velocities (else a position track). An option
/// that applies to one of them is taken (`data` reads several files with one set).
pub fn options_apply(args: &DataArgs, files: &[(String, bool)]) -> Result<(), CliError> {
    const VELOCITIES: &str = "velocities (t, v_cm, v_t), whose speeds --speed-unit reads";
    const TRACK: &str =
        "a position track (t, x, y), whose lengths --length-unit (or --scale, for pixels) reads";
    let for_tracks = [
        ("length_unit", args.length_unit.is_some()),
        ("scale", args.scale.is_some()),
        ("track", !args.track.is_empty()),
        ("window", args.window.is_some()),
    ];
    let refused = |velocities: bool, id: &'static str, holds: &'static str| match files
        .iter()
        .find(|(_, v)| *v == velocities)
    {
        Some((file, _)) if files.iter().all(|(_, v)| *v == velocities) => {
            Err(CliError::from(super::error::Usage::NotForFile {
                flag: Flag(id),
                file: file.clone(),
                holds,
            }))
        }
        _ => Ok(()),
    };
    if args.speed_unit.is_some() {
        refused(false, "speed_unit", TRACK)?;
    }
    for (id, given) in for_tracks {
        if given {
            refused(true, id, VELOCITIES)?;
        }
    }
    Ok(())
}

/// How the data options say to read a file, and to derive velocities from a track.
pub fn reading_of(args: &DataArgs) -> Result<(Reading, Derive), CliError> {
    let unit = |text: &Option<String>, dim: Dimension, id: &'static str| {
        text.as_ref()
            .map(|u| {
                crate::input::data::file_unit(u, dim).map_err(|source| BadValue::Unit {
                    flag: Flag(id),
                    text: u.clone(),
                    source,
                })
            })
            .transpose()
    };
    let named = |role: TrackRole| {
        args.track
            .iter()
            .rev()
            .find(|(r, _)| *r == role)
            .map(|(_, n)| n.clone())
    };
    let reading = Reading {
        time_unit: unit(&args.time_unit, Dimension::Time, "time_unit")?,
        speed_unit: unit(&args.speed_unit, Dimension::Speed, "speed_unit")?,
        length_unit: unit(&args.length_unit, Dimension::Length, "length_unit")?,
        scale: args.scale,
        impact_at: args.impact_at,
        centre: named(TrackRole::Centre),
        mark: named(TrackRole::Mark),
        own_lengths: false,
    };
    if let Some(w) = args.window
        && !(w > 0.0 && w <= 1.0)
    {
        return Err(BadValue::OutOfRange {
            flag: Flag("window"),
            value: w,
            dim: Dimension::Time,
            allowed: "a half-width 0 s < T ≤ 1 s",
        }
        .into());
    }
    let derive = Derive {
        half_window: args.window,
        ..Derive::default()
    };
    Ok((reading, derive))
}

/// [`lab`] for a command that has no status line to say which groove it used
/// (`fit`, `compare`): a data file that names no scene is refused, since working in
/// the default preset's groove would be a silent guess.
pub fn lab_of_stated_scene(scene_args: &SceneArgs, data: &DataArgs) -> Result<Lab, CliError> {
    if let Some(path) = scene_of_data(scene_args, data) {
        // A file that no scene could make fittable (accelerations only) says so
        // first: asking for the scene it was measured in would send the user to
        // find one in vain.
        if !super::video_data::is_video(path)
            && let Err(CliError::Data(e)) = load_series(data, scene_args)
            && matches!(
                e.what,
                crate::input::data::DataProblem::AccelerationsOnly(_)
            )
        {
            return Err(CliError::Data(e));
        }
        return Err(BadValue::DataWithoutScene {
            path: path.to_path_buf(),
        }
        .into());
    }
    lab(scene_args, data)
}

/// The lab on the scene the options describe, with `--data` replacing the preset's
/// measured series (the lab derives a position track's v_t with the r of each scene
/// it shows).
pub fn lab(scene_args: &SceneArgs, data: &DataArgs) -> Result<Lab, CliError> {
    let mut settings = scene_args.settings()?;
    let loaded = load_series(data, scene_args)?;
    let joined = join(scene_args, data, &settings, loaded)?;
    settings.scene_file = joined.scene_file;
    settings.from_data = joined.from_data;
    settings.file_keys = joined.file_keys;
    Ok(Lab::new(settings, joined.own)?)
}

/// What loaded data give the lab on `settings`: the user's own series, the values
/// they measure, and the file whose `# scene` lines are among the options.
struct Joined {
    own: Option<OwnData>,
    from_data: Option<SceneSpec>,
    file_keys: Vec<Key>,
    scene_file: Option<String>,
}

fn join(
    scene_args: &SceneArgs,
    data: &DataArgs,
    settings: &Layers,
    loaded: Option<(Series, SceneSpec)>,
) -> Result<Joined, CliError> {
    let mut joined = Joined {
        own: None,
        from_data: None,
        file_keys: Vec::new(),
        scene_file: None,
    };
    // The file's own scene lines are among the options when they were read with them
    // (`with_file_scene`): the scene is then the file's.
    if let Some((_, own_scene)) = &loaded
        && own_scene.given().next().is_some()
        && own_scene
            .given()
            .all(|(k, _)| scene_args.values.given().any(|(j, _)| j == k))
    {
        joined.scene_file = data.data.first().map(|p| p.display().to_string());
    }
    // The data give what they measure (v0) below the options and the file's lines,
    // over whichever preset is the template.
    if let Some((series, own_scene)) = &loaded {
        joined.from_data = Some(crate::lab::measured_values(series));
        // The file's lines among the options (an option typed over one wins, and
        // differs from it).
        joined.file_keys = own_scene
            .given()
            .filter(|&(k, v)| scene_args.values.given().any(|(j, w)| j == k && w == v))
            .map(|(k, _)| k)
            .collect();
    }
    joined.own = loaded.map(|(series, own_scene)| OwnData {
        groove: stated_groove(settings.preset(), &own_scene),
        name: data
            .data
            .iter()
            .map(|p| p.display().to_string())
            .collect::<Vec<_>>()
            .join(" + "),
        series,
    });
    // Said here with the options that set it right; the lab refuses it too (an R
    // edited in the app below the mark's distance).
    if let Some(found) = joined.own.as_ref().and_then(|o| o.series.found()) {
        let mut with = settings.clone();
        with.from_data = joined.from_data.clone();
        mark_on_the_ball(found, with.settle()?.0.radius)?;
    }
    Ok(joined)
}

/// The work of tracking the `--data` video on a worker and reading its tracks as the
/// lab's data, as [`lab`] would have read them (`options`: what it is tracked for).
fn video_work(
    scene_args: &SceneArgs,
    data: &DataArgs,
    options: crate::input::video::tracked::Options,
) -> impl FnOnce(&crate::lab::jobs::Ticket) -> crate::tui::jobs::VideoResult + Send + 'static {
    let (scene_args, data) = (scene_args.clone(), data.clone());
    move |ticket| {
        let path = data.data.first()?.clone();
        let kept = match crate::input::video::cache::tracks(&path, &options, &Ticked(ticket)) {
            Ok(k) => k?,
            Err(refused) => {
                let refused = *refused;
                return Some(Err(crate::tui::jobs::VideoRefused {
                    error: Arc::new(refused.error),
                    first_frame: refused.first_frame.map(Arc::new),
                }));
            }
        };
        let read = || -> Result<crate::tui::jobs::TrackedVideo, CliError> {
            let file = path.display().to_string();
            let texts = [(file.clone(), kept.text.clone())];
            let joined = series_of(&texts, &data)
                .and_then(|loaded| join(&scene_args, &data, &scene_args.settings()?, Some(loaded)));
            let (joined, unfit) = match joined {
                Ok(joined) => (joined, None),
                // Tracks that no fit can use (no impact in the clip): shown without.
                Err(e) => {
                    // Its tracks are in metres: the scale went into the tracking.
                    let (mut reading, _) = reading_of(&data)?;
                    reading.scale = None;
                    let unfit = unfit_of(&file, &kept.text, &reading, e)?;
                    let none = Joined {
                        own: None,
                        from_data: None,
                        file_keys: Vec::new(),
                        scene_file: None,
                    };
                    (none, Some(unfit))
                }
            };
            Ok(crate::tui::jobs::TrackedVideo {
                own: joined.own,
                unfit,
                from_data: joined.from_data,
                file_keys: joined.file_keys,
                scene_file: joined.scene_file,
                view: kept.view.clone(),
            })
        };
        Some(read().map_err(crate::tui::jobs::VideoRefused::of))
    }
}

/// How the app tracks the video again with other options (a click on a ball seeds
/// it): [`video_work`] for them.
fn video_tracker(
    scene_args: &SceneArgs,
    data: &DataArgs,
    options: crate::input::video::tracked::Options,
) -> crate::tui::layer::main::video::VideoTracker {
    let (scene_args, data) = (scene_args.clone(), data.clone());
    crate::tui::layer::main::video::VideoTracker {
        options,
        work: Arc::new(move |o| Box::new(video_work(&scene_args, &data, o))),
    }
}

/// A job's ticket as the tracking's progress: each frame counted, its stop obeyed.
struct Ticked<'a>(&'a crate::lab::jobs::Ticket);

impl crate::study::Progress for Ticked<'_> {
    fn tick(&self, done: u64, total: u64) {
        self.0.progress(done as usize, total as usize);
    }
    fn cancelled(&self) -> bool {
        self.0.cancelled()
    }
}

/// The groove a data file states it was measured in: its `# scene` lines' R and b
/// (the one they leave out is not stated: the preset's value stands in, and is never
/// said to be the data's); `None` if they give neither.
fn stated_groove(preset: &Preset, own_scene: &SceneSpec) -> Option<Groove> {
    let stated = [
        own_scene.get(Key::Radius).is_some(),
        own_scene.get(Key::Width).is_some(),
    ];
    if stated == [false; 2] {
        return None;
    }
    let (scene, _) = preset.spec.over(own_scene).resolve().ok()?;
    Some(Groove {
        stated,
        ..Groove::of(&scene)
    })
}

/// A rim mark tracked farther from the centre than the ball's radius (beyond the
/// noise, [`Found::least_radius`]) is not on this ball.
fn mark_on_the_ball(found: &Found, radius: f64) -> Result<(), CliError> {
    let (Some(mark), Some(least)) = (found.mark_radius, found.least_radius()) else {
        return Ok(());
    };
    let limit = radius + 3.0 * found.scatter;
    if radius < least {
        return Err(BadValue::MarkOffTheBall {
            mark,
            radius,
            limit,
        }
        .into());
    }
    Ok(())
}

/// The app on that lab, with the user's presets. A `--data` video not tracked yet
/// is tracked on a worker while the app runs ([`opened_tracking`]).
pub fn app(scene_args: &SceneArgs, data: &DataArgs) -> Result<App, CliError> {
    match super::video_data::pending(scene_args, data)? {
        Some(options) => opened_tracking(scene_args, data, Library::user(), options),
        None => opened(scene_args, data, Library::user()),
    }
}

/// The app opened on the options without their `--data` video, which is tracked on a
/// worker for `options` (checked readable first): its data join the lab when they
/// arrive, the tracking's progress shows meanwhile.
pub fn opened_tracking(
    scene_args: &SceneArgs,
    data: &DataArgs,
    library: Library,
    options: crate::input::video::tracked::Options,
) -> Result<App, CliError> {
    let without = DataArgs {
        data: Vec::new(),
        ..DataArgs::default()
    };
    let name = data.data.first().map(|p| p.display().to_string());
    let awaited = lab(scene_args, &without)?.awaiting_own_data(name.clone().unwrap_or_default());
    let mut app = App::new(awaited, library);
    app.set_video_tracker(video_tracker(scene_args, data, options.clone()));
    app.track_video(
        name.unwrap_or_default(),
        video_work(scene_args, data, options),
    );
    Ok(app)
}

/// The app as it opens on the options: the lab, and the status line asking for the
/// data's scene when none was named ([`scene_of_data`]).
pub fn opened(scene_args: &SceneArgs, data: &DataArgs, library: Library) -> Result<App, CliError> {
    let (lab, unfit) = match lab(scene_args, data) {
        Ok(lab) => (lab, None),
        // Data that `groovelab data` reads but no fit can use: the app opens on the
        // scene without them, shows what it can and says why there is no fit.
        Err(e) => {
            let unfit = unfit(scene_args, data, e)?;
            let lab = lab(scene_args, &DataArgs::default())?.with_unfit(unfit.clone());
            (lab, Some(unfit))
        }
    };
    let mut app = App::new(lab, library);
    // A video's tracks were read (and kept) with the lab: its pictures too.
    if let [path] = data.data.as_slice()
        && super::video_data::is_video(path)
    {
        let options = super::video_data::options(scene_args, data)?;
        let kept = crate::input::video::cache::kept(path, &options);
        app.set_video(path.display().to_string(), kept.and_then(|k| k.view));
        app.set_video_tracker(video_tracker(scene_args, data, options));
    }
    if let Some(u) = unfit {
        app.status = Status::Error(format!(
            "{}: no fit (f says why{})",
            short_name(&u.name),
            if u.in_file_time.is_some() {
                "; d shows its rows"
            } else {
                ""
            }
        ));
    } else if scene_of_data(scene_args, data).is_some() {
        // Short enough for the status line's second row at 80 columns: the file and
        // the preset are named at the line's right end.
        let s = &app.lab.scene;
        app.status = Status::Error(format!(
            "the data name no scene: using R = {}, b = {}; set yours",
            show(s.radius, Dimension::Length),
            show(s.width, Dimension::Length),
        ));
    }
    Ok(app)
}

/// The one rule for data and their scene, for the app, `render`, `compare` and `fit`:
/// a data file names no scene, so the one it was measured in is given by a preset or
/// the scene options. Without them, the file whose scene is missing: `fit` and
/// `compare` refuse, the app and `render` say which default the model uses and ask for
/// R and b.
pub fn scene_of_data<'a>(scene_args: &SceneArgs, data: &'a DataArgs) -> Option<&'a Path> {
    let path = data.data.first()?;
    (!scene_args.names_a_scene()).then_some(path.as_path())
}

/// Data that `groovelab data` reads but no fit can use (no impact found, too few
/// frames on a side of it, a unit in doubt): what the app shows of them, with
/// `error` (the fit's refusal) as why. `error` itself where it is not the data's, or
/// `data` cannot read them either (and for a video or two files, which keep their
/// own paths).
fn unfit(scene_args: &SceneArgs, data: &DataArgs, error: CliError) -> Result<Unfit, CliError> {
    let [path] = data.data.as_slice() else {
        return Err(error);
    };
    if !matches!(error, CliError::Data(_) | CliError::Implausible { .. }) {
        return Err(error);
    }
    let (mut reading, _) = reading_of(data)?;
    let text = if super::video_data::is_video(path) {
        // Its tracks (kept from the tracking that just read them) are in metres.
        reading.scale = None;
        super::video_data::text(path, scene_args, data)
    } else {
        crate::input::read_user_file(
            path,
            crate::input::FileRole::DataOption,
            crate::input::MAX_FILE_BYTES,
        )
        .map_err(CliError::from)
    };
    let Ok(text) = text else {
        return Err(error);
    };
    unfit_of(&path.display().to_string(), &text, &reading, error)
}

/// [`unfit`] of the text `text` of file `file` (a data file, or a video's tracks)
/// read as `reading` says.
fn unfit_of(file: &str, text: &str, reading: &Reading, error: CliError) -> Result<Unfit, CliError> {
    let file = file.to_string();
    let (reading, derive) = (reading.clone(), Derive::default());
    if crate::input::data::inspect(text, &file, &reading, &derive).is_err() {
        return Err(error);
    }
    // The centre's v_cm in the file's own time, where its lengths are metres (a
    // file whose unit is in doubt is not read at all: its table alone is shown).
    let in_file_time = match crate::input::data::read(text, &file, &reading) {
        Ok(RawSeries::Positions(track)) => in_file_time(&track).map(Arc::new),
        _ => None,
    };
    // The Fit view names the file first: its name is not said twice.
    let why = error.to_string();
    let why = why
        .strip_prefix(&format!("{file}: "))
        .map_or(why.clone(), str::to_string);
    Ok(Unfit {
        name: file,
        why,
        in_file_time,
    })
}

/// A path's last part, for the status line (its whole path is in the Fit view).
fn short_name(name: &str) -> &str {
    Path::new(name)
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or(name)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::data::{DataError, ScaleError};

    const TRACKS: &str = "# groovelab track clip.mp4: video\n# scale 5.46 ± 0.07 px/m: the balls' fitted radius 15.00 ± 0.20 px for R = 275 cm (--radius); speeds and μ_k from these tracks carry its 1.33 %\nt\tx\n";

    /// A video's tracks at a lab-impossible speed are said of R, `--scale` and
    /// `--fps` with the tracks' own scale line, never of a file's length unit (which a
    /// video refuses): a new user's bare `--radius 2.75` (metres) was told to give
    /// `--length-unit cm`.
    #[test]
    fn a_videos_tracks_off_any_balls_speed_name_r_scale_and_rate() {
        let e = DataError::new(
            "clip.mp4",
            ScaleError::LengthsNotMetres {
                speed: 79.5,
                unit: Some("cm"),
            },
        );
        let said = video_scale(e, "clip.mp4", TRACKS).to_string();
        assert_eq!(
            said,
            "clip.mp4: as tracked, the ball approaches at 79.5 m/s, no ball in a groove: its scale (5.46 ± 0.07 px/m: the balls' fitted radius 15.00 ± 0.20 px for R = 275 cm (--radius)) or its frame rate is off; check --radius (a number without a unit is metres: 2.75 is 2.75 m, 2.75cm a ball's), --scale and --fps"
        );
        let e = DataError::new("clip.mp4", ScaleError::TimesNotSeconds { frame: 2.0 });
        let said = video_scale(e, "clip.mp4", TRACKS).to_string();
        assert!(
            said.contains("as tracked, its frames are 2 s apart"),
            "{said}"
        );
        assert!(!said.contains("--length-unit") && !said.contains("--time-unit"));
        // Tracks without their scale line say where to look.
        let unscaled = DataError::new(
            "clip.mp4",
            ScaleError::TooSlow {
                speed: 1e-4,
                by: None,
                unit: None,
            },
        );
        let said = video_scale(unscaled, "clip.mp4", "").to_string();
        assert!(
            said.contains("its scale (as the tracks' file says)"),
            "{said}"
        );
        // Any other problem of the tracks is said as it was.
        let other = DataError::new(
            "clip.mp4",
            crate::input::data::DataProblem::NotSceneValue {
                line: 3,
                text: "# scene radius".into(),
            },
        );
        let want = other.to_string();
        assert_eq!(video_scale(other, "clip.mp4", TRACKS).to_string(), want);
    }
}
