//! Helpers of the plot tests: reading the SVG back.

/// Text content of every `<text>` element, unescaped enough for the tests' labels.
pub(super) fn texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        rest = &rest[i..];
        let open_end = rest.find('>').expect("tag end");
        let close = rest.find("</text>").expect("closing tag");
        out.push(rest[open_end + 1..close].trim().replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"));
        rest = &rest[close..];
    }
    out
}

pub(super) fn count(svg: &str, pat: &str) -> usize {
    svg.matches(pat).count()
}
