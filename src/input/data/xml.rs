//! The XML files of video tools (Tracker's `.trk`, Logger Pro's `.cmbl`), parsed with
//! `roxmltree`: no DTD (so no entities to expand: a "billion laughs" file is refused
//! at once), a bound on the nodes (memory), and an iterative parser (a deeply nested
//! file cannot overflow the stack). The file's size is bounded before it is read.

use roxmltree::{Document, Node, ParsingOptions};

/// Most XML nodes a data file may have: a Tracker project of 100,000 frames has
/// about 1.5 million; each node costs roughly a hundred bytes.
const MAX_NODES: u32 = 4_000_000;

/// The text of a video tool's XML file as a tree, or why it is not one (one line).
pub(super) fn parse<'i>(text: &'i str, what: &str) -> Result<Document<'i>, String> {
    let options = ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_NODES,
        ..ParsingOptions::default()
    };
    Document::parse_with_options(text, options).map_err(|e| match e {
        roxmltree::Error::DtdDetected => format!(
            "not a {what}: it declares a DTD (entities), which {what}s never have; refused unread"
        ),
        roxmltree::Error::NodesLimitReached => {
            format!("not a {what}: more than {MAX_NODES} XML nodes, far beyond any real recording")
        }
        e => format!("not a readable {what}: {e}"),
    })
}

/// The first child element of `node` named `name`.
pub(super) fn child<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

/// The trimmed text of `node`'s child element `name`.
pub(super) fn child_text<'a>(node: Node<'a, '_>, name: &str) -> Option<&'a str> {
    child(node, name).map(|c| c.text().unwrap_or("").trim())
}
