//! `groovelab sweep`: regime maps over one or two scene parameters, streamed in grid
//! order to an `--output` file with bounded memory, or built whole for stdout (up to
//! [`STDOUT_LIMIT`]); interrupted, it writes nothing (see `output`).

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicBool, Ordering};

use super::args::{SceneArgs, SweepArgs, SweepFormat};
use super::error::{BadValue, CliError, Flag, size_text};
use super::progress::Bar;
use crate::output::AtomicFile;
use crate::study::sweep::{self, GridPoint, SweepAxis};

fn grid(text: &str, two: bool) -> Result<(usize, usize), CliError> {
    match super::args::counts(text, 10_000) {
        // NX alone: a square grid for two parameters, one row for one.
        // The default's NX alone for one parameter; a second count given has no axis.
        Some((nx, Some(ny))) if !two && ny > 1 && text != super::args::DEFAULT_GRID => {
            Err(BadValue::GridWithoutY {
                text: text.to_string(),
                nx,
                ny,
            }
            .into())
        }
        Some((nx, ny)) => Ok((nx, ny.unwrap_or(if two { nx } else { 1 }))),
        None => Err(BadValue::Grid {
            text: text.to_string(),
        }
        .into()),
    }
}

/// Most output `sweep` builds in memory for stdout (which is written only once the
/// whole map is done, so an interruption or error prints nothing); a larger map is
/// refused there and streamed to disk with `--output FILE`.
pub const STDOUT_LIMIT: u64 = 256 * 1024 * 1024;
/// Outputs estimated above this get their size noted on stderr before the work.
const NOTE_ABOVE: u64 = 64 * 1024 * 1024;
/// Largest grid drawn as SVG: one rectangle per point, ~90 bytes each.
pub const MAX_SVG_AXIS: usize = 1000;

/// Typical bytes per point of each format (measured on a 200x100 width × e map:
/// CSV 99, JSON 168, SVG 86), for the size estimate.
fn bytes_per_point(format: SweepFormat) -> u64 {
    match format {
        SweepFormat::Csv => 100,
        SweepFormat::Json => 170,
        SweepFormat::Svg => 90,
    }
}

/// A writer into memory that refuses to grow past `limit` bytes (stdout's buffer).
struct Capped {
    bytes: Vec<u8>,
    limit: u64,
}

impl Write for Capped {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if (self.bytes.len() + buf.len()) as u64 > self.limit {
            return Err(std::io::Error::other(format!(
                "the output passed {} on stdout, allowed at most {}; write it with {} FILE",
                size_text(self.limit),
                size_text(self.limit),
                Flag("output")
            )));
        }
        self.bytes.extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// `sweep`: stops cleanly on a stop signal (exit 130, nothing written).
pub fn run(scene_args: &SceneArgs, args: &SweepArgs) -> Result<String, CliError> {
    crate::signals::watch();
    run_with_stop(scene_args, args, crate::signals::stop_flag())
}

/// `sweep` with its own stop flag: if `stop` is set before the output is committed
/// (renamed into place, or returned for stdout), the result is
/// [`CliError::Interrupted`] and nothing is written.
pub fn run_with_stop(
    scene_args: &SceneArgs,
    args: &SweepArgs,
    stop: &AtomicBool,
) -> Result<String, CliError> {
    let (preset, _, _) = scene_args.resolve()?;
    let base = preset.spec.over(&scene_args.values);
    let (nx, ny) = grid(&args.grid, args.y.is_some())?;
    let axis = |text: &str, n, id| {
        sweep::parse_axis(text, n).map_err(|source| BadValue::Axis {
            flag: Flag(id),
            source,
        })
    };
    let x = axis(&args.x, nx, "x")?;
    let y = args.y.as_ref().map(|t| axis(t, ny, "y")).transpose()?;
    for (a, id) in std::iter::once((&x, "x")).chain(y.as_ref().map(|y| (y, "y"))) {
        sweep::check_given(a, &scene_args.values).map_err(|source| BadValue::Axis {
            flag: Flag(id),
            source,
        })?;
    }
    if let Some(y) = &y {
        sweep::check_pair(&x, y).map_err(|source| BadValue::Axis {
            flag: Flag("y"),
            source,
        })?;
    }
    let ny = y.map_or(1, |_| ny);
    // The grid's corners are checked once, by the sweep itself, before any point is
    // solved or a byte is committed.
    if args.format == SweepFormat::Svg && (nx > MAX_SVG_AXIS || ny > MAX_SVG_AXIS) {
        return Err(BadValue::GridTooFineForSvg {
            grid: args.grid.clone(),
            max: MAX_SVG_AXIS,
        }
        .into());
    }
    let total = (nx * ny) as u64;
    let estimate = total * bytes_per_point(args.format);
    let name = format!("{:?}", args.format).to_uppercase();
    if args.output.is_none() && estimate > STDOUT_LIMIT {
        return Err(BadValue::TooLargeForStdout {
            grid: args.grid.clone(),
            points: total,
            bytes: estimate,
            format: args.format,
            limit: STDOUT_LIMIT,
        }
        .into());
    }
    // For the person watching (like the progress bar); scripts keep a stderr that is
    // empty on success and one `error:` line on failure.
    if estimate > NOTE_ABOVE && std::io::stderr().is_terminal() {
        eprintln!(
            "note: sweep of {total} points writes about {} of {name}{}",
            size_text(estimate),
            args.output
                .as_ref()
                .map_or(String::new(), |p| format!(" to {}", p.display()))
        );
    }
    let bar = Bar::with_stop("points", total >= 20_000, stop);
    bar.set_total(total);
    let tick = || bar.inc();
    let map = SweepJob {
        base: &base,
        x: &x,
        y: y.as_ref(),
        preset: &preset.name,
        stop,
        tick: &tick,
    };
    let result = match &args.output {
        Some(path) => {
            let mut file = AtomicFile::create(path)?;
            emit(&map, args.format, &mut file, &|e| output_error(path, e))
                .and_then(|()| file.commit(stop).map_err(CliError::from))
                .map(|()| format!("wrote {}\n", path.display()))
        }
        None => {
            let mut out = Capped {
                bytes: Vec::new(),
                limit: STDOUT_LIMIT,
            };
            emit(&map, args.format, &mut out, &CliError::Io).and_then(|()| {
                // Ctrl-C after the work but before the text is handed over.
                if stop.load(Ordering::Relaxed) {
                    return Err(CliError::Interrupted);
                }
                Ok(String::from_utf8(out.bytes).expect("CSV, JSON and SVG are UTF-8"))
            })
        }
    };
    bar.finish();
    result
}

fn output_error(path: &std::path::Path, source: std::io::Error) -> CliError {
    CliError::Write {
        path: path.to_path_buf(),
        source,
    }
}

/// What one sweep computes.
struct SweepJob<'a> {
    base: &'a crate::settings::spec::SceneSpec,
    x: &'a SweepAxis,
    y: Option<&'a SweepAxis>,
    preset: &'a str,
    stop: &'a AtomicBool,
    tick: &'a (dyn Fn() + Sync),
}

/// Computes the map and writes it to `out`: CSV and JSON row batch by row batch
/// (bounded memory), SVG whole (its grid is capped).
fn emit(
    map: &SweepJob,
    format: SweepFormat,
    out: &mut dyn Write,
    io_error: &dyn Fn(std::io::Error) -> CliError,
) -> Result<(), CliError> {
    let mut stream = |head: &[u8],
                      row: &dyn Fn(&mut Vec<u8>, &GridPoint, bool),
                      tail: &[u8]|
     -> Result<(), CliError> {
        out.write_all(head).map_err(io_error)?;
        let mut first = true;
        let mut buf = Vec::with_capacity(sweep::BATCH * 128);
        sweep::run_streamed(map.base, map.x, map.y, map.stop, map.tick, &mut |batch| {
            buf.clear();
            for p in batch {
                row(&mut buf, p, first);
                first = false;
            }
            out.write_all(&buf).map_err(io_error)
        })?;
        out.write_all(tail).map_err(io_error)
    };
    match format {
        SweepFormat::Csv => stream(
            b"x,y,regime,v_ratio,t_roll,impacts,t_accumulation\n",
            &|buf, p, _| csv_row(buf, p),
            b"",
        ),
        SweepFormat::Json => {
            // Byte for byte what serde_json writes for {x, y, points}, in pieces.
            let head = format!(
                "{{\"x\":{},\"y\":{},\"points\":[",
                serde_json::to_string(map.x).expect("plain data serializes"),
                serde_json::to_string(&map.y).expect("plain data serializes")
            );
            stream(
                head.as_bytes(),
                &|buf, p, first| {
                    if !first {
                        buf.push(b',');
                    }
                    serde_json::to_writer(&mut *buf, p).expect("plain data serializes");
                },
                b"]}\n",
            )
        }
        SweepFormat::Svg => {
            let points = sweep::run(map.base, map.x, map.y, map.stop, map.tick)?;
            let scene = map.base.resolve()?.0;
            let svg = crate::study::figures::regime_map(&points, map.x, map.y, &scene, map.preset)
                .map_err(|source| CliError::Draw {
                    what: "map",
                    source,
                })?;
            out.write_all(svg.as_bytes()).map_err(io_error)
        }
    }
}

/// interface.md: `x,y,regime,v_ratio,t_roll,impacts,t_accumulation`, SI, grid order.
fn csv_row(buf: &mut Vec<u8>, p: &GridPoint) {
    let opt = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    let _ = writeln!(
        buf,
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
