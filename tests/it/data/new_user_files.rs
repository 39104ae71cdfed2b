//! What a new user's files found (2026-11-30): a header's unit that groovelab does not
//! read was explained as a missing column, and pixels as no position at all; frames
//! 20 s apart were said to come at 0.1 frames/s (rounded to one decimal); times out
//! of order were quoted in s, not as the file writes them; one frame was "1 frames".

use groovelab::input::data::{self, Reading};

use crate::common::{run_in_process, scratch_dir};

/// Reads `text` as the file `f.csv` with `reading`: the error's message, if any.
fn error(text: &str, reading: &Reading) -> Option<String> {
    data::read(text, "f.csv", reading)
        .err()
        .map(|e| e.to_string())
}

#[test]
fn a_header_unit_not_read_is_named_with_the_units_allowed() {
    let positions = "-200.0,-14.85\n-180.0,-13.63\n-160.0,-12.48\n";
    let velocities = "-200.0,63.17,60.17\n-190.0,61.22,60.98\n-180.0,61.67,59.43\n";
    for (head, rows, want) in [
        (
            "t (ms),x (in)",
            positions,
            "line 1: unknown length unit 'in' in 'x (in)', expected one of m, cm, mm",
        ),
        (
            "t (ms),x (furlong)",
            positions,
            "line 1: unknown length unit 'furlong' in 'x (furlong)', expected one of m, cm, mm",
        ),
        (
            "t (ms),x (cm),y (in)",
            "-200.0,-14.85,1\n-180.0,-13.63,1\n",
            "line 1: unknown length unit 'in' in 'y (in)'",
        ),
        (
            "t (min),x (cm)",
            positions,
            "line 1: unknown time unit 'min' in 't (min)', expected one of s, ms, us, µs, μs",
        ),
        (
            "t (min),v_cm (cm/s),v_t (cm/s)",
            velocities,
            "line 1: unknown time unit 'min' in 't (min)', expected one of s, ms, us, µs, μs",
        ),
        (
            "t (ms),v_cm (in/s),v_t (in/s)",
            velocities,
            "line 1: unknown speed unit 'in/s' in 'v_cm (in/s)', expected one of m/s, cm/s, mm/s",
        ),
    ] {
        let e = error(&format!("{head}\n{rows}"), &Reading::default()).unwrap_or_default();
        assert!(e.contains(want), "{head}: {e}");
    }
}

#[test]
fn positions_in_pixels_name_the_scale_and_read_with_it() {
    let text = "t (ms),x (px)\n-200.0,-14.85\n-180.0,-13.63\n-160.0,-12.48\n";
    let e = error(text, &Reading::default()).unwrap_or_default();
    assert!(
        e.contains("line 1: 'x (px)' is in pixels, which need a scale: give the length one pixel shows with --scale (e.g. --scale 1.105mm"),
        "{e}"
    );
    let scaled = Reading {
        scale: Some(1e-3),
        ..Reading::default()
    };
    let track = data::read_track(text, "f.csv", &scaled).unwrap();
    assert!((track.x()[0] + 0.01485).abs() < 1e-12, "{:?}", track.x());
    // `data` shows such a file in its own unit, with the fix.
    let dir = scratch_dir("new_user_files", "pixels");
    let file = dir.join("px.csv");
    std::fs::write(&file, text).unwrap();
    let out = run_in_process(&["data", file.to_str().unwrap()]).unwrap();
    assert!(
        out.contains("length in the file's own unit") && out.contains("--scale"),
        "{out}"
    );
    // The header says what the unit is (pixels): the note must not say nothing does.
    assert!(
        out.contains("lengths shown in the file's own unit (\"units\"), not known to be metres: line 1: 'x (px)' is in pixels"),
        "{out}"
    );
}

#[test]
fn a_slow_frame_rate_is_not_rounded_away() {
    // Frames 20 apart without a unit: 0.05 frames/s as s (it said 0.1), 50 as ms; a
    // velocity file's v_cm drops at an impact halfway.
    let rows = |cells: &dyn Fn(i32) -> &'static str| -> String {
        (0..12)
            .map(|k| format!("{},{}\n", -200 + 20 * k, cells(k)))
            .collect()
    };
    let positions = format!("t,x\n{}", rows(&|_| "-0.1"));
    let velocities = format!(
        "t,v_cm,v_t\n{}",
        rows(&|k| if k < 6 { "63.17,60.17" } else { "10.2,35.1" })
    );
    for text in [positions, velocities] {
        let e = error(&text, &Reading::default()).unwrap_or_default();
        assert!(
            e.contains("frames 20 apart (as s: 0.05 frames/s; as ms: 50 frames/s)"),
            "{e}"
        );
    }
    // A stated unit that puts them 200 s apart: 0.005 frames/s (it said 0.01).
    let text: String = (0..12).map(|k| format!("{},0.1\n", 200 * k)).collect();
    let e = error(&format!("t (s),x (cm)\n{text}"), &Reading::default()).unwrap_or_default();
    assert!(
        e.contains("the frames are 200 s apart (0.005 frames/s)"),
        "{e}"
    );
}

#[test]
fn times_out_of_order_are_quoted_as_the_file_writes_them() {
    for (text, want) in [
        (
            "t (ms),x (cm)\n-100.0,-8.83\n380.0,-12.79\n-180.0,-13.63\n",
            "line 4: t = -180.0 ms does not increase (previous 380.0 ms)",
        ),
        (
            "t (ms);x (cm)\n20,0;1\n40,0;2\n40,0;3\n",
            "line 4: t = 40,0 ms does not increase (previous 40,0 ms)",
        ),
        (
            "t (us),v_cm (cm/s),v_t (cm/s)\n0,60,60\n25000,60,60\n2.0e4,60,60\n",
            "line 4: t = 2.0e4 us does not increase (previous 25000 us)",
        ),
        (
            "t,x\n0.1,0.01\n0.08,0.02\n",
            "line 3: t = 0.08 s does not increase (previous 0.1 s)",
        ),
    ] {
        let e = error(text, &Reading::default()).unwrap_or_default();
        assert!(e.contains(want), "{e}");
    }
    // An option's unit is the file's unit.
    let ms = Reading {
        time_unit: Some(1e-3),
        ..Reading::default()
    };
    let e = error("t,x\n10,1\n5,2\n", &ms).unwrap_or_default();
    assert!(
        e.contains("t = 5 ms does not increase (previous 10 ms)"),
        "{e}"
    );
}

#[test]
fn one_frame_or_row_is_singular() {
    let d = groovelab::study::measured::Derive::default();
    let one = |text: &str| data::load(text, "f.csv", &Reading::default(), &d).err();
    let e = one("t (ms),x (cm)\r\n0,1\r\n").unwrap().to_string();
    assert!(
        e.contains(": 1 frame with a centre position, at least 8 needed"),
        "{e}"
    );
    let e = one("t,v_cm,v_t\n0,1,1\n").unwrap().to_string();
    assert!(e.ends_with(": 1 data row, allowed at least 3"), "{e}");
    // Too few beside the impact: no track the detector accepts has only one there.
    let e = groovelab::study::measured::TrackError::FewFramesBeside {
        count: 1,
        side: "before",
        at: 0.2,
        min: 4,
    };
    assert!(
        e.to_string().starts_with("only 1 frame before the impact"),
        "{e}"
    );
}
