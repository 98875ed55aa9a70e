//! The plots of a run: which figures, with which series, from any [`RunReport`].

use vehicle_model::Wheel;

use crate::config::OutlineKind;
use crate::scenario::{RunReport, Scenario, ScenarioResult};
use crate::telemetry::{Sample, Telemetry, VehicleKind};

use super::plot::{Figure, Panel, Series, SeriesKind, XAxis};

/// Lines joined into one series, separated by a NaN point (a lift of the pen).
fn joined<'a>(lines: impl IntoIterator<Item = &'a Vec<[f64; 2]>>) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    for line in lines {
        if !out.is_empty() {
            out.push([f64::NAN; 2]);
        }
        out.extend(line.iter().copied());
    }
    out
}

/// The legend name of `t` of result `r` in `report`: the scenario when every scenario drove
/// one vehicle, the vehicle when one scenario ran, else both.
fn name_of(report: &RunReport, r: &ScenarioResult, t: &Telemetry) -> String {
    if report.results.iter().all(|x| x.telemetry.len() == 1) {
        r.name.clone()
    } else if report.results.len() == 1 {
        t.vehicle.clone()
    } else {
        format!("{}: {}", r.name, t.vehicle)
    }
}

/// Every telemetry of the run with its legend name.
fn runs(report: &RunReport) -> impl Iterator<Item = (String, &Telemetry)> {
    report
        .results
        .iter()
        .flat_map(move |r| r.telemetry.iter().map(move |t| (name_of(report, r, t), t)))
}

/// One series per telemetry of `kind` of `f(sample)` against time, leaving out those where
/// `f` gives nothing.
fn series(
    report: &RunReport,
    kind: VehicleKind,
    f: impl Fn(&Sample) -> Option<f64>,
) -> Vec<Series> {
    runs(report)
        .filter(|(_, t)| t.kind == kind)
        .filter_map(|(name, t)| {
            let points: Vec<[f64; 2]> = t
                .samples
                .iter()
                .filter_map(|s| f(s).map(|v| [s.time, v]))
                .collect();
            (!points.is_empty()).then(|| Series::line(name, points))
        })
        .collect()
}

/// The plots of a run, by file name: speed, rpm and gear, the energy flows (cars with
/// energy accounting), steering, the lane change and its tyres' friction use, and the
/// trajectory; a plot without data (e.g. rpm for a robot) is left out. Car speeds are in km/h, robot speeds in m/s.
pub fn figures(report: &RunReport) -> Vec<(&'static str, Figure)> {
    let title = |what: &str| format!("{what}: {}, {}", report.vehicle, report.scenario);
    let time = "time (s)".to_string();
    let mut out = Vec::new();
    let mut speed_panels = Vec::new();
    let car_speeds = series(report, VehicleKind::Car, |s| Some(s.speed_kmh));
    if !car_speeds.is_empty() {
        speed_panels.push(Panel {
            y_label: "car speed (km/h)".into(),
            series: car_speeds,
        });
    }
    let robot_speeds = series(report, VehicleKind::Robot, |s| Some(s.speed()));
    if !robot_speeds.is_empty() {
        speed_panels.push(Panel {
            y_label: "robot speed (m/s)".into(),
            series: robot_speeds,
        });
    }
    out.push((
        "speed.svg",
        Figure {
            title: title("Speed"),
            x_label: time.clone(),
            panels: speed_panels,
            equal_aspect: false,
            x_axis: XAxis::Continuous,
            legend_title: None,
        },
    ));
    // Runs whose engine never turned (braking in neutral) would only add a flat line.
    let rpm: Vec<Series> = series(report, VehicleKind::Car, |s| s.rpm)
        .into_iter()
        .filter(|s| s.points.iter().any(|p| p[1] != 0.0))
        .collect();
    let engine_runs: Vec<&str> = rpm.iter().map(|s| s.name.as_str()).collect();
    let gears: Vec<Series> = series(report, VehicleKind::Car, |s| s.gear.map(f64::from))
        .into_iter()
        .filter(|s| engine_runs.contains(&s.name.as_str()))
        .map(|s| Series {
            kind: SeriesKind::Steps,
            ..s
        })
        .collect();
    if !rpm.is_empty() {
        out.push((
            "rpm_gear.svg",
            Figure {
                title: title("Engine speed and gear"),
                x_label: time.clone(),
                panels: vec![
                    Panel {
                        y_label: "engine speed (rpm)".into(),
                        series: rpm,
                    },
                    Panel {
                        y_label: "gear".into(),
                        series: gears,
                    },
                ],
                equal_aspect: false,
                x_axis: XAxis::Continuous,
                legend_title: None,
            },
        ));
    }
    if let Some(figure) = energy(report, title("Energy")) {
        out.push(("energy.svg", figure));
    }
    let turning = |s: &Sample| s.steering_command.is_some_and(|d| d != 0.0);
    let mut lines = Vec::new();
    for (name, t) in runs(report).filter(|(_, t)| t.samples.iter().any(turning)) {
        for (what, f) in [
            (
                "commanded",
                (|s: &Sample| s.steering_command) as fn(&Sample) -> Option<f64>,
            ),
            ("measured", |s: &Sample| s.steering),
        ] {
            lines.push(Series::line(
                format!("{name} ({what})"),
                t.samples
                    .iter()
                    .filter_map(|s| f(s).map(|v| [s.time, v]))
                    .collect(),
            ));
        }
    }
    if !lines.is_empty() {
        out.push((
            "steering.svg",
            Figure {
                title: title("Steering angle (positive = right)"),
                x_label: time,
                panels: vec![Panel {
                    y_label: "steering angle (rad)".into(),
                    series: lines,
                }],
                equal_aspect: false,
                x_axis: XAxis::Continuous,
                legend_title: None,
            },
        ));
    }
    let lane_change = report.result(Scenario::LaneChange.name());
    if let Some(r) = lane_change {
        let mut series = course(r);
        series.extend(r.telemetry.iter().map(|t| {
            Series::line(
                "rear-axle centre",
                t.samples.iter().map(|s| [s.x, s.y]).collect(),
            )
        }));
        out.push((
            "lane_change.svg",
            Figure {
                title: title("Double lane change, lateral scale exaggerated"),
                x_label: "x (m)".into(),
                panels: vec![Panel {
                    y_label: "y (m)".into(),
                    series,
                }],
                equal_aspect: false,
                x_axis: XAxis::Continuous,
                legend_title: None,
            },
        ));
    }
    if let Some(figure) = lane_change.and_then(|r| {
        friction_use(
            &r.telemetry.first()?.samples,
            title("Tyre friction use, double lane change"),
        )
    }) {
        out.push(("friction_use.svg", figure));
    }
    out.push((
        "trajectory.svg",
        trajectory(report, title("Trajectory seen from above")),
    ));
    if let Some(figure) = lateral(
        report,
        title("Lateral position along the run, lateral scale exaggerated"),
    ) {
        out.push(("lateral.svg", figure));
    }
    out
}

/// W per kW.
const W_PER_KW: f64 = 1000.0;

/// The energy flows of the cars with energy accounting against time: the power at the driven
/// wheels and the battery's (kW), the state of charge (%) and the fuel rate (g/s), a panel
/// each where some car has it; `None` when no car has energy accounting.
fn energy(report: &RunReport, title: String) -> Option<Figure> {
    let kw = |v: Option<f64>| v.map(|v| v / W_PER_KW);
    let named = |suffix: &str, series: Vec<Series>| -> Vec<Series> {
        series
            .into_iter()
            .map(|s| Series {
                name: format!("{} ({suffix})", s.name),
                ..s
            })
            .collect()
    };
    let mut power = named(
        "wheels",
        series(report, VehicleKind::Car, |s| kw(s.wheel_power)),
    );
    power.extend(named(
        "battery",
        series(report, VehicleKind::Car, |s| kw(s.battery_power)),
    ));
    let panels: Vec<Panel> = [
        ("power (kW)", power),
        (
            "state of charge (%)",
            series(report, VehicleKind::Car, |s| s.soc_percent),
        ),
        (
            "fuel rate (g/s)",
            series(report, VehicleKind::Car, |s| s.fuel_rate),
        ),
    ]
    .into_iter()
    .filter(|(_, series)| !series.is_empty())
    .map(|(y_label, series)| Panel {
        y_label: y_label.into(),
        series,
    })
    .collect();
    (!panels.is_empty()).then(|| Figure {
        title,
        x_label: "time (s)".into(),
        panels,
        equal_aspect: false,
        x_axis: XAxis::Continuous,
        legend_title: None,
    })
}

/// How many times longer than wide a run is when its lateral motion gets its own plot: at
/// equal scales on a 760 × 560 px map, a run 5 times longer than wide draws its width in at
/// most a fifth of the map's height, where a lane change of a 3.5 m lane on a 2 km run is
/// under a pixel.
const LONG_RUN: f64 = 5.0;

/// Every vehicle's lateral position (m, left of the run's direction positive) against its
/// distance along the run (m), for a run at least [`LONG_RUN`] times longer than wide (a
/// convoy on a highway), whose lane changes vanish at equal scales. The run's direction is
/// from the first vehicle's first position to its last; `None` for a shorter or wider run.
fn lateral(report: &RunReport, title: String) -> Option<Figure> {
    let first = runs(report).next()?.1;
    let (start, end) = (first.samples.first()?, first.samples.last()?);
    let length = (end.x - start.x).hypot(end.y - start.y);
    if length < 1.0 {
        return None;
    }
    let (c, s) = ((end.x - start.x) / length, (end.y - start.y) / length);
    let frame = |p: &Sample| {
        let (dx, dy) = (p.x - start.x, p.y - start.y);
        [c * dx + s * dy, -s * dx + c * dy]
    };
    let series: Vec<Series> = runs(report)
        .map(|(name, t)| Series::line(name, t.samples.iter().map(frame).collect()))
        .collect();
    let extent = |i: usize| {
        let values = series
            .iter()
            .flat_map(|s| s.points.iter().map(move |p| p[i]));
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        hi - lo
    };
    (extent(0) >= LONG_RUN * extent(1)).then(|| Figure {
        title,
        x_label: "distance along the run (m)".into(),
        panels: vec![Panel {
            y_label: "lateral position, left + (m)".into(),
            series,
        }],
        equal_aspect: false,
        x_axis: XAxis::Continuous,
        legend_title: None,
    })
}

/// The course of `r` (lane edges and cones), as series.
fn course(r: &ScenarioResult) -> Vec<Series> {
    let mut out = Vec::new();
    if !r.guides.is_empty() {
        out.push(Series {
            name: "lane edges".into(),
            points: joined(&r.guides),
            kind: SeriesKind::Guide,
        });
    }
    if !r.cones.is_empty() {
        out.push(Series {
            name: "cones".into(),
            points: r.cones.clone(),
            kind: SeriesKind::Cones,
        });
    }
    out
}

/// Every vehicle's path over the world's obstacles and the scenarios' courses.
fn trajectory(report: &RunReport, title: String) -> Figure {
    let mut series = Vec::new();
    for kind in [
        OutlineKind::RoadEdge,
        OutlineKind::LaneLine,
        OutlineKind::Box,
        OutlineKind::Ramp,
        OutlineKind::Cone,
        OutlineKind::Body,
    ] {
        let outlines: Vec<&Vec<[f64; 2]>> = report
            .obstacles
            .iter()
            .filter(|o| o.kind == kind)
            .map(|o| &o.points)
            .collect();
        if !outlines.is_empty() {
            series.push(Series {
                name: kind.legend().into(),
                points: joined(outlines),
                // Roads' lines are open lines, drawn as guides under the paths.
                kind: match kind {
                    OutlineKind::RoadEdge | OutlineKind::LaneLine => SeriesKind::Guide,
                    _ => SeriesKind::Outline,
                },
            });
        }
    }
    for r in &report.results {
        series.extend(course(r));
    }
    series.extend(
        runs(report)
            .map(|(name, t)| Series::line(name, t.samples.iter().map(|s| [s.x, s.y]).collect())),
    );
    Figure {
        title,
        x_label: "x (m)".into(),
        panels: vec![Panel {
            y_label: "y (m)".into(),
            series,
        }],
        equal_aspect: true,
        x_axis: XAxis::Continuous,
        legend_title: None,
    }
}

/// The friction use (0–1) of each tyre against time, one line per wheel, with the grip limit
/// (1) as a guide; `None` for samples without tyres (a robot).
fn friction_use(samples: &[Sample], title: String) -> Option<Figure> {
    let names = ["front right", "front left", "rear right", "rear left"];
    let mut series: Vec<Series> = Wheel::ALL
        .into_iter()
        .zip(names)
        .map(|(w, name)| {
            Series::line(
                name,
                samples
                    .iter()
                    .filter_map(|s| s.tyres.map(|t| [s.time, t[w].friction_use]))
                    .collect(),
            )
        })
        .filter(|s| !s.points.is_empty())
        .collect();
    let span = series
        .first()
        .and_then(|s| Some([s.points.first()?[0], s.points.last()?[0]]))?;
    series.push(Series {
        name: "grip limit".into(),
        points: vec![[span[0], 1.0], [span[1], 1.0]],
        kind: SeriesKind::Guide,
    });
    Some(Figure {
        title,
        x_label: "time (s)".into(),
        panels: vec![Panel {
            y_label: "friction use (0 to 1)".into(),
            series,
        }],
        equal_aspect: false,
        x_axis: XAxis::Continuous,
        legend_title: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TyreTelemetry;
    use vehicle_model::PerWheel;

    /// A run of `cars` on a 2 km straight along the world's north-east diagonal, the second
    /// car changing lane by 3.5 m to the left half way.
    fn convoy(cars: usize) -> RunReport {
        let d = core::f64::consts::FRAC_1_SQRT_2;
        let telemetry = (0..cars)
            .map(|k| Telemetry {
                vehicle: format!("car-{k}"),
                kind: VehicleKind::Car,
                samples: (0..=200)
                    .map(|i| {
                        let along = 10.0 * f64::from(i);
                        let left = if k == 1 && along > 1000.0 { 3.5 } else { 0.0 };
                        Sample {
                            time: f64::from(i),
                            x: d * along - d * left,
                            y: d * along + d * left,
                            ..Sample::default()
                        }
                    })
                    .collect(),
                ..Telemetry::default()
            })
            .collect();
        RunReport {
            vehicle: "2 vehicles".into(),
            scenario: "programme".into(),
            results: vec![ScenarioResult::new("programme", telemetry)],
            ..RunReport::default()
        }
    }

    #[test]
    fn a_long_run_gets_its_lateral_motion_plotted() {
        let report = convoy(2);
        let all = figures(&report);
        let (_, f) = all.iter().find(|(n, _)| *n == "lateral.svg").unwrap();
        let series = &f.panels[0].series;
        assert_eq!(series.len(), 2);
        // The run's direction is the first car's: it stays on the x axis, 2 km long; the
        // second car's lane change is 3.5 m to the left (rounding of the rotation: 1e-9 m).
        let (lo, hi) = series[1]
            .points
            .iter()
            .fold((0.0_f64, 0.0_f64), |(lo, hi), p| {
                (lo.min(p[1]), hi.max(p[1]))
            });
        assert!(lo.abs() < 1e-9 && (hi - 3.5).abs() < 1e-9, "{lo} {hi}");
        assert!((series[0].points.last().unwrap()[0] - 2000.0).abs() < 1e-9);
        assert!(series[0].points.iter().all(|p| p[1].abs() < 1e-9));
        let svg = f.to_svg().unwrap();
        super::super::plot::svg_text::assert_inside(&svg);
        // Each car drawn in its own style: two legend entries, two colours.
        let trajectory = &all.iter().find(|(n, _)| *n == "trajectory.svg").unwrap().1;
        let svg = trajectory.to_svg().unwrap();
        super::super::plot::svg_text::assert_inside(&svg);
        assert!(svg.contains("#0072B2") && svg.contains("#D55E00"));
    }

    #[test]
    fn a_short_or_wide_run_has_no_lateral_plot() {
        // 2 km long, bulging 0.7 km to the side (1 km north at mid-run, across a north-east
        // run): the map shows it.
        let mut report = convoy(1);
        for s in &mut report.results[0].telemetry[0].samples {
            s.y += 1000.0 * (core::f64::consts::PI * s.time / 200.0).sin();
        }
        assert!(figures(&report).iter().all(|(n, _)| *n != "lateral.svg"));
    }

    #[test]
    fn friction_use_has_one_labelled_line_per_tyre() {
        let tyres = PerWheel::from_fn(|w| TyreTelemetry {
            friction_use: if w.is_front() { 0.5 } else { 0.25 },
            ..TyreTelemetry::default()
        });
        let samples: Vec<Sample> = (0..3)
            .map(|i| Sample {
                time: 0.01 * f64::from(i),
                tyres: Some(tyres),
                ..Sample::default()
            })
            .collect();
        let f = friction_use(&samples, "t".into()).unwrap();
        let panel = &f.panels[0];
        let names: Vec<&str> = panel.series.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "front right",
                "front left",
                "rear right",
                "rear left",
                "grip limit"
            ]
        );
        assert_eq!(
            panel.series[0].points,
            [[0.0, 0.5], [0.01, 0.5], [0.02, 0.5]]
        );
        assert_eq!(panel.series[3].points[2], [0.02, 0.25]);
        assert_eq!(panel.series[4].points, [[0.0, 1.0], [0.02, 1.0]]);
        // A robot has no tyres.
        assert_eq!(friction_use(&[Sample::default()], "t".into()), None);
    }
}
