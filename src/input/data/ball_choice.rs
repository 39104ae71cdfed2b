//! Which ball of a tracks file a series is derived from: the left ball's, or the
//! right ball's where the left one's frames give none; and the derivation itself.

use super::detect::read_with_notes;
use super::options::Reading;
use super::problem::DataError;
use crate::study::measured::{self, Derive, RawSeries, Series};

/// Derives what does not depend on the scene, errors naming `file`.
pub(super) fn prepare(
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

/// The series `data::load` gives of `text` (the file named `file`), and the reading
/// it took it with where that is not `reading`: the left ball's as `reading` says,
/// or, where that gives none and `reading` names no track, the right ball's
/// ([`right_ball`], its reading what `data` reports with, naming the ball `fit` fits).
pub(super) fn chosen(
    text: &str,
    file: &str,
    reading: &Reading,
    opts: &Derive,
) -> Result<(Series, Option<Reading>), DataError> {
    match prepare(read_with_notes(text, file, reading)?.0, file, reading, opts) {
        Err(e) if reading.centre.is_none() && reading.mark.is_none() => {
            let (series, right) = right_ball(text, file, reading, opts).ok_or(e)?;
            Ok((series, Some(right)))
        }
        done => done.map(|series| (series, None)),
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
fn right_ball(
    text: &str,
    file: &str,
    reading: &Reading,
    opts: &Derive,
) -> Option<(Series, Reading)> {
    let right = Reading {
        centre: Some("right ball".into()),
        mark: Some("right mark".into()),
        ..reading.clone()
    };
    let raw = read_with_notes(text, file, &right).ok()?.0;
    let RawSeries::Positions(track) = &raw else {
        return None;
    };
    let frames = track.t().len();
    let seen = (0..frames).filter(|&i| track.at(i).x.is_finite()).count();
    (2 * seen >= frames).then_some(())?;
    let series = prepare(raw, file, &right, opts).ok()?;
    Some((series, right))
}
