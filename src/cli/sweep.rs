//! `groovelab sweep`: regime maps over one or two scene parameters.

use std::fmt::Write as _;
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};

use serde::Serialize;

use super::{CliError, SceneArgs, SweepArgs, SweepFormat, methods::write_atomically};
use crate::study::sweep::{self, Axis, Point, SweepError};

/// Set by Ctrl-C while a sweep runs: the work stops and nothing is written.
static STOP: AtomicBool = AtomicBool::new(false);

fn grid(text: &str, two: bool) -> Result<(usize, usize), CliError> {
    let bad = || {
        CliError::Invalid(format!(
            "--grid {text} is not a grid, expected NX or NXxNY (1 ..= 10000 each), e.g. 400x200"
        ))
    };
    let (a, b) = match text.split_once(['x', 'X']) {
        Some((a, b)) => (a, Some(b)),
        None => (text, None),
    };
    let nx: usize = a.trim().parse().map_err(|_| bad())?;
    let ny: usize = match b {
        Some(b) => b.trim().parse().map_err(|_| bad())?,
        None => {
            if two {
                nx
            } else {
                1
            }
        }
    };
    if nx == 0 || ny == 0 || nx > 10_000 || ny > 10_000 {
        return Err(bad());
    }
    Ok((nx, ny))
}

#[derive(Serialize)]
struct SweepJson<'a> {
    x: &'a Axis,
    y: Option<&'a Axis>,
    points: &'a [Point],
}

pub fn run(scene_args: &SceneArgs, args: &SweepArgs) -> Result<String, CliError> {
    let (preset, _, _) = scene_args.resolve()?;
    let base = preset.spec.over(&scene_args.values);
    let (nx, ny) = grid(&args.grid, args.y.is_some())?;
    let x = sweep::parse_axis(&args.x, nx).map_err(|e| CliError::Invalid(format!("--x {e}")))?;
    let y = args
        .y
        .as_ref()
        .map(|t| sweep::parse_axis(t, ny).map_err(|e| CliError::Invalid(format!("--y {e}"))))
        .transpose()?;
    sweep::check(&base, &x, y.as_ref()).map_err(|e| CliError::Invalid(e.to_string()))?;
    let total = (nx * y.map_or(1, |_| ny)) as u64;
    let bar = (total >= 20_000 && std::io::stderr().is_terminal()).then(|| {
        let bar = indicatif::ProgressBar::new(total);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} points, {eta} left")
                .expect("a valid template"),
        );
        bar
    });
    STOP.store(false, Ordering::Relaxed);
    let _ = ctrlc::set_handler(|| STOP.store(true, Ordering::Relaxed));
    let tick = || {
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    let result = sweep::run(&base, &x, y.as_ref(), &STOP, &tick);
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let points = result.map_err(|e| match e {
        SweepError::Interrupted => CliError::Interrupted,
        SweepError::Invalid(m) => CliError::Invalid(m),
    })?;
    let text = match args.format {
        SweepFormat::Csv => csv(&points),
        SweepFormat::Json => {
            let mut s = serde_json::to_string(&SweepJson {
                x: &x,
                y: y.as_ref(),
                points: &points,
            })
            .expect("plain data serializes");
            s.push('\n');
            s
        }
        SweepFormat::Svg => {
            let scene = base
                .resolve()
                .map_err(|e| CliError::Invalid(e.to_string()))?
                .0;
            crate::study::figures::regime_map(&points, &x, y.as_ref(), &scene, &preset.name)
                .map_err(|e| CliError::Invalid(format!("cannot draw the map: {e}")))?
        }
    };
    match &args.output {
        None => Ok(text),
        Some(path) => {
            write_atomically(path, &text)?;
            Ok(format!("wrote {}\n", path.display()))
        }
    }
}

/// interface.md: `x,y,regime,v_ratio,t_roll,impacts,t_accumulation`, SI, grid order.
fn csv(points: &[Point]) -> String {
    let mut out = String::with_capacity(points.len() * 64);
    out.push_str("x,y,regime,v_ratio,t_roll,impacts,t_accumulation\n");
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    for p in points {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{}",
            p.x,
            opt(p.y),
            p.regime.name(),
            opt(p.v_ratio),
            opt(p.t_roll),
            p.impacts,
            opt(p.t_accumulation)
        );
    }
    out
}
