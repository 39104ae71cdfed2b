//! The fuzz harness: random argument vectors over every command and option (valid and
//! hostile values), random preset files, random CSV files and random key sequences,
//! driven through the in-process entry point, each checked against the contract:
//!
//! - exit status 0 or 2 (130 only for an interruption, which this never sends);
//! - on 2: nothing on stdout and exactly one stderr line, starting `error: `;
//! - on 0: nothing on stderr, JSON that parses, and no NaN or infinity in the output
//!   (serde writes a non-finite number as `null`: a `null` where the schema has no
//!   optional value counts as one);
//! - no panic, and each case within a time limit (a watchdog thread).
//!
//! A short run is part of `cargo test`. The long run:
//! `GROOVELAB_FUZZ_CASES=100000 cargo test --release --test it fuzz:: -- --nocapture`
//! (`GROOVELAB_FUZZ_SEED=N` picks another sequence; the default is fixed, so a failure
//! in CI reproduces; `GROOVELAB_FUZZ_KEEP=1` keeps the fixture files a report names).

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;
use std::sync::{Mutex, OnceLock, mpsc};
use std::time::{Duration, Instant};

use groovelab::cli::entry::{Exit, main_with};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

// ---------------------------------------------------------------------------------
// Known open failures.

/// A failure class the harness knows of and that is being fixed elsewhere (issue 10):
/// matching cases are skipped (`hang`: before running, because they do not end or eat
/// memory) or their failure is tolerated and counted. The lead empties this list as
/// the fixes land; with it empty, every case must keep the contract.
struct Known {
    id: &'static str,
    /// The issue-10 item that fixes it.
    item: u8,
    /// Skip before running (a hang or a memory blow-up); else run and tolerate.
    hang: bool,
    /// Does this case (and its verdict, after a run) belong to the class?
    applies: fn(&Case, Option<&Verdict>) -> bool,
}

const KNOWN_OPEN: &[Known] = &[];

impl Known {
    fn label(&self) -> String {
        format!("{} (item {})", self.id, self.item)
    }
}

// ---------------------------------------------------------------------------------
// Cases.

/// One run: the arguments, and the files to write first.
#[derive(Clone, Debug)]
struct Case {
    kind: &'static str,
    args: Vec<OsString>,
    files: Vec<(PathBuf, Vec<u8>)>,
}

impl Case {
    fn has(&self, arg: &str) -> bool {
        self.args.iter().any(|a| a == arg)
    }

    /// The value after `--flag` (the last one given).
    fn value(&self, flag: &str) -> Option<String> {
        self.args
            .windows(2)
            .rfind(|w| w[0] == flag)
            .map(|w| w[1].to_string_lossy().into_owned())
    }

    /// The command: the first argument that names one.
    fn command(&self) -> Option<&'static str> {
        self.args
            .iter()
            .find_map(|a| COMMANDS.iter().copied().find(|c| a == *c))
    }

    /// The command line as a shell would take it (for reports).
    fn shell(&self) -> String {
        let mut s = String::from("groovelab");
        for a in &self.args[1..] {
            let a = a.to_string_lossy();
            if !a.is_empty()
                && a.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c))
            {
                s.push(' ');
                s.push_str(&a);
            } else {
                s.push_str(&format!(" {a:?}"));
            }
        }
        for (path, bytes) in &self.files {
            let text = String::from_utf8_lossy(bytes);
            let shown: String = text.chars().take(400).collect();
            s.push_str(&format!(
                "\n    with {} = {shown:?}{}",
                path.display(),
                if text.chars().count() > 400 {
                    "…"
                } else {
                    ""
                }
            ));
        }
        s
    }
}

const COMMANDS: [&str; 8] = [
    "simulate", "render", "compare", "fit", "sweep", "presets", "data", "track",
];

/// Fixture files and paths, made once per process in a temporary folder.
struct Fixtures {
    dir: PathBuf,
}

fn fixtures() -> &'static Fixtures {
    static F: OnceLock<Fixtures> = OnceLock::new();
    F.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("groovelab-fuzz-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("a-directory")).unwrap();
        std::fs::create_dir_all(dir.join("user-presets")).unwrap();
        // The app's `s` key (render --keys) saves a preset: into this folder, never the
        // user's. Set once per process; the other tests of this binary read the
        // environment only through `std` (which serialises it with this write) and load
        // built-in presets or explicit paths, which the variable does not change.
        unsafe { std::env::set_var("GROOVELAB_PRESETS", dir.join("user-presets")) };
        // Tracking a video caches its tracks in the user's cache folder: here, never
        // the user's (same reasoning as above).
        unsafe { std::env::set_var("XDG_CACHE_HOME", dir.join("cache")) };
        hostile_files(&dir);
        std::fs::write(dir.join("empty.csv"), b"").unwrap();
        std::fs::write(dir.join("good.csv"), good_csv()).unwrap();
        let mut noise = Vec::new();
        let mut x: u32 = 12345;
        for _ in 0..4096 {
            x = x.wrapping_mul(1_103_515_245).wrapping_add(12345);
            noise.push((x >> 16) as u8);
        }
        std::fs::write(dir.join("random.bin"), noise).unwrap();
        std::fs::write(dir.join("target.txt"), b"keep me\n").unwrap();
        let status = std::process::Command::new("mkfifo")
            .arg(dir.join("fifo"))
            .status();
        assert!(status.is_ok_and(|s| s.success()), "mkfifo failed");
        Fixtures { dir }
    })
}

impl Fixtures {
    fn path(&self, name: &str) -> String {
        self.dir.join(name).display().to_string()
    }
}

/// A measured series like the paper's (b = 4.9 cm, 100 frames/s).
fn good_csv() -> String {
    let mut s = String::from("t,v_cm,v_t\n");
    for i in 0..60 {
        let t = -0.2 + 0.02 * i as f64;
        let (vc, vt) = if t < 0.0 {
            (0.79, 0.79)
        } else {
            let vc = (-0.36 + 3.67 * t).min(0.25);
            let vt = (0.79 - 1.9 * t).max(0.25);
            (vc, vt)
        };
        s.push_str(&format!("{t:.2},{vc:.4},{vt:.4}\n"));
    }
    s
}

fn s(items: &'static [&'static str]) -> BoxedStrategy<String> {
    prop::sample::select(items).prop_map(String::from).boxed()
}

/// Numbers that break things: overflow, underflow, signed zero, non-numbers, text.
const HOSTILE: &[&str] = &[
    "NaN",
    "nan",
    "inf",
    "-inf",
    "+inf",
    "infinity",
    "",
    " ",
    "abc",
    "1,5",
    "0x10",
    "１",
    "٣",
    "1e",
    "e5",
    "-",
    "1..2",
    "1e-300",
    "1e300",
    "1e155",
    "-1e155",
    "99999999999999999999999",
    "1e-21",
    "1 cm",
    "1\ncm",
    "1\n",
    "\n",
    "'1'",
    "💥",
    "1e-2147483648",
    "1e2147483648",
    "-0",
    "0",
    "-1",
    "1e308",
    "-1e308",
    "5e-324",
    "1.7976931348623157e308",
    "1e-320",
    "-1e-300",
    "+1",
    "1e-2147483648cm",
    "1e-2147483648ms",
    "7e-1000",
];

/// Numbers that parse but sit at the edges of what a double holds.
const EXTREME: &[&str] = &[
    "-0",
    "0",
    "-1",
    "1e308",
    "-1e308",
    "1e-308",
    "5e-324",
    "1e-300",
    "1e300",
    "1e155",
    "-1e155",
    "1e38",
    "1e-38",
    "1e9",
    "1e-9",
    "1.7976931348623157e308",
    "1e-2147483648",
    "1e2147483648",
    "99999999999999999999999",
    "2.2250738585072014e-308",
    "1e-320",
    "+1",
];

const WRONG_UNITS: &[&str] = &[
    "kg", "s", "m/s", "cm", "g", "furlong", "%", "µs", "us", "°C", "m/s²", "ms", "cm/s", "CM",
    "mm", "e5", "0", " m", "m m",
];

fn units(dim: char) -> &'static [&'static str] {
    match dim {
        'L' => &["m", "cm", "mm", ""],
        'M' => &["kg", "g", ""],
        'V' => &["m/s", "cm/s", "mm/s", ""],
        'T' => &["s", "ms", ""],
        'A' => &["m/s^2", "m/s²", "m/s2", ""],
        _ => &[""],
    }
}

/// A value for an option of dimension `dim` ('L', 'M', 'V', 'T', 'A', 'R'), drawn
/// from `valid` most of the time.
fn quantity(valid: &'static [&'static str], dim: char) -> BoxedStrategy<String> {
    prop_oneof![
        40 => s(valid),
        3 => (s(EXTREME), s(units(dim))).prop_map(|(n, u)| format!("{n}{u}")),
        1 => (s(valid), s(WRONG_UNITS)).prop_map(|(n, u)| format!("{n}{u}")),
        1 => s(HOSTILE),
        1 => prop_oneof![
            Just("9".repeat(400)),
            Just(format!("0.{}1", "0".repeat(400))),
            Just("x".repeat(3000)),
            "[ -~]{0,12}",
            "\\PC{0,6}",
        ],
    ]
    .boxed()
}

/// An option and its value strategy (`None`: a switch).
type Opt = (&'static str, Option<BoxedStrategy<String>>);

fn scene_options() -> Vec<Opt> {
    let f = fixtures();
    let presets: Vec<String> = [
        "paper-b3.5",
        "paper-b4.4",
        "paper-b4.9",
        "flat-table",
        "critical",
        "unequal-speeds",
        "inelastic",
        "steel-and-glass",
        "nonexistent",
        "",
        "paper-b4.9\n",
        "π",
        "/dev/null",
        "../presets/paper-b4.9.toml",
    ]
    .iter()
    .map(|s| s.to_string())
    .chain([
        f.path("a-directory"),
        f.path("random.bin"),
        f.path("missing.toml"),
    ])
    .collect();
    vec![
        ("--preset", Some(prop::sample::select(presets).boxed())),
        (
            "--radius",
            Some(quantity(&["2.75cm", "1cm", "0.0275", "5mm", "10cm"], 'L')),
        ),
        (
            "--width",
            Some(quantity(
                &["4.9cm", "3.5cm", "0", "4.26cm", "1cm", "5.4cm"],
                'L',
            )),
        ),
        (
            "--mass",
            Some(quantity(&["167g", "0.167", "20g", "1kg", "1mg"], 'M')),
        ),
        (
            "--mass-left",
            Some(quantity(&["167g", "64g", "20g", "2kg"], 'M')),
        ),
        (
            "--mass-right",
            Some(quantity(&["167g", "20g", "0.5", "1mg"], 'M')),
        ),
        (
            "--mu",
            Some(quantity(&["0.17", "0.5", "0.01", "1", "0"], 'R')),
        ),
        (
            "--v0",
            Some(quantity(
                &["60cm/s", "0.6", "0.7928m/s", "10mm/s", "1m/s", "0"],
                'V',
            )),
        ),
        ("--v0-left", Some(quantity(&["80cm/s", "0.4", "0"], 'V'))),
        ("--v0-right", Some(quantity(&["40cm/s", "0.8", "0"], 'V'))),
        (
            "--height",
            Some(quantity(&["9cm", "1cm", "0.5m", "0"], 'L')),
        ),
        (
            "--restitution",
            Some(quantity(&["1", "0.6", "0", "0.4", "0.99"], 'R')),
        ),
        (
            "--rolling-resistance",
            Some(quantity(&["0", "0.01", "0.1"], 'R')),
        ),
        (
            "--g",
            Some(quantity(
                &["9.81", "9.81m/s²", "1.62m/s^2", "24.8m/s2"],
                'A',
            )),
        ),
        (
            "--t-start",
            Some(quantity(&["-0.2", "-0.1s", "-50ms", "0"], 'T')),
        ),
        ("--t-end", Some(quantity(&["1", "0.5s", "800ms", "2"], 'T'))),
        ("--ascii", None),
    ]
}

fn data_paths() -> BoxedStrategy<String> {
    let f = fixtures();
    prop::sample::select(vec![
        f.path("good.csv"),
        f.path("good.csv"),
        f.path("good.trk"),
        f.path("good.cmbl"),
        f.path("vernier.txt"),
        f.path("laughs.trk"),
        f.path("deep.cmbl"),
        f.path("external.trk"),
        f.path("frames"),
        f.path("empty.csv"),
        f.path("random.bin"),
        f.path("a-directory"),
        f.path("missing.csv"),
        f.path("fifo"),
        "/dev/null".into(),
        "/dev/zero".into(),
        String::new(),
    ])
    .boxed()
}

fn data_options() -> Vec<Opt> {
    vec![
        ("--data", Some(data_paths())),
        (
            "--time-unit",
            Some(prop_oneof![s(&["s", "ms", "min"]), s(WRONG_UNITS), s(HOSTILE)].boxed()),
        ),
        (
            "--speed-unit",
            Some(prop_oneof![s(&["m/s", "cm/s", "mm/s"]), s(WRONG_UNITS), s(HOSTILE)].boxed()),
        ),
        ("--impact-at", Some(quantity(&["0", "0.18", "10ms"], 'T'))),
    ]
}

/// What `track` is given: frame folders (good, gappy, empty, junk inside), files that
/// are no video, devices.
fn video_paths() -> BoxedStrategy<String> {
    let f = fixtures();
    prop::sample::select(vec![
        f.path("frames"),
        f.path("frames"),
        f.path("frames-gappy"),
        f.path("a-directory"),
        f.path("frames-junk"),
        f.path("junk.mp4"),
        f.path("empty.mp4"),
        f.path("still.png"),
        f.path("good.trk"),
        f.path("missing.mp4"),
        f.path("fifo"),
        "/dev/zero".into(),
        String::new(),
    ])
    .boxed()
}

/// The hostile and the good files of the formats groovelab reads besides CSV: a
/// Tracker project, a Logger Pro file and its text export (made by the formats tests'
/// generators), XML that attacks the parser (entity expansion, deep nesting, an
/// external entity), and frame folders for `track`.
fn hostile_files(dir: &std::path::Path) {
    use crate::formats::{Coords, cmbl, filmed, trk, vernier};
    let track = filmed();
    let c = Coords {
        origin: (640.0, 360.0),
        angle: 2.0,
        scale: 2000.0,
    };
    std::fs::write(dir.join("good.trk"), trk(&track, 5, &c)).unwrap();
    std::fs::write(dir.join("good.cmbl"), cmbl(&track, "m")).unwrap();
    std::fs::write(dir.join("vernier.txt"), vernier(&track)).unwrap();
    let mut laughs =
        String::from("<?xml version=\"1.0\"?>\n<!DOCTYPE lolz [\n<!ENTITY lol \"lol\">\n");
    for i in 1..10 {
        let prev = if i == 1 {
            "lol".to_string()
        } else {
            format!("lol{}", i - 1)
        };
        laughs += &format!("<!ENTITY lol{i} \"{}\">\n", format!("&{prev};").repeat(10));
    }
    laughs += "]>\n<object class=\"x\"><property name=\"name\">&lol9;</property></object>\n";
    std::fs::write(dir.join("laughs.trk"), laughs).unwrap();
    let deep = format!(
        "<Document>{}{}</Document>",
        "<a>".repeat(200_000),
        "</a>".repeat(200_000)
    );
    std::fs::write(dir.join("deep.cmbl"), deep).unwrap();
    std::fs::write(
        dir.join("external.trk"),
        "<?xml version=\"1.0\"?>\n<!DOCTYPE x [<!ENTITY e SYSTEM \"file:///etc/passwd\">]>\n<object>&e;</object>\n",
    )
    .unwrap();
    // Frames: the paper's scene at 320×180, 500 px/m (R = 13.75 px), 100 frames/s.
    use groovelab::input::video::write;
    use crate::film::{Film, Look};
    let look = Look {
        width: 320,
        height: 180,
        px_per_m: 500.0,
        origin: (160.0, 85.0),
        from: -0.06,
        ..Look::default()
    };
    let film = Film::new(&crate::common::paper_scene(), look, 0.06);
    for (folder, skip) in [("frames", &[][..]), ("frames-gappy", &[3usize, 4, 7][..])] {
        let d = dir.join(folder);
        std::fs::create_dir_all(&d).unwrap();
        for k in 0..12 {
            if !skip.contains(&k) {
                let p = d.join(format!("frame{:04}.png", k + 1));
                write::png(&p, &film.rgb(k), look.width, look.height).unwrap();
            }
        }
    }
    let junk = dir.join("frames-junk");
    std::fs::create_dir_all(&junk).unwrap();
    std::fs::write(junk.join("frame0001.png"), b"not a png").unwrap();
    std::fs::write(junk.join("frame0002.jpg"), [0xff, 0xd8, 0xff, 0x00]).unwrap();
    write::png(
        &dir.join("still.png"),
        &film.rgb(0),
        look.width,
        look.height,
    )
    .unwrap();
    let mut noise = Vec::new();
    let mut x: u32 = 777;
    for _ in 0..20_000 {
        x = x.wrapping_mul(1_103_515_245).wrapping_add(12345);
        noise.push((x >> 16) as u8);
    }
    std::fs::write(dir.join("junk.mp4"), noise).unwrap();
    std::fs::write(dir.join("empty.mp4"), b"").unwrap();
}

/// A Tracker project, a Logger Pro file or its text export, damaged at random (a cut,
/// a repeat, a splice of hostile text, an early end), read by `data` or `fit`.
fn damaged_file_case() -> BoxedStrategy<Case> {
    const SPLICE: &[&str] = &[
        "<",
        ">",
        "&",
        "&amp;",
        "&#0;",
        "&#xFFFFFF;",
        "<!DOCTYPE a [<!ENTITY b \"c\">]>",
        "]]>",
        "<![CDATA[",
        "\u{0}",
        "NaN",
        "1e308",
        "-",
        "\r\n\r\n",
        "\t\t",
        "<property name=\"x\" type=\"double\">",
        "</object>",
        "<object class=\"org.opensourcephysics.cabrillo.tracker.PointMass\">",
        "<ColumnCells>",
        "</ColumnCells>",
        "inf\n",
        "Vernier Format 2\r\n",
    ];
    let base = prop::sample::select(vec!["good.trk", "good.cmbl", "vernier.txt"]);
    let damage = prop::collection::vec(
        (0u8..4, any::<prop::sample::Index>(), 1usize..400, s(SPLICE)),
        1..4,
    );
    (
        base,
        damage,
        s(&[
            "data",
            "data --format json",
            "fit --radius 2.75cm --width 4.9cm",
            "fit --format json",
        ]),
    )
        .prop_map(|(base, damage, command)| {
            let f = fixtures();
            let mut bytes = std::fs::read(f.dir.join(base)).unwrap();
            for (kind, at, len, splice) in damage {
                let i = at.index(bytes.len().max(1)).min(bytes.len());
                let j = (i + len).min(bytes.len());
                match kind {
                    0 => {
                        bytes.drain(i..j);
                    }
                    1 => {
                        let piece = bytes[i..j].to_vec();
                        bytes.splice(i..i, piece);
                    }
                    2 => {
                        bytes.splice(i..i, splice.bytes());
                    }
                    _ => bytes.truncate(i),
                }
            }
            let ext = base.rsplit('.').next().unwrap();
            let file = f.dir.join(format!("damaged.{ext}"));
            let flag = command.starts_with("fit").then_some("--data");
            file_case("damaged", &command, flag, (file, bytes), Vec::new())
        })
        .boxed()
}

fn output_paths() -> BoxedStrategy<String> {
    let f = fixtures();
    prop::sample::select(vec![
        f.path("out.txt"),
        f.path("out.txt"),
        f.path("a-directory"),
        f.path("no-such-dir/out.txt"),
        f.path("fifo-out"),
        f.path("link-out"),
        String::new(),
    ])
    .boxed()
}

fn methods_list() -> BoxedStrategy<String> {
    const M: &[&str] = &[
        "exact",
        "euler",
        "symplectic-euler",
        "rk4",
        "rk45",
        "moreau",
    ];
    prop_oneof![
        6 => (s(M), s(M)).prop_map(|(a, b)| format!("{a},{b}")),
        4 => s(M),
        1 => s(&["bogus", "", ",", "exact,,rk4", "RK4", "rk4 ", "euler,bogus"]),
    ]
    .boxed()
}

fn command_options(cmd: &str) -> Vec<Opt> {
    let fmt3 = |a: &'static str| {
        s(Box::leak(
            vec![a, "json", "table", "svg", "csv", "JSON", ""].into_boxed_slice(),
        ))
    };
    match cmd {
        "simulate" => vec![
            ("--format", Some(fmt3("table"))),
            ("--sample", Some(quantity(&["10ms", "0.01", "1ms", "0.1s"], 'T'))),
            ("--method", Some(s(&["exact", "euler", "symplectic-euler", "rk4", "rk45", "moreau", "bogus", ""]))),
            ("--dt", Some(quantity(&["0.1ms", "1e-4", "1ms", "0.01", "1e-5"], 'T'))),
            ("--tol", Some(quantity(&["1e-6", "1e-3", "1e-9", "0.1"], 'R'))),
            ("--epsilon", Some(quantity(&["1mm/s", "0.001", "1cm/s"], 'V'))),
            ("--output", Some(output_paths())),
        ],
        "render" => vec![
            ("--at", Some(quantity(&["0", "150ms", "0.5", "-0.1"], 'T'))),
            ("--size", Some(prop_oneof![
                6 => (1u16..=250, 1u16..=80).prop_map(|(c, r)| format!("{c}x{r}")),
                1 => s(&["0x0", "1x1", "1000x1000", "1001x5", "80X24", "80", "x", "", "-1x5", "80x24x3", "65536x1"]),
            ].boxed())),
            ("--keys", Some(key_script())),
            ("--output", Some(output_paths())),
        ],
        "compare" => vec![
            ("--format", Some(fmt3("table"))),
            ("--methods", Some(methods_list())),
            ("--epsilon", Some(quantity(&["1mm/s", "0.001", "1cm/s"], 'V'))),
            ("--output", Some(output_paths())),
        ],
        "fit" => vec![
            ("--from", Some(quantity(&["0.02", "0.1", "20ms", "0.3"], 'T'))),
            ("--to", Some(quantity(&["0.2", "0.3", "250ms", "0.04"], 'T'))),
            ("--free", Some(s(&["mu", "v0", "restitution", "mu,v0", "mu,restitution", "mu,v0,restitution", "v0,restitution", "", "bogus", "mu,mu"]))),
            ("--format", Some(fmt3("table"))),
            ("--output", Some(output_paths())),
        ],
        "data" => vec![
            ("--format", Some(s(&["table", "json", "csv", ""]))),
            ("--length-unit", Some(prop_oneof![s(&["m", "cm", "mm", "px"]), s(WRONG_UNITS), s(HOSTILE)].boxed())),
            ("--scale", Some(quantity(&["1mm", "1.105mm", "0.5cm"], 'L'))),
            ("--track", Some(s(&["centre=mass A", "mark=mass B", "centre=", "mark=nothing", "bogus", "centre=mass B"]))),
            ("--window", Some(quantity(&["20ms", "0.01", "1s"], 'T'))),
        ],
        "track" => vec![
            ("--fps", Some(prop_oneof![s(&["100", "240", "30", "1"]), s(HOSTILE)].boxed())),
            ("--format", Some(s(&["tracker", "json", "csv", ""]))),
            ("--output", Some(output_paths())),
        ],
        "sweep" => vec![
            ("--y", Some(axis())),
            ("--grid", Some(s(&["1", "5", "3x3", "20x10", "12x7", "0", "0x5", "10001", "abc", "", "5x", "x5", "1e3", "-1", "100", "7X3", "10000x10000"]))),
            ("--format", Some(s(&["csv", "json", "svg", "table", ""]))),
            ("--output", Some(output_paths())),
        ],
        _ => vec![],
    }
}

fn axis() -> BoxedStrategy<String> {
    const NAMES: &[&str] = &[
        "width",
        "radius",
        "mass",
        "mass-left",
        "mass_right",
        "mu",
        "v0",
        "v0_left",
        "height",
        "restitution",
        "rolling_resistance",
        "g",
        "t_end",
        "t_start",
        "bogus",
        "",
        "WIDTH",
    ];
    const RANGES: &[&str] = &[
        "0..5.4cm",
        "3cm..5cm",
        "0.3..1",
        "0..1",
        "0.01..0.5",
        "10cm/s..1m/s",
        "100g..1kg",
        "1..9.81",
        "1cm..2cm",
        "5..5",
        "1..0",
        "0..1e308",
        "-1e308..0",
        "NaN..1",
        "0..inf",
        "1e-2147483648..1",
        "..",
        "",
        "1",
        "1cm..2kg",
        "1..2..3",
        "0cm..",
        "..5cm",
    ];
    prop_oneof![
        8 => (s(NAMES), s(RANGES)).prop_map(|(n, r)| format!("{n}={r}")),
        1 => s(&["width", "=", "width=", "=0..1", "width==0..1"]),
    ]
    .boxed()
}

/// Key names from the key table, typing characters, and names that are not keys.
fn key_name() -> BoxedStrategy<String> {
    let mut names: Vec<String> = groovelab::tui::keys::TABLE
        .iter()
        .flat_map(|b| b.keys.iter().map(|k| k.to_string()))
        .collect();
    names.extend(
        [
            "enter",
            "esc",
            "backspace",
            "S-left",
            "S-right",
            "C-c",
            "home",
            "end",
            "pgup",
            "pgdn",
            "delete",
            "C-u",
            "C-w",
            "C-a",
            "C-e",
            "C-k",
        ]
        .map(String::from),
    );
    let typing: Vec<String> = "0123456789.e-+cmgskμ/ "
        .chars()
        .filter(|c| !c.is_whitespace())
        .map(String::from)
        .collect();
    prop_oneof![
        6 => prop::sample::select(names),
        4 => prop::sample::select(typing),
        1 => s(&["spacebar", "C-", "S-", "F1", "ctrl-c", "ENTER", "é", "💥", "\u{0}", "C-z", "alt-x"]),
    ]
    .boxed()
}

fn key_script() -> BoxedStrategy<String> {
    prop::collection::vec(key_name(), 0..24)
        .prop_map(|v| v.join(" "))
        .boxed()
}

/// Chooses a subset of `opts` (each with probability about 1/3) with their values.
fn some_of(opts: Vec<Opt>) -> BoxedStrategy<Vec<String>> {
    let parts: Vec<BoxedStrategy<Vec<String>>> = opts
        .into_iter()
        .map(|(flag, value)| {
            let present = prop::bool::weighted(0.3);
            match value {
                None => present
                    .prop_map(move |p| if p { vec![flag.to_string()] } else { vec![] })
                    .boxed(),
                Some(v) => (present, v)
                    .prop_map(move |(p, v)| if p { vec![flag.to_string(), v] } else { vec![] })
                    .boxed(),
            }
        })
        .collect();
    parts
        .prop_map(|v: Vec<Vec<String>>| v.into_iter().flatten().collect())
        .boxed()
}

fn to_case(kind: &'static str, args: Vec<String>) -> Case {
    Case {
        kind,
        args: std::iter::once("groovelab".to_string())
            .chain(args)
            .map(OsString::from)
            .collect(),
        files: Vec::new(),
    }
}

/// A case that writes a file (its path and bytes) and runs `command` (words split at
/// spaces) on it: the path after `flag` when there is one, then `extra`.
fn file_case(
    kind: &'static str,
    command: &str,
    flag: Option<&str>,
    (file, bytes): (PathBuf, Vec<u8>),
    extra: Vec<String>,
) -> Case {
    let mut args: Vec<String> = command.split(' ').map(String::from).collect();
    args.extend(flag.map(String::from));
    args.push(file.display().to_string());
    args.extend(extra);
    let mut case = to_case(kind, args);
    case.files.push((file, bytes));
    case
}

/// Random command lines over every command and option.
fn cli_case() -> BoxedStrategy<Case> {
    let junk = prop_oneof![
        20 => Just(vec![]),
        1 => s(&["--bogus", "extra", "-", "--", "-x", "--help", "--version", "-h", "--format", "--radius"]).prop_map(|a| vec![a]),
        1 => Just(vec!["--width".to_string(), "4cm".into(), "--width".into(), "5cm".into()]),
        1 => Just(vec!["--v0".to_string(), "1".into(), "--height".into(), "9cm".into()]),
    ];
    let per_command: Vec<BoxedStrategy<Case>> = COMMANDS
        .iter()
        .map(|&cmd| {
            let mut local = command_options(cmd);
            let mut scene = scene_options();
            if cmd == "compare" {
                // A compare over a long span is slow by design (and bounded by its
                // budget, not by this harness): keep it short.
                scene.retain(|(f, _)| !matches!(*f, "--t-start" | "--t-end"));
            }
            // `track` takes no data options, and `data` names its files without
            // `--data`: those are refused by design, so rarely worth a case.
            match cmd {
                "track" => {}
                "data" => local.extend(data_options().into_iter().filter(|(f, _)| *f != "--data")),
                _ => local.extend(data_options()),
            }
            let required = match cmd {
                "sweep" => axis().prop_map(|a| vec!["--x".to_string(), a]).boxed(),
                "compare" => (
                    prop_oneof![3 => s(&["-0.01", "-0.05", "-10ms"]), 1 => s(HOSTILE)],
                    prop_oneof![3 => s(&["0.01", "0.05", "50ms", "0.1"]), 1 => s(&["NaN", "-1", "", "abc", "0", "1e-300", "-0"])],
                    methods_list(),
                )
                    .prop_map(|(a, b, m)| {
                        vec!["--t-start".into(), a, "--t-end".into(), b, "--methods".into(), m]
                    })
                    .boxed(),
                "data" => prop::collection::vec(data_paths(), 1..3).boxed(),
                "track" => video_paths().prop_map(|v| vec![v]).boxed(),
                _ => Just(vec![]).boxed(),
            };
            (some_of(scene.clone()), some_of(scene), some_of(local), required, junk.clone(), any::<bool>())
                .prop_map(move |(before, after, local, req, junk, junk_first)| {
                    let mut a = before;
                    a.push(cmd.to_string());
                    if junk_first {
                        a.extend(junk.clone());
                    }
                    a.extend(req);
                    a.extend(after);
                    a.extend(local);
                    if !junk_first {
                        a.extend(junk);
                    }
                    to_case("cli", a)
                })
                .boxed()
        })
        .collect();
    prop::sample::select((0..per_command.len()).collect::<Vec<_>>())
        .prop_flat_map(move |i| per_command[i].clone())
        .boxed()
}

/// Random preset files (TOML-ish text), loaded with --preset FILE.
fn preset_case() -> BoxedStrategy<Case> {
    const KEYS: &[&str] = &[
        "radius",
        "width",
        "mass",
        "mass_left",
        "mass_right",
        "mu",
        "v0",
        "v0_left",
        "v0_right",
        "height",
        "restitution",
        "rolling_resistance",
        "g",
        "t_start",
        "t_end",
        "bogus",
        "name",
    ];
    const VALUES: &[&str] = &[
        "\"2.75cm\"",
        "\"4.9cm\"",
        "0.17",
        "1.0",
        "\"167g\"",
        "0.6",
        "\"60cm/s\"",
        "-0.2",
        "0.8",
        "0",
        "-0.0",
        "1e308",
        "-1e308",
        "1e-300",
        "1e300",
        "nan",
        "inf",
        "-inf",
        "\"NaN\"",
        "\"inf\"",
        "\"\"",
        "\"1e-2147483648cm\"",
        "true",
        "[1, 2]",
        "{ a = 1 }",
        "\"abc\"",
        "9223372036854775807",
        "-9223372036854775808",
        "1979-05-27",
        "\"3kg\"",
        "5e-324",
        "\"5.4cm\"",
        "\"1mm\"",
        "\"1kg\"",
        "0.99",
        "2",
        "\"9.81m/s²\"",
    ];
    const NAMES: &[&str] = &[
        "\"fuzz\"",
        "\"\"",
        "\"with \\\" quote\"",
        "\"line\\nbreak\"",
        "\"π\"",
        "1",
        "\"paper-b4.9\"",
    ];
    let line = prop_oneof![
        8 => (s(KEYS), s(VALUES)).prop_map(|(k, v)| format!("{k} = {v}")),
        1 => s(&["[scene]", "[measured]", "[other]", "x", "= 1", "[[scene]]", "\"", "# comment", "[scene", "mu = ", "mu == 1"]).prop_map(String::from),
        1 => measured_arrays(),
    ];
    let body = prop::collection::vec(line, 0..14);
    let head = (s(NAMES), s(NAMES), any::<bool>(), any::<bool>());
    let text = (
        head,
        body,
        prop::bool::weighted(0.1),
        prop::collection::vec(any::<u8>(), 0..64),
    )
        .prop_map(|((name, desc, with_name, with_scene), body, bytes, raw)| {
            if bytes {
                return raw;
            }
            let mut t = String::new();
            if with_name {
                t.push_str(&format!("name = {name}\ndescription = {desc}\n"));
            }
            if with_scene {
                t.push_str("[scene]\n");
            }
            for l in body {
                t.push_str(&l);
                t.push('\n');
            }
            t.into_bytes()
        });
    let command = prop_oneof![
        s(&[
            "simulate",
            "simulate --format json",
            "presets",
            "render --size 80x24",
            "fit --format json",
            "sweep --x width=3cm..5cm --grid 4"
        ]),
        Just("compare --methods rk45 --t-start -0.01 --t-end 0.02".to_string()),
    ];
    (text, command)
        .prop_map(|(text, command)| {
            let file = fixtures().dir.join("fuzz-preset.toml");
            file_case(
                "preset",
                &command,
                Some("--preset"),
                (file, text),
                Vec::new(),
            )
        })
        .boxed()
}

fn measured_arrays() -> BoxedStrategy<String> {
    let num = prop_oneof![
        6 => (-100i32..100).prop_map(|i| format!("{}", i as f64 / 100.0)),
        1 => s(&["nan", "inf", "1e308", "-0.0", "1e-300"]).prop_map(String::from),
    ];
    (
        s(&["t", "v_cm", "v_t", "x"]),
        prop::collection::vec(num, 0..12),
    )
        .prop_map(|(k, v)| format!("{k} = [{}]", v.join(", ")))
        .boxed()
}

/// Random CSV files, read by `fit --data FILE`.
fn csv_case() -> BoxedStrategy<Case> {
    const T: &[&str] = &[
        "t",
        "time",
        "t (s)",
        "t (ms)",
        "t [ms]",
        "t_s",
        "t2",
        "t_1",
        "time0",
        "\u{feff}t",
        "T",
        "\"t\"",
        "x",
        "",
    ];
    const VCM: &[&str] = &[
        "v_cm",
        "vcm",
        "v_cm (m/s)",
        "v_cm [cm/s]",
        "v_cm_cm_per_s",
        "v_cm7",
        "v_cm (furlong)",
        "v",
    ];
    const VT: &[&str] = &[
        "v_t",
        "vt",
        "v_t (m/s)",
        "v_t [cm/s]",
        "v_t_cm_per_s",
        "v_t0",
        "v_t",
    ];
    let cell = prop_oneof![
        20 => Just(None),
        1 => s(&["", "NaN", "inf", "-inf", "1e308", "-1e308", "abc", "1,5", "0,25", "1e-300", "\"0.5\"", " ", "5e-324"]).prop_map(Some),
    ];
    let row = (cell.clone(), cell.clone(), cell);
    let header = (s(T), s(VCM), s(VT), any::<bool>());
    (
        header,
        prop::collection::vec(row, 0..70),
        0usize..70,
        0.001f64..0.1,
        0.2f64..3.0,
        prop_oneof![4 => Just(','), 1 => Just(';'), 1 => Just('\t')],
    )
        .prop_map(|((t, vc, vt, swap), rows, len, dt, speed, sep)| {
            let mut text = if swap {
                format!("{vc}{sep}{t}{sep}{vt}\n")
            } else {
                format!("{t}{sep}{vc}{sep}{vt}\n")
            };
            for (i, (a, b, c)) in rows.iter().enumerate().take(len) {
                let tt = -0.2 + dt * i as f64;
                let v = if tt < 0.0 {
                    speed
                } else {
                    (-0.4 * speed + 3.6 * tt).min(0.3 * speed)
                };
                let u = if tt < 0.0 {
                    speed
                } else {
                    (speed - 1.9 * tt).max(0.3 * speed)
                };
                let a = a.clone().unwrap_or(format!("{tt:.4}"));
                let b = b.clone().unwrap_or(format!("{v:.4}"));
                let c = c.clone().unwrap_or(format!("{u:.4}"));
                if swap {
                    text.push_str(&format!("{b}{sep}{a}{sep}{c}\n"));
                } else {
                    text.push_str(&format!("{a}{sep}{b}{sep}{c}\n"));
                }
            }
            text
        })
        .prop_flat_map(|text| {
            let extra = some_of(vec![
                (
                    "--time-unit",
                    Some(prop_oneof![s(&["s", "ms"]), s(WRONG_UNITS), s(HOSTILE)].boxed()),
                ),
                (
                    "--speed-unit",
                    Some(prop_oneof![s(&["m/s", "cm/s"]), s(WRONG_UNITS), s(HOSTILE)].boxed()),
                ),
                ("--impact-at", Some(quantity(&["0", "0.18", "10ms"], 'T'))),
                ("--format", Some(s(&["table", "json", "svg"]))),
                ("--free", Some(s(&["mu", "mu,v0", "mu,v0,restitution"]))),
            ]);
            (
                Just(text),
                extra,
                s(&["fit", "fit", "fit", "render --size 100x30"]),
            )
        })
        .prop_map(|(text, extra, command)| {
            let file = fixtures().dir.join("fuzz-data.csv");
            let written = (file, text.into_bytes());
            file_case("csv", &command, Some("--data"), written, extra)
        })
        .boxed()
}

/// Random key sequences through `render --keys` at random sizes.
fn keys_case() -> BoxedStrategy<Case> {
    let preset = s(&[
        "paper-b3.5",
        "paper-b4.4",
        "paper-b4.9",
        "flat-table",
        "critical",
        "unequal-speeds",
        "inelastic",
        "steel-and-glass",
    ]);
    let at = prop_oneof![3 => Just(None), 1 => s(&["0", "0.1", "-0.1", "0.5"]).prop_map(Some)];
    (
        preset,
        key_script(),
        1u16..=250,
        1u16..=80,
        any::<bool>(),
        at,
    )
        .prop_map(|(preset, keys, c, r, ascii, at)| {
            let mut a = vec![
                "render".to_string(),
                "--preset".into(),
                preset,
                "--size".into(),
                format!("{c}x{r}"),
                "--keys".into(),
                keys,
            ];
            if ascii {
                a.push("--ascii".into());
            }
            if let Some(at) = at {
                a.push("--at".into());
                a.push(at);
            }
            to_case("keys", a)
        })
        .boxed()
}

// ---------------------------------------------------------------------------------
// Running and judging.

/// What a case did.
#[derive(Clone, Debug)]
enum Verdict {
    Pass,
    Fail { class: String, detail: String },
}

impl Verdict {
    fn class(&self) -> Option<&str> {
        match self {
            Verdict::Pass => None,
            Verdict::Fail { class, .. } => Some(class),
        }
    }
}

/// The name of the thread a case runs on (its panics are recorded, not printed).
const CASE_THREAD: &str = "fuzz-case";

fn panic_message() -> &'static Mutex<String> {
    static M: OnceLock<Mutex<String>> = OnceLock::new();
    M.get_or_init(|| Mutex::new(String::new()))
}

fn limit() -> Duration {
    let secs = std::env::var("GROOVELAB_FUZZ_TIMEOUT")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(if cfg!(debug_assertions) { 60.0 } else { 10.0 });
    Duration::from_secs_f64(secs)
}

/// Runs a case on its own thread under a watchdog.
fn run(case: &Case) -> Result<Result<Exit, String>, Duration> {
    let f = fixtures();
    // Targets that --output must not turn into regular files, made afresh.
    let fifo_out = f.dir.join("fifo-out");
    let link_out = f.dir.join("link-out");
    let _ = std::fs::remove_file(&fifo_out);
    let _ = std::fs::remove_file(&link_out);
    let _ = std::process::Command::new("mkfifo").arg(&fifo_out).status();
    let _ = std::os::unix::fs::symlink(f.dir.join("target.txt"), &link_out);
    for (path, bytes) in &case.files {
        std::fs::write(path, bytes).unwrap();
    }
    let args = case.args.clone();
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name(CASE_THREAD.into())
        .stack_size(64 << 20)
        .spawn(move || {
            let result = catch_unwind(AssertUnwindSafe(|| main_with(&args)));
            let _ = tx.send(result.map_err(|_| panic_message().lock().unwrap().clone()));
        })
        .unwrap();
    rx.recv_timeout(limit()).map_err(|_| limit())
}

/// Every command: keys of the parts several commands print (the scene, its derived
/// values, the run's summary and its solution).
const ANY: &[&str] = &COMMANDS;

/// Keys whose value may be `null` in JSON output (the `Option`s of the schema), each
/// with the commands whose output documents the `null` (docs/interface.md). A `null`
/// under a key elsewhere (say `frame_rate` from `fit`, where it is always a number)
/// is a non-finite number and fails.
const NULLABLE: &[(&str, &[&str])] = &[
    ("t_pure_gliding", ANY),
    ("t_pure_slipping", ANY),
    ("b_star", ANY),
    ("left_after_impact", ANY),
    ("accumulation_time", ANY),
    ("bridge", ANY),
    ("accumulation", ANY),
    ("t_end", ANY),
    ("label", ANY),
    // simulate --method: why a time-stepping run stalled, `null` when it did not.
    ("stalled", &["simulate"]),
    // compare's rows: the step or the tolerance (the other `null`), the errors a run
    // has no counterpart for, a stalled run's note, and where the step budget cut the
    // span (`null` when it covered it all).
    ("step", &["compare"]),
    ("tolerance", &["compare"]),
    ("err_t_roll", &["compare"]),
    ("err_t_impact", &["compare"]),
    ("note", &["compare"]),
    ("cut", &["compare"]),
    // fit's models: a value and its standard error, `null` where the data do not
    // determine it (with its reason), and the approach speed of the user's own data,
    // `null` where there are none (the preset's series) or they measure none.
    ("v0_se", &["fit"]),
    ("restitution_se", &["fit"]),
    ("rolling_resistance_se", &["fit"]),
    ("value", &["fit"]),
    ("se", &["fit"]),
    ("approach", &["fit"]),
    // sweep: a 1-D sweep's `y`; v'/v0 and t' without friction or impact; no
    // accumulation point.
    ("y", &["sweep", "track"]),
    ("v_ratio", &["sweep"]),
    ("t_roll", &["sweep"]),
    ("t_accumulation", &["sweep"]),
    // track's JSON: a ball's centre (`x`, `y`, `sigma`) or its mark (`mark_x`,
    // `mark_y`, `mark_sigma`) in a frame where it is left out, never filled in.
    ("x", &["track"]),
    ("sigma", &["track"]),
    ("mark_x", &["track"]),
    ("mark_y", &["track"]),
    ("mark_sigma", &["track"]),
    // data's report: a file with fewer than two distinct times has no frame rate.
    ("frame_rate", &["data"]),
];

/// May `key` be `null` in the JSON of `command`?
fn nullable(command: Option<&str>, key: &str) -> bool {
    NULLABLE
        .iter()
        .any(|(k, cs)| *k == key && command.is_some_and(|c| cs.contains(&c)))
}

/// The keys under which `v` holds a `null` that `command` may not print.
fn nulls(v: &serde_json::Value, command: Option<&str>, key: &str, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Null if !nullable(command, key) => out.push(key.to_string()),
        serde_json::Value::Array(a) => a.iter().for_each(|x| nulls(x, command, key, out)),
        serde_json::Value::Object(o) => o.iter().for_each(|(k, x)| nulls(x, command, k, out)),
        _ => {}
    }
}

/// Words that say a number was not finite, in text output.
fn nonfinite_words(text: &str) -> Vec<String> {
    // The accumulation time's label T∞ (ASCII: Tinf) is a name,
    // also where a popup's border hides its first letters.
    // A note about the file's cells names a NaN cell it left out ("empty or NaN").
    let text = [
        "Tinf",
        "T∞",
        "|inf",
        "+inf",
        "│∞",
        "╮∞",
        "╯∞",
        "empty or NaN",
    ]
    .iter()
    .fold(text.to_string(), |t, label| t.replace(label, "T"));
    let mut found: Vec<String> = text
        .split(|c: char| !(c.is_alphanumeric() || c == '.'))
        .filter(|w| matches!(*w, "NaN" | "nan" | "inf" | "Inf" | "infinity" | "∞"))
        .map(String::from)
        .collect();
    found.dedup();
    found
}

fn judge(case: &Case, result: &Result<Result<Exit, String>, Duration>) -> Verdict {
    let fail = |class: &str, detail: String| Verdict::Fail {
        class: class.to_string(),
        detail,
    };
    let exit = match result {
        Err(limit) => return fail("timeout", format!("no result within {limit:?}")),
        Ok(Err(msg)) => {
            // Panics differ by message; the class is where (file:line) and what.
            let short: String = msg.lines().next().unwrap_or("").chars().take(90).collect();
            return fail(&format!("panic: {short}"), msg.clone());
        }
        Ok(Ok(exit)) => exit,
    };
    let shown = || {
        format!(
            "exit {}\n--- stdout\n{}\n--- stderr\n{}",
            exit.code,
            head(&exit.stdout),
            exit.stderr
        )
    };
    match exit.code {
        2 => {
            if !exit.stdout.is_empty() {
                return fail("error: text on stdout", shown());
            }
            let lines: Vec<&str> = exit.stderr.lines().collect();
            if lines.len() != 1 || !exit.stderr.ends_with('\n') {
                let class = if exit.stderr.contains("For more information, try") {
                    "error: clap's usage error spans several lines (hint, possible values, usage)"
                } else {
                    "error: message spans several lines"
                };
                return fail(class, shown());
            }
            if !lines[0].starts_with("error: ") {
                return fail("error: line does not start with 'error: '", shown());
            }
            Verdict::Pass
        }
        0 => {
            if !exit.stderr.is_empty() {
                return fail("success: text on stderr", shown());
            }
            let wrote_to = |name: &str| case.value("--output").is_some_and(|o| o.ends_with(name));
            for special in ["fifo-out", "link-out"] {
                if wrote_to(special) {
                    let meta = std::fs::symlink_metadata(fixtures().dir.join(special));
                    if meta.is_ok_and(|m| m.file_type().is_file()) {
                        return fail(
                            "success: --output replaced a FIFO or symlink with a regular file",
                            shown(),
                        );
                    }
                }
            }
            let text = match case.value("--output") {
                Some(path) if exit.stdout.starts_with("wrote ") => {
                    std::fs::read_to_string(path).unwrap_or_default()
                }
                _ => exit.stdout.clone(),
            };
            let json_out = case.value("--format").as_deref() == Some("json")
                && !case.has("--help")
                && !case.has("-h")
                && !case.has("--version");
            if json_out {
                match serde_json::from_str::<serde_json::Value>(&text) {
                    Err(e) => {
                        return fail("success: JSON does not parse", format!("{e}\n{}", shown()));
                    }
                    Ok(v) => {
                        let mut found = Vec::new();
                        nulls(&v, case.command(), "", &mut found);
                        found.sort();
                        found.dedup();
                        if !found.is_empty() {
                            return fail(
                                &format!(
                                    "success: non-finite number (null) in JSON under {}",
                                    found.join(", ")
                                ),
                                shown(),
                            );
                        }
                    }
                }
            } else {
                let words = nonfinite_words(&text);
                if !words.is_empty() {
                    let lines: Vec<&str> = text
                        .lines()
                        .filter(|l| !nonfinite_words(l).is_empty())
                        .take(3)
                        .collect();
                    let what = if text.starts_with("<svg") || text.starts_with("<?xml") {
                        "SVG"
                    } else {
                        case.command().unwrap_or("output")
                    };
                    return fail(
                        &format!(
                            "success: non-finite number ({}) in {what} output",
                            words.join(", ")
                        ),
                        format!("at: {}\n{}", lines.join("\n"), shown()),
                    );
                }
            }
            Verdict::Pass
        }
        c => fail(&format!("exit status {c}"), shown()),
    }
}

fn head(s: &str) -> String {
    let h: String = s.chars().take(600).collect();
    if h.len() < s.len() {
        format!("{h}…")
    } else {
        h
    }
}

/// Tally of a run.
#[derive(Default)]
struct Tally {
    run: usize,
    passed: usize,
    skipped: BTreeMap<String, usize>,
    tolerated: BTreeMap<String, usize>,
    /// Failure class → (count, the shortest reproducer and its detail).
    failures: BTreeMap<String, (usize, String, String)>,
    by_kind: BTreeMap<&'static str, usize>,
    /// Per command: how many cases it accepted (exit 0) and refused (exit 2), so a run
    /// shows that each command was reached past its argument checks.
    outcomes: BTreeMap<&'static str, (usize, usize)>,
    /// Seconds spent per kind, and the slowest case.
    time_by_kind: BTreeMap<&'static str, f64>,
    slowest: (f64, String),
}

fn cases_wanted() -> usize {
    std::env::var("GROOVELAB_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200)
}

fn seed() -> u64 {
    std::env::var("GROOVELAB_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x9e0_07e1ab)
}

/// Runs `n` cases drawn from `strategy`, judging each.
fn fuzz(name: &'static str, strategy: BoxedStrategy<Case>, n: usize, tally: &mut Tally) {
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed().to_le_bytes());
    bytes[8..8 + name.len().min(24)].copy_from_slice(&name.as_bytes()[..name.len().min(24)]);
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &bytes);
    let mut runner = TestRunner::new_with_rng(Config::default(), rng);
    let verbose = std::env::var_os("GROOVELAB_FUZZ_VERBOSE").is_some();
    for i in 0..n {
        let case = strategy.new_tree(&mut runner).unwrap().current();
        if let Some(k) = KNOWN_OPEN
            .iter()
            .find(|k| k.hang && (k.applies)(&case, None))
        {
            *tally.skipped.entry(k.label()).or_default() += 1;
            continue;
        }
        if verbose {
            eprintln!("[{name} {i}] {}", case.shell());
        }
        let started = Instant::now();
        let result = run(&case);
        let verdict = judge(&case, &result);
        tally.run += 1;
        *tally.by_kind.entry(case.kind).or_default() += 1;
        if let Ok(Ok(exit)) = &result {
            let counts = tally
                .outcomes
                .entry(case.command().unwrap_or("(none)"))
                .or_default();
            match exit.code {
                0 => counts.0 += 1,
                _ => counts.1 += 1,
            }
        }
        let took = started.elapsed().as_secs_f64();
        *tally.time_by_kind.entry(case.kind).or_default() += took;
        if took > tally.slowest.0 {
            tally.slowest = (took, case.shell());
        }
        match &verdict {
            Verdict::Pass => tally.passed += 1,
            Verdict::Fail { class, detail } => {
                if let Some(k) = KNOWN_OPEN
                    .iter()
                    .find(|k| !k.hang && (k.applies)(&case, Some(&verdict)))
                {
                    *tally.tolerated.entry(k.label()).or_default() += 1;
                } else {
                    let repro = case.shell();
                    let entry = tally.failures.entry(class.clone()).or_insert((
                        0,
                        repro.clone(),
                        detail.clone(),
                    ));
                    entry.0 += 1;
                    if repro.len() < entry.1.len() {
                        entry.1 = repro;
                        entry.2 = detail.clone();
                    }
                }
            }
        }
        if result.is_err() {
            // The stuck case still runs on its thread: stop here.
            eprintln!(
                "fuzz {name}: stopping after a timeout ({:?})",
                started.elapsed()
            );
            break;
        }
    }
}

fn report(tally: &Tally, elapsed: Duration) -> String {
    let mut out = format!(
        "fuzz: {} cases run in {:.1} s ({:?}), {} passed, {} failed in {} classes; seed {}\n",
        tally.run,
        elapsed.as_secs_f64(),
        tally.by_kind,
        tally.passed,
        tally.failures.values().map(|f| f.0).sum::<usize>(),
        tally.failures.len(),
        seed()
    );
    let times: Vec<String> = tally
        .time_by_kind
        .iter()
        .map(|(k, t)| format!("{k} {t:.1} s"))
        .collect();
    out.push_str(&format!(
        "  time: {}; slowest case {:.2} s: {}\n",
        times.join(", "),
        tally.slowest.0,
        tally.slowest.1
    ));
    let outcomes: Vec<String> = tally
        .outcomes
        .iter()
        .map(|(c, (ok, refused))| format!("{c} {ok}/{refused}"))
        .collect();
    out.push_str(&format!(
        "  accepted/refused by command: {}\n",
        outcomes.join(", ")
    ));
    for (id, n) in &tally.skipped {
        out.push_str(&format!("  skipped (KNOWN_OPEN {id}, would hang): {n}\n"));
    }
    for (id, n) in &tally.tolerated {
        out.push_str(&format!("  tolerated (KNOWN_OPEN {id}): {n}\n"));
    }
    for (class, (n, repro, detail)) in &tally.failures {
        out.push_str(&format!(
            "\nFAIL [{n}×] {class}\n  {repro}\n  {}\n",
            head(detail).replace('\n', "\n  | ")
        ));
    }
    out
}

#[test]
fn fuzz_the_command_line() {
    fixtures();
    // The hook is the whole test binary's: other tests' panics still reach the
    // previous hook (and so their failure output); a case's panic is only recorded.
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        *panic_message().lock().unwrap() = info.to_string();
        if std::thread::current().name() != Some(CASE_THREAD) {
            previous(info);
        }
    }));
    let n = cases_wanted();
    let started = Instant::now();
    let mut tally = Tally::default();
    fuzz("cli", cli_case(), n * 55 / 100, &mut tally);
    fuzz("preset", preset_case(), n * 15 / 100, &mut tally);
    fuzz("csv", csv_case(), n * 10 / 100, &mut tally);
    fuzz("damaged", damaged_file_case(), n * 5 / 100, &mut tally);
    fuzz("keys", keys_case(), n - n * 85 / 100, &mut tally);
    let text = report(&tally, started.elapsed());
    eprintln!("{text}");
    if let Ok(path) = std::env::var("GROOVELAB_FUZZ_REPORT") {
        std::fs::write(path, &text).unwrap();
    }
    // GROOVELAB_FUZZ_KEEP=1 keeps the fixtures, so a reported case can be rerun by hand.
    if std::env::var_os("GROOVELAB_FUZZ_KEEP").is_none() {
        let _ = std::fs::remove_dir_all(&fixtures().dir);
    }
    assert!(tally.failures.is_empty(), "{text}");
    assert!(tally.run >= n / 2, "most cases were skipped: {text}");
}

#[test]
fn the_harness_sees_a_broken_contract() {
    // The judge itself: a second stderr line, text on stdout with an error, a panic
    // and a null in JSON are failures; a clean error and clean JSON pass.
    fixtures();
    let case = to_case(
        "cli",
        vec!["simulate".into(), "--format".into(), "json".into()],
    );
    let exit = |code, stdout: &str, stderr: &str| {
        Ok(Ok(Exit {
            code,
            stdout: stdout.into(),
            stderr: stderr.into(),
        }))
    };
    let class = |r| judge(&case, &r).class().map(String::from);
    assert_eq!(class(exit(2, "", "error: bad\n")), None);
    assert!(
        class(exit(
            2,
            "",
            "error: bad\n\nFor more information, try '--help'.\n"
        ))
        .is_some()
    );
    assert!(class(exit(2, "x", "error: bad\n")).is_some());
    assert!(class(exit(2, "", "bad\n")).is_some());
    assert!(class(exit(130, "", "error: interrupted\n")).is_some());
    assert_eq!(class(exit(0, "{\"b_star\": null, \"k\": 1.0}", "")), None);
    assert!(class(exit(0, "{\"k\": null}", "")).is_some());
    // A `null` is allowed only where the command documents it: `data` reports a file
    // with one time as having no frame rate; `fit`'s frame rate is always a number.
    let rate = "{\"frame_rate\": null}";
    let of = |command: &str| {
        let case = to_case(
            "cli",
            vec![command.into(), "--format".into(), "json".into()],
        );
        judge(&case, &exit(0, rate, "")).class().map(String::from)
    };
    assert_eq!(of("data"), None);
    assert!(of("fit").is_some());
    assert!(of("simulate").is_some());
    assert!(class(Ok(Err("boom".into()))).is_some());
    assert!(class(Err(Duration::from_secs(1))).is_some());
    let table = to_case("cli", vec!["simulate".into()]);
    assert!(
        judge(&table, &exit(0, "energy inf J", ""))
            .class()
            .is_some()
    );
    assert!(judge(&table, &exit(0, "information", "")).class().is_none());
}

#[test]
fn main_with_runs_in_process() {
    fixtures();
    let out = main_with(&["groovelab", "simulate", "--format", "json"].map(OsString::from));
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(v["scene"]["width"], 0.049);
    let bad = main_with(&["groovelab", "simulate", "--radius", "0"].map(OsString::from));
    assert_eq!(bad.code, 2);
    assert!(bad.stdout.is_empty());
    assert!(bad.stderr.starts_with("error: "), "{}", bad.stderr);
    // Without a terminal the app is refused, as the binary refuses it when piped.
    let app = main_with(&["groovelab"].map(OsString::from));
    assert_eq!(app.code, 2);
    assert!(app.stderr.contains("needs a terminal"), "{}", app.stderr);
}
