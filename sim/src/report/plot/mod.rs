//! Plots as standalone SVG documents, drawn with `plotters` (its SVG backend only).
//!
//! Every data series of a figure gets its own colour, dash pattern and marker shape, by its
//! name (a series in two panels, or a scatter and a line of one name, is drawn alike and
//! listed once in the legend), the markers of different series placed at different points,
//! so that a series lying on top of another stays visible; the legend sits right of the plot
//! area, never over the data, its names wrapped to fit the column, under an optional heading
//! (e.g. the axis the colours stand for). Tick labels are tidy (`100`, not `100.0`); a panel
//! of discrete quantities only (steps, e.g. the gear) and an integer x axis have integer
//! ticks; a categorical x axis has one tick per category, named, and each scatter a box per
//! category.
//!
//! The figure's types are here, its drawing in `draw`, the legend in `legend`, the styles
//! in `style`. Text widths are estimated, as no font is at hand: [`CHAR_WIDTH`] em per
//! character.

mod draw;
mod legend;
mod style;
#[cfg(test)]
pub(crate) mod svg_text;
#[cfg(test)]
mod tests;

pub(crate) use style::COLOURS;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesKind {
    /// A measured line: its own colour, dash pattern and markers.
    Line,
    /// A measured discrete quantity (e.g. the gear): held until the next point.
    Steps,
    /// A grey dashed reference line (e.g. lane edges, the grip limit).
    Guide,
    /// Cone markers (orange triangles), one per point.
    Cones,
    /// Closed outlines seen from above (obstacles), filled grey.
    Outline,
    /// A scatter of measured points: small translucent dots in the series' own colour, no
    /// line (e.g. the cases of a sweep against one axis). On a categorical x axis
    /// ([`XAxis::Categories`]) each category's points also get a box: the quartiles and the
    /// median.
    Points,
}

/// One named series of a plot; non-finite points break the line (and separate outlines).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// The points, in drawing order.
    pub points: Vec<[f64; 2]>,
    /// How it is drawn.
    pub kind: SeriesKind,
}

impl Series {
    /// A measured line.
    pub fn line(name: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        Series {
            name: name.into(),
            points,
            kind: SeriesKind::Line,
        }
    }
}

/// A plot panel: a y axis and its series.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Label of the y axis, with its unit.
    pub y_label: String,
    /// The series, drawn in order (outlines and guides first is best).
    pub series: Vec<Series>,
}

/// What the shared x axis holds.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum XAxis {
    /// Real numbers: ticks where plotters puts them, tidily labelled.
    #[default]
    Continuous,
    /// Whole numbers only (a count, a gear): every tick label is an integer.
    Integer,
    /// Named categories: category `i` is at x = `i` (a point's x within ±0.5 of it belongs
    /// to it), each labelled with its name.
    Categories(Vec<String>),
}

/// A figure: a title, one or more panels stacked vertically over a shared x axis, or one
/// panel with equal x and y scales (a map).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Title above the first panel.
    pub title: String,
    /// Label of the x axis, with its unit.
    pub x_label: String,
    /// What the x axis holds.
    pub x_axis: XAxis,
    /// The panels, top to bottom.
    pub panels: Vec<Panel>,
    /// Same scale on both axes (for trajectories seen from above).
    pub equal_aspect: bool,
    /// A heading above the legend's entries (e.g. the sweep axis whose values the colours
    /// stand for); `None`: none.
    pub legend_title: Option<String>,
}

/// A plot that `plotters` could not draw.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("cannot draw the plot '{title}': {message}")]
pub struct PlotError {
    /// The figure's title.
    pub title: String,
    /// What plotters reported.
    pub message: String,
}

impl Figure {
    /// The SVG document.
    ///
    /// # Errors
    /// [`PlotError`] when plotters refuses to draw (it never does for finite data).
    pub fn to_svg(&self) -> Result<String, PlotError> {
        let mut svg = String::new();
        self.draw(&mut svg).map_err(|message| PlotError {
            title: self.title.clone(),
            message,
        })?;
        Ok(svg)
    }
}
