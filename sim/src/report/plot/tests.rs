//! The figures' SVG read back: styles, legend, ticks, text inside the canvas.

use super::draw::{pieces, steps, thin};
use super::legend::wrap;
use super::style::{MARKERS, MAX_POINTS, PLOT_WIDTH, Y_LABEL_AREA, style_of, tidy};
use super::svg_text;
use super::*;

/// The x coordinate of the `<text>` element whose content is `label`.
fn text_x(svg: &str, label: &str) -> f64 {
    let end = svg
        .find(&format!(">\n{label}\n</text>"))
        .unwrap_or_else(|| panic!("no text {label} in {svg}"));
    let start = svg[..end].rfind("<text").unwrap();
    let tag = &svg[start..end];
    let x = tag.split("x=\"").nth(1).unwrap().split('"').next().unwrap();
    x.parse().unwrap()
}

fn two_equal_lines() -> Figure {
    let points: Vec<[f64; 2]> = (0..200)
        .map(|i| [f64::from(i), f64::from(i % 50)])
        .collect();
    Figure {
        title: "speed <km/h> & rpm".into(),
        x_label: "time (s)".into(),
        panels: vec![Panel {
            y_label: "speed (km/h)".into(),
            series: vec![
                Series {
                    name: "lane edges".into(),
                    points: vec![[0.0, -5.0], [200.0, -5.0]],
                    kind: SeriesKind::Guide,
                },
                Series::line("accel-speed", points.clone()),
                Series::line("brake", points),
                Series {
                    name: "cones".into(),
                    points: vec![[10.0, 1.0], [20.0, 1.0]],
                    kind: SeriesKind::Cones,
                },
            ],
        }],
        equal_aspect: false,
        x_axis: XAxis::Continuous,
        legend_title: None,
    }
}

#[test]
fn coinciding_series_stay_visible() {
    // Two identical series: the second has its own dash pattern and marker, and the
    // markers of each are drawn at their own points.
    assert_ne!(style_of(0), style_of(1));
    let all: Vec<_> = (0..8).map(style_of).collect();
    for (i, a) in all.iter().enumerate() {
        assert!(all.iter().skip(i + 1).all(|b| b != a), "{all:?}");
    }
    let svg = two_equal_lines().to_svg().unwrap();
    // Markers of the first series (circles, blue) and of the second (triangles, orange,
    // drawn as polygons): MARKERS of each plus one in the legend.
    assert_eq!(svg.matches("<circle").count(), MARKERS + 1, "{svg}");
    assert!(svg.matches("#0072B2").count() > MARKERS);
    assert!(svg.matches("#D55E00").count() > MARKERS);
}

#[test]
fn legend_sits_right_of_the_plot_area() {
    let svg = two_equal_lines().to_svg().unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    for label in ["accel-speed", "brake", "lane edges", "cones"] {
        let x = text_x(&svg, label);
        assert!(x > f64::from(PLOT_WIDTH), "{label} at x = {x}");
    }
    // The title is escaped.
    assert!(svg.contains("speed &lt;km/h&gt; &amp; rpm"), "{svg}");
}

#[test]
fn ticks_are_tidy_and_text_stays_on_the_canvas() {
    assert_eq!(tidy(100.0), "100");
    assert_eq!(tidy(5000.0), "5000");
    assert_eq!(tidy(0.1 + 0.2), "0.3");
    assert_eq!(tidy(-2.5), "-2.5");
    assert_eq!(tidy(-1e-9), "0");
    let mut f = two_equal_lines();
    // A name longer than the legend column: wrapped, not cut (before: "lane-change
    // (commanded" and the rest past the edge).
    f.panels[0].series[1].name = "lane-change: ToyotaPrius-1 (commanded)".into();
    let svg = f.to_svg().unwrap();
    svg_text::assert_inside(&svg);
    let texts: Vec<String> = svg_text::boxes(&svg).into_iter().map(|t| t.0).collect();
    // 19 characters a line: (200 − 46 − 10) px / (0.6 × 12.15 px).
    for line in ["lane-change:", "ToyotaPrius-1", "(commanded)"] {
        assert!(texts.contains(&line.to_string()), "{texts:?}");
    }
    assert!(texts.iter().all(|t| !t.ends_with(".0")), "{texts:?}");
    assert_eq!(wrap("abcdefgh", 3), ["abc", "def", "gh"]);
    assert_eq!(wrap("a bc d", 4), ["a bc", "d"]);
    assert_eq!(wrap("", 4), [""]);
}

#[test]
fn a_series_in_two_panels_is_one_legend_entry_and_gears_tick_in_integers() {
    let rpm: Vec<[f64; 2]> = (0..100)
        .map(|i| [f64::from(i), 1000.0 + 40.0 * f64::from(i)])
        .collect();
    let gear: Vec<[f64; 2]> = (0..100)
        .map(|i| [f64::from(i), f64::from(1 + i / 25)])
        .collect();
    let figure = Figure {
        title: "rpm and gear".into(),
        x_label: "time (s)".into(),
        panels: vec![
            Panel {
                y_label: "engine speed (rpm)".into(),
                series: vec![Series::line("accel-torque", rpm)],
            },
            Panel {
                y_label: "gear".into(),
                series: vec![Series {
                    name: "accel-torque".into(),
                    points: gear,
                    kind: SeriesKind::Steps,
                }],
            },
        ],
        equal_aspect: false,
        x_axis: XAxis::Continuous,
        legend_title: None,
    };
    let svg = figure.to_svg().unwrap();
    svg_text::assert_inside(&svg);
    let boxes = svg_text::boxes(&svg);
    let legend: Vec<&str> = boxes
        .iter()
        .filter(|(_, b)| b[0] > f64::from(PLOT_WIDTH))
        .map(|(t, _)| t.as_str())
        .collect();
    assert_eq!(legend, ["accel-torque"]);
    // The gear panel is the lower half: its y tick labels (right-aligned at the axis)
    // are whole numbers, the gears 1 to 4 among them.
    let [_, h] = svg_text::canvas(&svg);
    let gear_ticks: Vec<f64> = boxes
        .iter()
        .filter(|(_, b)| {
            b[2] <= f64::from(Y_LABEL_AREA) + 1.0 && b[1] > 0.55 * h && b[3] < h - 30.0
        })
        .filter_map(|(t, _)| t.parse().ok())
        .collect();
    assert!(gear_ticks.len() >= 4, "{boxes:?}");
    assert!(
        gear_ticks.iter().all(|g| g.fract() == 0.0),
        "{gear_ticks:?}"
    );
    for g in [1.0, 2.0, 3.0, 4.0] {
        assert!(gear_ticks.contains(&g), "{gear_ticks:?}");
    }
}

#[test]
fn thinning_and_steps() {
    let long: Vec<[f64; 2]> = (0..5000).map(|i| [f64::from(i), 1.0]).collect();
    let t = thin(&long);
    assert!(t.len() <= MAX_POINTS + 1);
    assert_eq!(t.last(), long.last());
    assert_eq!(
        steps(&[(0.0, 1.0), (1.0, 2.0)]),
        [(0.0, 1.0), (1.0, 1.0), (1.0, 2.0)]
    );
    assert_eq!(
        pieces(&[[0.0, 0.0], [f64::NAN, 1.0], [2.0, 5.0]]),
        [vec![(0.0, 0.0)], vec![(2.0, 5.0)]]
    );
}

#[test]
fn category_labels_never_overlap() {
    // 30 categories of 14 characters: 110 px a label with its gap, 23 px a column, so no more
    // than 6 labels (plotters names every 5th).
    // Few short ones: each named under its column.
    for (n, width) in [(30, 14), (3, 5)] {
        let names: Vec<String> = (0..n).map(|i| format!("{i:0width$}")).collect();
        let points = (0..n).map(|i| [i as f64, (i % 7) as f64]).collect();
        let figure = Figure {
            title: "t".into(),
            x_label: "model".into(),
            x_axis: XAxis::Categories(names.clone()),
            panels: vec![Panel {
                y_label: "m".into(),
                series: vec![Series {
                    name: "cases".into(),
                    points,
                    kind: SeriesKind::Points,
                }],
            }],
            equal_aspect: false,
            legend_title: None,
        };
        let svg = figure.to_svg().unwrap();
        svg_text::assert_inside(&svg);
        let mut labels: Vec<[f64; 4]> = svg_text::boxes(&svg)
            .into_iter()
            .filter(|(t, _)| names.contains(t))
            .map(|(_, b)| b)
            .collect();
        labels.sort_by(|a, b| a[0].total_cmp(&b[0]));
        assert!(labels.windows(2).all(|w| w[0][2] < w[1][0]), "{labels:?}");
        if n == 3 {
            assert_eq!(labels.len(), 3);
        } else {
            assert!((2..n).contains(&labels.len()), "{}", labels.len());
        }
    }
}
