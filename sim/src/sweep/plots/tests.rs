//! The sweep plots' accumulators, and their SVGs read back: one legend entry per value, a
//! colour per value of the second axis, a box and strip per category, integer ticks.

use super::*;

#[test]
fn the_sample_stays_small_and_the_means_exact() {
    let mut p = Pair::new();
    for k in 0..10_000 {
        p.add(f64::from(k % 3), f64::from(k));
    }
    assert!(p.points.len() <= MAX_POINTS, "{}", p.points.len());
    assert!(p.points.len() > MAX_POINTS / 2);
    // Every kept point is a row of the sample: a multiple of the stride.
    assert!(
        p.points
            .iter()
            .all(|q| (q[1] as usize).is_multiple_of(p.stride))
    );
    // Rows 0, 3, 6, … 9999 have x = 0: their mean is 4999.5.
    assert_eq!(p.means().unwrap()[0], [0.0, 4999.5]);
    let mut many = Pair::new();
    for k in 0..=MAX_LEVELS {
        many.add(k as f64, 1.0);
    }
    assert_eq!(many.means(), None);
    assert_eq!(file_name("box[1].friction"), "box_1_.friction.svg");
    assert_eq!(number("1.5"), Ok(Some(1.5)));
    assert_eq!(number(""), Ok(None));
    assert_eq!(number("true"), Err(()));
}

#[test]
fn strips_stay_in_their_column_and_colour_share() {
    // Two colours: colour 0 in [x − 0.4, x), colour 1 in [x, x + 0.4).
    for k in 0..100 {
        let a = strip_x(3.0, 0, 2, k);
        let b = strip_x(3.0, 1, 2, k);
        assert!(
            (2.6..3.0).contains(&a) && (3.0..3.4).contains(&b),
            "{a} {b}"
        );
    }
}

use crate::report::svg_text;

/// The left edge of the legend column (px): the plot column's width.
const LEGEND_X: f64 = 760.0;

/// Writes `results.csv` of `header` and `rows` (cells without commas) into a fresh
/// directory named after `name`, draws its plots, and returns each plot's file name and
/// SVG text.
fn plots(
    name: &str,
    axes: &[&str],
    header: &str,
    rows: &[String],
    color_by: &ColorBy,
) -> Result<Vec<(String, String)>, OutputError> {
    let dir = std::env::temp_dir().join(format!("sim-sweep-plots-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let results = dir.join("results.csv");
    std::fs::write(&results, format!("{header}\n{}\n", rows.join("\n"))).unwrap();
    let axes: Vec<String> = axes.iter().map(|a| a.to_string()).collect();
    let written = write_plots(&results, &axes, "brake", color_by, &dir.join("plots"));
    let out = written.map(|files| {
        files
            .iter()
            .map(|f| {
                let name = f.file_name().unwrap().to_string_lossy().to_string();
                (name, std::fs::read_to_string(f).unwrap())
            })
            .collect()
    });
    std::fs::remove_dir_all(&dir).unwrap();
    out
}

/// The texts of the legend column, top to bottom.
fn legend_of(svg: &str) -> Vec<String> {
    svg_text::boxes(svg)
        .into_iter()
        .filter(|(t, b)| b[0] > LEGEND_X && !t.is_empty())
        .map(|(t, _)| t)
        .collect()
}

/// The centres (px) of the scatter dots of `svg` (filled, translucent circles) by fill
/// colour, in order of first appearance.
fn dots(svg: &str) -> Vec<(String, Vec<[f64; 2]>)> {
    let mut out: Vec<(String, Vec<[f64; 2]>)> = Vec::new();
    for tag in svg
        .split("<circle")
        .skip(1)
        .map(|t| t.split('>').next().unwrap())
    {
        let attr = |n: &str| {
            tag.split(&format!(" {n}=\""))
                .nth(1)
                .map(|v| v.split('"').next().unwrap())
        };
        if attr("opacity") != Some("0.6") || attr("fill") == Some("none") {
            continue;
        }
        let (fill, cx, cy) = (
            attr("fill").unwrap(),
            attr("cx").unwrap(),
            attr("cy").unwrap(),
        );
        let p = [cx.parse().unwrap(), cy.parse().unwrap()];
        match out.iter_mut().find(|(f, _)| f == fill) {
            Some((_, v)) => v.push(p),
            None => out.push((fill.to_string(), vec![p])),
        }
    }
    out
}

#[test]
fn a_second_axis_colours_the_cases_with_one_legend() {
    // Gears 1 to 4 (whole numbers) × three frictions, each case twice: 24 rows, two
    // metrics. Against the gear, the cases are coloured by the friction (the other axis,
    // 3 values), and the reverse.
    let mut rows = Vec::new();
    for rep in 0..2 {
        for gear in 1..=4 {
            for mu in ["0.5", "1", "2"] {
                let k = rows.len();
                let m: f64 = mu.parse().unwrap();
                let y = f64::from(gear) * m + f64::from(rep);
                rows.push(format!("{k},{gear},{mu},{y},{},,,0", y + 1.0));
            }
        }
    }
    let header = "case,gear,mu,dist_m,time_s,notes,error,checksum";
    let out = plots("colour", &["gear", "mu"], header, &rows, &ColorBy::Auto).unwrap();
    let names: Vec<&str> = out.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["gear.svg", "mu.svg"]);
    let svg = &out[0].1;
    svg_text::assert_inside(svg);
    // One legend: its heading names the colour axis, then each value once, though two
    // panels show each of them (as dots and a mean line).
    let legend = legend_of(svg);
    assert_eq!(
        legend.first().map(String::as_str),
        Some("mu (lines: the mean at")
    );
    assert_eq!(legend[legend.len() - 3..], ["0.5", "1", "2"], "{legend:?}");
    assert_eq!(legend.iter().filter(|t| *t == "1").count(), 1);
    // A colour per friction, each with its 8 cases in each of the 2 panels.
    let by_colour = dots(svg);
    let plot_dots: Vec<(String, usize)> = by_colour
        .iter()
        .map(|(c, v)| (c.clone(), v.iter().filter(|p| p[0] < LEGEND_X).count()))
        .collect();
    assert_eq!(plot_dots.len(), 3, "{plot_dots:?}");
    assert!(plot_dots.iter().all(|(_, n)| *n == 16), "{plot_dots:?}");
    // The gear axis ticks in whole gears only: 1 to 4 under the lower panel.
    let [_, h] = svg_text::canvas(svg);
    let x_ticks: Vec<f64> = svg_text::boxes(svg)
        .iter()
        .filter(|(_, b)| b[1] > h - 60.0 && b[0] < LEGEND_X && b[0] > 64.0)
        .filter_map(|(t, _)| t.parse().ok())
        .collect();
    assert_eq!(x_ticks, [1.0, 2.0, 3.0, 4.0]);
    // Against the friction, coloured by gear: four colours, 6 cases each per panel.
    let svg = &out[1].1;
    svg_text::assert_inside(svg);
    let legend = legend_of(svg);
    assert_eq!(
        legend[legend.len() - 4..],
        ["1", "2", "3", "4"],
        "{legend:?}"
    );
    let counts: Vec<usize> = dots(svg)
        .iter()
        .map(|(_, v)| v.iter().filter(|p| p[0] < LEGEND_X).count())
        .collect();
    assert_eq!(counts, [12; 4], "{counts:?}");
}

#[test]
fn a_categorical_axis_has_a_box_and_strip_per_value() {
    // Three models × wet or not, 3 cases each: 18 rows. A boolean metric gets no panel.
    let mut rows = Vec::new();
    for rep in 0..3 {
        for (m, model) in ["BmwX5", "ToyotaPrius", "Bus"].into_iter().enumerate() {
            for wet in ["true", "false"] {
                let k = rows.len();
                let y = 40.0 + 10.0 * m as f64 + f64::from(rep);
                rows.push(format!("{k},{model},{wet},{y},{},,,0", wet == "true"));
            }
        }
    }
    let header = "case,vehicle.model,ground.wet,stop_distance_m,skidded,notes,error,checksum";
    let axes = ["vehicle.model", "ground.wet"];
    let out = plots("strips", &axes, header, &rows, &ColorBy::Auto).unwrap();
    let svg = &out[0].1;
    assert_eq!(out[0].0, "vehicle.model.svg");
    svg_text::assert_inside(svg);
    // One panel: the boolean metric has none.
    let texts: Vec<String> = svg_text::boxes(svg).into_iter().map(|t| t.0).collect();
    assert!(texts.contains(&"stop_distance_m".to_string()));
    assert!(!texts.contains(&"skidded".to_string()), "{texts:?}");
    // Each model named once under its column; its column holds its 6 cases, 3 of each
    // colour, and a box per colour.
    let columns: Vec<(String, f64)> = svg_text::boxes(svg)
        .into_iter()
        .filter(|(t, _)| ["BmwX5", "ToyotaPrius", "Bus"].contains(&t.as_str()))
        .map(|(t, b)| (t, 0.5 * (b[0] + b[2])))
        .collect();
    let names: Vec<&str> = columns.iter().map(|c| c.0.as_str()).collect();
    assert_eq!(names, ["BmwX5", "ToyotaPrius", "Bus"]);
    let width = columns[1].1 - columns[0].1;
    let by_colour = dots(svg);
    assert_eq!(by_colour.len(), 2, "one colour per value of ground.wet");
    for (_, x) in &columns {
        for (colour, points) in &by_colour {
            let n = points
                .iter()
                .filter(|p| (p[0] - x).abs() < 0.5 * width)
                .count();
            assert_eq!(n, 3, "{colour} at {x}");
        }
    }
    let boxes = svg.matches("<rect").count();
    // The background, then a filled and an outlined rectangle per box: 3 × 2 boxes.
    assert_eq!(boxes, 1 + 2 * 6, "{svg}");
    let legend = legend_of(svg);
    assert_eq!(
        legend,
        ["ground.wet (boxes:", "quartiles, median)", "true", "false"]
    );
    // Against ground.wet (two categories), coloured by the model.
    let svg = &out[1].1;
    svg_text::assert_inside(svg);
    assert_eq!(dots(svg).len(), 3);
}

#[test]
fn the_colour_axis_is_chosen_or_refused() {
    let rows: Vec<String> = (0..16)
        .map(|k| format!("{k},{},{},{}.5,,,0", k % 2, k, k))
        .collect();
    let header = "case,a,b,m,notes,error,checksum";
    // b has 16 values: too many to colour by; a is chosen automatically for b's plot.
    let out = plots("auto", &["a", "b"], header, &rows, &ColorBy::Auto).unwrap();
    assert_eq!(dots(&out[0].1).len(), 1, "a's plot: b has too many values");
    assert_eq!(
        dots(&out[1].1).len(),
        2,
        "b's plot: one colour per value of a"
    );
    let off = plots("off", &["a", "b"], header, &rows, &ColorBy::Off).unwrap();
    assert!(off.iter().all(|(_, svg)| dots(svg).len() == 1));
    // Uncoloured: the cases and their means, no heading.
    assert_eq!(legend_of(&off[1].1), ["cases", "mean at each value"]);
    for (axis, reason) in [
        ("c", "the sweep's axes are a, b"),
        ("b", "it has more than 7 values, one colour each"),
    ] {
        let e = plots(
            "refused",
            &["a", "b"],
            header,
            &rows,
            &ColorBy::Axis(axis.into()),
        );
        match e {
            Err(OutputError::ColorBy { axis: a, reason: r }) => {
                assert_eq!((a.as_str(), r.as_str()), (axis, reason));
            }
            other => panic!("{other:?}"),
        }
    }
}
