//! The legend: each series once, in the column right of the plot area, under the figure's
//! optional heading.

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::style::{
    CHAR_WIDTH, CONE, FONT, GREY, LEGEND_ROW, LEGEND_TEXT_X, LEGEND_WIDTH, MARGIN, Marker,
    SCATTER_ALPHA, SVG_FONT_SCALE, TEXT, color_of, style_of,
};
use super::{Figure, Series, SeriesKind};

/// Where the legend's heading starts in the legend column (px).
const HEADING_X: i32 = 8;

/// The characters of a legend line starting at `x` (px): what fits in the legend column at
/// the estimated width.
fn legend_chars(x: i32) -> usize {
    let px = f64::from(LEGEND_WIDTH) - f64::from(x) - f64::from(MARGIN);
    (px / (CHAR_WIDTH * TEXT * SVG_FONT_SCALE)).floor() as usize
}

/// `text` broken at spaces into lines of at most `width` characters (a longer word is cut).
pub(super) fn wrap(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let mut word: Vec<char> = word.chars().collect();
        loop {
            let used = line.chars().count();
            let sep = usize::from(used > 0);
            if used + sep + word.len() <= width {
                if sep == 1 {
                    line.push(' ');
                }
                line.extend(word.drain(..));
                break;
            }
            if used > 0 {
                lines.push(std::mem::take(&mut line));
                continue;
            }
            line = word.drain(..width).collect();
            lines.push(std::mem::take(&mut line));
        }
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// A legend entry: a series shown once, its style (index among the figure's data series),
/// whether the figure draws it as dots, as a line or both, its text lines and its first row.
pub(super) struct Entry<'a> {
    series: &'a Series,
    style: usize,
    dots: bool,
    line: bool,
    lines: Vec<String>,
    row: i32,
}

/// The legend's layout: its heading's lines, then its entries (rows counted below the
/// heading), and the rows it takes in all.
pub(super) struct Legend<'a> {
    heading: Vec<String>,
    pub(super) entries: Vec<Entry<'a>>,
    pub(super) rows: i32,
}

/// True for the series that get a style of their own (colour, dash, marker).
pub(super) fn is_data(s: &Series) -> bool {
    matches!(
        s.kind,
        SeriesKind::Line | SeriesKind::Steps | SeriesKind::Points
    )
}

impl Figure {
    /// The names of the data series, in order of first appearance: a series' style index.
    pub(super) fn styles(&self) -> Vec<&str> {
        let mut names: Vec<&str> = Vec::new();
        for s in self
            .panels
            .iter()
            .flat_map(|p| &p.series)
            .filter(|s| is_data(s))
        {
            if !names.contains(&s.name.as_str()) {
                names.push(&s.name);
            }
        }
        names
    }

    /// The legend: its heading, then each series once (by name, and kind for courses), panel
    /// by panel with a gap row between panels, names wrapped to the legend column.
    pub(super) fn legend(&self) -> Legend<'_> {
        let styles = self.styles();
        let all = || self.panels.iter().flat_map(|p| &p.series);
        let heading = self
            .legend_title
            .as_deref()
            .map(|t| wrap(t, legend_chars(HEADING_X)))
            .unwrap_or_default();
        let mut entries: Vec<Entry<'_>> = Vec::new();
        let mut row = i32::try_from(heading.len()).unwrap_or(0);
        for panel in &self.panels {
            let before = entries.len();
            for s in &panel.series {
                // A data series keeps its style by name in every panel, as a line, steps or
                // dots.
                let same = |e: &Entry<'_>| {
                    e.series.name == s.name
                        && (e.series.kind == s.kind || is_data(e.series) && is_data(s))
                };
                if entries.iter().any(same) {
                    continue;
                }
                let named = |kinds: &[SeriesKind]| {
                    is_data(s) && all().any(|o| o.name == s.name && kinds.contains(&o.kind))
                };
                let lines = wrap(&s.name, legend_chars(LEGEND_TEXT_X));
                let height = i32::try_from(lines.len()).unwrap_or(1);
                entries.push(Entry {
                    series: s,
                    style: styles.iter().position(|n| *n == s.name).unwrap_or(0),
                    dots: named(&[SeriesKind::Points]),
                    line: named(&[SeriesKind::Line, SeriesKind::Steps]),
                    lines,
                    row,
                });
                row += height;
            }
            if entries.len() > before {
                row += 1;
            }
        }
        Legend {
            heading,
            entries,
            rows: row,
        }
    }
}

/// Draws the legend in the legend column: the heading in bold, then the entries.
pub(super) fn draw_legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    legend: &Legend<'_>,
) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
    for (i, line) in (0..).zip(&legend.heading) {
        area.draw_text(
            line,
            &(FONT, TEXT)
                .into_font()
                .style(FontStyle::Bold)
                .color(&BLACK),
            (HEADING_X, LEGEND_ROW - 6 + LEGEND_ROW * i),
        )?;
    }
    for entry in &legend.entries {
        draw_entry(area, entry)?;
    }
    Ok(())
}

/// Draws one legend entry in the legend column.
fn draw_entry(
    legend: &DrawingArea<SVGBackend<'_>, Shift>,
    entry: &Entry<'_>,
) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
    let s = entry.series;
    let y = LEGEND_ROW + LEGEND_ROW * entry.row;
    let (x0, x1) = (8, 38);
    let mid = ((x0 + x1) / 2, y);
    match s.kind {
        SeriesKind::Line | SeriesKind::Steps | SeriesKind::Points => {
            let k = entry.style;
            let color = color_of(k);
            let (dash, marker) = style_of(k);
            let style = color.stroke_width(2);
            if entry.line {
                match dash {
                    None => legend.draw(&PathElement::new(vec![(x0, y), (x1, y)], style))?,
                    Some((on, off)) => legend.draw(&DashedPathElement::new(
                        vec![(x0, y), (x1, y)],
                        on,
                        off,
                        style,
                    ))?,
                }
                match marker {
                    Marker::Circle => legend.draw(&Circle::new(mid, 3, style))?,
                    Marker::Triangle => legend.draw(&TriangleMarker::new(mid, 4, style))?,
                    Marker::Cross => legend.draw(&Cross::new(mid, 4, style))?,
                    Marker::Dot => legend.draw(&Circle::new(mid, 3, color.filled()))?,
                }
            }
            if entry.dots {
                // The dots either side of a line's marker, or three in a row alone.
                let at: &[i32] = if entry.line { &[-11, 11] } else { &[-8, 0, 8] };
                for dx in at {
                    legend.draw(&Circle::new(
                        (mid.0 + dx, mid.1 - 4 * i32::from(entry.line)),
                        2,
                        color.mix(SCATTER_ALPHA).filled(),
                    ))?;
                }
            }
        }
        SeriesKind::Guide => legend.draw(&DashedPathElement::new(
            vec![(x0, y), (x1, y)],
            5,
            4,
            GREY.stroke_width(1),
        ))?,
        SeriesKind::Cones => legend.draw(&TriangleMarker::new(mid, 4, CONE.filled()))?,
        SeriesKind::Outline => legend.draw(&Rectangle::new(
            [(x0 + 6, y - 6), (x1 - 6, y + 6)],
            GREY.mix(0.25).filled(),
        ))?,
    }
    for (i, line) in (0..).zip(&entry.lines) {
        legend.draw_text(
            line,
            &(FONT, TEXT).into_font().color(&BLACK),
            (LEGEND_TEXT_X, y - 6 + LEGEND_ROW * i),
        )?;
    }
    Ok(())
}
