//! The fuzz harness's cases: hostile files, damaged files, each command's options, and the command-line, preset, CSV and key-sequence cases.

use super::*;

/// The hostile and the good files of the formats groovelab reads besides CSV: a
/// Tracker project, a Logger Pro file and its text export (made by the formats tests'
/// generators), XML that attacks the parser (entity expansion, deep nesting, an
/// external entity), and frame folders for `track`.
pub(super) fn hostile_files(dir: &std::path::Path) {
    use crate::data::formats::{Coords, cmbl, filmed, trk, vernier};
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
    use groovelab::vision::render::{Film, Look};
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
pub(super) fn damaged_file_case() -> BoxedStrategy<Case> {
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

pub(super) fn output_paths() -> BoxedStrategy<String> {
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

pub(super) fn methods_list() -> BoxedStrategy<String> {
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

pub(super) fn command_options(cmd: &str) -> Vec<Opt> {
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

pub(super) fn axis() -> BoxedStrategy<String> {
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
pub(super) fn key_name() -> BoxedStrategy<String> {
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

pub(super) fn key_script() -> BoxedStrategy<String> {
    prop::collection::vec(key_name(), 0..24)
        .prop_map(|v| v.join(" "))
        .boxed()
}

/// Chooses a subset of `opts` (each with probability about 1/3) with their values.
pub(super) fn some_of(opts: Vec<Opt>) -> BoxedStrategy<Vec<String>> {
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

pub(super) fn to_case(kind: &'static str, args: Vec<String>) -> Case {
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
pub(super) fn file_case(
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
pub(super) fn cli_case() -> BoxedStrategy<Case> {
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
pub(super) fn preset_case() -> BoxedStrategy<Case> {
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

pub(super) fn measured_arrays() -> BoxedStrategy<String> {
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
pub(super) fn csv_case() -> BoxedStrategy<Case> {
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
pub(super) fn keys_case() -> BoxedStrategy<Case> {
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
