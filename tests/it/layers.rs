//! Layers, of the source and of the settings. The source's layers are folders, each
//! using only those above it (physics → settings → methods → study → lab → the
//! edges): no source file of a layer names a later one, none imports itself through
//! others, no function runs over 100 lines, and no number is put in a unit by hand
//! outside the one unit table. The settings' layers (preset ← command line ← the
//! app's edits) settle into one snapshot (that the same scene reached by flags or by
//! keys draws the same screen is `lab_data`'s test): `u` takes back the last edit, `R`
//! all of them; a preset picked keeps the student's data; data without a scene are one
//! rule for the app, `render`, `compare` and `fit`; `simulate` prints the snapshot the
//! app shows for the same options, and `compare` compares over its span.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use groovelab::cli::{DataArgs, SceneArgs, SimulateArgs, SimulateFormat};
use groovelab::lab::SpanEnd;
use groovelab::methods::Method;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::preset::Preset;
use groovelab::tui::app::{App, Status};
use serde_json::Value;

use crate::common::{self, press, rendered, select, text};

/// The inner layers in order; everything else (`input`, `output`, `signals`, `cli`,
/// `tui`) is an edge and may use them all.
const LAYERS: [&str; 5] = ["physics", "settings", "methods", "study", "lab"];
const EDGES: [&str; 5] = ["input", "output", "signals", "cli", "tui"];

fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn no_layer_uses_a_later_one() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut bad = Vec::new();
    for (rank, layer) in LAYERS.iter().enumerate() {
        let mut files = Vec::new();
        sources(&src.join(layer), &mut files);
        assert!(!files.is_empty(), "{layer}");
        let later = LAYERS[rank + 1..].iter().chain(&EDGES);
        let later: Vec<String> = later.map(|l| format!("crate::{l}::")).collect();
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap();
            for (n, line) in text.lines().enumerate() {
                let code = line.split("//").next().unwrap_or("");
                if let Some(l) = later.iter().find(|l| code.contains(l.as_str())) {
                    bad.push(format!("{}:{}: {l}", file.display(), n + 1));
                }
            }
        }
    }
    assert!(bad.is_empty(), "upward imports:\n{}", bad.join("\n"));
}

/// One token of a source with its comments, strings and characters taken out: a word
/// (an identifier, keyword or lifetime), `::`, or one other character; with its line.
pub(crate) struct Token {
    pub(crate) text: String,
    pub(crate) line: usize,
}

pub(crate) fn tokens(text: &str) -> Vec<Token> {
    let c: Vec<char> = text.chars().collect();
    let word = |ch: char| ch.is_alphanumeric() || ch == '_';
    let (mut out, mut i, mut line) = (Vec::new(), 0, 1);
    while i < c.len() {
        if let Some(end) = skipped_end(&c, i) {
            line += c[i..end].iter().filter(|&&ch| ch == '\n').count();
            i = end;
        } else if word(c[i]) || c[i] == '\'' {
            let start = i;
            i += 1 + c[i + 1..].iter().take_while(|&&ch| word(ch)).count();
            let text = c[start..i].iter().collect();
            out.push(Token { text, line });
        } else {
            let two = c[i] == ':' && c.get(i + 1) == Some(&':');
            if !c[i].is_whitespace() {
                let text = if two { "::".into() } else { c[i].to_string() };
                out.push(Token { text, line });
            }
            line += usize::from(c[i] == '\n');
            i += 1 + usize::from(two);
        }
    }
    out
}

/// Where a comment, a string or a character literal that starts at `i` ends (one past
/// it; a line comment before its newline), if one starts there.
fn skipped_end(c: &[char], i: usize) -> Option<usize> {
    let at = |k: usize| c.get(i + k).copied().unwrap_or(' ');
    let after_word = i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_');
    let find = |from: usize, pattern: &[char]| {
        (from..c.len())
            .find(|&j| c[j..].starts_with(pattern))
            .map_or(c.len(), |j| j + pattern.len())
    };
    let hashes = (1..).take_while(|&k| at(k) == '#').count();
    match (c[i], at(1)) {
        ('/', '/') => Some(find(i, &['\n']) - 1),
        ('/', '*') => Some(find(i + 2, &['*', '/'])),
        ('"', _) => Some(quoted_end(c, i + 1, '"')),
        ('b', '"' | '\'') if !after_word => Some(quoted_end(c, i + 2, at(1))),
        ('r' | 'b', '#' | '"') if !after_word && at(1 + hashes) == '"' => {
            let close: Vec<char> = std::iter::once('"').chain(vec!['#'; hashes]).collect();
            Some(find(i + 2 + hashes, &close))
        }
        ('\'', '\\') => Some(quoted_end(c, i + 1, '\'')),
        ('\'', _) if at(2) == '\'' => Some(i + 3),
        _ => None,
    }
}

/// One past the `quote` that closes a literal whose text starts at `j`.
fn quoted_end(c: &[char], mut j: usize, quote: char) -> usize {
    while j < c.len() {
        match c[j] {
            '\\' => j += 2,
            ch if ch == quote => return j + 1,
            _ => j += 1,
        }
    }
    c.len()
}

/// The module a source file is: `src/tui/app.rs` and `src/tui/app/mod.rs` are `tui::app`.
fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let relative = file.strip_prefix(src).unwrap().with_extension("");
    let mut path: Vec<String> = relative
        .iter()
        .map(|s| s.to_string_lossy().into_owned())
        .collect();
    if matches!(path.last().map(String::as_str), Some("mod" | "lib")) {
        path.pop();
    }
    path
}

/// The file a module path lands in: the deepest existing `a/b.rs` or `a/b/mod.rs` along
/// it (what is left is an item of that file, or an inline module in it).
fn file_of(src: &Path, path: &[String]) -> PathBuf {
    let (mut dir, mut file) = (src.to_path_buf(), src.join("lib.rs"));
    for segment in path {
        let flat = dir.join(format!("{segment}.rs"));
        let folder = dir.join(segment).join("mod.rs");
        file = match (flat.is_file(), folder.is_file()) {
            (true, _) => flat,
            (_, true) => folder,
            _ => break,
        };
        dir = dir.join(segment);
    }
    file
}

/// The inline modules (`mod tests { ... }`) open at each token, and every module declared
/// in the file (`mod x;` or `mod x { ... }`), as paths below the file's module.
fn inline_modules(t: &[Token]) -> (Vec<Vec<String>>, Vec<Vec<String>>) {
    let (mut open, mut declared, mut at) = (Vec::new(), Vec::new(), Vec::new());
    let mut stack: Vec<(String, usize)> = Vec::new();
    let mut depth = 0;
    for (i, token) in t.iter().enumerate() {
        let names = |s: &[(String, usize)]| s.iter().map(|(n, _)| n.clone()).collect();
        at.push(names(&stack));
        match token.text.as_str() {
            "mod" if i + 2 < t.len() => {
                let mut path: Vec<String> = names(&stack);
                path.push(t[i + 1].text.clone());
                if t[i + 2].text == "{" {
                    open.push((t[i + 1].text.clone(), depth + 1));
                }
                declared.push(path);
            }
            "{" => {
                depth += 1;
                if let Some(module) = open.pop() {
                    stack.push(module);
                }
            }
            "}" => {
                if stack.last().is_some_and(|(_, d)| *d == depth) {
                    stack.pop();
                }
                depth -= 1;
            }
            _ => {}
        }
    }
    (at, declared)
}

/// The paths of a `use` tree starting at `i` (after `use`), each whole from its root.
fn use_tree(t: &[Token], i: &mut usize, prefix: Vec<String>, out: &mut Vec<Vec<String>>) {
    let mut path = prefix;
    while *i < t.len() {
        match t[*i].text.as_str() {
            "{" => {
                *i += 1;
                while *i < t.len() && t[*i].text != "}" {
                    use_tree(t, i, path.clone(), out);
                    *i += usize::from(t[*i].text == ",");
                }
                *i += 1;
                return;
            }
            "as" | "*" => {
                *i += if t[*i].text == "as" { 2 } else { 1 };
                break;
            }
            "," | ";" | "}" => break,
            "::" => *i += 1,
            word => {
                path.push(word.to_string());
                *i += 1;
            }
        }
    }
    out.push(path);
}

/// Where a path written in module `here` points from the crate's root, if it starts at
/// the crate (`crate`, `super`, `self`, or a module declared inside `here`).
fn absolute(path: &[String], here: &[String], declared: &[Vec<String>]) -> Option<Vec<String>> {
    let first = path.first()?.as_str();
    let child = [here, &path[..1]].concat();
    let mut whole = match first {
        "crate" => Vec::new(),
        "self" | "super" => here.to_vec(),
        _ if declared.contains(&child) => here.to_vec(),
        _ => return None,
    };
    let skip = usize::from(first == "crate");
    for segment in &path[skip..] {
        match segment.as_str() {
            "super" => drop(whole.pop()),
            "self" => {}
            s => whole.push(s.to_string()),
        }
    }
    Some(whole)
}

/// Each path a source names into the crate: from `use` items and from paths written
/// inline (`crate::a::f(...)`, `super::X`, `child::Y`), with its line, from the crate's root.
fn named_paths(src: &Path, file: &Path) -> Vec<(Vec<String>, usize)> {
    let t = tokens(&std::fs::read_to_string(file).unwrap());
    let module = module_of(src, file);
    let (open, declared) = inline_modules(&t);
    let declared: Vec<Vec<String>> = declared.iter().map(|d| [&module[..], d].concat()).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < t.len() {
        let here = [&module[..], &open[i][..]].concat();
        let (start, mut paths) = (i, Vec::new());
        if t[i].text == "use" {
            i += 1;
            use_tree(&t, &mut i, Vec::new(), &mut paths);
        } else if t.get(i + 1).is_some_and(|n| n.text == "::") && (i == 0 || t[i - 1].text != "::")
        {
            let mut path = vec![t[i].text.clone()];
            while t.get(i + 1).is_some_and(|n| n.text == "::") && i + 2 < t.len() {
                path.push(t[i + 2].text.clone());
                i += 2;
            }
            paths.push(path);
        }
        for path in paths {
            if let Some(whole) = absolute(&path, &here, &declared) {
                out.push((whole, t[start].line));
            }
        }
        i += 1;
    }
    out
}

/// The groups of files that import each other in a loop (strongly connected
/// components of more than one file), by Tarjan's algorithm.
fn circles(edges: &BTreeMap<PathBuf, BTreeSet<PathBuf>>) -> Vec<Vec<PathBuf>> {
    struct Walk<'a> {
        edges: &'a BTreeMap<PathBuf, BTreeSet<PathBuf>>,
        index: BTreeMap<&'a PathBuf, (usize, usize)>,
        stack: Vec<&'a PathBuf>,
        found: Vec<Vec<PathBuf>>,
    }
    fn visit<'a>(w: &mut Walk<'a>, v: &'a PathBuf) {
        let n = w.index.len();
        w.index.insert(v, (n, n));
        w.stack.push(v);
        for u in w.edges.get(v).into_iter().flatten() {
            if !w.index.contains_key(u) {
                visit(w, u);
                let low = w.index[u].1.min(w.index[v].1);
                w.index.get_mut(v).unwrap().1 = low;
            } else if w.stack.contains(&u) {
                let low = w.index[u].0.min(w.index[v].1);
                w.index.get_mut(v).unwrap().1 = low;
            }
        }
        if w.index[v].0 == w.index[v].1 {
            let at = w.stack.iter().rposition(|x| *x == v).unwrap();
            let group: Vec<PathBuf> = w.stack.drain(at..).cloned().collect();
            if group.len() > 1 {
                w.found.push(group);
            }
        }
    }
    let mut w = Walk {
        edges,
        index: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in edges.keys() {
        if !w.index.contains_key(v) {
            visit(&mut w, v);
        }
    }
    w.found
}

/// The library's source files (`main.rs` is another crate: nothing can import it).
pub(crate) fn library_sources() -> (PathBuf, Vec<PathBuf>) {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.retain(|f| f != &src.join("main.rs"));
    files.sort();
    (src, files)
}

#[test]
fn no_source_file_imports_itself_through_others() {
    let (src, files) = library_sources();
    let mut edges: BTreeMap<PathBuf, BTreeSet<PathBuf>> = BTreeMap::new();
    let mut why: BTreeMap<(PathBuf, PathBuf), String> = BTreeMap::new();
    for file in &files {
        let from = file.strip_prefix(&src).unwrap().to_path_buf();
        for (path, line) in named_paths(&src, file) {
            let to = file_of(&src, &path)
                .strip_prefix(&src)
                .unwrap()
                .to_path_buf();
            if to != from {
                edges.entry(from.clone()).or_default().insert(to.clone());
                why.entry((from.clone(), to))
                    .or_insert_with(|| format!("line {line}: {}", path.join("::")));
            }
        }
    }
    assert!(
        edges.len() > 50,
        "the graph was read: {} files",
        edges.len()
    );
    let found = circles(&edges);
    let report: Vec<String> = found
        .iter()
        .map(|group| {
            let ties = group.iter().flat_map(|a| {
                group.iter().filter_map(|b| {
                    let w = why.get(&(a.clone(), b.clone()))?;
                    Some(format!("    {} -> {} ({w})", a.display(), b.display()))
                })
            });
            let names: Vec<String> = group.iter().map(|f| f.display().to_string()).collect();
            format!(
                "  {}\n{}",
                names.join(", "),
                ties.collect::<Vec<_>>().join("\n")
            )
        })
        .collect();
    assert!(found.is_empty(), "import cycles:\n{}", report.join("\n"));
}

/// Each function with a body in a source: its name, and its first and last line (of
/// `fn` and of the closing brace).
fn function_spans(t: &[Token]) -> Vec<(String, usize, usize)> {
    let mut out = Vec::new();
    for i in 0..t.len().saturating_sub(1) {
        let named = t[i + 1]
            .text
            .starts_with(|c: char| c.is_alphabetic() || c == '_');
        if t[i].text != "fn" || !named {
            continue;
        }
        let (mut j, mut nesting) = (i + 2, 0i32);
        while j < t.len() && !(nesting == 0 && matches!(t[j].text.as_str(), "{" | ";")) {
            match t[j].text.as_str() {
                "(" | "[" => nesting += 1,
                ")" | "]" => nesting -= 1,
                _ => {}
            }
            j += 1;
        }
        if j == t.len() || t[j].text == ";" {
            continue;
        }
        let mut depth = 0;
        for token in &t[j..] {
            depth += i32::from(token.text == "{") - i32::from(token.text == "}");
            if depth == 0 {
                out.push((t[i + 1].text.clone(), t[i].line, token.line));
                break;
            }
        }
    }
    out
}

#[test]
fn no_function_is_longer_than_a_hundred_lines() {
    let (src, files) = library_sources();
    let mut long = Vec::new();
    let mut count = 0;
    for file in &files {
        let t = tokens(&std::fs::read_to_string(file).unwrap());
        for (name, first, last) in function_spans(&t) {
            count += 1;
            let lines = last - first + 1;
            if lines > 100 {
                let at = file.strip_prefix(&src).unwrap().display();
                long.push(format!("{at}:{first}: fn {name}, {lines} lines"));
            }
        }
    }
    assert!(count > 500, "the functions were found: {count}");
    assert!(
        long.is_empty(),
        "functions over 100 lines:\n{}",
        long.join("\n")
    );
}

/// Where a source writes a number followed by a unit that is not SI (`{:.2} mm`,
/// `{} cm`): such a number was converted by hand. `(file:line, text)`.
fn hand_written_units(src: &Path, files: &[PathBuf]) -> Vec<String> {
    const NOT_SI: [&str; 6] = ["cm", "mm", "ms", "g", "mg", "µs"];
    let mut found = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(file).unwrap();
        for (i, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            // Each `}` that closes a format argument, then an optional space.
            for (at, _) in line.match_indices('}') {
                let rest = line[at + 1..].strip_prefix(' ').unwrap_or(&line[at + 1..]);
                let word: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == 'µ')
                    .collect();
                if NOT_SI.contains(&word.as_str()) {
                    let at = file.strip_prefix(src).unwrap().display();
                    found.push(format!("{at}:{}: {}", i + 1, line.trim()));
                }
            }
        }
    }
    found
}

#[test]
fn display_units_are_written_once_in_the_unit_table() {
    let (src, mut files) = library_sources();
    // The one table (its own tests write what it prints).
    files.retain(|f| !f.ends_with("settings/units.rs"));
    let found = hand_written_units(&src, &files);
    assert!(
        found.is_empty(),
        "numbers converted to a unit by hand (use units::show or show_small):\n{}",
        found.join("\n")
    );
    // The scan sees what it looks for.
    let dir = std::env::temp_dir().join(format!("groovelab-units-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.rs");
    std::fs::write(
        &bad,
        "let a = format!(\"{:.2} mm\", 1e3 * x);\n// {} cm in a comment\nlet b = format!(\"{}cm/s\", v);\nlet c = format!(\"{} m/s, {} s\", v, t);\n",
    )
    .unwrap();
    let seen = hand_written_units(&dir, &[bad]);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(seen.len(), 2, "{seen:?}");
}

const TRACK: &str = "docs/video/paper-b4.9-tracker.txt";

fn library() -> groovelab::tui::app::Library {
    common::no_user_presets("layers")
}

fn scene(values: SceneSpec) -> SceneArgs {
    SceneArgs {
        preset: Some("paper-b4.9".into()),
        values,
    }
}

fn data(files: &[PathBuf]) -> DataArgs {
    DataArgs {
        data: files.to_vec(),
        ..DataArgs::default()
    }
}

#[test]
fn u_undoes_the_last_change_and_r_resets_all_to_the_preset() {
    let mut a = common::app("paper-b4.9", library());
    let fresh = a.lab.scene;
    let (b, end) = (a.lab.value(Key::Width), a.lab.span_end);
    press(&mut a, "u");
    assert_eq!(a.status, Status::Info("nothing to undo".into()));
    press(&mut a, "left");
    press(&mut a, "down down down enter 0 . 3 enter");
    assert_eq!(a.lab.scene.mu, 0.3);
    assert!(a.lab.value(Key::Width) < b);
    press(&mut a, "u");
    assert_eq!(a.lab.scene.mu, fresh.mu, "μ_k back");
    assert!(a.lab.value(Key::Width) < b, "b still changed");
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("undone: μ_k = 0.17 ")),
        "{:?}",
        a.status
    );
    // As the parameter row writes it: μ_k, and mu_k on an ASCII screen.
    assert!(text(&a, (120, 40), true).contains("undone: mu_k = 0.17 "));
    press(&mut a, "u");
    assert_eq!(a.lab.scene, fresh, "exactly the preset's scene again");
    // The span key is an edit too; R drops every edit.
    press(&mut a, "t right right");
    let (changed, spanned) = (a.lab.scene, a.lab.span_end);
    assert_ne!(spanned, end);
    press(&mut a, "R");
    assert_eq!((a.lab.scene, a.lab.span_end), (fresh, end));
    assert_eq!(
        a.status,
        Status::Info("reset to preset paper-b4.9 (u undoes it)".into())
    );
    press(&mut a, "R");
    assert_eq!(
        a.status,
        Status::Info("nothing to reset: the scene is the preset's".into()),
        "a second R adds nothing to undo"
    );
    // A reset pressed by accident loses nothing: u brings every change back.
    press(&mut a, "u");
    assert_eq!((a.lab.scene, a.lab.span_end), (changed, spanned));
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("undone: the reset")),
        "{:?}",
        a.status
    );
    // ... and the changes before it are undone one by one again: two steps of b
    // (the selected row), then the span key.
    press(&mut a, "u u");
    assert_eq!(a.lab.span_end, spanned);
    assert_eq!(a.lab.scene, fresh);
    press(&mut a, "u");
    assert_eq!(a.lab.span_end, end);
    press(&mut a, "u");
    assert_eq!(a.status, Status::Info("nothing to undo".into()));
}

#[test]
fn a_repeat_that_changes_nothing_adds_no_undo_step() {
    // Seen: `a` pressed twice made two undo steps for one change. A fit applied is no
    // change when it is in the scene already; the fit of the scene just applied is a
    // new fit (its candidate models are compared on the frames they all keep, which
    // move with the scene), within its ± of the one applied.
    let mut a = rendered(
        &scene(SceneSpec::default()),
        &data(&[]),
        None,
        Some("f a"),
        library(),
    );
    let fitted = a.lab.scene.mu;
    assert_ne!(fitted, 0.17, "the fit moved μ_k");
    assert_eq!(a.lab.settings().edits().len(), 1);
    let groovelab::lab::jobs::State::Ready(Ok(f)) = a.fit().fits() else {
        panic!("the refit")
    };
    let (refit, se) = (f.model_fit.mu, f.model_fit.mu_se);
    assert!(
        (refit - fitted).abs() < se,
        "{refit} ± {se} against {fitted}"
    );
    press(&mut a, "a");
    a.wait();
    let steps = a.lab.settings().edits().len();
    press(&mut a, "a");
    assert_eq!(a.lab.settings().edits().len(), steps, "a repeat is no step");
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("the fit is in the scene already: μ_k = ")),
        "{:?}",
        a.status
    );
    for _ in 0..steps {
        press(&mut a, "u");
    }
    assert_eq!(a.lab.scene.mu, 0.17, "u takes the fits back");
    // The same typed value, and the span key's choice again, are no change either.
    select(&mut a, Key::Width);
    press(&mut a, "enter 4 . 9 enter");
    assert_eq!(a.status, Status::Info("b = 4.9 cm (unchanged)".into()));
    assert!(a.lab.settings().edits().is_empty());
    press(&mut a, "right enter 4 . 9 enter");
    assert_eq!(a.lab.settings().edits().len(), 2, "a real change is a step");
}

#[test]
fn undo_reaches_a_span_set_with_t_end_and_keeps_the_command_lines_values() {
    let values = SceneSpec::default().with(Key::Width, 0.044);
    let mut a = rendered(&scene(values), &data(&[]), None, None, library());
    assert_eq!(a.lab.scene.width, 0.044);
    a.lab.set(Key::TEnd, 0.7).unwrap();
    assert!(matches!(a.lab.span_end, SpanEnd::Fixed { t_end: 0.7, .. }));
    press(&mut a, "right");
    press(&mut a, "R");
    assert_eq!(a.lab.scene.width, 0.044, "the command line's b stays");
    assert_eq!(a.lab.span_end, SpanEnd::Auto);
    assert_eq!(
        a.status,
        Status::Info(
            "reset to preset paper-b4.9 with the command line's values (u undoes it)".into()
        )
    );
}

#[test]
fn a_preset_picked_keeps_the_students_data_until_d_drops_them() {
    let d = data(&[PathBuf::from(TRACK)]);
    let mut a = rendered(&scene(SceneSpec::default()), &d, None, None, library());
    assert!(a.lab.measured().unwrap().x.is_some(), "a position track");
    // The picker opens on paper-b4.9; the one above it is paper-b4.4.
    press(&mut a, "p up enter");
    assert_eq!(a.lab.preset().name, "paper-b4.4");
    assert!(a.lab.measured().unwrap().x.is_some(), "still the track");
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("your data") && s.contains("kept")),
        "{:?}",
        a.status
    );
    press(&mut a, "D");
    let m = a.lab.measured().unwrap();
    assert!(m.x.is_none(), "the preset's own velocities");
    assert_eq!(m.t, a.lab.preset().measured.as_ref().unwrap().t);
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("dropped ")),
        "{:?}",
        a.status
    );
    press(&mut a, "D");
    assert!(matches!(&a.status, Status::Info(s) if s.starts_with("no data of your own")));
}

#[test]
fn the_methods_views_work_axis_moved_to_capital_x() {
    let mut a = common::app("paper-b4.9", library());
    let axis = a.methods_state().axis();
    press(&mut a, "X");
    assert_ne!(a.methods_state().axis(), axis);
}

#[test]
fn data_without_a_scene_one_rule_for_the_app_render_and_fit() {
    let unnamed = SceneArgs::default();
    let d = data(&[PathBuf::from(TRACK)]);
    let a = rendered(&unnamed, &d, None, None, library());
    let Status::Error(message) = &a.status else {
        panic!("{:?}", a.status)
    };
    assert!(
        message == "the data name no scene: using R = 2.75 cm, b = 4.9 cm; set yours",
        "{message}"
    );
    // `render` prints what the app shows; `fit` refuses.
    let out = common::groovelab(&["render", "--data", TRACK, "--size", "160x40"]);
    let screen = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success()
            && screen.contains("name no scene")
            && screen.contains("data: docs/video/paper-b4.9-tracker.txt"),
        "{screen}"
    );
    let out = common::groovelab(&["fit", "--data", TRACK]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(err.contains("names no scene"), "{err}");
    // With the scene named, nothing is asked.
    let b = rendered(&scene(SceneSpec::default()), &d, None, None, library());
    assert_eq!(b.status, Status::None);
}

#[test]
fn pinning_keeps_the_snapshots_analyses_and_an_edit_starts_them_over() {
    let (mut a, counted) = common::counted("paper-b4.9", library());
    press(&mut a, "f");
    a.wait();
    let runs = counted.get();
    assert!(runs > 0, "the Fit view's fits ran");
    // Pinning leaves the scene, its span and its data as they were: nothing again.
    press(&mut a, "P");
    a.wait();
    press(&mut a, "P");
    a.wait();
    assert_eq!(counted.get(), runs);
    // An edit is a new scene: the fits run again (and again for its undo).
    press(&mut a, "right");
    a.wait();
    let edited = counted.get();
    assert!(edited > runs, "{edited} after {runs}");
    press(&mut a, "u");
    a.wait();
    assert!(counted.get() > edited);
}

/// `simulate` on these options, in `format`.
fn simulate(scene: &SceneArgs, format: SimulateFormat) -> String {
    let args = SimulateArgs {
        format,
        sample: None,
        method: Method::Exact,
        dt: None,
        tol: None,
        epsilon: None,
        output: None,
    };
    groovelab::cli::simulate(scene, &args).unwrap()
}

#[test]
fn simulate_prints_the_apps_snapshot_of_the_same_scene_by_flags_or_keys() {
    let mut cases: Vec<SceneArgs> = groovelab::input::preset::all()
        .0
        .iter()
        .map(|p| common::scene_of(&p.name, SceneSpec::default()))
        .collect();
    let b_flag = cases.len();
    cases.push(scene(SceneSpec::default().with(Key::Width, 0.04)));
    cases.push(common::scene_of(
        "paper-b3.5",
        SceneSpec::default().with(Key::Mu, 0.1),
    ));
    cases.push(common::scene_of(
        "critical",
        SceneSpec::default().with(Key::TEnd, 0.5),
    ));
    let mut apps: Vec<(&SceneArgs, App)> = cases
        .iter()
        .map(|args| (args, rendered(args, &data(&[]), None, None, library())))
        .collect();
    // The same scene reached by keys in the app: b typed as 4 cm on paper-b4.9.
    let mut keyed = common::app("paper-b4.9", library());
    press(&mut keyed, "enter 4 enter");
    assert_eq!(keyed.lab.scene.width, 0.04);
    apps.push((&cases[b_flag], keyed));
    for (args, app) in &apps {
        let now = &app.lab;
        let json: Value = serde_json::from_str(&simulate(args, SimulateFormat::Json)).unwrap();
        let name = args.preset.as_deref().unwrap();
        // The same span (a preset's data reach past the motion: paper-b3.5's to 0.64 s),
        // hence the same final state and the same events.
        let same = |at: &Value, x: f64| {
            // The printed number read back: within an ulp or two (serde_json's parse
            // need not round-trip the last bit).
            let y = at.as_f64().unwrap();
            assert!(
                (y - x).abs() <= 4.0 * f64::EPSILON * x.abs(),
                "{name}: {y} vs {x}"
            );
        };
        same(&json["span"]["t_start"], now.span.t_start);
        same(&json["span"]["t_end"], now.solution.t_end);
        let last = now.solution.at(now.solution.t_end);
        same(&json["final"]["left"]["x"], last.left.x);
        same(&json["final"]["right"]["v"], last.right.v);
        let events = json["events"].as_array().unwrap().len();
        assert_eq!(events, now.solution.visible_events().count(), "{name}");
        // The table's story is the snapshot's: its verdict against the same rest band.
        let table = simulate(args, SimulateFormat::Table);
        let verdict = table.lines().find_map(|l| l.strip_prefix("verdict  "));
        assert_eq!(
            verdict.map(str::to_string),
            now.rest_band.map(|_| now.story.verdict.text("±")),
            "{name}"
        );
    }
}

/// `compare --methods exact --format json` on `scene` and `data`, in-process (the
/// exact engine alone: a few solves, cheap).
fn compare_exact(scene: &SceneArgs, data: &DataArgs) -> Value {
    let mut args: Vec<String> = [
        "groovelab",
        "compare",
        "--methods",
        "exact",
        "--format",
        "json",
    ]
    .map(String::from)
    .to_vec();
    if let Some(p) = &scene.preset {
        args.extend(["--preset".into(), p.clone()]);
    }
    for (key, value) in scene.values.given() {
        // SI values with no unit are read in SI.
        args.extend([format!("--{}", key.param().flag), format!("{value}")]);
    }
    for file in &data.data {
        args.extend(["--data".into(), file.display().to_string()]);
    }
    let out = groovelab::cli::entry::main_with(&args.iter().map(Into::into).collect::<Vec<_>>());
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    serde_json::from_str(&out.stdout).unwrap()
}

#[test]
fn compare_compares_over_the_span_the_methods_view_does() {
    // Every built-in preset, a scene by flags alone (the default preset under them),
    // and a velocity file whose last point (0.64 s) lies past the critical scene's
    // motion (it ends at about 0.33 s).
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut cases: Vec<(SceneArgs, DataArgs)> = Preset::built_in()
        .iter()
        .map(|p| (common::scene_of(&p.name, SceneSpec::default()), data(&[])))
        .collect();
    cases.push((
        SceneArgs {
            preset: None,
            values: SceneSpec::default().with(Key::Width, 0.035),
        },
        data(&[]),
    ));
    cases.push((
        common::scene_of("critical", SceneSpec::default()),
        data(&[root.join("data/gs-b3.5cm.csv")]),
    ));
    let mut past_the_motion = 0;
    for (scene, files) in &cases {
        // The Methods view's rows are computed over the app's snapshot's span.
        let app = rendered(scene, files, None, None, library());
        let now = &app.lab;
        let json = compare_exact(scene, files);
        let name = format!("{:?} {:?}", scene.preset, files.data);
        let read = |v: &Value| v.as_f64().unwrap();
        let (t0, t1) = (read(&json["span"]["t_start"]), read(&json["span"]["t_end"]));
        // The printed number read back: within an ulp or two.
        assert!(
            (t0 - now.span.t_start).abs() <= 4.0 * f64::EPSILON,
            "{name}: {t0}"
        );
        let end = now.span.t_end.unwrap();
        assert!(
            (t1 - end).abs() <= 4.0 * f64::EPSILON * end,
            "{name}: {t1} vs {end}"
        );
        // The exact row is the reference itself: no error at all.
        let exact = &json["rows"][0];
        assert_eq!(exact["method"], "exact", "{name}");
        for err in ["err_v", "err_u", "err_final"] {
            assert_eq!(read(&exact[err]), 0.0, "{name}: {err}");
        }
        let auto = groovelab::physics::scene::Span {
            t_end: None,
            ..now.span
        };
        let motion = groovelab::physics::engine::solve(&now.scene, &auto).t_end;
        if end > motion + 1e-9 {
            past_the_motion += 1;
        }
    }
    // Measured series that reach past the motion are what this is about: paper-b3.5's
    // own and the file on the critical scene at least.
    assert!(past_the_motion >= 2, "{past_the_motion}");
}

#[test]
fn u_after_picking_a_preset_brings_back_the_preset_its_edits_and_data() {
    // The command line's b and two edits on paper-b4.9 with its own data.
    let flags = SceneSpec::default().with(Key::Width, 0.046);
    let mut a = rendered(&scene(flags), &data(&[]), None, None, library());
    let fresh = a.lab.scene;
    press(&mut a, "left");
    press(&mut a, "down down down enter 0 . 3 enter");
    let edited = (a.lab.scene, a.lab.span_end);
    let b49_data = a.lab.measured().unwrap().t.clone();
    // The picker opens on paper-b4.9; the one above it is paper-b4.4.
    press(&mut a, "p up enter");
    let b44 = groovelab::input::preset::load("paper-b4.4").unwrap();
    assert_eq!(a.lab.preset().name, "paper-b4.4");
    assert_eq!(a.lab.value(Key::Width), 0.044, "the preset alone: no flag");
    assert_eq!(
        a.lab.measured().unwrap().t,
        b44.measured.as_ref().unwrap().t
    );
    // An edit on the picked preset, and a reset to it, are undone first.
    press(&mut a, "right R");
    assert_eq!(
        a.status,
        Status::Info("reset to preset paper-b4.4 (u undoes it)".into()),
        "the command line's values are not in force after a pick"
    );
    press(&mut a, "u u");
    assert_eq!(a.lab.preset().name, "paper-b4.4");
    assert_eq!(a.lab.value(Key::Width), 0.044);
    // Then the pick: the preset before, its edits and its data.
    press(&mut a, "u");
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("undone: preset paper-b4.4: back to paper-b4.9")),
        "{:?}",
        a.status
    );
    assert_eq!(a.lab.preset().name, "paper-b4.9");
    assert_eq!((a.lab.scene, a.lab.span_end), edited);
    assert_eq!(a.lab.measured().unwrap().t, b49_data);
    // The older steps survive: μ_k, then b, then nothing.
    press(&mut a, "u u");
    assert_eq!(a.lab.scene, fresh);
    assert_eq!(a.lab.value(Key::Width), 0.046, "the command line's b again");
    press(&mut a, "u");
    assert_eq!(a.status, Status::Info("nothing to undo".into()));
}

#[test]
fn u_after_picking_a_preset_keeps_the_students_data() {
    let d = data(&[PathBuf::from(TRACK)]);
    let mut a = rendered(&scene(SceneSpec::default()), &d, None, None, library());
    let before = a.lab.scene;
    press(&mut a, "p up enter u");
    assert_eq!(a.lab.preset().name, "paper-b4.9");
    assert_eq!(a.lab.scene, before);
    assert!(a.lab.measured().unwrap().x.is_some(), "still the track");
    assert_eq!(a.lab.own_data().unwrap().name, TRACK);
}
