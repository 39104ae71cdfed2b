//! The XML files of video tools (Tracker's `.trk`, Logger Pro's `.cmbl`), parsed with
//! `roxmltree`: no DTD (so no entities to expand: a "billion laughs" file is refused
//! at once), a bound on the nodes (memory), and an iterative parser (a deeply nested
//! file cannot overflow the stack). The file's size is bounded before it is read.

use roxmltree::{Document, Node, ParsingOptions};

/// Most XML nodes a data file may have: a Tracker project of 100,000 frames has
/// about 1.5 million; each node costs roughly a hundred bytes.
const MAX_NODES: u32 = 4_000_000;

/// Why a video tool's XML file (`what`: "Tracker project", "Logger Pro file") is not
/// one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum XmlError {
    #[error("not a {what}: it declares a DTD (entities), which {what}s never have; refused unread")]
    Dtd { what: &'static str },
    #[error("not a {what}: more than {MAX_NODES} XML nodes, far beyond any real recording")]
    TooManyNodes { what: &'static str },
    #[error("not a readable {what}: {error}")]
    Unreadable {
        what: &'static str,
        error: roxmltree::Error,
    },
}

/// The text of a video tool's XML file as a tree, or why it is not one.
pub(super) fn parse<'i>(text: &'i str, what: &'static str) -> Result<Document<'i>, XmlError> {
    let options = ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_NODES,
        ..ParsingOptions::default()
    };
    Document::parse_with_options(text, options).map_err(|e| match e {
        roxmltree::Error::DtdDetected => XmlError::Dtd { what },
        roxmltree::Error::NodesLimitReached => XmlError::TooManyNodes { what },
        error => XmlError::Unreadable { what, error },
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
