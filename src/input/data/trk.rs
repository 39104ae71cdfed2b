//! Tracker's project file (`.trk`, XML): each point-mass track's positions in the
//! video's pixels (`PointMass` frame data, by frame number), the coordinate system's
//! origin, angle and scale (per frame where they change: each frame takes the last
//! one given at or before it), the clip's start frame and start time, and the frame
//! duration Δt. Positions become world coordinates as Tracker's own table shows them
//! (pixel y down, world y up, the x axis turned by the angle, in the project's length
//! unit); times are `start time + (frame − start frame)·Δt`.

use roxmltree::Node;

use super::layout::pick_roles;
use super::notes::{Notes, UnitNote};
use super::options::{MAX_ROWS, Reading};
use super::problem::{DataError, DataProblem};
use super::scales::{Given, LENGTHS, check_track_as_read};
use super::xml::{self, child};
use crate::settings::units::{Dimension, significant};
use crate::study::measured::{Track, TrackParts};

/// The format's name, as `groovelab data` and the fit say it.
pub const FORMAT: &str = "Tracker project (.trk)";

/// True when `text` looks like a Tracker project (before it is parsed).
pub(super) fn is_trk(text: &str) -> bool {
    let head = &text[..text.len().min(2000)];
    head.trim_start_matches('\u{feff}')
        .trim_start()
        .starts_with('<')
        && head.contains("cabrillo.tracker.TrackerPanel")
}

/// One frame's coordinate system: the image position of the origin (px), the x
/// axis's angle counter-clockwise from the image's x axis (rad) and the scale (px
/// per world unit) along each image axis.
#[derive(Clone, Copy, Debug)]
struct Coords {
    origin: (f64, f64),
    angle: f64,
    scale: (f64, f64),
}

impl Coords {
    /// World coordinates of the image point `(px, py)` (Tracker's `toWorld`).
    fn world(&self, px: f64, py: f64) -> (f64, f64) {
        let (dx, dy) = (
            (px - self.origin.0) / self.scale.0,
            (py - self.origin.1) / self.scale.1,
        );
        let (sin, cos) = self.angle.sin_cos();
        (cos * dx - sin * dy, -sin * dx - cos * dy)
    }
}

/// The `<property name="NAME">` child of `node`.
fn prop<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.children()
        .find(|c| c.has_tag_name("property") && c.attribute("name") == Some(name))
}

/// The `<object>` a property holds.
fn object<'a, 'i>(node: Node<'a, 'i>) -> Option<Node<'a, 'i>> {
    child(node, "object")
}

/// A property's number.
fn number(node: Node<'_, '_>, name: &str) -> Option<f64> {
    prop(node, name)?
        .text()?
        .trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
}

/// The entries `[n]` of an array property, as (n, the object it holds).
fn frames<'a, 'i>(array: Node<'a, 'i>) -> impl Iterator<Item = (usize, Node<'a, 'i>)> {
    array.children().filter_map(|c| {
        let n = c
            .attribute("name")?
            .strip_prefix('[')?
            .strip_suffix(']')?
            .parse()
            .ok()?;
        Some((n, object(c)?))
    })
}

/// One point-mass track: its name and (frame, pixel x, pixel y) in frame order.
struct Points {
    name: String,
    at: Vec<(usize, f64, f64)>,
}

/// The point-mass tracks of the project, in file order.
fn point_masses(root: Node<'_, '_>) -> Result<Vec<Points>, DataProblem> {
    let mut out = Vec::new();
    let Some(tracks) = prop(root, "tracks") else {
        return Ok(out);
    };
    for item in tracks.children().filter_map(object) {
        if !item
            .attribute("class")
            .is_some_and(|c| c.ends_with(".PointMass"))
        {
            continue;
        }
        let name = prop(item, "name")
            .and_then(|n| n.text())
            .unwrap_or("")
            .trim()
            .to_string();
        let mut at = Vec::new();
        if let Some(data) = prop(item, "framedata") {
            for (n, f) in frames(data) {
                if at.len() == MAX_ROWS {
                    return Err(DataProblem::TooManyFrames { track: name });
                }
                if let (Some(x), Some(y)) = (number(f, "x"), number(f, "y")) {
                    at.push((n, x, y));
                }
            }
        }
        at.sort_by_key(|p| p.0);
        out.push(Points { name, at });
    }
    Ok(out)
}

/// The coordinate system's frames, in frame order (none: Tracker's default, pixels).
fn coords(root: Node<'_, '_>) -> Vec<(usize, Coords)> {
    let Some(data) = prop(root, "coords")
        .and_then(object)
        .and_then(|c| prop(c, "framedata"))
    else {
        return Vec::new();
    };
    let mut out: Vec<(usize, Coords)> = frames(data)
        .map(|(n, f)| {
            let get = |k: &str, default: f64| number(f, k).unwrap_or(default);
            let c = Coords {
                origin: (get("xorigin", 0.0), get("yorigin", 0.0)),
                // Tracker saves the angle in degrees.
                angle: get("angle", 0.0).to_radians(),
                scale: (get("xscale", 1.0), get("yscale", 1.0)),
            };
            (n, c)
        })
        .collect();
    out.sort_by_key(|c| c.0);
    out
}

/// The clip's timing: start frame, start time (s) and frame duration (s).
fn timing(root: Node<'_, '_>) -> Result<(usize, f64, f64), DataProblem> {
    let clip = prop(root, "videoclip").and_then(object);
    let start_frame = clip.and_then(|c| number(c, "startframe")).unwrap_or(0.0);
    let start_time = clip.and_then(|c| number(c, "starttime")).unwrap_or(0.0) / 1e3;
    let dt = prop(root, "clipcontrol")
        .and_then(object)
        .and_then(|c| number(c, "delta_t"))
        .filter(|&dt| dt > 0.0)
        .ok_or(DataProblem::NoFrameDuration)?;
    Ok((start_frame.max(0.0) as usize, start_time, dt / 1e3))
}

/// Reads a Tracker project (see the module doc) into a track in SI units and what it
/// said about itself.
pub(super) fn read(text: &str, file: &str, reading: &Reading) -> Result<(Track, Notes), DataError> {
    let err = |what: DataProblem| DataError::new(file, what);
    let doc = xml::parse(text, "Tracker project").map_err(|e| err(e.into()))?;
    let root = doc.root_element();
    if !root
        .attribute("class")
        .is_some_and(|c| c.ends_with("TrackerPanel"))
    {
        return Err(err(DataProblem::NotTracker));
    }
    let (start_frame, start_time, dt) = timing(root).map_err(err)?;
    let tracks = point_masses(root).map_err(err)?;
    let names: Vec<String> = tracks
        .iter()
        .filter(|p| !p.at.is_empty())
        .map(|p| p.name.clone())
        .collect();
    if names.is_empty() {
        return Err(err(DataProblem::NoPointMass));
    }
    let (centre, mark) = pick_roles(&names, reading).map_err(|e| err(e.into()))?;
    let coords = coords(root);
    let (factor, length) = length_unit(root, &coords, reading).map_err(err)?;
    // The roles are picked among these tracks' names, so both are found.
    let points = |name: &str| tracks.iter().find(|p| p.name == name);
    let Some(centre_points) = points(&centre) else {
        return Err(err(DataProblem::NoPointMass));
    };
    let mark_points = mark.as_deref().and_then(points);
    let frame_list = frame_union(centre_points, mark_points);
    let time = |f: usize| start_time + (f as f64 - start_frame as f64) * dt;
    let at = |p: &Points, f: usize| -> (f64, f64) {
        let found = p.at.binary_search_by_key(&f, |a| a.0).ok();
        match found.and_then(|i| p.at.get(i)) {
            Some(&(_, px, py)) => {
                let c = coords_at(&coords, f, factor.is_pixels);
                let (x, y) = c.world(px, py);
                (x * factor.si, y * factor.si)
            }
            None => (f64::NAN, f64::NAN),
        }
    };
    let mut track = TrackParts {
        centre_name: centre.clone(),
        mark_name: mark.clone(),
        format: FORMAT,
        mark: mark.as_ref().map(|_| (Vec::new(), Vec::new())),
        ..TrackParts::default()
    };
    for &f in &frame_list {
        track.t.push(time(f));
        let (x, y) = at(centre_points, f);
        track.x.push(x);
        track.y.push(y);
        if let (Some(m), Some((mx, my))) = (mark_points, track.mark.as_mut()) {
            let (a, b) = at(m, f);
            mx.push(a);
            my.push(b);
        }
    }
    let given = Given {
        time: (1.0, Some("the project")),
        length: (factor.si, Some(factor.by)),
    };
    let track = Track::new(track).map_err(|e| err(e.into()))?;
    check_track_as_read(&track, &given, reading.own_lengths).map_err(|e| err(e.into()))?;
    let notes = Notes {
        cut_row: None,
        impact_in_file: None,
        format: FORMAT.into(),
        tracks: names,
        units: vec![
            UnitNote {
                quantity: "time",
                unit: "s".into(),
                how: format!(
                    "the project's frame duration ({}, {} frames/s)",
                    crate::settings::units::show_small(dt, Dimension::Time),
                    // As the frames' line says it (4 digits: 15.15, not 15.1515).
                    significant(1.0 / dt, 4)
                ),
            },
            length,
        ],
    };
    Ok((track, notes))
}

/// The frames with the centre or the mark, in order.
fn frame_union(centre: &Points, mark: Option<&Points>) -> Vec<usize> {
    let mut all: Vec<usize> = centre.at.iter().map(|p| p.0).collect();
    if let Some(m) = mark {
        all.extend(m.at.iter().map(|p| p.0));
    }
    all.sort_unstable();
    all.dedup();
    all
}

/// Frame `f`'s coordinate system: the last one given at or before it (the first
/// before any); with `pixels`, its origin and angle at a scale of 1.
fn coords_at(coords: &[(usize, Coords)], f: usize, pixels: bool) -> Coords {
    let i = coords.partition_point(|c| c.0 <= f).saturating_sub(1);
    let mut c = coords.get(i).map_or(
        Coords {
            origin: (0.0, 0.0),
            angle: 0.0,
            scale: (1.0, 1.0),
        },
        |c| c.1,
    );
    if pixels {
        c.scale = (1.0, 1.0);
    }
    c
}

/// How world coordinates become metres.
struct Factor {
    /// Metres per world unit (per pixel with `is_pixels`).
    si: f64,
    is_pixels: bool,
    by: &'static str,
}

/// The SI factor of the project's world coordinates, and its note: the project's
/// calibration in its length unit (m when it names none), an option over it, or
/// `--scale` for a video never calibrated (a scale of 1 pixel per unit).
fn length_unit(
    root: Node<'_, '_>,
    coords: &[(usize, Coords)],
    reading: &Reading,
) -> Result<(Factor, UnitNote), DataProblem> {
    let calibrated = coords.iter().any(|(_, c)| c.scale != (1.0, 1.0));
    if let Some(px) = reading.scale {
        let f = Factor {
            si: px,
            is_pixels: true,
            by: "--scale",
        };
        let note = UnitNote {
            quantity: "length",
            unit: format!(
                "pixels of {}",
                crate::settings::units::show_small(px, Dimension::Length)
            ),
            how: "--scale".into(),
        };
        return Ok((f, note));
    }
    if let Some(u) = reading.length_unit {
        let f = Factor {
            si: u,
            is_pixels: !calibrated,
            by: "--length-unit",
        };
        return Ok((
            f,
            UnitNote::of("length", &LENGTHS, u, Some("--length-unit")),
        ));
    }
    if !calibrated {
        return Err(DataProblem::Uncalibrated);
    }
    let named = prop(root, "length_unit")
        .and_then(|n| n.text())
        .map(str::trim);
    let si = match named {
        None | Some("") => 1.0,
        Some(u) => super::table::file_unit(u, Dimension::Length)
            .map_err(|_| DataProblem::ProjectUnit { unit: u.into() })?,
    };
    let Some(&(_, c)) = coords.first() else {
        return Err(DataProblem::Uncalibrated);
    };
    let how = format!(
        "the project's calibration ({} pixels per {}){}",
        significant(c.scale.0, 5),
        named.filter(|u| !u.is_empty()).unwrap_or("m"),
        if named.is_none_or(str::is_empty) {
            ", m as Tracker's default unit"
        } else {
            ""
        }
    );
    let note = UnitNote {
        how,
        ..UnitNote::of("length", &LENGTHS, si, None)
    };
    Ok((
        Factor {
            si,
            is_pixels: false,
            by: "the project",
        },
        note,
    ))
}
