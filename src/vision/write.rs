//! Tracks as text: a Tracker-style multi-track data file (`#multi:`, the tracks'
//! names, then `t x y x y …` in metres and seconds; empty cells where a point is left
//! out), headed by `#` comment lines saying how it was made, which `input::data`
//! skips but for `# scene radius = …`, the R the scale comes from, and
//! `# scale = S ± σ px/m`, the scale's ± that the fit adds to μ_k's; after the table,
//! each point's standard error as `#` lines ([`SIGMA_HEADER`], [`SIGMA_ROW`]), which
//! the position fit weights by.

use std::fmt::Write as _;

use super::tracks::Tracks;

/// The comment line that states the scale and its ±: `# scale = S ± σ px/m`.
pub const SCALE_COMMENT: &str = "# scale =";

/// The first cell of the line naming the σ columns after the table:
/// `# sigma (m)`, then `t` and the tracks' names, tab-separated.
pub const SIGMA_HEADER: &str = "# sigma (m)";

/// The first cell of each σ line: `# sigma`, then the frame's t and each track's
/// point's standard error (of x and of y), m, tab-separated; empty where left out.
pub const SIGMA_ROW: &str = "# sigma";

/// The tracks as a Tracker-style multi-track file, the `notes` as comment lines
/// first. Per ball: its centre ("left ball") then its mark ("left mark").
#[allow(clippy::indexing_slicing)] // every track has one value per time
pub fn tracker_text(tracks: &Tracks, notes: &[String]) -> String {
    let mut out = String::new();
    for n in notes {
        for line in n.lines() {
            let _ = writeln!(out, "# {line}");
        }
    }
    let _ = writeln!(
        out,
        "# scene radius = {}",
        crate::settings::units::show_exact(
            tracks.calibration.radius_m,
            crate::settings::units::Dimension::Length
        )
    );
    let c = &tracks.calibration;
    if !c.scale_given && c.px_per_m_sigma > 0.0 {
        // Read back by `input::data` ([`SCALE_COMMENT`]): the fit adds its ± to μ_k's.
        let _ = writeln!(
            out,
            "{SCALE_COMMENT} {:.6} ± {:.6} px/m",
            c.px_per_m, c.px_per_m_sigma
        );
    }
    out.push_str("#multi:\n");
    let mut names = String::new();
    let mut header = String::from("t");
    for b in &tracks.balls {
        let _ = write!(names, "\t{} ball\t\t{} mark\t", b.name, b.name);
        header.push_str("\tx\ty\tx\ty");
    }
    out.push_str(&names);
    out.push('\n');
    out.push_str(&header);
    out.push('\n');
    let cell = |v: f64| {
        if v.is_finite() {
            format!("{v:.6E}")
        } else {
            String::new()
        }
    };
    for (k, t) in tracks.t.iter().enumerate() {
        out.push_str(&cell(*t));
        for b in &tracks.balls {
            for v in [b.x[k], b.y[k], b.mark_x[k], b.mark_y[k]] {
                out.push('\t');
                out.push_str(&cell(v));
            }
        }
        out.push('\n');
    }
    sigma_lines(tracks, &mut out, cell);
    out
}

/// Each point's standard error as `#` lines after the table (a Tracker-style reader
/// skips them; `input::data` reads them back): [`SIGMA_HEADER`] with the track names,
/// then one [`SIGMA_ROW`] per frame.
fn sigma_lines(tracks: &Tracks, out: &mut String, cell: impl Fn(f64) -> String) {
    out.push_str(SIGMA_HEADER);
    out.push_str("\tt");
    for b in &tracks.balls {
        let _ = write!(out, "\t{} ball\t{} mark", b.name, b.name);
    }
    out.push('\n');
    for (k, t) in tracks.t.iter().enumerate() {
        out.push_str(SIGMA_ROW);
        out.push('\t');
        out.push_str(&cell(*t));
        for b in &tracks.balls {
            let at = |v: &[f64]| v.get(k).copied().unwrap_or(f64::NAN);
            for v in [at(&b.sigma), at(&b.mark_sigma)] {
                out.push('\t');
                out.push_str(&cell(v));
            }
        }
        out.push('\n');
    }
}
