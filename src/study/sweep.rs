//! Regime maps: one scene parameter (or two) swept over a grid, each point solved
//! exactly, in parallel, with results in grid order whatever the thread count.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;
use serde::Serialize;

use crate::physics::derived::{Derived, Regime};
use crate::physics::engine;
use crate::physics::scene::Span;
use crate::settings::params::Key;
use crate::settings::spec::{SceneError, SceneSpec};
use crate::settings::units::{UnitError, parse_quantity};

/// One swept parameter: `key` from `lo` to `hi` (SI) in `n` points, both ends included.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SweepAxis {
    #[serde(serialize_with = "key_name")]
    pub key: Key,
    pub lo: f64,
    pub hi: f64,
    pub n: usize,
}

fn key_name<S: serde::Serializer>(k: &Key, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(k.name())
}

impl SweepAxis {
    pub fn value(&self, i: usize) -> f64 {
        if self.n <= 1 {
            self.lo
        } else {
            let v = self.lo + (self.hi - self.lo) * i as f64 / (self.n - 1) as f64;
            if v.is_finite() {
                v
            } else {
                // (hi − lo)·i overflowed near 1.8e308; the fraction first cannot. Only
                // here, so every map that worked keeps its exact values.
                self.lo + (self.hi - self.lo) * (i as f64 / (self.n - 1) as f64)
            }
        }
    }
}

/// What a grid point's scene does.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct GridPoint {
    pub x: f64,
    pub y: Option<f64>,
    pub regime: Regime,
    /// The left ball's rolling speed after the first impact over its v0 (positive:
    /// back toward the other ball); `None` without friction or impact.
    pub v_ratio: Option<f64>,
    /// The left ball's t' (s).
    pub t_roll: Option<f64>,
    pub impacts: usize,
    pub t_accumulation: Option<f64>,
}

/// Why a sweep cannot run.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SweepError {
    /// A corner of the grid (and so, the constraints being monotone, part of it) is
    /// not a valid scene.
    #[error(
        "the grid corner {x}{} is not a valid scene: {source}",
        y.map_or(String::new(), |y| format!(", {y}"))
    )]
    Corner {
        x: GridValue,
        y: Option<GridValue>,
        source: SceneError,
    },
    #[error("grid point {x} is not a valid scene")]
    Point { x: GridValue },
    /// The two axes sweep one value twice (see [`check_pair`]).
    #[error(transparent)]
    Axes(AxisError),
    #[error("interrupted: nothing was written")]
    Interrupted,
}

/// One axis's value at a grid point, shown `name = value` in the unit people read
/// (`width = 5.5 cm`), as the scene's own range message that follows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridValue {
    pub key: Key,
    pub value: f64,
}

impl std::fmt::Display for GridValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let shown = crate::settings::units::show(self.value, self.key.param().dim);
        write!(f, "{} = {shown}", self.key.name())
    }
}

/// Why an axis (`NAME=LO..HI` of `n` points) cannot be swept.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum AxisError {
    #[error(
        "'{}' is not NAME=LO..HI, e.g. width=0..5.4cm",
        crate::settings::quote::clip(text)
    )]
    NotAnAxis { text: String },
    #[error(
        "unknown parameter '{}', allowed: {}",
        crate::settings::quote::clip(name),
        sweepable_names()
    )]
    UnknownParameter { name: String },
    #[error("{} is not a scene parameter to sweep", key.name())]
    NotOfScene { key: Key },
    #[error(
        "'{}' is not LO..HI, e.g. 0..5.4cm",
        crate::settings::quote::clip(range)
    )]
    NotARange { range: String },
    #[error(transparent)]
    Bound(#[from] UnitError),
    #[error(
        "'{}' runs backwards, allowed LO ≤ HI",
        crate::settings::quote::clip(range)
    )]
    Backwards { range: String },
    #[error(
        "'{}' is too wide to step through, allowed HI − LO below 1.8e308",
        crate::settings::quote::clip(range)
    )]
    TooWide { range: String },
    #[error("{n} points on an axis, allowed 1 ..= 10000")]
    Points { n: usize },
    /// The second axis sweeps the first one's parameter again.
    #[error("{} is the other axis's parameter already, allowed a parameter other than {}", key.name(), key.name())]
    Twice { key: Key },
    /// The second axis would overwrite values the first one sets (`why`: the value
    /// they share, or which of them replaces which).
    #[error(
        "{} would overwrite what the other axis, {}, sets ({why}), allowed a parameter that sets other values",
        key.name(),
        other.name()
    )]
    Overwrites { key: Key, other: Key, why: Overlap },
    /// A scene option on the command line gives a value the axis sets at every point:
    /// it would be ignored.
    #[error(
        "{} sweeps the value --{} gives{}, allowed: the axis or the option, not both (the axis sets it at every point)",
        key.name(),
        option.param().flag,
        why.map_or(String::new(), |w| format!(" ({w})"))
    )]
    GivenToo {
        key: Key,
        option: Key,
        why: Option<Overlap>,
    },
}

/// How two swept parameters would write the same value of a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overlap {
    /// Both set this key (`mass` and `mass_left`).
    Both(Key),
    /// The first key replaces the second (a release height replaces the speed).
    Replaces(Key, Key),
}

impl std::fmt::Display for Overlap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Overlap::Both(k) => write!(f, "both set {}", k.name()),
            Overlap::Replaces(a, b) => write!(f, "{} replaces {}", a.name(), b.name()),
        }
    }
}

/// How the parameters `a` and `b` would write the same value of a scene, if they
/// would: a grid point sets one after the other, so the second would silently undo
/// part of the first.
fn overlap(a: Key, b: Key) -> Option<Overlap> {
    let (sa, sb) = (a.param().sets, b.param().sets);
    if let Some(&k) = sa.iter().find(|k| sb.contains(k)) {
        return Some(Overlap::Both(k));
    }
    let replacing = |from: &[Key], to: &[Key]| {
        from.iter().find_map(|&k| {
            k.param()
                .replaces
                .filter(|r| to.contains(r))
                .map(|r| (k, r))
        })
    };
    replacing(sa, sb)
        .or_else(|| replacing(sb, sa))
        .map(|(k, r)| Overlap::Replaces(k, r))
}

/// Checks that the second axis `y` sweeps values of its own, not the first axis's
/// `x` again (`width` twice) nor values that overwrite it (`height` against `v0`):
/// either would print points under values they were not solved at.
pub fn check_pair(x: &SweepAxis, y: &SweepAxis) -> Result<(), AxisError> {
    if x.key == y.key {
        return Err(AxisError::Twice { key: y.key });
    }
    match overlap(x.key, y.key) {
        Some(why) => Err(AxisError::Overwrites {
            key: y.key,
            other: x.key,
            why,
        }),
        None => Ok(()),
    }
}

/// Checks that no scene option on the command line (`given`: that layer) gives a
/// value the axis sets at every point (`--width` with `width=3..5cm`, `--mass-left`
/// with `mass`, `--height` with `v0`), which the sweep would silently ignore.
pub fn check_given(axis: &SweepAxis, given: &SceneSpec) -> Result<(), AxisError> {
    given
        .rows()
        .into_iter()
        .find_map(|option| {
            let why = overlap(axis.key, option);
            (option == axis.key || why.is_some()).then_some(AxisError::GivenToo {
                key: axis.key,
                option,
                why: why.filter(|_| option != axis.key),
            })
        })
        .map_or(Ok(()), Err)
}

/// The parameters an axis may sweep, for the error that names an unknown one.
fn sweepable_names() -> String {
    let names: Vec<&str> = Key::ALL
        .iter()
        .filter(|k| k.param().of_scene())
        .map(|k| k.name())
        .collect();
    names.join(", ")
}

/// The scene at grid point (i, j).
fn spec_at(
    base: &SceneSpec,
    x: &SweepAxis,
    y: Option<&SweepAxis>,
    i: usize,
    j: usize,
) -> SceneSpec {
    let mut spec = base.clone();
    // A swept speed replaces a release height (SceneSpec::set).
    let mut set = |axis: &SweepAxis, k: usize| spec.set(axis.key, axis.value(k));
    set(x, i);
    if let Some(y) = y {
        set(y, j);
    }
    spec
}

/// Solves one grid point.
pub fn point(spec: &SceneSpec) -> Result<(crate::physics::scene::Scene, GridPoint), SceneError> {
    let (scene, _) = spec.resolve()?;
    let derived = Derived::of(&scene);
    let sol = engine::solve(
        &scene,
        &Span {
            t_start: 0.0,
            t_end: None,
        },
    );
    let rec = derived.left_after_impact;
    Ok((
        scene,
        GridPoint {
            x: 0.0,
            y: None,
            regime: derived.regime,
            v_ratio: rec
                .filter(|_| scene.left.v0 != 0.0)
                .map(|r| r.v_roll / scene.left.v0),
            t_roll: rec.map(|r| r.t_roll),
            impacts: sol.impacts,
            t_accumulation: sol.accumulation,
        },
    ))
}

/// Checks that the axes make one map ([`check_pair`]) and the grid's corners (and
/// so, for these monotone constraints, every point).
pub fn check(base: &SceneSpec, x: &SweepAxis, y: Option<&SweepAxis>) -> Result<(), SweepError> {
    if let Some(y) = y {
        check_pair(x, y).map_err(SweepError::Axes)?;
    }
    let nx = x.n.max(1);
    let ny = y.map_or(1, |a| a.n.max(1));
    for (i, j) in [(0, 0), (nx - 1, 0), (0, ny - 1), (nx - 1, ny - 1)] {
        let spec = spec_at(base, x, y, i, j);
        spec.resolve().map_err(|source| SweepError::Corner {
            x: at(x, i),
            y: y.map(|y| at(y, j)),
            source,
        })?;
    }
    Ok(())
}

fn at(a: &SweepAxis, i: usize) -> GridValue {
    GridValue {
        key: a.key,
        value: a.value(i),
    }
}

/// Points solved per batch when streaming: enough to keep every core busy, few
/// enough that a batch (about 1.5 MB of points) bounds the memory of any grid.
pub const BATCH: usize = 16_384;

/// Solves every grid point, in parallel within batches of [`BATCH`] points, and hands
/// the batches to `sink` in grid order (y outer, x inner), so memory stays bounded
/// whatever the grid. `stop` ends the work early with [`SweepError::Interrupted`];
/// `tick` is called once per point (for a progress bar).
/// A failing `sink` ends the sweep with its own error.
pub fn run_streamed<E: From<SweepError>>(
    base: &SceneSpec,
    x: &SweepAxis,
    y: Option<&SweepAxis>,
    stop: &AtomicBool,
    tick: &(dyn Fn() + Sync),
    sink: &mut dyn FnMut(&[GridPoint]) -> Result<(), E>,
) -> Result<(), E> {
    check(base, x, y)?;
    let nx = x.n.max(1);
    let ny = y.map_or(1, |a| a.n.max(1));
    let total = nx * ny;
    let mut start = 0;
    while start < total {
        let end = (start + BATCH).min(total);
        let batch: Vec<Option<GridPoint>> = (start..end)
            .into_par_iter()
            .map(|idx| {
                if stop.load(Ordering::Relaxed) {
                    return None;
                }
                let (i, j) = (idx % nx, idx / nx);
                let spec = spec_at(base, x, y, i, j);
                let (_, mut p) = point(&spec).ok()?;
                p.x = x.value(i);
                p.y = y.map(|a| a.value(j));
                tick();
                Some(p)
            })
            .collect();
        if stop.load(Ordering::Relaxed) {
            return Err(SweepError::Interrupted.into());
        }
        let points: Vec<GridPoint> = batch
            .into_iter()
            .enumerate()
            .map(|(k, p)| {
                p.ok_or(SweepError::Point {
                    x: at(x, (start + k) % nx),
                })
            })
            .collect::<Result<_, _>>()?;
        sink(&points)?;
        start = end;
    }
    if stop.load(Ordering::Relaxed) {
        return Err(SweepError::Interrupted.into());
    }
    Ok(())
}

/// Solves every grid point in parallel; rows come in grid order (y outer, x inner).
/// `stop` ends the work early (the result is then an error, never a partial map);
/// `tick` is called once per point (for a progress bar).
pub fn run(
    base: &SceneSpec,
    x: &SweepAxis,
    y: Option<&SweepAxis>,
    stop: &AtomicBool,
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<GridPoint>, SweepError> {
    let mut all = Vec::new();
    run_streamed(base, x, y, stop, tick, &mut |batch| {
        all.extend_from_slice(batch);
        Ok::<_, SweepError>(())
    })?;
    Ok(all)
}

/// Parses `name=lo..hi` with units (`width=0..5.4cm`: a bare bound takes the other's
/// unit) into an axis of `n` points.
pub fn parse_axis(text: &str, n: usize) -> Result<SweepAxis, AxisError> {
    let (name, range) = text.split_once('=').ok_or_else(|| AxisError::NotAnAxis {
        text: text.to_string(),
    })?;
    let key = Key::from_name(&name.trim().replace('-', "_")).ok_or_else(|| {
        AxisError::UnknownParameter {
            name: name.to_string(),
        }
    })?;
    if !key.param().of_scene() {
        return Err(AxisError::NotOfScene { key });
    }
    let (a, b) = range.split_once("..").ok_or_else(|| AxisError::NotARange {
        range: range.to_string(),
    })?;
    let dim = key.dimension();
    // The unit after a bound's number; none if the bound does not start with one
    // (then it is lent to nobody and its own parse error names it).
    let unit_of = |s: &str| {
        let t = s.trim();
        let rest = t.trim_start_matches(|c: char| c.is_ascii_digit() || "+-.eE".contains(c));
        if rest.len() < t.len() {
            rest.to_string()
        } else {
            String::new()
        }
    };
    let (ua, ub) = (unit_of(a), unit_of(b));
    // A bare number takes the other bound's unit; an error in it then names the
    // range as typed (`3..5kg`), not the bound with a unit the user never wrote.
    let bound = |s: &str, other: &str| {
        if s.trim().parse::<f64>().is_ok() && !other.is_empty() {
            parse_quantity(&format!("{}{other}", s.trim()), dim)
                .map_err(|e| e.with_text(range.to_string()))
        } else {
            parse_quantity(s.trim(), dim)
        }
    };
    let lo = bound(a, &ub)?;
    let hi = bound(b, &ua)?;
    let range = || range.to_string();
    if hi < lo {
        return Err(AxisError::Backwards { range: range() });
    }
    if !(hi - lo).is_finite() {
        return Err(AxisError::TooWide { range: range() });
    }
    if n == 0 || n > 10_000 {
        return Err(AxisError::Points { n });
    }
    Ok(SweepAxis { key, lo, hi, n })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_take_units_for_both_ends() {
        let a = parse_axis("width=0..5.4cm", 10).unwrap();
        assert_eq!((a.key, a.lo, a.hi), (Key::Width, 0.0, 0.054));
        let a = parse_axis("width=2..5cm", 4).unwrap();
        assert_eq!((a.lo, a.hi), (0.02, 0.05));
        assert_eq!(a.value(3), 0.05);
        let a = parse_axis("restitution=0.3..1", 8).unwrap();
        assert_eq!((a.lo, a.hi), (0.3, 1.0));
        assert!(parse_axis("colour=0..1", 3).is_err());
        assert!(parse_axis("width=5..1cm", 3).is_err());
        assert!(parse_axis("width", 3).is_err());
        // Huge but valid bounds step without overflow.
        let a = parse_axis("mass=1e-300..1e308", 5).unwrap();
        assert!((0..5).all(|i| a.value(i).is_finite()));
        assert_eq!(a.value(4), 1e308);
        let e = parse_axis("mu=0..abc", 3).unwrap_err();
        assert!(e.to_string().contains("'abc' is not a number"), "{e}");
        // A bound lent the other's unit is named as typed.
        let e = parse_axis("width=3..5kg", 3).unwrap_err().to_string();
        assert!(
            e.starts_with("unknown unit 'kg' in '3..5kg', expected"),
            "{e}"
        );
        let e = parse_axis("width=abc..5cm", 3).unwrap_err().to_string();
        assert!(e.starts_with("'abc' is not a number"), "{e}");
    }
}
