//! What every figure is drawn with: the error, the one set-up of an SVG and its
//! charts (frame, axes, legend), axis ranges plotters can draw, the measured points'
//! marks, and numbers rounded for captions.

use plotters::coord::Shift;
use plotters::prelude::*;

/// Why a figure cannot be drawn.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// The input has nothing a figure could show (the text says what is missing).
    #[error("{0}")]
    NothingToDraw(&'static str),
    /// plotters failed while drawing into the SVG text.
    #[error(transparent)]
    Plot(#[from] plotters::drawing::DrawingAreaErrorKind<std::io::Error>),
}

/// `v` rounded to its meaning in a caption: 4 significant digits, or "not measured"
/// when it is not a number (μ_k,t without a rim mark); never `NaN`.
pub(crate) fn rounded(v: f64) -> String {
    if v.is_finite() {
        crate::settings::units::significant(v, 4)
    } else {
        "not measured".into()
    }
}

/// An axis label as plotters writes it (one to five decimals), but never "-0.0": a key
/// point a rounding below zero is 0.
pub(super) fn tick(v: &f64) -> String {
    let text = plotters::data::float::FloatPrettyPrinter {
        allow_scientific: false,
        min_decimal: 1,
        max_decimal: 5,
    }
    .print(*v);
    match text.strip_prefix('-') {
        Some(zero) if zero.chars().all(|c| c == '0' || c == '.') => zero.to_string(),
        _ => text,
    }
}

/// Largest magnitude put on an axis; beyond it spans overflow.
const AXIS_LIMIT: f64 = 1e300;

/// A chart on an SVG with linear axes.
pub(super) type SvgChart<'a, 'b> = plotters::chart::ChartContext<
    'a,
    SVGBackend<'b>,
    plotters::coord::cartesian::Cartesian2d<
        plotters::coord::types::RangedCoordf64,
        plotters::coord::types::RangedCoordf64,
    >,
>;

/// A part of an SVG figure (the whole of it, or a panel).
pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// An SVG figure of `size` pixels on white, drawn by `draw` into its whole area.
pub(super) fn svg(
    size: (u32, u32),
    draw: impl FnOnce(&Area) -> Result<(), FigureError>,
) -> Result<String, FigureError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        draw(&root)?;
        root.present()?;
    }
    Ok(svg)
}

/// How a chart sits in its area: its caption (text and font size), margin, the sizes
/// of the label areas below and left of it, and room added to the margin above and
/// right of it (for labels a figure draws there itself; 0 for none).
pub(super) struct FigureFrame {
    pub caption: Option<(String, u32)>,
    pub margin: u32,
    pub label_areas: (u32, u32),
    pub room: (u32, u32),
}

impl FigureFrame {
    /// The frame of the run and fit charts: margin 12, label areas 35 and 55.
    pub(super) fn plain(caption: Option<String>) -> FigureFrame {
        FigureFrame {
            caption: caption.map(|c| (c, 18)),
            margin: 12,
            label_areas: (35, 55),
            room: (0, 0),
        }
    }

    /// A chart builder on `area` set up as the frame says: every figure's start.
    pub(super) fn builder<'a, 'b>(
        &self,
        area: &'a Area<'b>,
    ) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
        let mut builder = ChartBuilder::on(area);
        if let Some((text, size)) = &self.caption {
            builder.caption(text, ("sans-serif", *size));
        }
        builder
            .margin(self.margin)
            .x_label_area_size(self.label_areas.0)
            .y_label_area_size(self.label_areas.1)
            .margin_top(self.margin + self.room.0)
            .margin_right(self.margin + self.room.1);
        builder
    }
}

/// A chart with linear axes `x` and `y` on `area`, framed by `frame`, its axes named
/// `desc` and labelled by [`tick`]; with the mesh's grid lines, or (`grid` false)
/// only its axes and ticks.
pub(super) fn linear_chart<'a, 'b>(
    area: &'a Area<'b>,
    frame: &FigureFrame,
    (x, y): ((f64, f64), (f64, f64)),
    desc: (&str, &str),
    grid: bool,
) -> Result<SvgChart<'a, 'b>, FigureError> {
    let mut chart = frame.builder(area).build_cartesian_2d(x.0..x.1, y.0..y.1)?;
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(desc.0)
        .y_desc(desc.1)
        .x_label_formatter(&tick)
        .y_label_formatter(&tick);
    if !grid {
        mesh.disable_mesh();
    }
    mesh.draw()?;
    Ok(chart)
}

/// A line's legend mark: a short line in `style`.
pub(super) fn line_mark(style: ShapeStyle) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style)
}

/// Draws `chart`'s legend as every figure does, boxed on white, at `position`.
pub(super) fn draw_legend<'a, 'b: 'a, CT: plotters::coord::CoordTranslate>(
    chart: &mut ChartContext<'a, SVGBackend<'b>, CT>,
    position: SeriesLabelPosition,
) -> Result<(), FigureError> {
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.9))
        .position(position)
        .draw()?;
    Ok(())
}

/// Measured points as the figures mark them, with their legend entries: v_cm as
/// crosses, v_t as circles, in the colours given.
pub(super) fn draw_measured_marks(
    chart: &mut SvgChart,
    v_cm: impl Iterator<Item = (f64, f64)>,
    v_t: impl Iterator<Item = (f64, f64)>,
    (cm, t): (plotters::style::RGBColor, plotters::style::RGBColor),
) -> Result<(), FigureError> {
    use plotters::element::{Circle, Cross};
    chart
        .draw_series(v_cm.map(|p| Cross::new(p, 4, cm)))?
        .label("measured v_cm")
        .legend(move |(x, y)| Cross::new((x + 10, y), 4, cm));
    chart
        .draw_series(v_t.map(|p| Circle::new(p, 3, t)))?
        .label("measured v_t")
        .legend(move |(x, y)| Circle::new((x + 10, y), 3, t));
    Ok(())
}

/// The smallest and largest finite value, if any.
pub fn finite_bounds(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// A linear axis range plotters can draw: finite, within ±1e300, and wider than a
/// millionth of its magnitude (a thinner one is padded by a tenth of it, an empty
/// one at 0 becomes −1 … 1).
pub fn linear_axis(lo: f64, hi: f64) -> (f64, f64) {
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let (lo, hi) = (
        lo.min(hi).clamp(-AXIS_LIMIT, AXIS_LIMIT),
        hi.max(lo).clamp(-AXIS_LIMIT, AXIS_LIMIT),
    );
    let mag = lo.abs().max(hi.abs());
    if hi - lo >= (mag * 1e-6).max(1e-100) {
        return (lo, hi);
    }
    let pad = if mag < 1e-100 { 1.0 } else { 0.1 * mag };
    (lo - pad, hi + pad)
}

/// A log axis range plotters can draw: positive, finite, within 1e-300 … 1e300, and
/// at least a factor 1.01 wide (else widened tenfold each way).
pub fn log_axis(lo: f64, hi: f64) -> (f64, f64) {
    let ok = |v: f64| v.is_finite() && v > 0.0;
    let (lo, hi) = match (ok(lo), ok(hi)) {
        (true, true) => (lo.min(hi), hi.max(lo)),
        (true, false) => (lo, lo),
        (false, true) => (hi, hi),
        (false, false) => (1.0, 1.0),
    };
    let (lo, hi) = (
        lo.clamp(1.0 / AXIS_LIMIT, AXIS_LIMIT),
        hi.clamp(1.0 / AXIS_LIMIT, AXIS_LIMIT),
    );
    if hi >= lo * 1.01 {
        (lo, hi)
    } else {
        (lo / 10.0, hi * 10.0)
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    #[test]
    fn a_tick_at_zero_has_no_minus() {
        assert_eq!(tick(&-1e-17), "0.0");
        assert_eq!(tick(&-0.0), "0.0");
        assert_eq!(tick(&-0.1), "-0.1");
        assert_eq!(tick(&0.25), "0.25");
    }

    #[test]
    fn caption_numbers_are_rounded_to_their_meaning() {
        assert_eq!(rounded(0.16667742330550958), "0.1667");
        assert_eq!(rounded(f64::NAN), "not measured");
    }
    use crate::physics::scene::Scene;
    use crate::study::preset::Preset;

    /// Runs `f` on a thread and fails if it takes longer than 30 s (a figure once
    /// looped forever on an infinite axis).
    pub(crate) fn within_30s<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let _ = tx.send(f());
        });
        rx.recv_timeout(std::time::Duration::from_secs(30))
            .expect("the figure finished")
    }

    pub(crate) fn paper() -> (Scene, crate::study::measured::series::Measured) {
        let p = Preset::built_in_named("paper-b4.9").unwrap().unwrap();
        let (scene, _) = p.spec.resolve().unwrap();
        (scene, p.measured.unwrap())
    }

    #[test]
    fn axes_are_always_finite_and_wide_enough() {
        let cases = [
            (f64::INFINITY, 0.0),
            (f64::NAN, 1.0),
            (0.0, 0.0),
            (1e300, 1e300),
            (-f64::MAX, f64::MAX),
            (1.0, 1.0 + 1e-15),
            (5.0, 2.0),
        ];
        for (lo, hi) in cases {
            let (a, b) = linear_axis(lo, hi);
            assert!(
                a.is_finite() && b.is_finite() && (b - a).is_finite(),
                "{lo} {hi}"
            );
            assert!(b - a >= 1e-6 * a.abs().max(b.abs()), "{lo} {hi}: {a} {b}");
            let (a, b) = log_axis(lo, hi);
            assert!(
                a > 0.0 && b.is_finite() && b >= 1.01 * a,
                "{lo} {hi}: {a} {b}"
            );
        }
        assert_eq!(linear_axis(-0.2, 0.9), (-0.2, 0.9));
        assert_eq!(log_axis(1e-9, 1e-3), (1e-9, 1e-3));
    }
}
