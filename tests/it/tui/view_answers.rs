//! Each view answers for itself what `W` writes from it (issue 36: its pane in
//! `layer/main`) and what it draws (its `MainView` in `view/`): no match on the view
//! shown decides for it. Over every view, chart, hiding and data the answers are held
//! to the rules the views keep, and a figure withheld from the file is withheld on
//! the screen too.

use groovelab::tui::app::export::{Figure, NoExport};
use groovelab::tui::app::{App, View};

use crate::common::{self, press, text};

/// How the outcome is hidden: not, b hidden (`B`), or a prediction pending (`y 3`).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Hiding {
    None,
    B,
    Pending,
}

/// What the chart shows: velocities, positions (`x`) or the energy (`e`).
const CHARTS: [Option<&str>; 3] = [None, Some("x"), Some("e")];

/// `W`'s answer in a few words: the figure, or why none.
fn answer(a: &App) -> String {
    match a.figure_on_screen() {
        Ok(figure) => format!("{figure:?}"),
        Err(NoExport::Hidden(what)) => format!("hidden: {what}"),
        Err(NoExport::Forces) => "forces".into(),
        Err(NoExport::Energy) => "energy".into(),
        Err(other) => format!("other: {other}"),
    }
}

/// The rules: the chart's figure (none for the energy chart yet); the Map's, the
/// Methods' and (with data) the Fit's own, each withheld while it would tell the
/// outcome as its panels are; none from the Forces view.
fn expected(view: View, chart: Option<&str>, data: bool, hiding: Hiding) -> String {
    let chart = match chart {
        Some("e") => "energy".to_string(),
        Some("x") => format!("{:?}", Figure::Positions),
        _ => format!("{:?}", Figure::Velocities),
    };
    let derived = hiding != Hiding::None;
    match view {
        View::Charts => chart,
        View::Fit if !data => chart,
        View::Fit if derived => "hidden: the fit".into(),
        View::Fit => format!("{:?}", Figure::Fit),
        View::Map if hiding == Hiding::Pending => "hidden: the regime map".into(),
        View::Map => format!("{:?}", Figure::Map),
        View::Methods if derived => "hidden: the Methods diagram".into(),
        View::Methods => format!("{:?}", Figure::Methods),
        View::Forces => "forces".into(),
    }
}

/// Shows `view` by its key (the charts: the shown view's key again).
fn show(a: &mut App, view: View) {
    let key = |v: View| match v {
        View::Methods => "c",
        View::Map => "g",
        View::Forces => "v",
        View::Fit => "f",
        View::Charts => unreachable!("the charts have no key of their own"),
    };
    if a.view() != view {
        let shown = a.view();
        press(a, key(if view == View::Charts { shown } else { view }));
    }
    assert_eq!(a.view(), view);
}

/// True when the screen withholds a panel: its note starts "predict first: …" or
/// "b hidden: …" (the rest may wrap).
fn withholds(screen: &str) -> bool {
    screen.contains("predict first: ") || screen.contains("b hidden: ")
}

/// The note of the panel a view withholds with its figure `figure` (the start of it,
/// which no panel wraps): the view's own panel, not another view's.
fn note(figure: &str, hiding: Hiding) -> String {
    let what = match figure {
        "hidden: the Methods diagram" => "error against work",
        "hidden: the regime map" => "the regime map",
        "hidden: the fit" => "the fit",
        other => panic!("no panel withholds {other}"),
    };
    match hiding {
        Hiding::B => format!("b hidden: {what}"),
        _ => format!("predict first: {what}"),
    }
}

#[test]
fn every_view_says_what_shift_w_writes_and_withholds_it_as_its_screen_does() {
    let library = || common::no_user_presets("tui-view-answers");
    // The views whose figure depends on data are tried with data; the others on a
    // preset without (its views are the same, and no fit job runs for them).
    let cases: [(&str, &[View]); 2] = [
        (
            "critical",
            &[
                View::Charts,
                View::Map,
                View::Methods,
                View::Forces,
                View::Fit,
            ],
        ),
        ("paper-b4.9", &[View::Fit]),
    ];
    let mut withheld_seen = 0;
    for (preset, views) in cases {
        let data = preset != "critical";
        for hiding in [Hiding::None, Hiding::B, Hiding::Pending] {
            let mut a = common::app(preset, library());
            match hiding {
                Hiding::None => {}
                Hiding::B => press(&mut a, "B"),
                Hiding::Pending => press(&mut a, "y 3"),
            }
            assert_eq!(a.hidden().derived(), hiding != Hiding::None, "{hiding:?}");
            for chart in CHARTS {
                if let Some(k) = chart {
                    press(&mut a, k);
                }
                for &view in views {
                    show(&mut a, view);
                    let said = answer(&a);
                    let case = format!("{preset}, {view:?}, chart {chart:?}, {hiding:?}");
                    assert_eq!(said, expected(view, chart, data, hiding), "{case}");
                    // A figure withheld from the file is withheld on the screen, in
                    // the view's own panel: the view's two answers agree.
                    if said.starts_with("hidden") {
                        let screen = text(&a, (120, 40), false);
                        let note = note(&said, hiding);
                        assert!(screen.contains(&note), "{case}: {note}\n{screen}");
                        withheld_seen += 1;
                    } else if hiding == Hiding::None && chart.is_none() {
                        let screen = text(&a, (120, 40), false);
                        assert!(!withholds(&screen), "{case}\n{screen}");
                    }
                }
                // Back to the charts with the velocities for the next chart.
                show(&mut a, View::Charts);
                if let Some(k) = chart {
                    press(&mut a, k);
                }
            }
        }
    }
    // Methods (b hidden, pending), Map (pending), Fit with data (b hidden, pending),
    // each for the three charts.
    assert_eq!(withheld_seen, 3 * (2 + 1 + 2), "withheld screens");
}
