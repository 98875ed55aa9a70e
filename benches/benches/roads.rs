//! Criterion benchmarks of roads: the step of a cast car whose four wheels stand on a road's
//! triangle meshes against the same car on the flat ground (same run, the ratio printed), and
//! the import of a 10 km OpenDRIVE network.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use std::fmt::Write as _;
use std::hint::black_box;

use benches::control::LoopMode;
use benches::report::{self, Medians, format_ns};
use benches::scenes::{CarScene, flat_world, ring_road_world};
use criterion::{BenchmarkId, Criterion, criterion_group};
use sim::{Mounting, TyreChoice, World, WorldConfig};

/// Steps before measuring: the car reaches its cruising speed on its circle.
const SETTLE_STEPS: usize = 800;

fn scene(world: World) -> CarScene {
    let mut s = CarScene::in_world(
        world,
        1,
        LoopMode::Speed,
        &TyreChoice::default(),
        Mounting::Cast,
    )
    .unwrap();
    if report::is_bench_run() {
        for _ in 0..SETTLE_STEPS {
            s.step().unwrap();
        }
    }
    s
}

/// An OpenDRIVE network of `roads` roads of 100 m (line, spiral, arc, spiral, line: 20 m
/// each), two 3.5 m lanes each way with marks, an elevation and a superelevation record,
/// each road placed beside the last: 10 km for 100 roads.
fn network(roads: usize) -> String {
    let mut x = String::from(
        "<?xml version=\"1.0\"?>\n<OpenDRIVE><header revMajor=\"1\" revMinor=\"6\"/>\n",
    );
    for r in 0..roads {
        let y = 30.0 * r as f64;
        let _ = write!(
            x,
            "<road id=\"{r}\" length=\"100\" junction=\"-1\"><planView>"
        );
        let mut s = 0.0;
        let (mut px, mut py, mut h) = (0.0_f64, y, 0.0_f64);
        for shape in [
            "<line/>",
            "<spiral curvStart=\"0\" curvEnd=\"0.01\"/>",
            "<arc curvature=\"0.01\"/>",
            "<spiral curvStart=\"0.01\" curvEnd=\"0\"/>",
            "<line/>",
        ] {
            let _ = write!(
                x,
                "<geometry s=\"{s}\" x=\"{px:.12}\" y=\"{py:.12}\" hdg=\"{h:.12}\" length=\"20\">{shape}</geometry>"
            );
            let seg = sim::road::Segment {
                s: 0.0,
                start: sim::nalgebra::Point2::new(px, py),
                heading: h,
                length: 20.0,
                curve: curve(shape),
            };
            let end = seg.end();
            (px, py, h) = (end.point.x, end.point.y, end.heading);
            s += 20.0;
        }
        x.push_str("</planView><elevationProfile><elevation s=\"0\" a=\"0\" b=\"0.01\" c=\"0\" d=\"0\"/></elevationProfile>");
        x.push_str("<lateralProfile><superelevation s=\"0\" a=\"0.02\" b=\"0\" c=\"0\" d=\"0\"/></lateralProfile><lanes><laneSection s=\"0\">");
        x.push_str("<left><lane id=\"1\" type=\"driving\"><width sOffset=\"0\" a=\"3.5\"/><roadMark type=\"solid\" width=\"0.12\"/></lane></left>");
        x.push_str("<center><lane id=\"0\"><roadMark type=\"broken\" color=\"yellow\" width=\"0.12\"/></lane></center>");
        x.push_str("<right><lane id=\"-1\" type=\"driving\"><width sOffset=\"0\" a=\"3.5\"/><roadMark type=\"solid\" width=\"0.12\"/></lane></right>");
        x.push_str("</laneSection></lanes></road>\n");
    }
    x.push_str("</OpenDRIVE>\n");
    x
}

fn curve(shape: &str) -> sim::road::Curve {
    use sim::road::Curve;
    match shape {
        "<arc curvature=\"0.01\"/>" => Curve::Arc { curvature: 0.01 },
        "<spiral curvStart=\"0\" curvEnd=\"0.01\"/>" => Curve::Spiral {
            curvature_start: 0.0,
            curvature_end: 0.01,
        },
        "<spiral curvStart=\"0.01\" curvEnd=\"0\"/>" => Curve::Spiral {
            curvature_start: 0.01,
            curvature_end: 0.0,
        },
        _ => Curve::Line,
    }
}

fn roads(c: &mut Criterion) {
    let mut g = c.benchmark_group("roads");
    let mut flat = scene(flat_world().unwrap());
    g.bench_function(BenchmarkId::new("cast_car_step", "flat"), |b| {
        b.iter(|| flat.step().unwrap())
    });
    let mut road = scene(ring_road_world().unwrap());
    g.bench_function(BenchmarkId::new("cast_car_step", "road"), |b| {
        b.iter(|| road.step().unwrap())
    });
    let text = network(100);
    g.bench_function(BenchmarkId::new("opendrive_import", "10km"), |b| {
        b.iter(|| sim::road::opendrive::parse_str("net.xodr", black_box(&text)).unwrap())
    });
    let net = sim::road::opendrive::parse_str("net.xodr", &text)
        .unwrap()
        .network;
    g.sample_size(10);
    g.bench_function(BenchmarkId::new("world_with_network", "10km"), |b| {
        b.iter(|| {
            World::new(WorldConfig {
                roads: net.clone(),
                ..WorldConfig::default()
            })
            .unwrap()
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = roads
}

fn summary(m: &Medians) {
    let (Some(flat), Some(road)) = (
        m.get("roads/cast_car_step/flat"),
        m.get("roads/cast_car_step/road"),
    ) else {
        return;
    };
    println!(
        "\nroads: a cast car's step on the road {} vs {} on the flat: {:+.1} % (target: at most +20 %)",
        format_ns(road),
        format_ns(flat),
        100.0 * (road / flat - 1.0)
    );
    if let Some(import) = m.get("roads/opendrive_import/10km") {
        println!(
            "roads: importing a 10 km OpenDRIVE network: {} (target: under 1 s)",
            format_ns(import)
        );
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
