//! Reading a user's measured series from the text of a file: velocity files
//! (`velocities`) and position tracks from video analysis (`positions`), both on the
//! same table reader (`table`: the `csv` crate, separators, units, numbers). A reader
//! gives a [`RawSeries`] in SI units and nothing that depends on the scene: deriving
//! velocities for a scene is `study::measured`'s.

mod ball_choice;
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

use crate::study::measured::{Derive, RawSeries, Series, Track};
use ball_choice::prepare;
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

/// Reads a velocity file or a position track and derives what does not depend on the
/// scene (`study::measured::prepare`); `study::measured::for_scene` then gives it for
/// a scene. The time of the first impact, when given, is `reading.impact_at`. Of a
/// file of both balls (`groovelab track`'s) whose left ball gives no series, the right
/// ball's (`ball_choice::chosen`).
pub fn load(text: &str, file: &str, reading: &Reading, opts: &Derive) -> Result<Series, DataError> {
    ball_choice::chosen(text, file, reading, opts).map(|(series, _)| series)
}
