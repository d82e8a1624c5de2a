//! The report's pages as a static HTML site (`html/` in the report folder): one HTML file per Markdown page
//! (`README.md` becomes `html/index.html`, `families/hertz.md` `html/families/hertz.html`), the SVG figures inline,
//! links between pages turned into links between the HTML files and links to the data (CSV, JSON) pointing into the
//! report folder. The Markdown is the report's own subset (headings, paragraphs, tables, lists, images, links, code
//! spans, bold): this renders that subset, nothing more.

use crate::error::Result;
use crate::io::write_atomic;
use std::fmt::Write as _;
use std::path::Path;

/// The HTML folder, in the report folder.
pub const FOLDER: &str = "html";

/// The HTML file of a Markdown page (relative to the report folder): `html/index.html` for `README.md`.
pub fn file_of(page: &str) -> String {
    let stem = page.strip_suffix(".md").unwrap_or(page);
    let stem = if stem == "README" { "index" } else { stem };
    format!("{FOLDER}/{stem}.html")
}

/// Render `md` (links relative to the report folder, as the report writes them before [`super::pages::relink`])
/// for the page `page` and write it to [`file_of`]`(page)` under `out`; returns that path relative to `out`.
pub fn write_page(out: &Path, page: &str, md: &str) -> Result<String> {
    let file = file_of(page);
    let depth = file.matches('/').count();
    let title = md.lines().find_map(|l| l.strip_prefix("# ")).unwrap_or("rollbem report");
    let body = render(md, out, depth);
    let html = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n<style>\n\
         body {{ font-family: sans-serif; max-width: 1200px; margin: 2em auto; padding: 0 1em; line-height: 1.45; }}\n\
         table {{ border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }}\n\
         th, td {{ border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: left; vertical-align: top; }}\n\
         th {{ background: #f0f0f0; }}\nfigure svg {{ max-width: 100%; height: auto; }}\n\
         code {{ background: #f4f4f4; padding: 0 0.2em; }}\n</style>\n</head>\n<body>\n{body}</body>\n</html>\n",
        escape(title)
    );
    write_atomic(&out.join(&file), &html)?;
    Ok(file)
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// A heading's anchor as GitHub makes it: lower case, spaces to `-`, punctuation other than `-` and `_` dropped.
pub fn anchor(text: &str) -> String {
    text.to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// A link target of the Markdown (relative to the report folder) as seen from an HTML page `depth` folders below
/// the report folder: another page's HTML file, or the data file in the report folder.
fn target(t: &str, depth: usize) -> String {
    if t.starts_with("http://") || t.starts_with("https://") || t.starts_with('#') {
        return t.to_string();
    }
    let up = "../".repeat(depth);
    let (path, frag) = t.split_once('#').map_or((t, None), |(p, f)| (p, Some(f)));
    let frag = frag.map(|f| format!("#{f}")).unwrap_or_default();
    if path.ends_with(".md") && !path.starts_with("peer-") {
        // From html/x/y.html back to html/, then the page's HTML file below it.
        let inner = file_of(path);
        let inner = inner.strip_prefix(&format!("{FOLDER}/")).unwrap_or(&inner);
        format!("{}{inner}{frag}", "../".repeat(depth - 1))
    } else {
        format!("{up}{path}{frag}")
    }
}

/// Inline Markdown: code spans, bold, links and images (an image of an SVG in the report folder inline).
fn inline(s: &str, out: &Path, depth: usize) -> String {
    let mut html = String::new();
    let mut rest = s;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('`') {
            if let Some(end) = r.find('`') {
                write!(html, "<code>{}</code>", escape(&r[..end])).unwrap();
                rest = &r[end + 1..];
                continue;
            }
        }
        if let Some(r) = rest.strip_prefix("**") {
            if let Some(end) = r.find("**") {
                write!(html, "<strong>{}</strong>", inline(&r[..end], out, depth)).unwrap();
                rest = &r[end + 2..];
                continue;
            }
        }
        let image = rest.starts_with("![");
        if image || rest.starts_with('[') {
            let open = if image { 2 } else { 1 };
            if let Some((text, t, len)) = link_at(&rest[open..]) {
                if image {
                    html.push_str(&figure(text, t, out, depth));
                } else {
                    write!(html, "<a href=\"{}\">{}</a>", escape(&target(t, depth)), inline(text, out, depth)).unwrap();
                }
                rest = &rest[open + len..];
                continue;
            }
        }
        let c = rest.chars().next().expect("non-empty");
        html.push_str(&escape(&c.to_string()));
        rest = &rest[c.len_utf8()..];
    }
    html
}

/// `text](target)` at the start of `s`: (text, target, length consumed).
fn link_at(s: &str) -> Option<(&str, &str, usize)> {
    let close = s.find("](")?;
    let end = s[close + 2..].find(')')? + close + 2;
    Some((&s[..close], &s[close + 2..end], end + 1))
}

/// An image: an SVG of the report folder inline (its XML declaration dropped), anything else as `<img>`.
fn figure(alt: &str, t: &str, out: &Path, depth: usize) -> String {
    if t.ends_with(".svg") && !t.contains("..") {
        if let Ok(svg) = std::fs::read_to_string(out.join(t)) {
            let svg = svg.find("<svg").map_or(svg.as_str(), |i| &svg[i..]);
            return format!("<figure>{svg}<figcaption>{}</figcaption></figure>", escape(alt));
        }
    }
    format!("<img src=\"{}\" alt=\"{}\">", escape(&target(t, depth)), escape(alt))
}

/// The cells of a table row (`\|` is a literal bar inside a cell).
pub(super) fn cells(line: &str) -> Vec<String> {
    let t = line.trim().trim_start_matches('|');
    let t = t.strip_suffix('|').unwrap_or(t);
    let mut v = vec![String::new()];
    let mut chars = t.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                v.last_mut().expect("one cell").push('|');
                chars.next();
            }
            '|' => v.push(String::new()),
            c => v.last_mut().expect("one cell").push(c),
        }
    }
    v.into_iter().map(|c| c.trim().to_string()).collect()
}

/// A block of Markdown lines into HTML.
fn render(md: &str, out: &Path, depth: usize) -> String {
    let mut html = String::new();
    let lines: Vec<&str> = md.lines().collect();
    let mut i = 0;
    let mut para: Vec<&str> = Vec::new();
    let flush = |para: &mut Vec<&str>, html: &mut String| {
        if !para.is_empty() {
            let text = inline(&para.join(" "), out, depth);
            // A figure alone is a block of its own, not a paragraph's content.
            if text.starts_with("<figure>") && text.ends_with("</figure>") {
                writeln!(html, "{text}").unwrap();
            } else {
                writeln!(html, "<p>{text}</p>").unwrap();
            }
            para.clear();
        }
    };
    while i < lines.len() {
        let line = lines[i];
        let level = line.chars().take_while(|c| *c == '#').count();
        if (1..=6).contains(&level) && line[level..].starts_with(' ') {
            flush(&mut para, &mut html);
            let text = line[level + 1..].trim();
            writeln!(html, "<h{level} id=\"{}\">{}</h{level}>", anchor(text), inline(text, out, depth)).unwrap();
        } else if line.starts_with('|') {
            flush(&mut para, &mut html);
            let start = i;
            while i + 1 < lines.len() && lines[i + 1].starts_with('|') {
                i += 1;
            }
            html.push_str(&table(&lines[start..=i], out, depth));
        } else if let Some(item) = line.strip_prefix("- ") {
            flush(&mut para, &mut html);
            html.push_str("<ul>\n");
            writeln!(html, "<li>{}</li>", inline(item, out, depth)).unwrap();
            while let Some(item) = lines.get(i + 1).and_then(|l| l.strip_prefix("- ")) {
                writeln!(html, "<li>{}</li>", inline(item, out, depth)).unwrap();
                i += 1;
            }
            html.push_str("</ul>\n");
        } else if line.trim().is_empty() {
            flush(&mut para, &mut html);
        } else {
            para.push(line);
        }
        i += 1;
    }
    flush(&mut para, &mut html);
    html
}

/// A Markdown table (header, separator, rows) into HTML.
fn table(rows: &[&str], out: &Path, depth: usize) -> String {
    let mut html = String::from("<table>\n");
    for (k, row) in rows.iter().enumerate() {
        if k == 1 && row.chars().all(|c| matches!(c, '|' | '-' | ':' | ' ')) {
            continue;
        }
        let tag = if k == 0 { "th" } else { "td" };
        let cells: String = cells(row).iter().map(|c| format!("<{tag}>{}</{tag}>", inline(c, out, depth))).collect();
        writeln!(html, "<tr>{cells}</tr>").unwrap();
    }
    html.push_str("</table>\n");
    html
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_point_to_pages_and_data_from_the_html_folder() {
        // html/families/hertz.html: two levels below the report folder, one below html/.
        assert_eq!(target("methods.md#timing", 2), "../methods.html#timing");
        assert_eq!(target("README.md", 2), "../index.html");
        assert_eq!(target("sweeps/a.csv", 2), "../../sweeps/a.csv");
        assert_eq!(target("families/hertz.md", 1), "families/hertz.html");
        assert_eq!(target("peer-lcp.md", 2), "../../peer-lcp.md");
        assert_eq!(anchor("How to read the tables"), "how-to-read-the-tables");
    }

    #[test]
    fn the_report_subset_renders() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(dir.path().join("figures")).unwrap();
        std::fs::write(dir.path().join("figures/f.svg"), "<?xml version=\"1.0\"?>\n<svg id=\"x\"></svg>").unwrap();
        let md = "# T\n\nSome **bold** `a<b` [m](methods.md).\n\n| a | b \\| c |\n|---|---|\n| 1 | 2 |\n\n- x\n- y\n\n![cap](figures/f.svg)\n";
        let html = render(md, dir.path(), 1);
        assert!(html.contains("<h1 id=\"t\">T</h1>"), "{html}");
        assert!(html.contains("<strong>bold</strong> <code>a&lt;b</code> <a href=\"methods.html\">m</a>"), "{html}");
        assert!(html.contains("<tr><th>a</th><th>b | c</th></tr>\n<tr><td>1</td><td>2</td></tr>"), "{html}");
        assert!(html.contains("<ul>\n<li>x</li>\n<li>y</li>\n</ul>"), "{html}");
        assert!(html.contains("<figure><svg id=\"x\"></svg><figcaption>cap</figcaption></figure>"), "{html}");
    }
}
