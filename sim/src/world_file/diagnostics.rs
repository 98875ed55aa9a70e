//! Every error of a world file in one run, in file order, each shown with its line and a
//! caret under the key or value (annotate-snippets).
//!
//! The reader stops at its first error; [`parse_all`] reads the file again with that error's
//! line blanked (a section header's whole section), until the file reads or an error repeats,
//! so a file with three typos reports three errors. Blanking keeps the line numbers. An error
//! that only the blanking could cause (invalid TOML, or an unlocated structure error such as
//! "no `[vehicle]` section", after a first error) is not reported: the file was valid TOML, and
//! the section existed.

use core::fmt;

use annotate_snippets::{AnnotationKind, Level, Renderer, Snippet};

use super::{WorldDescription, WorldFileError, WorldFileErrorKind, parse_str};

/// Most errors reported for one file: past this many, the rest is noise from the first.
pub const MAX_ERRORS: usize = 50;

/// Every error found in one world file, in file order (never empty), with the file's text
/// to show their lines.
#[derive(Debug, Clone, PartialEq)]
pub struct WorldFileErrors {
    /// The errors, in file order (by line, then column; unlocated ones first).
    pub errors: Vec<WorldFileError>,
    /// The text of the file, if it was read.
    pub text: Option<String>,
}

impl From<WorldFileError> for WorldFileErrors {
    fn from(e: WorldFileError) -> Self {
        WorldFileErrors {
            errors: vec![e],
            text: None,
        }
    }
}

impl WorldFileErrors {
    /// The first error in file order.
    pub fn first(&self) -> Option<&WorldFileError> {
        self.errors.first()
    }
}

/// Parses world-file text as [`parse_str`] does, but reports every error of the file.
///
/// # Errors
/// Every error of the file, in file order, at most [`MAX_ERRORS`].
pub fn parse_all(file: &str, text: &str) -> Result<WorldDescription, WorldFileErrors> {
    collect(text, |t| parse_str(file, t))
}

/// Runs `parse` (a reader that stops at its first error) on `text`, then again with each
/// error's line blanked, until it reads or an error repeats: every error of the text, in
/// file order (at most [`MAX_ERRORS`]). A sweep file's errors are collected this way too
/// ([`crate::sweep::Sweep::load_all`]).
///
/// # Errors
/// Every error found.
pub fn collect<T>(
    text: &str,
    mut parse: impl FnMut(&str) -> Result<T, WorldFileError>,
) -> Result<T, WorldFileErrors> {
    let mut errors: Vec<WorldFileError> = Vec::new();
    let mut current = text.to_string();
    loop {
        let e = match parse(&current) {
            Ok(value) if errors.is_empty() => return Ok(value),
            Ok(_) => break,
            Err(e) => e,
        };
        let consequence = !errors.is_empty()
            && (matches!(e.kind, WorldFileErrorKind::Syntax(_)) || e.location.is_none());
        let repeated = errors.iter().any(|seen| seen.location == e.location);
        if consequence || repeated {
            break;
        }
        let line = e.location.map(|l| l.line);
        errors.push(e);
        match line {
            Some(line) if errors.len() < MAX_ERRORS => current = blank(&current, line),
            _ => break,
        }
    }
    errors.sort_by_key(|e| e.location.map(|l| (l.line, l.column)));
    Err(WorldFileErrors {
        errors,
        text: Some(text.to_string()),
    })
}

/// `text` with line `line` (1-based) blanked, and when that line is a section header
/// (`[…]` or `[[…]]`), every line up to the next header.
fn blank(text: &str, line: u32) -> String {
    let index = usize::try_from(line)
        .unwrap_or(usize::MAX)
        .saturating_sub(1);
    let is_header = |l: &str| l.trim_start().starts_with('[');
    let mut in_section = false;
    let mut out = String::with_capacity(text.len());
    for (i, l) in text.split_inclusive('\n').enumerate() {
        let blanked = if i == index {
            in_section = is_header(l);
            true
        } else if in_section && is_header(l) {
            in_section = false;
            false
        } else {
            in_section && i > index
        };
        if blanked {
            // The line ending stays, so later lines keep their numbers.
            out.push_str(&l[l.trim_end_matches(['\r', '\n']).len()..]);
        } else {
            out.push_str(l);
        }
    }
    out
}

/// The byte range of the token at `line`:`column` (1-based, in characters) of `text`: up to
/// the next blank, `=`, `,` or bracket, at least one character; `None` past the text.
fn token_span(text: &str, line: u32, column: u32) -> Option<core::ops::Range<usize>> {
    let line_start: usize = text
        .split_inclusive('\n')
        .take(usize::try_from(line).ok()?.checked_sub(1)?)
        .map(str::len)
        .sum();
    let rest = text.get(line_start..)?;
    let line_text = rest.split('\n').next()?;
    let skip = usize::try_from(column).ok()?.checked_sub(1)?;
    let (offset, _) = line_text.char_indices().nth(skip)?;
    let token = &line_text[offset..];
    let delimiter = |c: char| c.is_whitespace() || "=,[]{}".contains(c);
    let len = token
        .char_indices()
        .find(|&(i, c)| i > 0 && (delimiter(c) || token.starts_with(delimiter)))
        .map_or(token.len(), |(i, _)| i)
        .max(token.chars().next().map_or(0, char::len_utf8));
    let start = line_start + offset;
    Some(start..start + len)
}

/// One error as compilers show it: `error: message`, then `--> file:line:column`, the line's
/// text and a caret under the key or value (the plain one-line form when it has no location).
pub fn render(error: &WorldFileError, text: &str) -> String {
    let title = error.message().to_string();
    let span = error
        .location
        .and_then(|l| token_span(text, l.line, l.column));
    let Some(span) = span.filter(|_| !matches!(error.kind, WorldFileErrorKind::Io(_))) else {
        return format!("error: {error}");
    };
    let label = error.key.as_deref().unwrap_or("");
    // Control characters shown as spaces: a damaged file's ESC or NUL would otherwise reach
    // the terminal as it is (an escape sequence from a file is not ours to run), and a tab's
    // width is the terminal's, so the caret could miss its token. One byte for one byte, so
    // the span still points at the same token.
    let shown: String = text
        .chars()
        .map(|c| {
            if c.is_ascii_control() && c != '\n' {
                ' '
            } else {
                c
            }
        })
        .collect();
    let report = &[Level::ERROR.primary_title(&title).element(
        Snippet::source(&shown)
            .line_start(1)
            .path(&error.file)
            .fold(true)
            .annotation(AnnotationKind::Primary.span(span).label(label)),
    )];
    Renderer::plain().render(report)
}

impl fmt::Display for WorldFileErrors {
    /// Every error rendered ([`render`]), a blank line between them, then how many there
    /// were when more than one.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.errors.iter().enumerate() {
            if i > 0 {
                f.write_str("\n\n")?;
            }
            match &self.text {
                Some(text) => f.write_str(&render(e, text))?,
                None => write!(f, "error: {e}")?,
            }
        }
        if self.errors.len() > 1 {
            write!(f, "\n\n{} errors in this file", self.errors.len())?;
        }
        Ok(())
    }
}

impl std::error::Error for WorldFileErrors {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_line_of_tabs_and_nuls_renders_without_panicking() {
        // The `world_file` fuzz target's crash of 2026-11-28 (a syntax error at 2:135 on a line
        // of tabs and NULs): annotate-snippets' margin overflowed when it was rendered.
        let text = format!(
            "[vehichicle]\n{}{}\t\t\tnan{}){}model = \"BmwX2\"\ntransrtlinoaamme]]\nat = 1e9\n\
             throttle = \x0c\0\0\0\0\0]\01\n",
            "\t".repeat(8),
            "\0".repeat(123),
            "\t".repeat(9),
            "\t".repeat(3)
        );
        let errors = parse_all("w.toml", &text).unwrap_err();
        assert_eq!(
            errors.errors[0].location.map(|l| (l.line, l.column)),
            Some((2, 135))
        );
        let shown = errors.to_string();
        assert!(shown.contains("w.toml:"), "{shown}");
    }

    #[test]
    fn leading_tabs_a_carriage_return_and_nuls_render_without_panicking() {
        // The `world_file` fuzz target's second crash of 2026-11-28, its input byte for byte:
        // 64 tabs, a lone carriage return, NULs around a `2`, long runs of tabs. The margin
        // arithmetic of annotate-snippets 0.11 overflowed on it.
        let bytes = include_bytes!("../../tests/fuzz/crashes/world_file-4478f3bb");
        let text = String::from_utf8_lossy(bytes);
        let errors = parse_all("w.toml", &text).unwrap_err();
        let shown = errors.to_string();
        assert!(shown.contains("w.toml:1:"), "{shown}");
    }

    #[test]
    fn blanking_keeps_line_numbers() {
        let t = "a = 1\n[x]\nb = 2\nc = 3\n[y]\nd = 4\n";
        assert_eq!(blank(t, 1), "\n[x]\nb = 2\nc = 3\n[y]\nd = 4\n");
        assert_eq!(blank(t, 2), "a = 1\n\n\n\n[y]\nd = 4\n");
        assert_eq!(blank(t, 6), "a = 1\n[x]\nb = 2\nc = 3\n[y]\n\n");
    }

    #[test]
    fn token_spans() {
        let t = "a = 1\nmaxVelocty = 30\n  é = [1, 2]\n";
        assert_eq!(token_span(t, 2, 1), Some(6..16));
        assert_eq!(&t[token_span(t, 2, 14).unwrap()], "30");
        assert_eq!(&t[token_span(t, 3, 3).unwrap()], "é");
        assert_eq!(&t[token_span(t, 3, 7).unwrap()], "[");
        assert_eq!(token_span(t, 9, 1), None);
    }
}
