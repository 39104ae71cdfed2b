//! A run as CSV, one writer for every front end: `simulate --format csv` and the app's
//! export (`w`) write the same columns, SI units; the app's export starts with its
//! scene as comment lines ([`scene_comments`]), so that it loads back as data.

use crate::physics::solution::{Snapshot, Solution};
use crate::settings::spec::SceneSpec;
use crate::settings::units::significant;

/// What starts a scene comment line: `# scene width = 4.9 cm`.
pub const SCENE_COMMENT: &str = "# scene ";

/// The scene of `spec` (not its time span) as comment lines, one per value given, in the unit the lab reads
/// it in and rounded to 6 significant digits (a fitted μ_k of 0.16667742330550958
/// reads 0.166677: far finer than any measurement, without the float's noise). The
/// data reader takes them back as the file's scene (`input::data::scene_of`).
pub fn scene_comments(spec: &SceneSpec) -> String {
    let mut out = String::from(
        "# groovelab run: the scene it was computed in (read back with --data; options given on the command line win)\n",
    );
    for (key, value) in spec.given().filter(|(k, _)| k.param().of_scene()) {
        let dim = key.dimension();
        out += &format!(
            "{SCENE_COMMENT}{} = {}{}\n",
            key.name(),
            significant(dim.to_display(value), 6),
            dim.suffix()
        );
    }
    out
}

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
