//! Reading the text of a drawn SVG back, for tests: every `<text>` element's content and its
//! estimated box.

use super::style::CHAR_WIDTH;

/// The value of attribute `name` in the tag `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    tag.split(&format!(" {name}=\"")).nth(1)?.split('"').next()
}

/// The canvas size of `svg` (px).
pub(crate) fn canvas(svg: &str) -> [f64; 2] {
    let head = &svg[..svg.find('>').unwrap()];
    [attr(head, "width"), attr(head, "height")].map(|v| v.unwrap().parse().unwrap())
}

/// Every text element of `svg`: its content (entities decoded) and its box
/// `[x0, y0, x1, y1]` (px), the width estimated as [`CHAR_WIDTH`] em per character and the
/// height one em, placed by its anchor and baseline shift, rotated with it.
pub(crate) fn boxes(svg: &str) -> Vec<(String, [f64; 4])> {
    let mut out = Vec::new();
    for part in svg.split("<text").skip(1) {
        let (tag, rest) = part.split_once('>').unwrap();
        let content = rest.split("</text>").next().unwrap().trim();
        let content = content
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&quot;", "\"")
            .replace("&apos;", "'")
            .replace("&amp;", "&");
        let num = |name: &str| attr(tag, name).unwrap().parse::<f64>().unwrap();
        let (x, y, size) = (num("x"), num("y"), num("font-size"));
        let w = CHAR_WIDTH * size * content.chars().count() as f64;
        // Along the text: where the anchor puts it.
        let (a0, a1) = match attr(tag, "text-anchor") {
            Some("middle") => (-0.5 * w, 0.5 * w),
            Some("end") => (-w, 0.0),
            _ => (0.0, w),
        };
        // Across: the em box below the anchor point (0.76em: y is the top), centred
        // (0.5ex) or above it (-0.5ex: y is the bottom).
        let (c0, c1) = match attr(tag, "dy") {
            Some("0.76em") => (0.0, size),
            Some("-0.5ex") => (-size, 0.0),
            _ => (-0.5 * size, 0.5 * size),
        };
        let rotated = attr(tag, "transform").is_some_and(|t| t.starts_with("rotate(270"));
        let b = if rotated {
            // rotate(270) turns the text's direction up and its "down" to the right.
            [x + c0, y - a1, x + c1, y - a0]
        } else {
            [x + a0, y + c0, x + a1, y + c1]
        };
        out.push((content, b));
    }
    out
}

/// Panics unless every text element of `svg` lies inside its canvas.
pub(crate) fn assert_inside(svg: &str) {
    let [w, h] = canvas(svg);
    for (text, b) in boxes(svg) {
        assert!(
            b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= w && b[3] <= h,
            "'{text}' at {b:?} leaves the {w} × {h} canvas"
        );
    }
}
