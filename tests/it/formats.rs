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
use groovelab::study::preset::Preset;
use groovelab::study::video::{self, Video};

fn scene() -> Scene {
    Preset::load("paper-b4.9")
        .unwrap()
        .spec
        .resolve()
        .unwrap()
        .0
}

fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("groovelab-formats-{}-{test}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
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
fn filmed() -> Track {
    video::track(
        &scene(),
        &Video {
            seed: 11,
            noise: 2e-4,
            ..Video::default()
        },
    )
}

/// A Tracker coordinate system: origin (px), x axis turned by `angle` (degrees, ccw
/// as the viewer sees it) and `scale` px per metre, image y downward.
struct Coords {
    origin: (f64, f64),
    angle: f64,
    scale: f64,
}

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
fn trk(track: &Track, start: usize, c: &Coords) -> String {
    let dt = (track.t[1] - track.t[0]) * 1e3;
    let (mx, my) = track.mark.clone().unwrap();
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
        frames = start + track.t.len(),
        t0 = track.t[0] * 1e3,
        ox = c.origin.0,
        oy = c.origin.1,
        angle = c.angle,
        scale = c.scale,
    );
    s += &point_mass("mass A", start, &track.x, &track.y, c);
    s += &point_mass("mass B", start, &mx, &my, c);
    s + "    </property>\n    <property name=\"selectedtrack\" type=\"string\">mass A</property>\n</object>\n"
}

/// A Logger Pro 3.8 file (`.cmbl`) of `track` as acceleratingcar.cmbl is laid out: no
/// XML declaration, a `VideoAnalysis` data set whose columns hold one cell per line
/// (Time, X, Y, X2, Y2 in `unit`, "" when the video was never scaled), calculated
/// velocity columns without cells, and a curve-fit data set with entities in its name.
fn cmbl(track: &Track, unit: &str) -> String {
    let (mx, my) = track.mark.clone().unwrap();
    let column = |id: usize, name: &str, short: &str, unit: &str, cells: &[f64]| {
        let cells: String = cells.iter().map(|v| format!("{v}\n")).collect();
        format!(
            "    <DataColumn>\n      <ID>{id} </ID>\n      <DataObjectName>{name}</DataObjectName>\n      <DataObjectShortName>{short}</DataObjectShortName>\n      <ColumnUnits>{unit}</ColumnUnits>\n      <ColumnCells>\n{cells}</ColumnCells>\n    </DataColumn>\n"
        )
    };
    let mut s = String::from(
        "<Document>\n  <FileCoherence>1</FileCoherence>\n  <Version>3.8.7</Version>\n  <Copyright>Copyright (c) 2012 Vernier Software &#38; Technology</Copyright>\n  <Page>\n    <PageMovie>\n      <VAMovieActualDistance>1</VAMovieActualDistance>\n      <VAMoviePixelDistance>0.00625250824844</VAMoviePixelDistance>\n      <VAMovieScaleUnits></VAMovieScaleUnits>\n    </PageMovie>\n  </Page>\n  <DataSet>\n    <ID>109 </ID>\n    <DataSetName>VideoAnalysis</DataSetName>\n    <DataSetVideoAnalysis>1</DataSetVideoAnalysis>\n",
    );
    s += &column(110, "Time", "t", "s", &track.t);
    s += &column(112, "X", "X", unit, &track.x);
    s += &column(114, "Y", "Y", unit, &track.y);
    s += &column(115, "X2", "X2", unit, &mx);
    s += &column(116, "Y2", "Y2", unit, &my);
    s += "    <DataColumn>\n      <DataObjectName>X Velocity</DataObjectName>\n      <ColumnUnits></ColumnUnits>\n    </DataColumn>\n  </DataSet>\n";
    s += "  <DataSet>\n    <DataSetName>&#38;&#38;^% CurveFitFunctions %^&#38;&#38;</DataSetName>\n  </DataSet>\n</Document>\n";
    s
}

/// Logger Pro's "Export As Text" (Vernier Format 2) of `track`, CRLF line ends,
/// positions in cm with a decimal comma (a German Logger Pro), velocity columns
/// computed beside them.
fn vernier(track: &Track) -> String {
    let (mx, my) = track.mark.clone().unwrap();
    let mut s = String::from(
        "Vernier Format 2\r\nball.cmbl 11/26/2026 09:41:07 .\r\nLatest\r\nTime\tX\tY\tX2\tY2\tX Velocity\r\nt\tX\tY\tX2\tY2\tVx\r\ns\tcm\tcm\tcm\tcm\tcm/s\r\n\r\n",
    );
    let comma = |v: f64| format!("{:.4}", 100.0 * v).replace('.', ",");
    for i in 0..track.t.len() {
        let vx = if i + 1 < track.t.len() {
            comma((track.x[i + 1] - track.x[i]) / (track.t[i + 1] - track.t[i]))
        } else {
            String::new()
        };
        s += &format!(
            "{:.6}\t{}\t{}\t{}\t{}\t{vx}\r\n",
            track.t[i],
            comma(track.x[i]),
            comma(track.y[i]),
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
    assert_eq!(got.t.len(), want.t.len());
    let (gx, gy) = got.mark.clone().unwrap();
    let (wx, wy) = want.mark.clone().unwrap();
    for i in 0..want.t.len() {
        assert!((got.t[i] - want.t[i]).abs() < tol, "t[{i}]");
        for (a, b) in [
            (got.x[i], want.x[i]),
            (got.y[i], want.y[i]),
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
    // A camera turned by 2.5° and 905 px per metre, as the NTNU lab's V10.trk.
    let c = Coords {
        origin: (179.38, 641.01),
        angle: 2.5,
        scale: 904.778,
    };
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
    let (code, _, err) = groovelab(&["data", f]);
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
