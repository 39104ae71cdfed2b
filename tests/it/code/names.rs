//! One name, one thing: no struct, enum, trait or type alias name is defined twice in
//! `src/` (in two modules, or twice in one), so a name read anywhere means one type.
//! An associated type (`type Target = …` in an `impl` or a trait) names the trait's
//! slot, not a type of ours, and is not counted.

use std::collections::BTreeMap;

use crate::code::layers::{library_sources, tokens};

/// Every type name a source defines, with its line: the word after `struct`, `enum`,
/// `trait` or `type`, except a `type` directly inside an `impl` or trait block.
fn defined_types(text: &str) -> Vec<(String, usize)> {
    let t = tokens(text);
    let mut out = Vec::new();
    // Per open brace: whether it opened an impl or trait body. The item a brace opens
    // is named by the first item keyword since the last `;`, `{` or `}`.
    let (mut blocks, mut item): (Vec<bool>, Option<&str>) = (Vec::new(), None);
    for (i, token) in t.iter().enumerate() {
        match token.text.as_str() {
            "{" => {
                blocks.push(matches!(item, Some("impl" | "trait")));
                item = None;
            }
            "}" => {
                blocks.pop();
                item = None;
            }
            ";" => item = None,
            word @ ("fn" | "impl" | "trait" | "mod" | "struct" | "enum" | "type") => {
                item = item.or(Some(word));
                let in_impl = blocks.last().copied().unwrap_or(false);
                let named = t
                    .get(i + 1)
                    .filter(|n| n.text.starts_with(char::is_uppercase));
                let counted = matches!(word, "struct" | "enum" | "trait" | "type")
                    && !(word == "type" && in_impl);
                if let (true, Some(name)) = (counted, named) {
                    out.push((name.text.clone(), token.line));
                }
            }
            _ => {}
        }
    }
    out
}

#[test]
fn no_type_name_is_defined_twice() {
    let (src, files) = library_sources();
    let mut main = files.clone();
    main.push(src.join("main.rs"));
    let mut places: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for file in &main {
        let text = std::fs::read_to_string(file).unwrap();
        let at = file.strip_prefix(&src).unwrap().display().to_string();
        for (name, line) in defined_types(&text) {
            places.entry(name).or_default().push(format!("{at}:{line}"));
        }
    }
    assert!(
        places.len() > 100,
        "the scan found the types: {}",
        places.len()
    );
    let twice: Vec<String> = places
        .iter()
        .filter(|(_, at)| at.len() > 1)
        .map(|(name, at)| format!("{name}: {}", at.join(", ")))
        .collect();
    assert!(
        twice.is_empty(),
        "type names defined twice:\n{}",
        twice.join("\n")
    );
}

#[test]
fn the_scan_sees_what_it_should_and_skips_associated_types() {
    let text = r#"
        pub struct A { x: u8 }
        enum B { One }
        pub(crate) type C = u8;
        trait D { type Out; fn f(&self) -> impl Fn() { || {} } }
        impl std::ops::Deref for A { type Target = u8; fn deref(&self) -> &u8 { &self.x } }
        fn g() -> impl Iterator<Item = u8> { struct E; std::iter::empty() }
        const S: &str = "struct F";
    "#;
    let names: Vec<String> = defined_types(text).into_iter().map(|(n, _)| n).collect();
    assert_eq!(names, ["A", "B", "C", "D", "E"]);
}
