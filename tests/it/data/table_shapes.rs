//! Tables of any shape the formats allow, through the whole data path (issue 35):
//! proptest writes 0–1000 rows of one or two balls, with rim marks or none, gaps,
//! repeated and falling times, huge and tiny values, balls that stand, jump, cross
//! and circle, as Tracker, CSV and Logger Pro text; `data`, `fit` and `render` run on
//! each in this process. Never a panic (the test would fail), exit status 0 or 2, one
//! `error:` line on 2, and no printed number that is not finite.
//!
//! `PROPTEST_CASES=N` runs more (each case runs `data`; every fourth `fit` and
//! `render`, which fit and solve: the cost of a case).

use std::ffi::OsString;

use groovelab::cli::entry::main_with;
use proptest::prelude::*;

use crate::common::{cases, scratch_dir};

/// How a ball moves along x over time `t`, s (its y follows from it).
#[derive(Clone, Copy, Debug)]
enum Motion {
    /// At rest.
    Stands,
    /// Steady, then slowed at an impact at 0.3 s.
    Impact { v: f64, after: f64 },
    /// Jumps by `by` each frame (tracking gone wrong).
    Jumps { by: f64 },
    /// Along a circle of radius `r` (a mark, or a ball spun around).
    Circles { r: f64, w: f64 },
    /// Steady toward and past the other ball.
    Crosses { v: f64 },
}

impl Motion {
    fn at(self, t: f64, k: usize) -> (f64, f64) {
        match self {
            Motion::Stands => (0.1, 0.2),
            Motion::Impact { v, after } => {
                let x = if t < 0.3 {
                    v * t
                } else {
                    0.3 * v + after * (t - 0.3)
                };
                (x, 0.1)
            }
            Motion::Jumps { by } => (if k.is_multiple_of(2) { by } else { -by }, 0.0),
            Motion::Circles { r, w } => ((w * t).cos() * r, (w * t).sin() * r),
            Motion::Crosses { v } => (-0.2 + v * t, 0.05),
        }
    }
}

fn motion() -> impl Strategy<Value = Motion> {
    prop_oneof![
        Just(Motion::Stands),
        (0.05..2.0f64, -1.0..1.0f64).prop_map(|(v, after)| Motion::Impact { v, after }),
        prop_oneof![Just(1e-9), Just(0.5), Just(1e6), Just(1e11)]
            .prop_map(|by| Motion::Jumps { by }),
        (1e-4..1.0f64, 0.1..100.0f64).prop_map(|(r, w)| Motion::Circles { r, w }),
        (-3.0..3.0f64).prop_map(|v| Motion::Crosses { v }),
    ]
}

/// What happens to a row's time.
#[derive(Clone, Copy, Debug)]
enum Times {
    Steady,
    Repeats,
    Falls,
    Jittered,
}

/// A table to write.
#[derive(Clone, Debug)]
struct Table {
    rows: usize,
    dt: f64,
    times: Times,
    balls: Vec<Motion>,
    mark: bool,
    /// Every `gap`-th row has empty position cells (0: none).
    gap: usize,
    /// Scale of every length (tiny to huge units).
    scale: f64,
    format: usize,
    /// Cut the last row short.
    cut: bool,
}

fn table() -> impl Strategy<Value = Table> {
    (
        prop_oneof![0..20usize, 20..200usize, 200..=1000usize],
        prop_oneof![
            Just(1.0 / 30.0),
            Just(0.01),
            Just(1.0 / 240.0),
            Just(1e-6),
            Just(2.0)
        ],
        prop_oneof![
            4 => Just(Times::Steady),
            1 => Just(Times::Repeats),
            1 => Just(Times::Falls),
            1 => Just(Times::Jittered)
        ],
        prop::collection::vec(motion(), 1..=2),
        any::<bool>(),
        prop_oneof![Just(0usize), Just(3), Just(17)],
        prop_oneof![4 => Just(1.0), 1 => Just(1e-12), 1 => Just(1e3), 1 => Just(1e11)],
        0..3usize,
        prop::bool::weighted(0.2),
    )
        .prop_map(
            |(rows, dt, times, balls, mark, gap, scale, format, cut)| Table {
                rows,
                dt,
                times,
                balls,
                mark,
                gap,
                scale,
                format,
                cut,
            },
        )
}

impl Table {
    /// The table as text: Tracker multi-track (tabs), CSV with `x_mark` columns, or
    /// Logger Pro's `Latest: X (m)` columns (X2, Y2 the mark).
    fn text(&self) -> String {
        let cell = |v: f64| format!("{v}");
        let mut tracks: Vec<(String, Motion, bool)> = Vec::new();
        for (i, &b) in self.balls.iter().enumerate() {
            tracks.push((format!("ball {i}"), b, false));
            if self.mark {
                tracks.push((format!("mark {i}"), b, true));
            }
        }
        let mut out = match self.format {
            0 => {
                let names: Vec<String> = tracks.iter().map(|t| format!("\t{}\t", t.0)).collect();
                let cols: Vec<&str> = tracks.iter().map(|_| "x\ty").collect();
                format!("#multi:\n{}\nt\t{}\n", names.concat(), cols.join("\t"))
            }
            1 => {
                let cols: Vec<String> = tracks
                    .iter()
                    .enumerate()
                    .map(|(i, _)| match i {
                        0 => "x,y".to_string(),
                        1 if self.mark => "x_mark,y_mark".to_string(),
                        i => format!("x_b{i},y_b{i}"),
                    })
                    .collect();
                format!("t,{}\n", cols.join(","))
            }
            _ => {
                let cols: Vec<String> = tracks
                    .iter()
                    .enumerate()
                    .map(|(i, _)| match i {
                        0 => "Latest: X (m),Latest: Y (m)".to_string(),
                        i => format!("Latest: X{} (m),Latest: Y{} (m)", i + 1, i + 1),
                    })
                    .collect();
                format!("Latest: Time (s),{}\n", cols.join(","))
            }
        };
        let sep = if self.format == 0 { "\t" } else { "," };
        for k in 0..self.rows {
            let t = match self.times {
                Times::Steady => k as f64 * self.dt,
                Times::Repeats => (k / 2) as f64 * self.dt,
                Times::Falls => (self.rows - k) as f64 * self.dt,
                Times::Jittered => (k as f64 + 0.3 * ((k * 7919) % 13) as f64 / 13.0) * self.dt,
            };
            let mut row = vec![cell(t)];
            for (i, (_, m, is_mark)) in tracks.iter().enumerate() {
                let (mut x, mut y) = m.at(t, k);
                if i % 2 == 1 && self.balls.len() == 2 && !self.mark {
                    x = 0.3 - x;
                }
                if *is_mark {
                    x += 0.02 * (30.0 * t).sin();
                    y += 0.02 * (30.0 * t).cos();
                }
                if self.gap > 0 && k % self.gap == self.gap - 1 {
                    row.push(String::new());
                    row.push(String::new());
                } else {
                    row.push(cell(x * self.scale));
                    row.push(cell(y * self.scale));
                }
            }
            out += &row.join(sep);
            out.push('\n');
        }
        if self.cut && out.ends_with('\n') {
            out.pop();
            let keep = out.rfind(sep).unwrap_or(out.len());
            out.truncate(keep);
        }
        out
    }
}

/// Runs `args` in this process: its exit status and what it printed.
fn run(args: &[&str]) -> groovelab::cli::entry::Exit {
    let argv: Vec<OsString> = std::iter::once("groovelab")
        .chain(args.iter().copied())
        .map(OsString::from)
        .collect();
    main_with(&argv)
}

/// The contract on one run: 0 with no stderr and finite numbers, or 2 with one
/// `error:` line.
fn keeps_the_contract(what: &str, exit: &groovelab::cli::entry::Exit) -> Result<(), TestCaseError> {
    match exit.code {
        0 => {
            // "empty or NaN" is the note that names rows a file left out, not a number.
            let said = exit.stdout.replace("empty or NaN", "empty");
            let bad: Vec<&str> = said
                .split(|c: char| !(c.is_alphanumeric() || c == '.'))
                .filter(|w| matches!(*w, "NaN" | "nan" | "inf" | "Inf" | "infinity"))
                .collect();
            prop_assert!(bad.is_empty(), "{what}: printed {bad:?}:\n{}", exit.stdout);
            prop_assert!(
                !exit.stdout.contains('∞') || exit.stdout.contains("T∞"),
                "{what}"
            );
        }
        2 => {
            prop_assert!(exit.stdout.is_empty(), "{what}: {}", exit.stdout);
            prop_assert!(
                exit.stderr.starts_with("error: ") && exit.stderr.trim_end().lines().count() == 1,
                "{what}: {}",
                exit.stderr
            );
        }
        c => prop_assert!(false, "{what}: exit {c}: {}", exit.stderr),
    }
    Ok(())
}

proptest! {
    #![proptest_config(cases(24))]

    #[test]
    fn any_table_gives_an_answer_never_a_panic(t in table(), id in 0u64..1_000_000) {
        let dir = scratch_dir("table-shapes", &format!("case-{id}"));
        let file = dir.join("table.txt");
        std::fs::write(&file, t.text()).unwrap();
        let f = file.to_str().unwrap();
        keeps_the_contract("data", &run(&["data", f]))?;
        keeps_the_contract("data json", &run(&["data", "--format", "json", f]))?;
        if id.is_multiple_of(4) {
            keeps_the_contract("fit", &run(&["fit", "--preset", "paper-b4.9", "--data", f]))?;
            keeps_the_contract(
                "render",
                &run(&["render", "--preset", "paper-b4.9", "--data", f, "--size", "60x20"]),
            )?;
        }
    }
}
