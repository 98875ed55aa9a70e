//! The staged libraries as a whole: exported symbols against the headers, both libraries
//! loaded separately by Python's ctypes (as Webots' Python binding does), the static libraries,
//! the pkg-config file, the robot functions, the car library alone, invalid worlds, the
//! world's `duration`, and the controller of the crate README.
//!
//! Needs `cc`, `nm` and, for the ctypes check, `python3` on the PATH.

// Test helpers report failures by panicking.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use std::process::Command;

use common::*;

/// The function names a header declares (`wb_*`, `wbu_*` and `initialization_is_possible`).
fn declared_functions(header: &str) -> Vec<String> {
    let text = std::fs::read_to_string(include_dir().join("webots").join(header)).unwrap();
    let mut names: Vec<String> = text
        .lines()
        .filter(|l| !l.trim_start().starts_with('*') && !l.trim_start().starts_with("/*"))
        // Macros (camera.h's wb_camera_image_get_*) are no exported functions.
        .filter(|l| !l.trim_start().starts_with('#'))
        .filter_map(|l| {
            let (head, _) = l.split_once('(')?;
            let name = head.split_whitespace().last()?.trim_start_matches('*');
            let ours = name.starts_with("wb_")
                || name.starts_with("wbu_")
                || name == "initialization_is_possible";
            ours.then(|| name.to_string())
        })
        .collect();
    names.sort();
    names.dedup();
    names
}

/// The dynamic symbols a shared library defines.
fn defined_symbols(library: &str) -> Vec<String> {
    let out = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(lib_dir().join(library))
        .output()
        .expect("running nm");
    assert!(out.status.success());
    let mut names: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| l.split_whitespace().nth(2).map(String::from))
        .collect();
    names.sort();
    names
}

/// libdriver exports exactly the functions of `driver.h`; libcar those of `car.h`, `robot.h`
/// and `differential_wheels.h` plus the internal `vehicle_capi_driver_*` entry points, and no
/// `wbu_driver_*` symbol (so that linking both never defines one twice).
#[test]
fn exported_symbols_match_the_headers() {
    let driver_h = declared_functions("vehicle/driver.h");
    assert_eq!(driver_h.len(), 34, "{driver_h:?}");
    let driver_so: Vec<String> = defined_symbols("libdriver.so")
        .into_iter()
        .filter(|s| s.starts_with("wb") || s == "initialization_is_possible")
        .collect();
    assert_eq!(driver_so, driver_h);

    let car = defined_symbols("libcar.so");
    let mut expected: Vec<String> = [
        "vehicle/car.h",
        "robot.h",
        "differential_wheels.h",
        "device.h",
        "gps.h",
        "inertial_unit.h",
        "gyro.h",
        "accelerometer.h",
        "compass.h",
        "camera.h",
        "display.h",
        "keyboard.h",
        "distance_sensor.h",
        "radar.h",
        "lidar.h",
    ]
    .iter()
    .flat_map(|h| declared_functions(h))
    .collect();
    // car 21, robot 12 (the battery sensor's 4 included), DifferentialWheels 11, device 3, GPS 8, inertial unit 6, gyro,
    // accelerometer and compass 6 each, camera 18, display 21, keyboard 4, distance sensor 10,
    // radar 9, lidar 21.
    assert_eq!(
        expected.len(),
        21 + 12 + 11 + 3 + 8 + 6 + 3 * 6 + 18 + 21 + 4 + 10 + 9 + 21,
        "{expected:?}"
    );
    expected.extend(
        driver_h
            .iter()
            .filter(|n| n.starts_with("wbu_driver_"))
            .map(|n| n.replace("wbu_driver_", "vehicle_capi_driver_")),
    );
    expected.sort();
    let exported: Vec<String> = car
        .into_iter()
        .filter(|s| s.starts_with("wb") || s.starts_with("vehicle_capi_") || s.starts_with("init"))
        .collect();
    assert_eq!(exported, expected);
}

/// Runs the python3 `script` with the staged library directory as its argument and no
/// `VEHICLE_WORLD`.
fn run_python(script: &str) -> Run {
    let mut cmd = Command::new("python3");
    cmd.arg("-c").arg(script).arg(lib_dir());
    run_command(cmd, None)
}

/// Webots' Python binding opens `libcar.so` and `libdriver.so` one by one with ctypes: both
/// must share one car. Initialised through libdriver, read through libcar, and back.
#[test]
fn python_ctypes_loads_both_libraries_separately() {
    if Command::new("python3").arg("--version").output().is_err() {
        eprintln!("python_ctypes_loads_both_libraries_separately: skipped, no python3 on PATH");
        return;
    }
    let script = r#"
import ctypes, sys
lib = sys.argv[1]
car = ctypes.CDLL(lib + "/libcar.so")
driver = ctypes.CDLL(lib + "/libdriver.so")
assert not hasattr(car, "wbu_driver_init"), "libcar exports a driver symbol"
double = ctypes.c_double
for f in ("wbu_car_get_wheelbase", "wbu_car_get_wheel_speed", "wb_robot_get_time"):
    getattr(car, f).restype = double
car.wbu_car_get_wheel_speed.argtypes = [ctypes.c_int]
driver.wbu_driver_set_cruising_speed.argtypes = [double]
driver.wbu_driver_get_target_cruising_speed.restype = double
driver.wbu_driver_get_current_speed.restype = double
driver.wbu_driver_get_control_mode.restype = ctypes.c_int
driver.initialization_is_possible.restype = ctypes.c_bool
assert driver.initialization_is_possible()
driver.wbu_driver_init()
assert car.wbu_car_get_wheelbase() == 2.995, car.wbu_car_get_wheelbase()
driver.wbu_driver_set_cruising_speed(20.0)
for _ in range(300):
    assert driver.wbu_driver_step() == 0
assert abs(car.wb_robot_get_time() - 3.0) < 1e-9
w = car.wbu_car_get_wheel_speed(0)
assert abs(w - 20 / 3.6 / 0.374) < 0.3, w
car.wbu_car_set_indicator_period.argtypes = [double]
car.wbu_car_get_indicator_period.restype = double
car.wbu_car_set_indicator_period(0.5)
driver.wbu_driver_cleanup()
assert car.wbu_car_get_indicator_period() == 0.0
car.wbu_car_init()
assert driver.wbu_driver_get_control_mode() == -1
driver.wbu_driver_init()
assert driver.wbu_driver_get_control_mode() == -1
assert car.wbu_car_get_indicator_period() == 0.34
print("ctypes: PASS")
"#;
    let Run {
        status,
        stdout,
        stderr,
    } = run_python(script);
    assert!(
        status.success() && stdout.contains("ctypes: PASS"),
        "{stdout}{stderr}"
    );
    // The two "before init" calls after the cleanup are the only messages.
    assert_eq!(
        stderr.lines().collect::<Vec<_>>(),
        [
            "Warning: 'wbu_car_init()' should be called before to use 'wbu_car_get_indicator_period()'.",
            "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_control_mode()'.",
        ]
    );

    // The other order: libdriver first (it brings libcar in), then libcar by path.
    let reverse = r#"
import ctypes, sys
driver = ctypes.CDLL(sys.argv[1] + "/libdriver.so")
car = ctypes.CDLL(sys.argv[1] + "/libcar.so")
car.wbu_car_get_wheelbase.restype = ctypes.c_double
car.wbu_car_init()
driver.wbu_driver_init()
driver.wbu_driver_set_gear(2)
assert driver.wbu_driver_get_gear() == 2
assert car.wbu_car_get_wheelbase() == 2.995
print("reverse: PASS")
"#;
    let Run {
        status,
        stdout,
        stderr,
    } = run_python(reverse);
    assert!(
        status.success() && stdout.contains("reverse: PASS") && stderr.is_empty(),
        "{stdout}{stderr}"
    );
}

/// `wb_robot_*`: step rounding, time, devices, duration and the end of the simulation.
const ROBOT_PROGRAM: &str = r#"
#include <stdio.h>
#include <webots/robot.h>
#include <webots/vehicle/driver.h>

int main(void) {
  int steps = 0, status;
  wb_robot_init();
  printf("step %g\n", wb_robot_get_basic_time_step());
  /* One lookup per declarator, so that the warnings come in this order. */
  WbDeviceTag steer = wb_robot_get_device("right_steer"), speaker = wb_robot_get_device("engine_speaker"),
              front = wb_robot_get_device("right_front_wheel"), rear = wb_robot_get_device("left_rear_wheel"),
              nothing = wb_robot_get_device("nothing");
  printf("devices %d %d %d %d %d\n", steer, speaker, front, rear, nothing);
  status = wb_robot_step(15);
  printf("step(15) %d time %g\n", status, wb_robot_get_time());
  status = wb_robot_step(0);
  printf("step(0) %d time %g\n", status, wb_robot_get_time());
  status = wb_robot_step(-5);
  printf("step(-5) %d time %g\n", status, wb_robot_get_time());
  wbu_driver_init();
  while (wbu_driver_step() != -1)
    steps++;
  printf("driver steps %d time %g\n", steps, wb_robot_get_time());
  status = wbu_driver_step();
  printf("again %d", status);
  status = wb_robot_step(20);
  printf(" %d time %g\n", status, wb_robot_get_time());
  wbu_driver_cleanup();
  return 0;
}
"#;

#[test]
fn robot_functions_and_the_world_duration() {
    let world = write_source(
        "duration.toml",
        "basicTimeStep = 20\nduration = 1.0\n[vehicle]\nmodel = \"TeslaModel3\"\n",
    );
    let exe = compile(
        "cc",
        "c99",
        &write_source("robot.c", ROBOT_PROGRAM),
        "robot",
        &shared_link_flags(),
    );
    let r = run(&exe, Some(&world.display().to_string()));
    assert!(r.status.success(), "{}{}", r.stdout, r.stderr);
    // 15 ms are rounded up to one 20 ms step; 0 ms does not advance; the TeslaModel3 is
    // rear-wheel drive. The duration ends at 1 s = 50 steps: one before the driver loop,
    // 48 steps returning 0, the 49th reaching 1 s returns -1.
    assert_eq!(
        r.stdout,
        "step 20\n\
         devices 1 24 0 8 0\n\
         step(15) 0 time 0.02\n\
         step(0) 0 time 0.02\n\
         step(-5) 0 time 0.02\n\
         driver steps 48 time 1\n\
         again -1 -1 time 1\n"
    );
    // The rear-driven car has no front wheel motor: Webots warns for it as for any name the
    // robot lacks.
    assert_eq!(
        r.stderr,
        "Warning: \"right_front_wheel\" device not found.\n\
         Warning: \"nothing\" device not found.\n\
         Warning: wb_robot_step() called with a negative duration (-5 ms); the simulation does \
         not advance.\n"
    );
}

/// The car library alone: direct steering acts at once and `wb_robot_step` advances with it;
/// the driven wheels are held at 0 rad/s (no driver step measures the wheel speeds).
const CAR_ONLY_PROGRAM: &str = r#"
#include <stdio.h>
#include <webots/robot.h>
#include <webots/vehicle/car.h>

int main(void) {
  wbu_car_init();
  wbu_car_set_right_steering_angle(0.1);
  wbu_car_set_left_steering_angle(-0.05);
  wb_robot_step(1000);
  printf("%.6f %.6f %.6f %g %g %d\n", wbu_car_get_right_steering_angle(), wbu_car_get_left_steering_angle(),
         wbu_car_get_wheel_encoder(WBU_CAR_WHEEL_FRONT_RIGHT), wbu_car_get_wheel_speed(WBU_CAR_WHEEL_REAR_LEFT),
         wb_robot_get_time(), (int)wbu_car_get_type());
  wbu_car_cleanup();
  return 0;
}
"#;

#[test]
fn car_library_alone() {
    let exe = compile(
        "cc",
        "c99",
        &write_source("car_only.c", CAR_ONLY_PROGRAM),
        "car_only",
        &shared_link_flags(),
    );
    let r = run(&exe, None);
    assert!(r.status.success(), "{}{}", r.stdout, r.stderr);
    assert_eq!(r.stderr, "");
    let v: Vec<f64> = r
        .stdout
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    // Steering reached within 0.01 rad (a 10 000 N·m motor); the parked front wheel turned by
    // less than 0.05 rad while it steered; no driver step, so no wheel speed; 1 s elapsed;
    // traction (0).
    assert_eq!(v.len(), 6, "{}", r.stdout);
    assert!(
        (v[0] - 0.1).abs() < 0.01 && (v[1] + 0.05).abs() < 0.01,
        "{}",
        r.stdout
    );
    assert!(v[2].abs() < 0.05, "{}", r.stdout);
    assert_eq!(&v[3..], [0.0, 1.0, 0.0], "{}", r.stdout);
}

/// A world that cannot be loaded, or a car library on a DifferentialWheels robot, ends the
/// controller with status 1 and says why.
#[test]
fn invalid_worlds_exit_with_status_1() {
    let exe = compile(
        "cc",
        "c99",
        &write_source(
            "init_only.c",
            "#include <webots/vehicle/driver.h>\nint main(void) { wbu_driver_init(); wbu_driver_cleanup(); return 0; }\n",
        ),
        "init_only",
        &shared_link_flags(),
    );
    let r = run(&exe, Some("BmwX6"));
    assert_eq!(r.status.code(), Some(1), "{}", r.stderr);
    assert!(
        r.stderr.starts_with(
            "Error: cannot load the world VEHICLE_WORLD=BmwX6: 'BmwX6' is neither a world file, \
             a shipped world nor a vehicle model"
        ),
        "{}",
        r.stderr
    );
    assert!(r.stderr.contains("'BmwX5'"), "{}", r.stderr);

    let bad = write_source("bad.toml", "[vehicle]\nmodel = \"BmwX5\"\ntimeTo100 = 7\n");
    let r = run(&exe, Some(&bad.display().to_string()));
    assert_eq!(r.status.code(), Some(1), "{}", r.stderr);
    assert!(
        r.stderr
            .contains("bad.toml:3:1: unknown key 'vehicle.timeTo100'")
            && r.stderr.contains("'time0To100'"),
        "{}",
        r.stderr
    );

    // Three typos: all three in one run, in file order, one `Error: ` line each.
    let typos = write_source(
        "typos.toml",
        "[vehicle]\nmodel = \"BmwX5\"\ntrackFrnt = 1.6\ntimeTo100 = 7\nwheelbse = 3\n",
    );
    let r = run(&exe, Some(&typos.display().to_string()));
    assert_eq!(r.status.code(), Some(1), "{}", r.stderr);
    let errors: Vec<&str> = r
        .stderr
        .lines()
        .filter(|l| l.starts_with("Error: cannot load the world"))
        .collect();
    assert_eq!(errors.len(), 3, "{}", r.stderr);
    for (line, (at, key)) in errors.iter().zip([
        ("typos.toml:3:1", "trackFrnt"),
        ("typos.toml:4:1", "timeTo100"),
        ("typos.toml:5:1", "wheelbse"),
    ]) {
        assert!(
            line.contains(at) && line.contains(&format!("unknown key 'vehicle.{key}'")),
            "{line}"
        );
    }

    let r = run(&exe, Some(&differential_wheels_world()));
    assert_eq!(r.status.code(), Some(1), "{}", r.stderr);
    assert_eq!(
        r.stderr,
        "Error: Only nodes based on the 'Car' node can use the car library.\n"
    );
}

/// `wbu_driver_initialization_is_possible` (and its old name) on a robot that is not a car:
/// 0, without ending the process; car functions then only warn.
#[test]
fn initialization_is_not_possible_on_a_differential_wheels_robot() {
    let exe = compile(
        "cc",
        "c99",
        &write_source(
            "possible.c",
            "#include <stdio.h>\n#include <webots/vehicle/car.h>\n#include <webots/vehicle/driver.h>\n\
             int main(void) {\n  printf(\"%d %d %g\\n\", (int)wbu_driver_initialization_is_possible(),\n\
             (int)initialization_is_possible(), wbu_car_get_wheelbase());\n  return 0;\n}\n",
        ),
        "possible",
        &shared_link_flags(),
    );
    let r = run(&exe, Some(&differential_wheels_world()));
    assert!(r.status.success(), "{}", r.stderr);
    assert_eq!(r.stdout, "0 0 0\n");
    assert_eq!(
        r.stderr,
        "Warning: 'wbu_car_init()' should be called before to use 'wbu_car_get_wheelbase()'.\n"
    );
}

/// The static libraries together (`libdriver.a libcar.a` and the system libraries of the
/// pkg-config file's `Libs.private`), with no duplicate symbol.
#[test]
fn static_libraries() {
    let pc = std::fs::read_to_string(prefix().join("lib/pkgconfig/webots-vehicle.pc")).unwrap();
    let private = pc
        .lines()
        .find_map(|l| l.strip_prefix("Libs.private: "))
        .expect("Libs.private in webots-vehicle.pc");
    let mut link = vec![
        lib_dir().join("libdriver.a").display().to_string(),
        lib_dir().join("libcar.a").display().to_string(),
    ];
    link.extend(private.split_whitespace().map(String::from));
    let exe = compile(
        "cc",
        "c99",
        &tests_dir().join("torque_combustion.c"),
        "torque_combustion_static",
        &link,
    );
    let needed = Command::new("readelf").arg("-d").arg(&exe).output();
    if let Ok(out) = needed {
        let dynamic = String::from_utf8_lossy(&out.stdout);
        assert!(
            !dynamic.contains("libcar.so") && !dynamic.contains("libdriver.so"),
            "{dynamic}"
        );
    }
    let r = run(&exe, None);
    assert_passed("torque_combustion", r.status, &r.stdout);
    assert_eq!(r.stderr, "");
}

/// The controller of the crate README compiles (C99, warnings as errors) and runs.
#[test]
fn readme_controller() {
    let readme = std::fs::read_to_string(capi_dir().join("README.md")).unwrap();
    let start = readme.find("```c\n").expect("a C block in README.md") + "```c\n".len();
    let end = start + readme[start..].find("```").unwrap();
    let exe = compile(
        "cc",
        "c99",
        &write_source("my_controller.c", &readme[start..end]),
        "my_controller",
        &shared_link_flags(),
    );
    let r = run(&exe, None);
    assert!(r.status.success(), "{}{}", r.stdout, r.stderr);
    assert_eq!(r.stderr, "");
    let mut lines = r.stdout.lines();
    assert_eq!(
        lines.next(),
        Some("wheelbase 2.995 m, 6 gear ratios, time step 10 ms")
    );
    let last = lines.next().unwrap();
    assert!(last.starts_with("t = 12.0 s, speed "), "{last}");
    // Braked to a stop from 30 km/h within 4 s.
    let speed: f64 = last
        .trim_start_matches("t = 12.0 s, speed ")
        .trim_end_matches(" km/h")
        .parse()
        .unwrap();
    assert!(speed.abs() < 0.5, "{last}");
}
