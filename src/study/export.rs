//! A run as CSV, one writer for every front end: `simulate --format csv` and the app's
//! export (`e`) write the same columns, SI units.

use crate::physics::solution::{Snapshot, Solution};

/// The samples (`t` and both balls' x, v, u) if given, else the events (`t`, kind,
/// ball, then the same state columns).
pub fn run_csv(solution: &Solution, samples: Option<&[Snapshot]>) -> Result<String, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let state_cols = [
        "x_left", "v_left", "u_left", "x_right", "v_right", "u_right",
    ];
    let values = |s: &Snapshot| {
        [
            s.left.x, s.left.v, s.left.u, s.right.x, s.right.v, s.right.u,
        ]
        .map(|v| v.to_string())
    };
    match samples {
        Some(samples) => {
            w.write_record(std::iter::once("t").chain(state_cols))?;
            for s in samples {
                w.write_record(std::iter::once(s.t.to_string()).chain(values(s)))?;
            }
        }
        None => {
            w.write_record(["t", "kind", "ball"].into_iter().chain(state_cols))?;
            for e in solution.visible_events() {
                let snap = Snapshot {
                    t: e.t,
                    left: e.left,
                    right: e.right,
                };
                let head = [e.t.to_string(), e.kind.name().into(), e.ball.name().into()];
                w.write_record(head.into_iter().chain(values(&snap)))?;
            }
        }
    }
    let bytes = w
        .into_inner()
        .map_err(|e| csv::Error::from(e.into_error()))?;
    Ok(String::from_utf8(bytes).expect("csv of ASCII numbers"))
}
