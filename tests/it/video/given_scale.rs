//! A scale given (`--scale`, issue 34's handle) is taken as the scale, but radii that
//! scatter as they would refuse a scale from them say the balls' outlines, and the
//! centres fitted with them, are in doubt: the handles' run on tracker 33's refusals
//! (BENCHMARKS.md) gave three wrong μ_k with the true scale, each with radii
//! scattering by 6–14 %. The tracks say so in their scale line, with the scatter
//! (`Calibration::radius_scatter`, in the JSON too).

use groovelab::input::video::tracked::scale_note;
use groovelab::vision::tracks::Calibration;
use groovelab::vision::{self, Params, TracksError};

use crate::film::looks::Size;

/// The small look 78 (black balls on a striped wall of their brightness) decoded:
/// without a scale it is refused for its radii's scatter; with its true scale it is
/// tracked, and the calibration carries the very scatter the refusal named.
#[test]
fn a_given_scale_keeps_the_radii_scatter_the_refusal_names() {
    let Some((clip, frames)) = super::decoded_look("given_scale", 78, Size::Small) else {
        return;
    };
    let (r, truth, times) = super::look_truth(&clip, frames.len());
    let t = vision::track(&frames, Params::default());
    let Err(TracksError::RadiiDisagree { scatter, .. }) =
        vision::tracks(&t, times.clone(), r, None)
    else {
        panic!("look 78 was not refused for its radii");
    };
    let tracks = vision::tracks(&t, times, r, Some(truth)).expect("tracked with its scale");
    let c = tracks.calibration;
    assert!(c.scale_given && c.px_per_m == truth);
    assert!(
        (c.radius_scatter - scatter).abs() < 1e-12 && scatter > Params::default().max_radius_spread,
        "{} against the refusal's {scatter}",
        c.radius_scatter
    );
}

fn given(scatter: f64) -> Calibration {
    Calibration {
        px_per_m: 523.55,
        px_per_m_sigma: 0.0,
        scale_given: true,
        radius_px: 14.5,
        radius_px_sigma: 1.9,
        radius_scatter: scatter,
        radius_m: 0.0275,
        groove_deg: 0.0,
        groove_deg_sigma: 0.0,
        groove_found: false,
        colour_edge_px: None,
        origin_px: (0.0, 0.0),
    }
}

/// The scale line says the outlines are in doubt exactly where the radii scatter
/// beyond what gives a scale (`max_radius_spread`), with the scatter and the radius;
/// a scale from the radius, refused there, never says it.
#[test]
fn the_scale_line_says_the_outlines_are_in_doubt_where_the_radii_scatter() {
    let limit = Params::default().max_radius_spread;
    let doubt = "are in doubt in many frames";
    let line = scale_note(&given(0.11), "--radius");
    assert!(
        line.starts_with("scale 523.55 px/m: given (--scale"),
        "{line}"
    );
    assert!(
        line.contains("radii scatter by 11 % about 14.5 px") && line.contains(doubt),
        "{line}"
    );
    assert!(!scale_note(&given(0.5 * limit), "--radius").contains(doubt));
    assert!(scale_note(&given(1.01 * limit), "--radius").contains(doubt));
    let from_radius = Calibration {
        scale_given: false,
        px_per_m_sigma: 3.0,
        ..given(0.5 * limit)
    };
    let line = scale_note(&from_radius, "--radius");
    assert!(
        line.contains("the balls' fitted radius") && !line.contains(doubt),
        "{line}"
    );
}

/// A given scale that puts the balls' fitted radius more than 10 % off R says so in
/// the scale line, with the radius in pixels and in length and the share off; one
/// within 10 % says nothing (a new user's `--scale 0.5mm`, 27 px balls of R 2.75 cm,
/// gave μ_k half the truth without a word). 14.5 px at 523.55 px/m is 2.77 cm.
#[test]
fn a_given_scale_that_puts_the_radius_off_r_says_so() {
    let off = "at this scale the balls' fitted radius";
    let at = |px_per_m: f64| {
        scale_note(
            &Calibration {
                px_per_m,
                ..given(0.01)
            },
            "--radius",
        )
    };
    assert!(!at(523.55).contains(off), "{}", at(523.55));
    // 14.5 px / 0.0275 m = 527.3 px/m agrees; 10 % either side is the edge.
    assert!(!at(527.27 / 1.09).contains(off));
    assert!(!at(527.27 / 0.91).contains(off));
    let line = at(2000.0);
    assert!(
        line.contains("at this scale the balls' fitted radius 14.5 px is 0.725 cm, 74 % under R = 2.75 cm (--radius)"),
        "{line}"
    );
    assert!(
        at(527.27 / 1.12).contains("12 % over R"),
        "{}",
        at(527.27 / 1.12)
    );
}

/// A scale from outlines whose edge in colour lies far inside them, let through by
/// the balls' stacked pictures (tracker 62), says so in its line: how far, the
/// share of the radius, and that the ± holds it; a scale without says nothing of it.
#[test]
fn the_scale_line_says_why_an_edge_in_colour_widens_its_plus_minus() {
    let from_radius = Calibration {
        scale_given: false,
        px_per_m: 527.3,
        px_per_m_sigma: 92.0,
        radius_px: 14.5,
        radius_px_sigma: 2.53,
        ..given(0.01)
    };
    let said = "their edge in colour lies";
    assert!(!scale_note(&from_radius, "--radius").contains(said));
    let line = scale_note(
        &Calibration {
            colour_edge_px: Some(-2.5),
            ..from_radius
        },
        "--radius",
    );
    assert!(
        line.contains("their edge in colour lies 2.5 px inside their outlines in brightness, 17 % of the radius")
            && line.contains("the ± holds the difference")
            && line.contains("17.45 %"),
        "{line}"
    );
}
