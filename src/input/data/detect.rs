//! Which reader a data file needs, from its first lines: a Tracker project (`.trk`),
//! a Logger Pro file (`.cmbl`) or its text export (Vernier Format 2), else a table (a
//! velocity file when its header names v_cm, else a position track); and a file of
//! accelerations only (phyphox), refused with what groovelab needs instead.

use super::notes::Notes;
use super::options::Reading;
use super::problem::{AccelerationsOnly, DataError, DataProblem};
use super::table::{self, Table};
use super::{cmbl, positions, trk, velocities, vernier};
use crate::study::measured::{RawSeries, Track, TrackParts};

/// [`read`] with what the file said about itself: its format, its tracks, and how
/// each unit was decided.
pub fn read_with_notes(
    text: &str,
    file: &str,
    reading: &Reading,
) -> Result<(RawSeries, Notes), DataError> {
    let (raw, mut notes) = read_any(text, file, reading)?;
    // Rows and cells are a table's: an XML project (Tracker, Logger Pro) ending
    // without a line end after its last tag has lost nothing.
    if !is_xml(text) {
        notes.cut_row = table::cut_short_last(text);
    }
    if let RawSeries::Positions(t) = &raw {
        super::roles::swapped(t).map_err(|e| DataError::new(file, e))?;
    }
    let raw = match raw {
        RawSeries::Positions(t) => RawSeries::Positions(
            Track::new(TrackParts {
                scale_rel_se: super::scene::scale_rel_se(text),
                ..t.into_parts()
            })
            .and_then(|t| super::sigmas::with_sigmas(text, t))
            .map_err(|e| DataError::new(file, DataProblem::from(e)))?,
        ),
        v => v,
    };
    Ok((raw, notes))
}

/// [`read_with_notes`] but for the scale's ± a comment line states.
fn read_any(text: &str, file: &str, reading: &Reading) -> Result<(RawSeries, Notes), DataError> {
    if trk::is_trk(text) {
        return trk::read(text, file, reading).map(|(t, n)| (RawSeries::Positions(t), n));
    }
    if cmbl::is_cmbl(text) {
        return cmbl::read(text, file, reading).map(|(t, n)| (RawSeries::Positions(t), n));
    }
    if is_xml(text) {
        return Err(DataError::new(file, DataProblem::OtherXml));
    }
    if vernier::is_vernier(text) {
        let (raw, notes) = read_table(&Table::new(&vernier::as_table(text)), file, reading)?;
        let raw = match raw {
            RawSeries::Positions(t) => RawSeries::Positions(t.with_format(vernier::FORMAT)),
            v => v,
        };
        let notes = Notes {
            format: vernier::FORMAT.into(),
            ..notes
        };
        return Ok((raw, notes));
    }
    read_table(&Table::new(text), file, reading)
}

/// Whether the file is XML (its first character a tag's), not a table.
fn is_xml(text: &str) -> bool {
    text.trim_start_matches('\u{feff}')
        .trim_start()
        .starts_with('<')
}

/// A table's series: velocities when its header names v_cm, else a position track.
fn read_table(
    table: &Table,
    file: &str,
    reading: &Reading,
) -> Result<(RawSeries, Notes), DataError> {
    let velocities = table
        .rows()
        .next()
        .is_some_and(|header| (0..header.len()).any(|i| velocities::names_v_cm(header.cell(i))));
    if velocities {
        return velocities::read_table(table, file, reading)
            .map(|(m, n)| (RawSeries::Velocities(m), n));
    }
    accelerations_only(table).map_err(|e| DataError::new(file, e))?;
    positions::read_table(table, file, reading).map(|(t, n)| (RawSeries::Positions(t), n))
}

/// A table of accelerations only (phyphox's accelerometer): refused with what
/// groovelab needs instead.
fn accelerations_only(table: &Table) -> Result<(), AccelerationsOnly> {
    let Some(header) = table.rows().take(4).find(|r| {
        (0..r.len()).any(|i| {
            let c = table::clean(r.cell(i));
            c.starts_with("time") || c == "t" || c.starts_with("t ")
        })
    }) else {
        return Ok(());
    };
    let cells: Vec<&str> = (0..header.len()).map(|i| header.cell(i)).collect();
    let accelerations = cells
        .iter()
        .any(|c| c.to_lowercase().contains("acceleration"));
    let positions = cells.iter().any(|c| {
        super::layout::position_column(c).is_some_and(|c| c.axis == super::layout::Axis::X)
    });
    if accelerations && !positions {
        return Err(AccelerationsOnly {
            line: header.line,
            columns: cells
                .iter()
                .filter(|c| !c.is_empty())
                .copied()
                .collect::<Vec<_>>()
                .join(", "),
        });
    }
    Ok(())
}
