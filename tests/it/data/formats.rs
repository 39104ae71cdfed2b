//! The video tools' own files (issue 27), each made here by a generator modelled on
//! real ones (their headers, number styles and XML structure) from the exact solution
//! of the paper's scene: Tracker's project (`.trk`: pixels, a turned and scaled
//! coordinate system, a clip that starts at frame 52), Logger Pro's file (`.cmbl`:
//! columns with one cell per line, a calculated column without cells, a curve-fit data
//! set) and its text export (Vernier Format 2). Each reader must give back the
//! positions, and the fit μ_k within its ± of the truth. Also: units checked for
//! plausibility whether stated or not, missing frames said, `groovelab data` on any
//! file, and hostile XML refused in one line.

use crate::common;
use std::path::PathBuf;

use groovelab::input::data::{self, Reading};
use groovelab::physics::scene::Scene;
use groovelab::study::measured::{RawSeries, Track};
use groovelab::study::video::{self, Video};

fn scene() -> Scene {
    crate::common::paper_scene()
}

fn scratch(test: &str) -> PathBuf {
    crate::common::scratch_dir("formats", test)
}

fn groovelab(args: &[&str]) -> (Option<i32>, String, String) {
    let out = common::groovelab(args);
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The paper's scene filmed at 120 frames/s, centre and rim mark, 0.2 mm of noise.
pub(crate) fn filmed() -> Track {
    video::track(
        &scene(),
        &Video {
            seed: 11,
            noise: 2e-4,
            ..Video::default()
        },
    )
    .unwrap()
}

/// A Tracker coordinate system: origin (px), x axis turned by `angle` (degrees, ccw
/// as the viewer sees it) and `scale` px per metre, image y downward.
pub(crate) struct Coords {
    pub(crate) origin: (f64, f64),
    pub(crate) angle: f64,
    pub(crate) scale: f64,
}

/// A camera turned by 2.5° and 905 px per metre, as the NTNU lab's V10.trk.
const V10: Coords = Coords {
    origin: (179.38, 641.01),
    angle: 2.5,
    scale: 904.778,
};

impl Coords {
    /// The image point of the world point (x, y), m: Tracker's `toImage`.
    fn image(&self, x: f64, y: f64) -> (f64, f64) {
        let (sin, cos) = self.angle.to_radians().sin_cos();
        let s = self.scale;
        (
            self.origin.0 + s * cos * x - s * sin * y,
            self.origin.1 - s * sin * x - s * cos * y,
        )
    }
}

/// One `PointMass` of a Tracker project, its frame data by frame number.
fn point_mass(name: &str, first_frame: usize, x: &[f64], y: &[f64], c: &Coords) -> String {
    let mut s = format!(
        "        <property name=\"item\" type=\"object\">\n        <object class=\"org.opensourcephysics.cabrillo.tracker.PointMass\">\n            <property name=\"mass\" type=\"double\">1.0</property>\n            <property name=\"name\" type=\"string\">{name}</property>\n            <property name=\"footprint\" type=\"string\">Footprint.Diamond</property>\n            <property name=\"framedata\" type=\"array\" class=\"[Lorg.opensourcephysics.cabrillo.tracker.PointMass$FrameData;\">\n"
    );
    for i in 0..x.len() {
        let (px, py) = c.image(x[i], y[i]);
        s += &format!(
            "                <property name=\"[{}]\" type=\"object\">\n                <object class=\"org.opensourcephysics.cabrillo.tracker.PointMass$FrameData\">\n                    <property name=\"x\" type=\"double\">{px:?}</property>\n                    <property name=\"y\" type=\"double\">{py:?}</property>\n                </object>\n                </property>\n",
            first_frame + i
        );
    }
    s + "            </property>\n        </object>\n        </property>\n"
}

/// A Tracker 4.11 project (`.trk`) of `track` (centre "mass A", rim mark "mass B"), as
/// V10.trk of the NTNU lab is laid out: the clip starting at frame `start`, Δt from
/// the frame rate, one coordinate frame, a calibration stick, positions in pixels.
pub(crate) fn trk(track: &Track, start: usize, c: &Coords) -> String {
    let dt = (track.t()[1] - track.t()[0]) * 1e3;
    let (mx, my) = track.mark().unwrap();
    let mut s = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<object class="org.opensourcephysics.cabrillo.tracker.TrackerPanel">
    <property name="semantic_version" type="string">4.11.0</property>
    <property name="width" type="double">1280.0</property>
    <property name="videoclip" type="object">
    <object class="org.opensourcephysics.media.core.VideoClip">
        <property name="video_framecount" type="int">{frames}</property>
        <property name="startframe" type="int">{start}</property>
        <property name="stepsize" type="int">1</property>
        <property name="starttime" type="double">{t0:?}</property>
    </object>
    </property>
    <property name="clipcontrol" type="object">
    <object class="org.opensourcephysics.media.core.StepperClipControl">
        <property name="rate" type="double">1.0</property>
        <property name="delta_t" type="double">{dt:?}</property>
    </object>
    </property>
    <property name="coords" type="object">
    <object class="org.opensourcephysics.media.core.ImageCoordSystem">
        <property name="framedata" type="array" class="[Lorg.opensourcephysics.media.core.ImageCoordSystem$FrameData;">
            <property name="[0]" type="object">
            <object class="org.opensourcephysics.media.core.ImageCoordSystem$FrameData">
                <property name="xorigin" type="double">{ox:?}</property>
                <property name="yorigin" type="double">{oy:?}</property>
                <property name="angle" type="double">{angle:?}</property>
                <property name="xscale" type="double">{scale:?}</property>
                <property name="yscale" type="double">{scale:?}</property>
            </object>
            </property>
        </property>
    </object>
    </property>
    <property name="tracks" type="collection" class="java.util.ArrayList">
        <property name="item" type="object">
        <object class="org.opensourcephysics.cabrillo.tracker.CoordAxes">
            <property name="name" type="string">axes</property>
        </object>
        </property>
        <property name="item" type="object">
        <object class="org.opensourcephysics.cabrillo.tracker.TapeMeasure">
            <property name="name" type="string">calibration stick A</property>
            <property name="stickmode" type="boolean">true</property>
        </object>
        </property>
"#,
        frames = start + track.t().len(),
        t0 = track.t()[0] * 1e3,
        ox = c.origin.0,
        oy = c.origin.1,
        angle = c.angle,
        scale = c.scale,
    );
    s += &point_mass("mass A", start, track.x(), track.y(), c);
    s += &point_mass("mass B", start, mx, my, c);
    s + "    </property>\n    <property name=\"selectedtrack\" type=\"string\">mass A</property>\n</object>\n"
}

/// A Logger Pro 3.8 file (`.cmbl`) of `track` as acceleratingcar.cmbl is laid out: no
/// XML declaration, a `VideoAnalysis` data set whose columns hold one cell per line
/// (Time, X, Y, X2, Y2 in `unit`, "" when the video was never scaled), calculated
/// velocity columns without cells, and a curve-fit data set with entities in its name.
pub(crate) fn cmbl(track: &Track, unit: &str) -> String {
    let (mx, my) = track.mark().unwrap();
    let column = |id: usize, name: &str, short: &str, unit: &str, cells: &[f64]| {
        let cells: String = cells.iter().map(|v| format!("{v}\n")).collect();
        format!(
            "    <DataColumn>\n      <ID>{id} </ID>\n      <DataObjectName>{name}</DataObjectName>\n      <DataObjectShortName>{short}</DataObjectShortName>\n      <ColumnUnits>{unit}</ColumnUnits>\n      <ColumnCells>\n{cells}</ColumnCells>\n    </DataColumn>\n"
        )
    };
    let mut s = String::from(
        "<Document>\n  <FileCoherence>1</FileCoherence>\n  <Version>3.8.7</Version>\n  <Copyright>Copyright (c) 2012 Vernier Software &#38; Technology</Copyright>\n  <Page>\n    <PageMovie>\n      <VAMovieActualDistance>1</VAMovieActualDistance>\n      <VAMoviePixelDistance>0.00625250824844</VAMoviePixelDistance>\n      <VAMovieScaleUnits></VAMovieScaleUnits>\n    </PageMovie>\n  </Page>\n  <DataSet>\n    <ID>109 </ID>\n    <DataSetName>VideoAnalysis</DataSetName>\n    <DataSetVideoAnalysis>1</DataSetVideoAnalysis>\n",
    );
    s += &column(110, "Time", "t", "s", track.t());
    s += &column(112, "X", "X", unit, track.x());
    s += &column(114, "Y", "Y", unit, track.y());
    s += &column(115, "X2", "X2", unit, mx);
    s += &column(116, "Y2", "Y2", unit, my);
    s += "    <DataColumn>\n      <DataObjectName>X Velocity</DataObjectName>\n      <ColumnUnits></ColumnUnits>\n    </DataColumn>\n  </DataSet>\n";
    s += "  <DataSet>\n    <DataSetName>&#38;&#38;^% CurveFitFunctions %^&#38;&#38;</DataSetName>\n  </DataSet>\n</Document>\n";
    s
}

/// Logger Pro's "Export As Text" (Vernier Format 2) of `track`, CRLF line ends,
/// positions in cm with a decimal comma (a German Logger Pro), velocity columns
/// computed beside them.
pub(crate) fn vernier(track: &Track) -> String {
    let (mx, my) = track.mark().unwrap();
    let mut s = String::from(
        "Vernier Format 2\r\nball.cmbl 11/26/2026 09:41:07 .\r\nLatest\r\nTime\tX\tY\tX2\tY2\tX Velocity\r\nt\tX\tY\tX2\tY2\tVx\r\ns\tcm\tcm\tcm\tcm\tcm/s\r\n\r\n",
    );
    let comma = |v: f64| format!("{:.4}", 100.0 * v).replace('.', ",");
    for i in 0..track.t().len() {
        let vx = if i + 1 < track.t().len() {
            comma((track.x()[i + 1] - track.x()[i]) / (track.t()[i + 1] - track.t()[i]))
        } else {
            String::new()
        };
        s += &format!(
            "{:.6}\t{}\t{}\t{}\t{}\t{vx}\r\n",
            track.t()[i],
            comma(track.x()[i]),
            comma(track.y()[i]),
            comma(mx[i]),
            comma(my[i])
        );
    }
    s
}

/// The positions of `got` are those of `want` within `tol` m.
fn same_positions(got: &RawSeries, want: &Track, tol: f64) {
    let RawSeries::Positions(got) = got else {
        panic!("not a track");
    };
    assert_eq!(got.t().len(), want.t().len());
    let (gx, gy) = got.mark().unwrap();
    let (wx, wy) = want.mark().unwrap();
    for i in 0..want.t().len() {
        assert!((got.t()[i] - want.t()[i]).abs() < tol, "t[{i}]");
        for (a, b) in [
            (got.x()[i], want.x()[i]),
            (got.y()[i], want.y()[i]),
            (gx[i], wx[i]),
            (gy[i], wy[i]),
        ] {
            assert!((a - b).abs() < tol, "frame {i}: {a} vs {b}");
        }
    }
}

/// `fit` on `file` (with more options) in the paper's groove: μ_k of the position fit
/// is within twice its standard error of the truth (the ± the table prints).
fn fits_the_truth(file: &std::path::Path, extra: &[&str]) {
    let mut args = vec![
        "fit",
        "--preset",
        "paper-b4.9",
        "--format",
        "json",
        "--data",
        file.to_str().unwrap(),
    ];
    args.extend(extra);
    let (code, out, err) = groovelab(&args);
    assert_eq!(code, Some(0), "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let fit = &j["model_fit"];
    let (mu, se) = (fit["mu"].as_f64().unwrap(), fit["mu_se"].as_f64().unwrap());
    let truth = scene().mu;
    assert!(
        (mu - truth).abs() <= 2.0 * se,
        "{}: μ_k = {mu} ± {se}, truth {truth}",
        file.display()
    );
}

#[test]
fn a_tracker_project_gives_its_positions_in_metres_and_fits() {
    let track = filmed();
    let c = V10;
    let text = trk(&track, 52, &c);
    let raw = data::read(&text, "ball.trk", &Reading::default()).unwrap();
    // Positions written with 17 digits in pixels: back to 1e-9 m.
    same_positions(&raw, &track, 1e-9);
    let dir = scratch("trk");
    let file = dir.join("ball.trk");
    std::fs::write(&file, &text).unwrap();
    fits_the_truth(&file, &[]);
    // The same video never calibrated: pixels, and the error names --scale.
    let pixels = trk(&track, 52, &Coords { scale: 1.0, ..c });
    let e = data::read(&pixels, "px.trk", &Reading::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("not calibrated") && e.contains("--scale"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_xml_project_without_a_final_line_end_is_not_said_cut_short() {
    // Tracker writes its project without a line end after `</object>` (V10.trk of
    // the NTNU lab, BallToss.trk of Tracker's examples): no row was dropped, and
    // `data` said "line 5882, the last, is cut short (... fewer cells ...)".
    let track = filmed();
    let c = V10;
    let dir = scratch("xml-no-line-end");
    for (name, text) in [
        ("ball.trk", trk(&track, 52, &c)),
        ("ball.cmbl", cmbl(&track, "m")),
    ] {
        let file = dir.join(name);
        std::fs::write(&file, text.trim_end()).unwrap();
        let (code, out, err) = groovelab(&["data", file.to_str().unwrap()]);
        assert_eq!(code, Some(0), "{name}: {err}");
        assert!(!out.contains("cut short"), "{name}: {out}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A Tracker project's frame duration of 66 ms (BallToss.trk of Tracker's examples) is
/// said at the rate the frames' line says, to four digits: "15.15 frames/s" on both
/// lines (the unit's line said 15.1515).
#[test]
fn a_projects_frame_rate_is_said_alike_on_both_lines() {
    let track = video::track(
        &scene(),
        &Video {
            seed: 11,
            noise: 2e-4,
            fps: 1000.0 / 66.0,
            ..Video::default()
        },
    )
    .unwrap();
    let c = V10;
    let dir = scratch("trk-66ms");
    let file = dir.join("ball.trk");
    std::fs::write(&file, trk(&track, 0, &c)).unwrap();
    let (code, out, err) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains(" frames at 15.15 frames/s"), "{out}");
    assert!(
        out.contains("frame duration (66 ms, 15.15 frames/s)"),
        "{out}"
    );
    assert!(!out.contains("15.1515"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_logger_pro_file_gives_its_video_analysis_and_fits() {
    let track = filmed();
    let text = cmbl(&track, "m");
    let raw = data::read(&text, "ball.cmbl", &Reading::default()).unwrap();
    same_positions(&raw, &track, 1e-12);
    let dir = scratch("cmbl");
    let file = dir.join("ball.cmbl");
    std::fs::write(&file, &text).unwrap();
    fits_the_truth(&file, &[]);
    // A video never scaled: no units; the error names --scale and --length-unit, and
    // the unit given reads it.
    let file = dir.join("unscaled.cmbl");
    std::fs::write(&file, cmbl(&track, "")).unwrap();
    let f = file.to_str().unwrap();
    // `data` shows it in its own unit, with the doubt; `fit` refuses it.
    let (code, out, _) = groovelab(&["data", f]);
    assert_eq!(code, Some(0));
    assert!(
        out.contains("lengths shown in the file's own unit") && out.contains("no unit"),
        "{out}"
    );
    let (code, _, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("no unit") && err.contains("--scale") && err.contains("--length-unit"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1);
    fits_the_truth(&file, &["--length-unit", "m"]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_vernier_format_2_export_reads_its_units_line_and_fits() {
    let track = filmed();
    let text = vernier(&track);
    let raw = data::read(&text, "ball.txt", &Reading::default()).unwrap();
    // Written in cm to 4 decimals: 0.5 µm.
    same_positions(&raw, &track, 6e-7);
    let dir = scratch("vernier");
    let file = dir.join("ball.txt");
    std::fs::write(&file, &text).unwrap();
    fits_the_truth(&file, &[]);
    let (code, out, err) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("Logger Pro text (Vernier Format 2)")
            && out.contains("centre x, y (unnamed), rim mark 'point 2'")
            && out.contains("length in cm: the header"),
        "{out}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The paper's scene's left ball at 100 frames/s, impact at t = 0 (left out: the
/// frame at the impact is neither before nor after it).
fn velocities() -> Vec<(f64, f64, f64)> {
    let sol = groovelab::physics::engine::solve(
        &scene(),
        &groovelab::physics::scene::Span {
            t_start: -0.2,
            t_end: Some(0.6),
        },
    );
    (-10..=50)
        .filter(|&k| k != 0)
        .map(|k| {
            let t = f64::from(k) * 0.01;
            let st = sol.at(t);
            (t, st.left.v, st.left.u)
        })
        .collect()
}

#[test]
fn a_header_that_states_the_wrong_unit_is_refused_naming_the_unit_that_fits() {
    let dir = scratch("mislabelled");
    // Numbers in cm/s under a header that says m/s: once fitted as μ_k = 13.8.
    let file = dir.join("mislabelled.csv");
    let mut text = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
    for (t, v, u) in velocities() {
        text += &format!("{t:.3},{:.3},{:.3}\n", 100.0 * v, 100.0 * u);
    }
    std::fs::write(&file, &text).unwrap();
    let f = file.to_str().unwrap();
    let (code, out, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
    assert_eq!(code, Some(2), "{out}");
    assert!(
        err.contains("do not fit the units the header gives")
            && err.contains("fix the header (v_cm (cm/s), v_t (cm/s)) or give --speed-unit cm/s")
            && err.lines().count() == 1,
        "{err}"
    );
    // The option its error names wins over the header and fits the truth.
    let (code, out, err) = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        f,
        "--speed-unit",
        "cm/s",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let mu = j["model_fit"]["mu"].as_f64().unwrap();
    assert!((mu - scene().mu).abs() < 0.002, "μ_k = {mu}");
    // A file in s and cm/s without units: the hint names cm/s only, not t (ms).
    let file = dir.join("unitless.csv");
    std::fs::write(
        &file,
        text.replace("t (s),v_cm (m/s),v_t (m/s)", "t,v_cm,v_t"),
    )
    .unwrap();
    let (code, _, err) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("give --speed-unit cm/s (or units in the header: v_cm (cm/s), v_t (cm/s))")
            && !err.contains("ms"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A plain CSV track with the header `header` and rows of t (scaled by `tk`), x, y.
fn csv_track(header: &str, track: &Track, tk: f64, keep: impl Fn(usize) -> bool) -> String {
    let mut s = format!("{header}\n");
    for i in (0..track.t().len()).filter(|&i| keep(i)) {
        s += &format!(
            "{:.4},{:.6},{:.6}\n",
            track.t()[i] * tk,
            track.x()[i],
            track.y()[i]
        );
    }
    s
}

#[test]
fn position_headers_microseconds_and_missing_frames_are_read_and_said() {
    let track = filmed();
    let dir = scratch("headers");
    // `Position x (m)` names the axis; µs as the time unit.
    let file = dir.join("us.csv");
    let text = csv_track(
        "Time (µs),Position x (m),Position y (m)",
        &track,
        1e6,
        |_| true,
    );
    std::fs::write(&file, &text).unwrap();
    let f = file.to_str().unwrap();
    let (code, out, err) = groovelab(&["data", f, "--format", "json"]);
    assert_eq!(code, Some(0), "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j[0]["units"][0]["unit"], "us", "{out}");
    assert_eq!(j[0]["frames"].as_u64(), Some(track.t().len() as u64));
    assert!(j[0]["missing"].as_array().unwrap().is_empty());
    // Ten frames missing in the middle: said by `data` and by `fit`.
    let file = dir.join("gap.csv");
    let gap = 60..70;
    let text = csv_track("t (s),x (m),y (m)", &track, 1.0, |i| !gap.contains(&i));
    std::fs::write(&file, &text).unwrap();
    let f = file.to_str().unwrap();
    let (code, out, err) = groovelab(&["data", f]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("10 frames missing: 10 at t = "), "{out}");
    let (code, out, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("10 frames missing from the file"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn data_describes_any_file_and_refuses_what_it_cannot_use_in_one_line() {
    let dir = scratch("any");
    // A ball rolling alone: no impact, described all the same.
    let file = dir.join("alone.csv");
    let mut text = String::from("t,x,y\n");
    for i in 0..100 {
        let t = f64::from(i) / 100.0;
        text += &format!("{t:.2},{:.5},0.1\n", 0.4 * t);
    }
    std::fs::write(&file, &text).unwrap();
    let (code, out, err) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("a single ball's track, no impact found") && out.contains("100 frames"),
        "{out}"
    );
    // phyphox: accelerations only.
    let file = dir.join("phone.csv");
    std::fs::write(
        &file,
        "\"Time (s)\"\t\"Linear Acceleration x (m/s^2)\"\t\"Absolute acceleration (m/s^2)\"\n9.998000000E-3\t1.2E-1\t1.3E-1\n",
    )
    .unwrap();
    let (code, _, err) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("accelerations only") && err.lines().count() == 1,
        "{err}"
    );
    // Hostile XML: entities, a node bomb, deep nesting: one line each, at once.
    let panel = "<object class=\"org.opensourcephysics.cabrillo.tracker.TrackerPanel\">";
    let laughs = format!(
        "<?xml version=\"1.0\"?><!DOCTYPE x [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;\">]>{panel}&b;</object>"
    );
    let many = format!("{panel}{}</object>", "<p/>".repeat(4_100_000));
    let deep = format!(
        "{panel}{}{}</object>",
        "<p>".repeat(200_000),
        "</p>".repeat(200_000)
    );
    for (name, text, want) in [
        ("laughs.trk", laughs, "DTD"),
        ("many.trk", many, "nodes"),
        ("deep.trk", deep, "no frame duration"),
    ] {
        let file = dir.join(name);
        std::fs::write(&file, text).unwrap();
        let (code, _, err) = groovelab(&["data", file.to_str().unwrap()]);
        assert_eq!(code, Some(2), "{name}: {err}");
        assert!(
            err.contains(want) && err.lines().count() == 1,
            "{name}: {err}"
        );
    }
    // A decimal comma on the command line, as the app accepts it.
    let (code, out, err) = groovelab(&[
        "simulate",
        "--preset",
        "paper-b4.9",
        "--width",
        "4,9cm",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["scene"]["width"].as_f64(), Some(0.049), "{}", j["scene"]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A file of one frame has no frame rate: `data` says so (it said "NaN frames/s") and
/// its JSON has `null` (the fuzz harness found it in a damaged Vernier export).
#[test]
fn a_file_of_one_frame_has_no_frame_rate() {
    let dir = scratch("one-frame");
    let file = dir.join("one.csv");
    std::fs::write(&file, "t,x,y\n0.0,0.10,0.02\n").unwrap();
    let path = file.display().to_string();
    let (code, out, err) = groovelab(&["data", &path]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("1 frame at no frame rate"), "{out}");
    assert!(!out.contains("NaN"), "{out}");
    let (code, out, err) = groovelab(&["data", "--format", "json", &path]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v[0]["frame_rate"].is_null(), "{out}");
    assert_eq!(v[0]["frames"], 1, "{out}");
}
