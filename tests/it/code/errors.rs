//! Typed errors to the edge: no function of `src/` returns `Result<_, String>`, and no
//! error type carries its message as a `String`. A struct named `…Error` has no
//! `String` field at all (its file is a `PathBuf`, its problem an enum); no error type
//! (named `…Error`, or deriving `Error`) has a `String` tuple field (`Other(String)`) or
//! a `String` field named like a sentence (`what`, `why`, `message`, …). What a user
//! typed or a file holds may be a named field of a named variant (`cell: String`): the
//! value, not a sentence about it. The sentence is made by `Display`, where it is
//! printed.

use crate::code::layers::{Token, library_sources, tokens};

/// Field names that say a `String` holds a sentence rather than a value.
const SENTENCES: [&str; 11] = [
    "what",
    "why",
    "message",
    "msg",
    "reason",
    "detail",
    "details",
    "error",
    "cause",
    "description",
    "note",
];

/// One past the bracket that closes the one opened at `open`: `(`, `[` or `{` (any
/// of them nest inside), or `<` (only angle brackets count; `->` is an arrow).
fn closing(t: &[Token], open: usize) -> usize {
    let angle = t[open].text == "<";
    let (mut depth, mut i) = (0i32, open);
    while i < t.len() {
        let arrow = i > 0 && t[i - 1].text == "-";
        match (t[i].text.as_str(), angle) {
            ("(" | "[" | "{", false) | ("<", true) => depth += 1,
            (")" | "]" | "}", false) => depth -= 1,
            (">", true) if !arrow => depth -= 1,
            _ => {}
        }
        i += 1;
        if depth == 0 {
            break;
        }
    }
    i
}

/// The top-level comma-separated parts of the tokens between `open` and its closing
/// bracket.
fn parts(t: &[Token], open: usize) -> Vec<(usize, usize)> {
    let end = closing(t, open) - 1;
    let (mut out, mut start, mut i) = (Vec::new(), open + 1, open + 1);
    while i < end {
        match t[i].text.as_str() {
            "(" | "[" | "{" | "<" => i = closing(t, i),
            "#" => i = closing(t, i + 1),
            "," => {
                out.push((start, i));
                start = i + 1;
                i += 1;
            }
            _ => i += 1,
        }
    }
    if start < end {
        out.push((start, end));
    }
    out
}

fn text(t: &[Token], (a, b): (usize, usize)) -> String {
    t[a..b].iter().map(|x| x.text.as_str()).collect()
}

/// True when a type's tokens are `String` (or an `Option` of it).
fn is_string(t: &[Token], span: (usize, usize)) -> bool {
    let s = text(t, span);
    let s = s.strip_prefix("pub(crate)").unwrap_or(&s);
    let s = s.strip_prefix("pub(super)").unwrap_or(s);
    let s = s.strip_prefix("pub").unwrap_or(s);
    matches!(
        s,
        "String" | "std::string::String" | "Option<String>" | "Box<str>"
    )
}

/// A span without its leading attributes (`#[…]`, doc comments are gone already).
fn without_attributes(t: &[Token], (mut a, b): (usize, usize)) -> (usize, usize) {
    while a < b && t[a].text == "#" {
        a = closing(t, a + 1);
    }
    (a, b)
}

/// What is wrong with the fields in `fields` (named `name: Type` when `named`, else
/// tuple types) of the error type `owner`; `strict`: no `String` at all.
fn field_faults(t: &[Token], open: usize, owner: &str, strict: bool, out: &mut Vec<String>) {
    let named = t[open].text == "{";
    for part in parts(t, open) {
        let (a, b) = without_attributes(t, part);
        let (name, ty) = if named {
            let Some(colon) = (a..b).find(|&i| t[i].text == ":") else {
                continue;
            };
            (t[colon - 1].text.clone(), (colon + 1, b))
        } else {
            (String::new(), (a, b))
        };
        if is_string(t, ty) && (strict || !named || SENTENCES.contains(&name.as_str())) {
            let field = if named { name } else { "(String)".into() };
            out.push(format!("line {}: {owner} {field}", t[a].line));
        }
    }
}

/// The error types of a source that carry a message as a `String`, and its
/// `Result<_, String>`s, each with its line.
fn faults(source: &str) -> (Vec<String>, usize) {
    let t = tokens(source);
    let (mut out, mut errors, mut derives_error) = (Vec::new(), 0, false);
    let mut i = 0;
    while i < t.len() {
        let word = t[i].text.as_str();
        if word == "#" && t.get(i + 1).is_some_and(|n| n.text == "[") {
            let end = closing(&t, i + 1);
            let attr = &t[i + 2..end - 1];
            if attr.first().is_some_and(|a| a.text == "derive") {
                derives_error |= attr.iter().any(|a| a.text == "Error");
            }
            i = end;
            continue;
        }
        if word == "Result" && t.get(i + 1).is_some_and(|n| n.text == "<") {
            let args = parts(&t, i + 1);
            if args.len() == 2 && is_string(&t, args[1]) {
                out.push(format!("line {}: Result<_, String>", t[i].line));
            }
        }
        if matches!(word, "struct" | "enum") && i + 1 < t.len() {
            let name = t[i + 1].text.clone();
            let named_error = name.ends_with("Error");
            let error = named_error || derives_error;
            let mut j = i + 2;
            if t.get(j).is_some_and(|n| n.text == "<") {
                j = closing(&t, j);
            }
            if error && j < t.len() && matches!(t[j].text.as_str(), "{" | "(") {
                errors += 1;
                if word == "struct" {
                    field_faults(&t, j, &name, named_error, &mut out);
                } else {
                    for variant in parts(&t, j) {
                        let (a, b) = without_attributes(&t, variant);
                        if a + 1 < b && matches!(t[a + 1].text.as_str(), "{" | "(") {
                            let owner = format!("{name}::{}", t[a].text);
                            field_faults(&t, a + 1, &owner, false, &mut out);
                        }
                    }
                }
            }
        }
        if matches!(word, "{" | "}" | ";") {
            derives_error = false;
        }
        i += 1;
    }
    (out, errors)
}

#[test]
fn errors_are_typed_values_not_strings() {
    let (src, files) = library_sources();
    let (mut bad, mut errors) = (Vec::new(), 0);
    for file in &files {
        let (found, n) = faults(&std::fs::read_to_string(file).unwrap());
        errors += n;
        let at = file.strip_prefix(&src).unwrap().display().to_string();
        bad.extend(found.into_iter().map(|f| format!("{at} {f}")));
    }
    assert!(errors > 30, "the scan found the error types: {errors}");
    assert!(
        bad.is_empty(),
        "errors carrying strings (make the values fields of a thiserror enum, the sentence its #[error]):\n{}",
        bad.join("\n")
    );
}

#[test]
fn the_scan_sees_string_errors_and_lets_values_be() {
    let text = r#"
        fn a() -> Result<u8, String> { Ok(1) }
        fn b() -> Result<Vec<(u8, String)>, std::io::Error> { todo!() }
        type C = Result<(), String>;
        pub struct FileError { pub path: String, why: Why }
        #[derive(Debug, thiserror::Error)]
        #[error("{0}")]
        pub struct Damaged(String);
        #[derive(Debug, thiserror::Error)]
        pub enum SceneError {
            #[error("bad {value}: {} <{x}>", if *x { "a" } else { "b" })]
            OutOfRange { value: String, x: bool },
            #[error("{0}")]
            Other(String),
            #[error("{what}")]
            Data { line: usize, what: Option<String> },
            Plain,
        }
        struct Fine { what: String }
        fn d() -> impl Fn(u8) -> Result<u8, Box<dyn std::error::Error>> { todo!() }
        const S: &str = "Result<u8, String>";
    "#;
    let (found, errors) = faults(text);
    let lines: Vec<&str> = found
        .iter()
        .map(|f| f.split_once(": ").unwrap().1)
        .collect();
    assert_eq!(
        lines,
        [
            "Result<_, String>",
            "Result<_, String>",
            "FileError path",
            "Damaged (String)",
            "SceneError::Other (String)",
            "SceneError::Data what",
        ]
    );
    assert_eq!(errors, 3);
}
