//! What the exact run does, in words: the closed-form recovery only where the run
//! bears it out (issue 11: paper-b3.5 with e = 0.2 accumulates before t').

use crate::common::stdout;

use groovelab::physics::derived::Derived;
use groovelab::physics::engine::solve;
use groovelab::physics::scene::{Scene, Span};
use groovelab::physics::story::{After, after_first_impact};
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;

/// The scene and span of `preset` with the values `extra` over it.
fn scene_of(preset: &str, extra: &[(Key, f64)]) -> (Scene, Span) {
    let p = groovelab::input::preset::load(preset).unwrap();
    let spec = extra
        .iter()
        .fold(SceneSpec::default(), |s, &(k, v)| s.with(k, v));
    p.spec.over(&spec).resolve().unwrap()
}

fn story(preset: &str, extra: &[(Key, f64)]) -> After {
    let (scene, span) = scene_of(preset, extra);
    let sol = solve(&scene, &span);
    after_first_impact(&sol, &Derived::of(&scene)).unwrap()
}

#[test]
fn low_restitution_tells_the_runs_events_not_the_closed_form() {
    let After::Interrupted(i) = story("paper-b3.5", &[(Key::Restitution, 0.2)]) else {
        panic!("the run is interrupted by the second impact");
    };
    // The numbers: second impact at 0.1125 s, T∞ = 0.1407 s, rest at 0.189 s,
    // the closed form's t' = 0.1357 s never reached.
    assert!((i.first.1 - 0.112547).abs() < 1e-6, "{i:?}");
    assert!((i.t_roll_closed_form - 0.1357).abs() < 5e-5, "{i:?}");
    let (t_inf, _) = i.accumulation.unwrap();
    assert!((t_inf - 0.1407).abs() < 5e-5, "{t_inf}");
    let (rest, pressed) = i.rest_from.unwrap();
    assert!(
        (rest - 0.189141).abs() < 1e-6 && pressed,
        "{rest} {pressed}"
    );
    let table = stdout(&["simulate", "--preset", "paper-b3.5", "--restitution", "0.2"]);
    let line = table
        .lines()
        .find(|l| l.starts_with("left ball after the first impact"))
        .unwrap();
    assert_eq!(
        line,
        "left ball after the first impact: slides into the next impact at t = 0.1125 s, before the closed form's t' = 0.1357 s; impacts accumulate at T∞ = 0.1407 s; pressed together, at rest from 0.1891 s"
    );
    assert!(!table.contains("x' ="), "{table}");
    // The Why panel says the same.
    let screen = stdout(&[
        "render",
        "--preset",
        "paper-b3.5",
        "--restitution",
        "0.2",
        "--size",
        "120x40",
    ]);
    for want in [
        "slides into the next impact",
        "T∞ = 0.1407 s",
        "at rest from 0.1891 s",
    ] {
        assert!(screen.contains(want), "{want}\n{screen}");
    }
    assert!(!screen.contains("x' "), "{screen}");
}

#[test]
fn the_closed_forms_stand_where_the_run_rolls_again_at_t_prime() {
    for preset in [
        "paper-b3.5",
        "paper-b4.4",
        "paper-b4.9",
        "flat-table",
        "critical",
        "inelastic",
        "steel-and-glass",
    ] {
        assert!(matches!(story(preset, &[]), After::Recovers(_)), "{preset}");
    }
    let table = stdout(&["simulate", "--preset", "paper-b4.9"]);
    assert!(table.contains("rolls again after t' = 0.2849 s"), "{table}");
}

/// The left ball's heading after the first impact follows its motion: "back toward
/// the other ball" only where the impact sent it away (x' < 0: paper-b4.9, whose
/// ball rolls back from −7.7 cm); a heavy ball hitting a light one goes on (x' > 0:
/// steel-and-glass was said to roll "back" though it never reversed); a light one
/// hitting a heavy one rolls away.
#[test]
fn the_heading_after_the_impact_says_whether_the_ball_came_back() {
    let heading = |args: &[&str]| {
        let mut all = vec!["simulate"];
        all.extend_from_slice(args);
        let table = stdout(&all);
        let line = table
            .lines()
            .find(|l| l.starts_with("left ball after the first impact"))
            .unwrap_or_else(|| panic!("{table}"))
            .to_string();
        let x = line
            .split("x' = ")
            .nth(1)
            .and_then(|r| r.split(' ').next())
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or_else(|| panic!("{line}"));
        (line, x)
    };
    let (line, x) = heading(&["--preset", "paper-b4.9"]);
    assert!(
        x < 0.0 && line.contains("(back toward the other ball)"),
        "{line}"
    );
    let (line, x) = heading(&["--preset", "steel-and-glass"]);
    assert!(
        x > 0.0 && line.contains("(toward the other ball)"),
        "{line}"
    );
    let (line, _) = heading(&["--mass-left", "50g"]);
    assert!(line.contains("(away from the other ball)"), "{line}");
}

/// The Why panel's heading and reason say what the run does, in the corners a teacher
/// tried: rolling resistance stops the return, a pair moving on together, e = 0
/// (pressed together from the impact), no friction (nothing rolls), no closing speed.
#[test]
fn headings_and_reasons_follow_the_run() {
    let case = |extra: &[(Key, f64)]| {
        let (scene, span) = scene_of("paper-b4.9", extra);
        let sol = solve(&scene, &span);
        let d = Derived::of(&scene);
        (groovelab::study::story::headline(&sol, &d), d.why())
    };
    let (h, _) = case(&[(Key::RollingResistance, 0.05)]);
    assert_eq!(h, "STOPPED: they stop before they meet again");
    let (h, _) = case(&[(Key::V0Left, 1.0), (Key::V0Right, -1.0)]);
    assert_eq!(h, "TOGETHER: the pair moves on as one");
    let (h, why) = case(&[(Key::Restitution, 0.0)]);
    assert_eq!(h, "PRESSED: friction holds them together");
    assert!(why.starts_with("D e = 0.000 < 1"), "{why}");
    let (h, why) = case(&[(Key::Mu, 0.0)]);
    assert_eq!(h, "DEPART: the balls move apart");
    assert!(
        why.contains("without friction") && !why.contains("spin"),
        "{why}"
    );
    let (h, why) = case(&[(Key::V0, 0.0)]);
    assert!(!why.contains("spin"), "{h}: {why}");
    // The paper's own scene keeps its heading and the D e reason.
    let (h, why) = case(&[]);
    assert_eq!(h, "RECOLLIDE: they come back");
    assert!(why.contains("the spin rolls them back"));
}

#[test]
fn a_run_that_comes_to_rest_elsewhere_is_not_said_to_slide_into_an_impact() {
    let After::Interrupted(i) = story("paper-b4.9", &[(Key::Restitution, 0.0)]) else {
        panic!("e = 0 does not recover freely");
    };
    let first = i.clauses("∞")[0].clone();
    assert!(!first.contains("next impact"), "{first}");
    assert!(first.contains("not at the closed form's t'"), "{first}");
}

/// `summary.outcome` in the JSON and the table's outcome line say what the run does,
/// beside the paper's criterion (issue 18).
#[test]
fn simulate_reports_the_outcome_beside_the_criterion() {
    for (args, outcome) in [
        (&["--restitution", "0"][..], "pressed"),
        (&["--rolling-resistance", "0.05"][..], "stopped"),
        (&[][..], "recollide"),
        (&["--preset", "paper-b3.5"][..], "depart"),
        (&["--preset", "critical"][..], "rest"),
    ] {
        let mut json_args = vec!["simulate", "--format", "json"];
        json_args.extend(args);
        let doc: serde_json::Value = serde_json::from_str(&stdout(&json_args)).unwrap();
        assert_eq!(doc["summary"]["outcome"], outcome, "{args:?}");
        let mut table_args = vec!["simulate"];
        table_args.extend(args);
        let table = stdout(&table_args);
        let line = table.lines().find(|l| l.starts_with("outcome  ")).unwrap();
        assert!(line.starts_with(&format!("outcome  {outcome}: ")), "{line}");
        // The criterion is named where the run does otherwise.
        let differs = matches!(outcome, "pressed" | "stopped");
        assert_eq!(line.contains("criterion says recollide"), differs, "{line}");
        // And the verdict, which judges the criterion's regime against the data's
        // rest band, says whose regime it is and what this run does: it read
        // "verdict recollide" under "outcome stopped".
        // (paper-b4.9, the default, has the paper's series and so its rest band.)
        let verdict = table.lines().find(|l| l.starts_with("verdict  "));
        assert!(verdict.is_some() || !differs, "{table}");
        if let Some(verdict) = verdict {
            let named = verdict.contains("by the paper's criterion")
                && verdict.ends_with(&format!("; this run: {outcome}"));
            assert_eq!(named, differs, "{verdict}");
        }
    }
}

#[test]
fn rest_without_friction_says_the_balls_keep_spinning() {
    // μ_k = 0 and e = 0: the impact stops the centres, and nothing takes the spin
    // (v = 0, u = v0 for ever: 0.20 J of rotation left in the trial's scene).
    let frictionless = stdout(&[
        "simulate",
        "--preset",
        "paper-b4.9",
        "--mu",
        "0",
        "--restitution",
        "0",
    ]);
    assert!(
        frictionless.contains(
            "outcome  rest: the balls stop moving along the groove; they keep spinning (0.20 J)"
        ),
        "{frictionless}"
    );
    // The Why panel's heading says the same (wrapped in the panel).
    let why = stdout(&[
        "render",
        "--preset",
        "paper-b4.9",
        "--mu",
        "0",
        "--restitution",
        "0",
        "--size",
        "200x50",
    ]);
    let why: String = why
        .lines()
        .filter_map(|l| l.rsplit("││").next())
        .map(|l| l.trim_end_matches('│').trim())
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        why.contains("REST: the balls stop moving along the groove; they keep spinning (0.20 J)"),
        "{why}"
    );
    // The critical groove's rest is a true stop: both balls roll to rest together.
    let critical = stdout(&["simulate", "--preset", "critical"]);
    assert!(
        critical.contains("outcome  rest: the balls stop"),
        "{critical}"
    );
}

/// Balls that never meet (the right ball runs away as fast as the left one follows,
/// or neither moves) get no verdict of the criterion: its "rest" means only "no
/// closing speed" there, and a pair moving on at 100 m/s is not at rest.
#[test]
fn balls_that_never_meet_get_no_regime_verdict() {
    use groovelab::physics::story::Verdict;
    let verdict = |extra: &[(Key, f64)]| {
        let (scene, span) = scene_of("paper-b4.9", extra);
        Verdict::of(&solve(&scene, &span), &Derived::of(&scene), None).text("±")
    };
    let never = "no impact: the balls never meet";
    assert_eq!(
        verdict(&[(Key::V0Left, 100.0), (Key::V0Right, -100.0)]),
        never
    );
    assert_eq!(verdict(&[(Key::V0Left, 0.0), (Key::V0Right, 0.0)]), never);
    // A head-on run keeps its regime.
    assert!(verdict(&[]).starts_with("recollide"));
    let out = stdout(&["simulate", "--v0-left", "100", "--v0-right", "-100"]);
    assert!(out.contains("verdict  no impact"), "{out}");
}

/// Balls at rest from the start (v0 = 0 for both) are not said to "stop": the outcome
/// says neither moves, beside the verdict that they never meet; a run that meets and
/// then stops (the critical width) keeps "the balls stop".
#[test]
fn balls_at_rest_from_the_start_are_not_said_to_stop() {
    let out = stdout(&["simulate", "--v0", "0"]);
    assert!(
        out.contains("outcome  rest: neither ball moves: no speed toward the other"),
        "{out}"
    );
    assert!(
        out.contains("verdict  no impact: the balls never meet"),
        "{out}"
    );
    assert!(!out.contains("the balls stop"), "{out}");
    let critical = stdout(&["simulate", "--preset", "critical"]);
    assert!(
        critical.contains("outcome  rest: the balls stop"),
        "{critical}"
    );
}
