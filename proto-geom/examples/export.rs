//! Writes a Webots wheel or a whole shipped vehicle to Wavefront OBJ and/or binary glTF.
//!
//! ```text
//! cargo run -p proto-geom --example export -- --wheel BmwX5Wheel --obj wheel.obj
//! cargo run -p proto-geom --example export -- --vehicle BmwX5 --glb bmw.glb
//! cargo run -p proto-geom --example export -- --list
//! ```
//!
//! Without `--wheel` or `--vehicle` the default `VehicleWheel {}` is exported. An OBJ file gets
//! its materials in a `.mtl` file beside it. `--help` prints the usage.

use std::error::Error;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use ackermann::Wheel;
use proto_geom::export::{ChassisBox, Scene};
use proto_geom::{ShippedVehicle, TriMesh, WheelPreset};

/// A body box for the vehicle: from the rear to the front sensor slot and up to the roof slot
/// when the model has them, else around the wheels (m).
fn chassis(vehicle: ShippedVehicle) -> ChassisBox<f64> {
    let layout = vehicle.layout::<f64>();
    let d = layout.dimensions();
    let front = layout.wheel(Wheel::FrontRight).params();
    let rear = layout.wheel(Wheel::RearRight).params();
    let width = d.track_front.max(d.track_rear) + 0.5 * front.thickness.max(rear.thickness);
    match vehicle.sensor_slots::<f64>() {
        Some(s) => ChassisBox::from_extents(
            s.rear.translation.x,
            s.front.translation.x,
            width,
            0.0,
            s.top.translation.z,
        ),
        None => ChassisBox::from_extents(
            -1.2 * rear.tire_radius,
            d.wheelbase + 1.2 * front.tire_radius,
            width,
            0.0,
            3.0 * front.tire_radius,
        ),
    }
}

fn write_obj(scene: &Scene, path: &Path) -> Result<(), Box<dyn Error>> {
    let mtl = path.with_extension("mtl");
    let mtl_name = mtl
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or("materials.mtl");
    let mut out = BufWriter::new(File::create(path)?);
    scene.write_obj(&mut out, Some(mtl_name))?;
    out.flush()?;
    let mut out = BufWriter::new(File::create(&mtl)?);
    scene.write_mtl(&mut out)?;
    out.flush()?;
    println!("wrote {} and {}", path.display(), mtl.display());
    Ok(())
}

/// The usage text of `--help`.
const USAGE: &str = "\
Usage: export [--wheel NAME | --vehicle NAME] [--obj FILE] [--glb FILE]
       export --list
       export --help

Writes a Webots wheel (default: VehicleWheel) or a whole shipped vehicle to Wavefront OBJ
(with its .mtl beside it) and/or binary glTF.

  --wheel NAME    a shipped wheel PROTO (see --list)
  --vehicle NAME  a shipped vehicle PROTO (see --list)
  --obj FILE      write Wavefront OBJ
  --glb FILE      write binary glTF
  --list          list the wheels and vehicles
  -h, --help      print this help";

/// What the command line asks for.
#[derive(Debug, Default, PartialEq)]
struct Args {
    help: bool,
    list: bool,
    wheel: Option<String>,
    vehicle: Option<String>,
    obj: Option<String>,
    glb: Option<String>,
}

/// Parses the arguments (without the program name).
fn parse_args(args: impl IntoIterator<Item = String>) -> Result<Args, String> {
    let mut a = Args::default();
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let slot = match arg.as_str() {
            "-h" | "--help" => {
                a.help = true;
                continue;
            }
            "--list" => {
                a.list = true;
                continue;
            }
            "--wheel" => &mut a.wheel,
            "--vehicle" => &mut a.vehicle,
            "--obj" => &mut a.obj,
            "--glb" => &mut a.glb,
            other => return Err(format!("unknown argument {other:?} (see --help)")),
        };
        *slot = Some(args.next().ok_or(format!("{arg} needs a value"))?);
    }
    Ok(a)
}

fn main() -> Result<(), Box<dyn Error>> {
    let Args {
        help,
        list,
        wheel,
        vehicle,
        obj,
        glb,
    } = parse_args(std::env::args().skip(1))?;
    if help {
        println!("{USAGE}");
        return Ok(());
    }
    if list {
        let wheels: Vec<_> = WheelPreset::ALL.iter().map(|w| w.proto_name()).collect();
        let vehicles: Vec<_> = ShippedVehicle::ALL.iter().map(|v| v.proto_name()).collect();
        println!("wheels:   {}", wheels.join(" "));
        println!("vehicles: {}", vehicles.join(" "));
        return Ok(());
    }
    if obj.is_none() && glb.is_none() {
        return Err("nothing to write: give --obj FILE and/or --glb FILE (see --help)".into());
    }

    let scene = if let Some(name) = vehicle {
        let v = ShippedVehicle::from_proto_name(&name)
            .ok_or_else(|| format!("unknown vehicle {name:?} (see --list)"))?;
        let layout = v.layout::<f64>();
        println!(
            "{}: wheelbase {} m, tracks {} / {} m",
            v.proto_name(),
            layout.dimensions().wheelbase,
            layout.dimensions().track_front,
            layout.dimensions().track_rear
        );
        Scene::vehicle(v.proto_name(), &layout, &chassis(v))
    } else {
        let name = wheel.unwrap_or_else(|| "VehicleWheel".to_string());
        let preset = WheelPreset::from_proto_name(&name)
            .ok_or_else(|| format!("unknown wheel {name:?} (see --list)"))?;
        let (valid, warnings) = preset.params::<f64>().validate();
        for w in &warnings {
            eprintln!("warning: {w}");
        }
        let tyre = valid.tyre();
        println!(
            "{}: tyre {} vertices / {} triangles, rim {} / {}, hub {} / {}",
            preset.proto_name(),
            tyre.vertex_count(),
            tyre.triangle_count(),
            valid.rim_contour().vertex_count(),
            valid.rim_contour().triangle_count(),
            valid.rim_centre().vertex_count(),
            valid.rim_centre().triangle_count()
        );
        Scene::wheel(&valid)
    };

    if let Some(path) = obj {
        write_obj(&scene, Path::new(&path))?;
    }
    if let Some(path) = glb {
        std::fs::write(&path, scene.to_glb()?)?;
        println!("wrote {path}");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<Args, String> {
        parse_args(args.iter().map(|a| a.to_string()))
    }

    #[test]
    fn help_is_not_an_error() {
        // Before, `--help` was an "unknown argument" error.
        assert!(parse(&["--help"]).unwrap().help);
        assert!(parse(&["-h"]).unwrap().help);
        let a = parse(&["--vehicle", "BmwX5", "--glb", "b.glb"]).unwrap();
        assert_eq!(
            (a.vehicle.as_deref(), a.glb.as_deref()),
            (Some("BmwX5"), Some("b.glb"))
        );
        assert_eq!(parse(&["--obj"]).unwrap_err(), "--obj needs a value");
        assert!(parse(&["--fast"]).unwrap_err().contains("unknown argument"));
    }
}
