//! Layers of the source: folders, each using only those above it (physics → settings →
//! methods → vision → study → lab → the edges): no source file of a layer names a later
//! one, none imports itself through others, no two folders import each other, `output`
//! needs nothing from `input`, no function runs over 100 lines, and no number is put in
//! a unit by hand outside the one unit table.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The inner layers in order; everything else (`input`, `output`, `signals`, `cli`,
/// `tui`) is an edge and may use them all.
const LAYERS: [&str; 6] = ["physics", "settings", "methods", "vision", "study", "lab"];

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

/// The edges use the inner layers, and `output` (the one file writer) none of the
/// other edges: what a writer needs to name a file's kind lives with it.
#[test]
fn output_uses_no_other_edge() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let text = std::fs::read_to_string(src.join("output.rs")).unwrap();
    let bad: Vec<&str> = text
        .lines()
        .filter(|line| {
            let code = line.split("//").next().unwrap_or("");
            ["input", "cli", "tui"]
                .iter()
                .any(|e| code.contains(&format!("crate::{e}::")))
        })
        .collect();
    assert!(
        bad.is_empty(),
        "output.rs uses another edge:\n{}",
        bad.join("\n")
    );
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
                    let before = *i;
                    use_tree(t, i, path.clone(), out);
                    // A token no tree takes (a `;` in braces: no use tree) is passed.
                    *i += usize::from(*i == before || t.get(*i).is_some_and(|n| n.text == ","));
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
        // `use<…>` bounds a return type's captures (`impl Fn() + use<>`): no import.
        if t[i].text == "use" && t.get(i + 1).is_none_or(|n| n.text != "<") {
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

/// Each import of `file`: the source file it names (relative to `src`), its line and
/// its path as written.
fn imports_of(src: &Path, file: &Path) -> Vec<(PathBuf, usize, String)> {
    named_paths(src, file)
        .into_iter()
        .map(|(path, line)| {
            let to = file_of(src, &path).strip_prefix(src).unwrap().to_path_buf();
            (to, line, path.join("::"))
        })
        .collect()
}

/// The paths a file of `text` at `src/a/b.rs` names, read as the scans read them.
fn paths_in(text: &str) -> Vec<Vec<String>> {
    let dir = crate::common::scratch_dir("code_layers", "paths_in");
    let file = dir.join("src/a/b.rs");
    std::fs::create_dir_all(file.parent().unwrap()).unwrap();
    std::fs::write(&file, text).unwrap();
    named_paths(&dir.join("src"), &file)
        .into_iter()
        .map(|(p, _)| p)
        .collect()
}

/// A return type's `use<>` (precise capturing) is read as no import, and the scan
/// ends: it once took it for a use tree and looped on the body's `;`, filling the
/// memory.
#[test]
fn a_use_bound_in_a_return_type_is_no_import() {
    let found = paths_in(
        "use crate::x::y;\nfn f() -> impl Fn(f64) -> f64 + use<> { let a = 1; move |x| x }\n",
    );
    assert_eq!(found, vec![vec!["x".to_string(), "y".to_string()]]);
}

#[test]
fn no_source_file_imports_itself_through_others() {
    let (src, files) = library_sources();
    let mut edges: BTreeMap<PathBuf, BTreeSet<PathBuf>> = BTreeMap::new();
    let mut why: BTreeMap<(PathBuf, PathBuf), String> = BTreeMap::new();
    for file in &files {
        let from = file.strip_prefix(&src).unwrap().to_path_buf();
        for (to, line, path) in imports_of(&src, file) {
            if to != from {
                edges.entry(from.clone()).or_default().insert(to.clone());
                why.entry((from.clone(), to))
                    .or_insert_with(|| format!("line {line}: {path}"));
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

/// No two sibling modules (folders or files of one folder) import each other: a pair
/// that does is one module in two places, and neither can be read, tested or moved
/// without the other (`study/measured` and `study/fit` once did).
#[test]
fn no_two_modules_import_each_other() {
    let (src, files) = library_sources();
    // The sibling modules a file's import runs between: where the two paths part,
    // each side's component named as a module (`fit.rs` and `fit/` are one).
    let module = |c: &std::path::Component| {
        let name = c.as_os_str().to_string_lossy();
        name.strip_suffix(".rs").unwrap_or(&name).to_string()
    };
    let mut pairs: BTreeMap<(String, String), String> = BTreeMap::new();
    // A module's own tests (`tests.rs`) may use its siblings to check it against them.
    for file in files.iter().filter(|f| !f.ends_with("tests.rs")) {
        let from = file.strip_prefix(&src).unwrap().to_path_buf();
        for (to, line, path) in imports_of(&src, file) {
            let (a, b): (Vec<_>, Vec<_>) = (from.components().collect(), to.components().collect());
            let shared = a
                .iter()
                .zip(&b)
                .take_while(|(x, y)| module(x) == module(y))
                .count();
            let (Some(x), Some(y)) = (a.get(shared), b.get(shared)) else {
                continue;
            };
            let parent: Vec<String> = a[..shared].iter().map(&module).collect();
            let name = |c| [&parent[..], &[module(c)]].concat().join("/");
            let (x, y) = (name(x), name(y));
            if x == "mod" || y == "mod" || x.ends_with("/mod") || y.ends_with("/mod") {
                continue;
            }
            pairs
                .entry((x, y))
                .or_insert_with(|| format!("{}:{line}: {path}", from.display()));
        }
    }
    let both: Vec<String> = pairs
        .iter()
        .filter(|((x, y), _)| x < y && pairs.contains_key(&(y.clone(), x.clone())))
        .map(|((x, y), why)| {
            format!(
                "  {x} <-> {y} ({why}; back: {})",
                pairs[&(y.clone(), x.clone())]
            )
        })
        .collect();
    assert!(
        both.is_empty(),
        "modules importing each other:\n{}",
        both.join("\n")
    );
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
    let dir = crate::common::scratch_dir("code", "units-scan");
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
