//! Each tracked point's standard error, read from the `#` lines `groovelab track`
//! writes after its table (`# sigma (m)` naming the tracks, then one `# sigma` line
//! per frame: t and each track's σ, m, tab-separated; `vision::write`), and
//! put beside the centre's and the mark's positions of a track already read. A file
//! without them, or with lines that do not read, keeps no σ: the fit then weights
//! every point alike, as before.

use crate::study::measured::{Rule, Track, TrackParts};
use crate::vision::write::{SIGMA_HEADER, SIGMA_ROW};

/// `track` with the σ of its centre and mark where `text` states them (the tracks
/// named as `track.centre_name` and `track.mark_name`), matched to its frames by time
/// (within a quarter of a frame; a frame without a σ line gets NaN).
/// A σ the track's rules refuse (a negative one) is said as such.
pub fn with_sigmas(text: &str, track: Track) -> Result<Track, Rule> {
    let Some((names, rows)) = sigma_lines(text) else {
        return Ok(track);
    };
    let column = |name: &str| names.iter().position(|n| same(n, name));
    let Some(centre) = column(track.centre_name()) else {
        return Ok(track);
    };
    let mark = track
        .mark_name()
        .filter(|_| track.mark().is_some())
        .and_then(column);
    let sigma = Some(on_frames(track.t(), &rows, centre));
    let mark_sigma = mark.map(|m| on_frames(track.t(), &rows, m));
    Track::new(TrackParts {
        sigma,
        mark_sigma,
        ..track.into_parts()
    })
}

fn same(a: &str, b: &str) -> bool {
    a.trim().eq_ignore_ascii_case(b.trim())
}

/// The track names of the σ header and each σ line's numbers (t first; NaN for an
/// empty cell); `None` without a header, or with a line whose cells do not read.
fn sigma_lines(text: &str) -> Option<(Vec<String>, Vec<Vec<f64>>)> {
    let mut names: Option<Vec<String>> = None;
    let mut rows = Vec::new();
    for line in text.lines() {
        let mut cells = line.trim_end_matches('\r').split('\t');
        let first = cells.next().unwrap_or("").trim();
        if first == SIGMA_HEADER {
            names = Some(cells.skip(1).map(str::to_string).collect());
        } else if first == SIGMA_ROW && names.is_some() {
            let row = cells
                .map(|c| match c.trim() {
                    "" => Some(f64::NAN),
                    v => v.parse::<f64>().ok(),
                })
                .collect::<Option<Vec<f64>>>()?;
            rows.push(row);
        }
    }
    names.filter(|_| !rows.is_empty()).map(|n| (n, rows))
}

/// Column `col` of the σ `rows` (t in their first cell) on the frames `t`: each
/// positive finite σ put on the frame within a quarter of a frame of its time.
fn on_frames(t: &[f64], rows: &[Vec<f64>], col: usize) -> Vec<f64> {
    let mut out = vec![f64::NAN; t.len()];
    let mut gaps: Vec<f64> = t
        .windows(2)
        .filter_map(|w| w.last().zip(w.first()).map(|(b, a)| b - a))
        .collect();
    gaps.sort_by(f64::total_cmp);
    let near = 0.25 * gaps.get(gaps.len() / 2).copied().unwrap_or(f64::INFINITY);
    for row in rows {
        let (Some(&at), Some(&s)) = (row.first(), row.get(col + 1)) else {
            continue;
        };
        if !(at.is_finite() && s > 0.0 && s.is_finite()) {
            continue;
        }
        let j = t.partition_point(|&x| x < at - near);
        let near_frame =
            (j..t.len().min(j + 2)).find(|&k| t.get(k).is_some_and(|tk| (tk - at).abs() <= near));
        if let Some(cell) = near_frame.and_then(|k| out.get_mut(k)) {
            *cell = s;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn track() -> Track {
        Track::new(TrackParts {
            t: vec![0.0, 0.01, 0.02],
            x: vec![0.1, 0.2, 0.3],
            y: vec![0.0; 3],
            mark: Some((vec![0.1; 3], vec![0.01; 3])),
            centre_name: "left ball".into(),
            mark_name: Some("left mark".into()),
            ..TrackParts::default()
        })
        .unwrap()
    }

    #[test]
    fn the_sigma_lines_go_to_the_named_tracks_by_time() {
        let text = "#multi:\n\tleft ball\t\tleft mark\t\nt\tx\ty\tx\ty\n\
                    # sigma (m)\tt\tleft ball\tleft mark\n\
                    # sigma\t0.0E0\t1.0E-5\t3.0E-5\n\
                    # sigma\t2.0E-2\t2.0E-5\t\n";
        let t = with_sigmas(text, track()).unwrap();
        let s = t.sigma().unwrap();
        assert_eq!((s[0], s[2]), (1e-5, 2e-5));
        assert!(s[1].is_nan(), "no line for t = 0.01");
        let m = t.mark_sigma().unwrap();
        assert_eq!(m[0], 3e-5);
        assert!(m[2].is_nan(), "an empty cell is no σ");
    }

    #[test]
    fn without_readable_sigma_lines_the_track_keeps_none() {
        for text in [
            "t,x\n0,1\n",
            "# sigma (m)\tt\tleft ball\n# sigma\t0\tabc\n",
            "# sigma (m)\tt\tright ball\n# sigma\t0\t1e-5\n",
            "# sigma\t0\t1e-5\n",
        ] {
            let t = with_sigmas(text, track()).unwrap();
            assert_eq!((t.sigma(), t.mark_sigma()), (None, None), "{text}");
        }
    }
}
