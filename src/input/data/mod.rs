//! Reading a user's measured series from the text of a file: velocity files
//! (`velocities`) and position tracks from video analysis (`positions`), both on the
//! same table reader (`table`: the `csv` crate, separators, units, numbers). A reader
//! gives a [`RawSeries`] in SI units and nothing that depends on the scene: deriving
//! velocities for a scene is `study::measured`'s.

mod cmbl;
mod detect;
mod layout;
mod misfit;
mod notes;
mod options;
mod positions;
mod problem;
mod report;
mod roles;
mod scales;
mod scene;
mod sigmas;
mod table;
mod trk;
mod velocities;
mod vernier;
mod xml;

pub use detect::read_with_notes;
pub use notes::{Notes, UnitNote};
pub use options::{MAX_ROWS, Reading};
pub use problem::{DataError, DataProblem, VideoScale};
pub use report::{Gap, Report, inspect};
pub use scales::ScaleError;
pub use scene::scene_of;
pub use table::file_unit;
pub use velocities::detect_impact;

use crate::study::measured::{self, Derive, RawSeries, Series, Track};
use table::Table;

/// Reads `text` (the file named `file`): a Tracker project (`.trk`), a Logger Pro
/// file (`.cmbl`) or text export (Vernier Format 2), else a table: a velocity file
/// when its header names t, v_cm and v_t, else a position track (Tracker, Logger Pro,
/// or CSV/TSV with t, x, y).
pub fn read(text: &str, file: &str, reading: &Reading) -> Result<RawSeries, DataError> {
    detect::read_with_notes(text, file, reading).map(|(raw, _)| raw)
}

/// Reads a position track (see [`read`]); a velocity file is an error here.
pub fn read_track(text: &str, file: &str, reading: &Reading) -> Result<Track, DataError> {
    positions::parse(text, file, reading)
}

/// Reads two one-track exports (Tracker writes one track per file), `centre` and
/// `mark` as (file name, text), into one track: the mark's positions matched to the
/// centre's frames by time; then as [`load`]. `reading.centre` and `reading.mark`
/// name the track each file holds, if it holds several.
pub fn load_pair(
    centre: &(String, String),
    mark: &(String, String),
    reading: &Reading,
    opts: &Derive,
) -> Result<Series, DataError> {
    let one = |(file, text): &(String, String), name: &Option<String>| {
        let r = Reading {
            centre: name.clone(),
            mark: None,
            ..reading.clone()
        };
        positions::from_table(&Table::new(text), file, &r)
    };
    let ball = one(centre, &reading.centre)?;
    let rim = one(mark, &reading.mark)?;
    let track = ball
        .with_mark(&rim)
        .map_err(|what| DataError::new(&mark.0, what))?;
    roles::swapped(&track).map_err(|e| DataError::new(&centre.0, e))?;
    prepare(RawSeries::Positions(track), &centre.0, reading, opts)
}

/// Derives what does not depend on the scene, errors naming `file`.
fn prepare(
    raw: RawSeries,
    file: &str,
    reading: &Reading,
    opts: &Derive,
) -> Result<Series, DataError> {
    let opts = Derive {
        impact_at: reading.impact_at.or(opts.impact_at),
        ..*opts
    };
    measured::prepare(raw, &opts).map_err(|e| DataError::new(file, e))
}

/// Reads a velocity file or a position track and derives what does not depend on the
/// scene (`study::measured::prepare`); `study::measured::for_scene` then gives it for
/// a scene. The time of the first impact, when given, is `reading.impact_at`. Of a
/// file of both balls (`groovelab track`'s) whose left ball gives no series, the right
/// ball's ([`right_ball`]).
pub fn load(text: &str, file: &str, reading: &Reading, opts: &Derive) -> Result<Series, DataError> {
    match prepare(read(text, file, reading)?, file, reading, opts) {
        Err(e) if reading.centre.is_none() && reading.mark.is_none() => {
            right_ball(text, file, reading, opts).ok_or(e)
        }
        done => done,
    }
}

/// The right ball's series of a tracks file of both balls (`groovelab track`'s
/// "right ball" and "right mark"), mirrored into the model's left ball as a file of
/// that ball alone is: where the left ball's motion gives none (found in a few frames
/// about the impact, or on one side of it: small look 47, 12 frames of 36, a disc of
/// the wall taken for the left ball before and after it was found; full look 126)
/// while the right ball, found in half the frames or more, shows the impact. `None`
/// without such tracks or where they give no series either: the left ball's refusal
/// then stands (small look 49, the right ball in 13 frames of 41, whose series gave
/// μ_k 0.277 ± 0.025 for 0.170).
fn right_ball(text: &str, file: &str, reading: &Reading, opts: &Derive) -> Option<Series> {
    let right = Reading {
        centre: Some("right ball".into()),
        mark: Some("right mark".into()),
        ..reading.clone()
    };
    let raw = read(text, file, &right).ok()?;
    let RawSeries::Positions(track) = &raw else {
        return None;
    };
    let frames = track.t().len();
    let seen = (0..frames).filter(|&i| track.at(i).x.is_finite()).count();
    (2 * seen >= frames).then_some(())?;
    prepare(raw, file, &right, opts).ok()
}
