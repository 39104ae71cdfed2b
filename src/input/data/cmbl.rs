//! Logger Pro's own file (`.cmbl`, XML): data sets (`DataSet`), each with columns
//! (`DataColumn`: a name, a unit, and its cells one number per line). The data set
//! of a video analysis is taken (else the first with a time and a position column),
//! its columns laid out as a table and read as a position track. A video that was
//! never scaled leaves the position columns without a unit: the numbers are then the
//! video's own units, and the length one of them shows must be given.

use roxmltree::Node;

use super::layout::{Axis, position_column};
use super::notes::Notes;
use super::options::Reading;
use super::positions::read_table;
use super::problem::{DataError, DataProblem, VideoScale};
use super::table::Table;
use super::xml::{self, child_text};
use crate::study::measured::Track;

/// The format's name, as `groovelab data` and the fit say it.
pub const FORMAT: &str = "Logger Pro file (.cmbl)";

/// True when `text` is a Logger Pro file by its structure: XML whose root is a
/// `Document` holding a `DataSet` of `DataColumn`s (not by one incidental tag such
/// as `FileCoherence`, which files of other versions may lack).
pub(super) fn is_cmbl(text: &str) -> bool {
    let body = text.trim_start_matches('\u{feff}').trim_start();
    if !body.starts_with('<') {
        return false;
    }
    let Ok(doc) = xml::parse(body, FORMAT) else {
        return false;
    };
    let root = doc.root_element();
    root.has_tag_name("Document")
        && root.children().any(|set| {
            set.has_tag_name("DataSet") && set.children().any(|c| c.has_tag_name("DataColumn"))
        })
}

/// One column of a data set.
struct Column {
    name: String,
    unit: String,
    cells: Vec<String>,
}

/// A data set's name, whether it is a video analysis, and its columns with cells.
fn data_set(node: Node<'_, '_>) -> (String, bool, Vec<Column>) {
    let name = child_text(node, "DataSetName").unwrap_or("").to_string();
    let video = child_text(node, "DataSetVideoAnalysis") == Some("1");
    let columns = node
        .children()
        .filter(|c| c.has_tag_name("DataColumn"))
        .map(|c| Column {
            name: child_text(c, "DataObjectName").unwrap_or("").to_string(),
            unit: child_text(c, "ColumnUnits").unwrap_or("").to_string(),
            cells: child_text(c, "ColumnCells")
                .unwrap_or("")
                .lines()
                .map(|l| l.trim().to_string())
                .collect::<Vec<_>>(),
        })
        .filter(|c| c.cells.iter().any(|v| !v.is_empty()))
        .collect();
    (name, video, columns)
}

/// The axis a column's name gives (Time, X, Y, X2 …), if any.
fn axis(c: &Column) -> Option<Axis> {
    position_column(&c.name).map(|col| col.axis)
}

/// The video's scale as the file states it, for the message when it is missing.
fn video_scale(root: Node<'_, '_>) -> Option<VideoScale> {
    let movie = root
        .descendants()
        .find(|n| n.has_tag_name("VAMovieActualDistance"))?;
    let actual = movie.text()?.trim().to_string();
    let parent = movie.parent()?;
    let pixels = child_text(parent, "VAMoviePixelDistance")?;
    let unit = child_text(parent, "VAMovieScaleUnits").unwrap_or("");
    Some(VideoScale {
        actual,
        unit: unit.to_string(),
        pixels: pixels.to_string(),
    })
}

/// Reads a Logger Pro file (see the module doc) into a track in SI units and what it
/// said about itself.
pub(super) fn read(text: &str, file: &str, reading: &Reading) -> Result<(Track, Notes), DataError> {
    let err = |what: DataProblem| DataError::new(file, what);
    let doc = xml::parse(text, "Logger Pro file").map_err(|e| err(e.into()))?;
    let root = doc.root_element();
    if !root.has_tag_name("Document") {
        return Err(err(DataProblem::NotLoggerPro));
    }
    let sets: Vec<_> = root
        .children()
        .filter(|c| c.has_tag_name("DataSet"))
        .map(data_set)
        .filter(|(_, _, cols)| {
            cols.iter().any(|c| axis(c) == Some(Axis::T))
                && cols.iter().any(|c| axis(c) == Some(Axis::X))
        })
        .collect();
    let Some((name, _, columns)) = sets.iter().find(|s| s.1).or(sets.first()) else {
        let found: Vec<String> = root
            .children()
            .filter(|c| c.has_tag_name("DataSet"))
            .filter_map(|c| child_text(c, "DataSetName").map(str::to_string))
            .collect();
        return Err(err(DataProblem::NoDataSet { found }));
    };
    let unscaled = columns
        .iter()
        .filter(|c| matches!(axis(c), Some(Axis::X | Axis::Y)))
        .all(|c| c.unit.is_empty());
    if unscaled && reading.length_unit.is_none() && reading.scale.is_none() && !reading.own_lengths
    {
        return Err(err(DataProblem::Unscaled {
            set: name.clone(),
            scale: video_scale(root),
        }));
    }
    let table = Table::new(&as_table(columns));
    let (track, mut notes) = read_table(&table, file, reading).map_err(|e| DataError {
        what: DataProblem::InDataSet {
            set: name.clone(),
            problem: Box::new(e.what),
        },
        ..e
    })?;
    notes.format = format!("{FORMAT}, data set '{name}'");
    Ok((track.with_format(FORMAT), notes))
}

/// The columns as a tab-separated table: a header `Name (unit)`, then a row per cell
/// (a shorter column leaves its cells empty).
fn as_table(columns: &[Column]) -> String {
    let rows = columns.iter().map(|c| c.cells.len()).max().unwrap_or(0);
    let mut out = columns
        .iter()
        .map(|c| {
            if c.unit.is_empty() {
                c.name.clone()
            } else {
                format!("{} ({})", c.name, c.unit)
            }
        })
        .collect::<Vec<_>>()
        .join("\t");
    out.push('\n');
    for i in 0..rows {
        let row: Vec<&str> = columns
            .iter()
            .map(|c| c.cells.get(i).map_or("", String::as_str))
            .collect();
        out += &row.join("\t");
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::is_cmbl;

    const COLUMN: &str = "<DataColumn><DataObjectName>Time</DataObjectName><ColumnCells>0\n0.01\n</ColumnCells></DataColumn>";

    #[test]
    fn a_logger_pro_file_is_known_by_its_data_sets_not_one_tag() {
        // Without FileCoherence (and with a BOM and an XML declaration): still one.
        let plain = format!(
            "\u{feff}<?xml version=\"1.0\"?>\n<Document><Version>3.8</Version><DataSet>{COLUMN}</DataSet></Document>"
        );
        assert!(is_cmbl(&plain));
        // The tag alone, or data columns not in a data set, or another root: not one.
        assert!(!is_cmbl(
            "<Document><FileCoherence>1</FileCoherence></Document>"
        ));
        assert!(!is_cmbl(&format!(
            "<Document><FileCoherence>1</FileCoherence>{COLUMN}</Document>"
        )));
        assert!(!is_cmbl(&format!(
            "<object class=\"x\"><DataSet>{COLUMN}</DataSet></object>"
        )));
        assert!(!is_cmbl("<Document><DataSet>"));
        assert!(!is_cmbl("t,x\n0,1\n"));
    }
}
