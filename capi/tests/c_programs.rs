//! The C and C++ test programs of `capi/tests/` (see `README.md` there), as Webots controllers
//! use the API: `capi/stage.sh` stages the headers and the libraries, each program is compiled
//! with the system compiler (`cc`, `c++`) against the staged tree and run with its
//! `VEHICLE_WORLD`, and must exit 0 with exactly the stderr lines Webots prints. Also the
//! header checks of `check_headers.sh`.
//!
//! Needs `cc` and `c++` on the PATH.

mod common;

use std::process::Command;

use common::*;

#[test]
fn cruise_bmw() {
    run_exact(
        "cruise_bmw",
        None,
        &shared_link_flags(),
        &["Warning: \"no such device\" device not found."],
    );
}

#[test]
fn torque_combustion() {
    run_exact(
        "torque_combustion",
        Some("BmwX5"),
        &shared_link_flags(),
        &[],
    );
}

#[test]
fn torque_electric() {
    run_exact(
        "torque_electric",
        Some("TeslaModel3"),
        &shared_link_flags(),
        &[],
    );
}

/// `lights` is built with the flags of the staged pkg-config file (read directly, so that the
/// test does not need pkg-config itself).
#[test]
fn lights_built_with_the_pkg_config_flags() {
    let pc = std::fs::read_to_string(prefix().join("lib/pkgconfig/webots-vehicle.pc")).unwrap();
    let field = |name: &str| {
        pc.lines()
            .find_map(|l| l.strip_prefix(&format!("{name}: ")))
            .unwrap_or_else(|| panic!("no {name} in webots-vehicle.pc"))
            .replace("${includedir}", &include_dir().display().to_string())
            .replace("${libdir}", &lib_dir().display().to_string())
    };
    assert_eq!(field("Cflags"), format!("-I{}", include_dir().display()));
    let libs: Vec<String> = field("Libs").split_whitespace().map(String::from).collect();
    run_exact(
        "lights",
        None,
        &libs,
        &[
            "Warning: Deprecated 'wbu_driver_set_brake' use 'wbu_driver_set_brake_intensity' instead.",
            "Warning: Deprecated 'wbu_driver_get_brake' use 'wbu_driver_get_brake_intensity' instead.",
            "Warning: Deprecated 'wbu_driver_set_brake' use 'wbu_driver_set_brake_intensity' instead.",
        ],
    );
}

#[test]
fn bad_input() {
    // 12 calls before init, 4 gears, 6 throttle/brake clamps, 3 NaN steerings, 5 wheel
    // indices, 2 SPEED-mode getters, 2 after cleanup: 34 announced texts.
    run_announcing("bad_input", None, 34);
}

#[test]
fn differential_wheels() {
    run_announcing("differential_wheels", Some(&differential_wheels_world()), 9);
}

/// The sensors of a world file's car, the device enumeration and the sensor misuse messages.
#[test]
fn sensors() {
    // 1 index out of bounds, 2 disabled reads, 1 negative period, 5 wrong tags (one of them
    // two lines) and the accelerometer's silent one (not counted).
    run_announcing("sensors", Some(&sensors_world()), 9);
}

/// A GPS in a world whose `gpsCoordinateSystem` is WGS84.
#[test]
fn gps_wgs84() {
    run_announcing("gps_wgs84", Some(&world_path("gps_wgs84.toml")), 0);
}

/// The RoadSensor extension of a world file's car against the road's closed forms, and its
/// misuse messages.
#[test]
fn road_sensor() {
    // 1 disabled read, 1 negative period, 1 wrong tag.
    run_announcing("road_sensor", Some(&world_path("road.toml")), 3);
}

/// The camera of a world file's car, its Recognition and the camera misuse messages.
#[test]
fn camera() {
    // 1 wrong tag, 1 disabled image, 1 negative period, 1 disabled Recognition, 1 JPEG.
    run_announcing("camera", Some(&world_path("camera.toml")), 5);
}

/// The keys a world's programme presses, read through webots/keyboard.h.
#[test]
fn keyboard() {
    // 1 disabled read, 1 negative period.
    run_announcing("keyboard", Some(&world_path("keyboard.toml")), 2);
}

/// The battery sensor of a car with Webots' battery field, and the controller stopped when
/// it empties.
#[test]
fn battery() {
    // 1 disabled read, 1 negative period.
    run_announcing("battery", Some(&world_path("battery.toml")), 2);
}

/// Drawing into a car's Display through webots/display.h, and the display misuse messages.
#[test]
fn display() {
    // 1 wrong tag, 1 bad colour, 1 bad opacity, 1 bad format, 1 stale image, 1 missing file,
    // 1 bad font size, 1 NULL font.
    run_announcing("display", Some(&world_path("display.toml")), 8);
}

/// The radar, lidars and distance sensor of a world file's car, and their misuse messages.
#[test]
fn ray_sensors() {
    // 1 frequency out of range, 1 disabled read, 1 negative period, 1 disabled cloud, 2 bad
    // layers, 3 wrong tags, 1 layer of a disabled lidar.
    run_announcing("ray_sensors", Some(&rays_world()), 10);
}

/// The C++ wrapper, linked with the libraries in the other order (`-lcar -ldriver`).
#[test]
fn cpp_wrapper() {
    let lib = lib_dir().display().to_string();
    let link = [
        format!("-L{lib}"),
        "-lcar".into(),
        "-ldriver".into(),
        format!("-Wl,-rpath,{lib}"),
    ];
    let exe = compile(
        "c++",
        "c++17",
        &tests_dir().join("cpp_wrapper.cpp"),
        "cpp_wrapper",
        &link,
    );
    let r = run(&exe, None);
    assert_passed("cpp_wrapper", r.status, &r.stdout);
    let lines: Vec<&str> = r.stderr.lines().collect();
    assert_eq!(
        lines,
        [
            // Driver::getGPS("gps") on a car without one, as in Webots.
            "Warning: \"gps\" device not found.",
            "Warning: Deprecated 'setWipersMode' use 'setWiperMode' instead.",
            "Warning: Deprecated 'getWipersMode' use 'getWiperMode' instead.",
            "Warning: Deprecated 'setBrake' use 'setBrakeIntensity' instead.",
            "Warning: Deprecated 'setBrake' use 'setBrakeIntensity' instead.",
        ]
    );
}

/// The C++ RoadSensor through Driver::getRoadSensor(), as C++11, against road_sensor.c's
/// closed forms.
#[test]
fn road_sensor_cpp() {
    let lib = lib_dir().display().to_string();
    let link = [
        format!("-L{lib}"),
        "-ldriver".into(),
        "-lcar".into(),
        format!("-Wl,-rpath,{lib}"),
    ];
    let exe = compile(
        "c++",
        "c++11",
        &tests_dir().join("road_sensor_cpp.cpp"),
        "road_sensor_cpp",
        &link,
    );
    let r = run(&exe, Some(&world_path("road.toml")));
    assert_passed("road_sensor_cpp", r.status, &r.stdout);
    let lines: Vec<&str> = r.stderr.lines().collect();
    // Driver::getRoadSensor("nothing"), as Webots' getters warn.
    assert_eq!(lines, ["Warning: \"nothing\" device not found."]);
}

/// Every header alone in every C and C++ standard, and the programs' syntax.
#[test]
fn check_headers() {
    let out = Command::new("bash")
        .arg(tests_dir().join("check_headers.sh"))
        .arg(include_dir())
        .env("CC", "cc")
        .env("CXX", "c++")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "check_headers.sh failed:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn announced_stderr_checker() {
    let ok = "p: start\np: call: x -> stderr: Warning: a\nWarning: a\np: ok: 1\n\
              p: call: y -> stderr: Warning: no newline\nWarning: no newlinep: ok: 2\n\
              p: call: z\nlibrary's own text\np: PASS (2 checks)\n";
    assert_eq!(check_announced_stderr("p", ok), Ok(2));
    let extra = "p: call: x -> stderr: W\nW\nsurprise\np: PASS\n";
    assert!(check_announced_stderr("p", extra).is_err());
    let missing = "p: call: x -> stderr: W\np: PASS\n";
    assert!(check_announced_stderr("p", missing).is_err());
    let stray = "p: start\nstray\n";
    assert!(check_announced_stderr("p", stray).is_err());
    let two_lines = "p: call: x -> stderr: E: a\\nE: b\nE: a\nE: b\np: PASS\n";
    assert_eq!(check_announced_stderr("p", two_lines), Ok(1));
}

/// A controller run with `VEHICLE_OUT` writes `telemetry.csv`, `metrics.json` and
/// `replay.glb`; its telemetry rows equal those of the same commands given to `vehicle-sim` as
/// a programme (`--scenario programme`, whose code this runs), value for value, but for the
/// run's name in the first column. The world puts the car on joints with Webots' tyre and
/// proportioned brakes, so that nothing of it may be dropped on either way.
#[test]
fn a_controller_run_writes_the_outputs_of_the_same_programme() {
    let world = tests_dir().join("worlds/outputs.toml");
    let out = scratch().join("outputs-controller");
    let _ = std::fs::remove_dir_all(&out);
    let exe = compile(
        "cc",
        "c99",
        &tests_dir().join("outputs.c"),
        "outputs",
        &shared_link_flags(),
    );
    let mut cmd = Command::new(&exe);
    cmd.env("VEHICLE_OUT", &out);
    let r = run_command(cmd, Some(&world.display().to_string()));
    assert!(r.status.success(), "outputs: {}{}", r.stdout, r.stderr);
    // The world's programme is the other way to drive it: the controller is told it does not
    // run.
    assert_eq!(
        r.stderr,
        format!(
            "Warning: {}: the world's programme is not run: the controller drives (vehicle-sim \
             runs programmes).\n",
            world.display()
        ),
        "outputs: stderr"
    );

    let description = sim::world_file::load_file(&world).unwrap();
    let report = sim::scenario::run(
        &description,
        sim::scenario::Scenario::Programme,
        &mut |_| {},
    )
    .unwrap();
    let expected = scratch().join("outputs-programme");
    let _ = std::fs::remove_dir_all(&expected);
    sim::report::write_data(&report, &[], &expected).unwrap();

    let rows = |dir: &std::path::Path| -> Vec<String> {
        std::fs::read_to_string(dir.join("telemetry.csv"))
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| l.split_once(',').unwrap().1.to_string())
            .collect()
    };
    let (controller, programme) = (rows(&out), rows(&expected));
    // 4 s of 10 ms steps and the state at the start.
    assert_eq!(controller.len(), 401);
    assert_eq!(controller, programme);
    let first = std::fs::read_to_string(out.join("telemetry.csv")).unwrap();
    assert!(
        first
            .lines()
            .nth(1)
            .unwrap()
            .starts_with("controller,BmwX5,0,")
    );

    let metrics: String = std::fs::read_to_string(out.join("metrics.json")).unwrap();
    assert!(metrics.contains("\"scenario\":\"controller\""), "{metrics}");
    assert!(metrics.contains("\"distance_m\""), "{metrics}");
    let glb = std::fs::read(out.join("replay.glb")).unwrap();
    assert_eq!(&glb[..4], b"glTF");
    // The GPS the controller enabled: 80 samples in 4 s at 50 ms, 7 values each.
    let devices = std::fs::read_to_string(out.join("devices.csv")).unwrap();
    let mut lines = devices.lines();
    assert_eq!(lines.next(), Some("time,car,device,quantity,value"));
    assert_eq!(lines.clone().count(), 80 * 7);
    assert!(
        lines.next().unwrap().starts_with("0.05,BmwX5,gps,x,"),
        "{devices}"
    );
}

/// The adaptive cruise controller example (`examples/acc/acc.c`) in `sim/worlds/acc.toml`:
/// the lead car drives at 20 m/s, slows to 15 m/s at 20 s and stops from 40 s.
#[test]
fn acc_example() {
    let root = capi_dir().join("..");
    let exe = compile(
        "cc",
        "c99",
        &root.join("examples/acc/acc.c"),
        "acc",
        &shared_link_flags(),
    );
    let world = root.join("sim/worlds/acc.toml").display().to_string();
    let r = run(&exe, Some(&world));
    assert!(r.status.success(), "{}{}", r.stdout, r.stderr);
    assert_eq!(r.stderr, "", "no warning");
    let log: Vec<[f64; 3]> = r
        .stdout
        .lines()
        .filter_map(|l| l.strip_prefix("acc: "))
        .map(|l| {
            let v: Vec<f64> = l.split(' ').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    // One line per 0.5 s; the step that ends the 60 s returns -1 before the last.
    assert_eq!(log.len(), 119);
    check_time_gap(&log);
}

/// The time gap the ACC examples keep (`TIME_GAP` 1.5 s beyond `STANDSTILL` 7 m): within
/// 10 % over the last 5 s before each of the lead car's speed steps (20 m/s until 20 s, 15 m/s
/// until 40 s, its target always in sight), and stopped behind it at the end: between
/// `STANDSTILL` and the distance where the command falls below `CREEP` (7 + 0.5/0.4 m), as the
/// radar measures it (1.5 m: three standard deviations of the Delphi ESR's range noise).
fn check_time_gap(log: &[[f64; 3]]) {
    for &[t, v, d] in log {
        let settled = (15.0..=20.0).contains(&t) || (35.0..=40.0).contains(&t);
        if settled {
            let gap = (d - 7.0) / v;
            assert!(
                (gap - 1.5).abs() <= 0.15,
                "time gap {gap} s at {t} s ({v} m/s, {d} m)"
            );
        }
    }
    let [t, v, d] = log[log.len() - 1];
    assert_eq!(t, 59.5);
    assert!(v.abs() < 0.1, "still moving at {v} m/s");
    assert!(
        (7.0 - 1.5..=8.25 + 1.5).contains(&d),
        "stopped {d} m behind"
    );
}
