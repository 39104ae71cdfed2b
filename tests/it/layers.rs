//! The layers are folders, each using only those above it (physics → settings →
//! methods → study → lab → the edges): no source file of a layer names a later one.

use std::path::Path;

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
