//! The C ABI fuzz harness: every `extern "C"` entry point of `libcar` (the driver library's
//! under their internal `vehicle_capi_driver_*` names), called in any order with hostile
//! values, before the libraries are initialised, after initialisation and after cleanup, in a
//! car world (cast or joints) or a DifferentialWheels world.
//!
//! Shared by the property tests of this directory and the coverage-guided target
//! `fuzz/fuzz_targets/capi.rs` (which includes this file by path). Invariants: no panic, not
//! even one caught by the entry points' guard (a panic hook records it); every
//! floating-point result finite. A robot world never gets `wbu_car_init` or `wbu_driver_init`:
//! Webots (and this library) end the process there, by design.

use std::ffi::{CString, c_int};
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, Once, PoisonError};

use car::*;

/// Setters of one `double`.
pub const F64_SETTERS: [(&str, extern "C" fn(f64)); 8] = [
    ("wbu_car_set_indicator_period", wbu_car_set_indicator_period),
    (
        "wbu_car_set_left_steering_angle",
        wbu_car_set_left_steering_angle,
    ),
    (
        "wbu_car_set_right_steering_angle",
        wbu_car_set_right_steering_angle,
    ),
    (
        "wbu_driver_set_steering_angle",
        vehicle_capi_driver_set_steering_angle,
    ),
    (
        "wbu_driver_set_cruising_speed",
        vehicle_capi_driver_set_cruising_speed,
    ),
    ("wbu_driver_set_throttle", vehicle_capi_driver_set_throttle),
    (
        "wbu_driver_set_brake_intensity",
        vehicle_capi_driver_set_brake_intensity,
    ),
    ("wbu_driver_set_brake", vehicle_capi_driver_set_brake),
];

/// Setters of two `double`s.
pub const F64_PAIR_SETTERS: [(&str, extern "C" fn(f64, f64)); 2] = [
    (
        "wb_differential_wheels_set_speed",
        wb_differential_wheels_set_speed,
    ),
    (
        "wb_differential_wheels_set_encoders",
        wb_differential_wheels_set_encoders,
    ),
];

/// Setters of one `int`.
pub const INT_SETTERS: [(&str, extern "C" fn(c_int)); 5] = [
    (
        "wbu_driver_set_indicator",
        vehicle_capi_driver_set_indicator,
    ),
    ("wbu_driver_set_gear", vehicle_capi_driver_set_gear),
    (
        "wbu_driver_set_wiper_mode",
        vehicle_capi_driver_set_wiper_mode,
    ),
    (
        "wbu_driver_set_wipers_mode",
        vehicle_capi_driver_set_wipers_mode,
    ),
    (
        "wb_differential_wheels_enable_encoders",
        wb_differential_wheels_enable_encoders,
    ),
];

/// Setters of one C `bool` (a byte: any value).
pub const BOOL_SETTERS: [(&str, extern "C" fn(u8)); 6] = [
    (
        "wbu_car_enable_limited_slip_differential",
        wbu_car_enable_limited_slip_differential,
    ),
    (
        "wbu_car_enable_indicator_auto_disabling",
        wbu_car_enable_indicator_auto_disabling,
    ),
    (
        "wbu_driver_set_hazard_flashers",
        vehicle_capi_driver_set_hazard_flashers,
    ),
    (
        "wbu_driver_set_dipped_beams",
        vehicle_capi_driver_set_dipped_beams,
    ),
    (
        "wbu_driver_set_antifog_lights",
        vehicle_capi_driver_set_antifog_lights,
    ),
    (
        "wbu_driver_set_indicator_warning",
        vehicle_capi_driver_set_indicator_warning,
    ),
];

/// Getters of a `double`.
pub const F64_GETTERS: [(&str, extern "C" fn() -> f64); 23] = [
    ("wbu_car_get_indicator_period", wbu_car_get_indicator_period),
    ("wbu_car_get_track_front", wbu_car_get_track_front),
    ("wbu_car_get_track_rear", wbu_car_get_track_rear),
    ("wbu_car_get_wheelbase", wbu_car_get_wheelbase),
    (
        "wbu_car_get_front_wheel_radius",
        wbu_car_get_front_wheel_radius,
    ),
    (
        "wbu_car_get_rear_wheel_radius",
        wbu_car_get_rear_wheel_radius,
    ),
    (
        "wbu_car_get_right_steering_angle",
        wbu_car_get_right_steering_angle,
    ),
    (
        "wbu_car_get_left_steering_angle",
        wbu_car_get_left_steering_angle,
    ),
    (
        "wbu_driver_get_steering_angle",
        vehicle_capi_driver_get_steering_angle,
    ),
    (
        "wbu_driver_get_target_cruising_speed",
        vehicle_capi_driver_get_target_cruising_speed,
    ),
    (
        "wbu_driver_get_current_speed",
        vehicle_capi_driver_get_current_speed,
    ),
    ("wbu_driver_get_throttle", vehicle_capi_driver_get_throttle),
    (
        "wbu_driver_get_brake_intensity",
        vehicle_capi_driver_get_brake_intensity,
    ),
    ("wbu_driver_get_brake", vehicle_capi_driver_get_brake),
    ("wbu_driver_get_rpm", vehicle_capi_driver_get_rpm),
    ("wb_robot_get_time", wb_robot_get_time),
    ("wb_robot_get_basic_time_step", wb_robot_get_basic_time_step),
    (
        "wb_differential_wheels_get_left_speed",
        wb_differential_wheels_get_left_speed,
    ),
    (
        "wb_differential_wheels_get_right_speed",
        wb_differential_wheels_get_right_speed,
    ),
    (
        "wb_differential_wheels_get_max_speed",
        wb_differential_wheels_get_max_speed,
    ),
    (
        "wb_differential_wheels_get_speed_unit",
        wb_differential_wheels_get_speed_unit,
    ),
    (
        "wb_differential_wheels_get_left_encoder",
        wb_differential_wheels_get_left_encoder,
    ),
    (
        "wb_differential_wheels_get_right_encoder",
        wb_differential_wheels_get_right_encoder,
    ),
];

/// Getters of a wheel's `double`, by raw wheel index.
pub const WHEEL_GETTERS: [(&str, extern "C" fn(c_int) -> f64); 2] = [
    ("wbu_car_get_wheel_encoder", wbu_car_get_wheel_encoder),
    ("wbu_car_get_wheel_speed", wbu_car_get_wheel_speed),
];

/// Getters of an `int` (and `wb_robot_init`, which returns one).
pub const INT_GETTERS: [(&str, extern "C" fn() -> c_int); 11] = [
    ("wbu_car_get_type", wbu_car_get_type),
    ("wbu_car_get_engine_type", wbu_car_get_engine_type),
    (
        "wbu_driver_get_indicator",
        vehicle_capi_driver_get_indicator,
    ),
    ("wbu_driver_get_gear", vehicle_capi_driver_get_gear),
    (
        "wbu_driver_get_gear_number",
        vehicle_capi_driver_get_gear_number,
    ),
    (
        "wbu_driver_get_control_mode",
        vehicle_capi_driver_get_control_mode,
    ),
    (
        "wbu_driver_get_wiper_mode",
        vehicle_capi_driver_get_wiper_mode,
    ),
    (
        "wbu_driver_get_wipers_mode",
        vehicle_capi_driver_get_wipers_mode,
    ),
    (
        "wb_differential_wheels_get_encoders_sampling_period",
        wb_differential_wheels_get_encoders_sampling_period,
    ),
    ("wbu_driver_step", vehicle_capi_driver_step),
    ("wb_robot_init", wb_robot_init),
];

/// Getters of a C `bool`.
pub const BOOL_GETTERS: [(&str, extern "C" fn() -> u8); 6] = [
    ("wbu_car_get_backwards_lights", wbu_car_get_backwards_lights),
    ("wbu_car_get_brake_lights", wbu_car_get_brake_lights),
    (
        "wbu_driver_get_hazard_flashers",
        vehicle_capi_driver_get_hazard_flashers,
    ),
    (
        "wbu_driver_get_dipped_beams",
        vehicle_capi_driver_get_dipped_beams,
    ),
    (
        "wbu_driver_get_antifog_lights",
        vehicle_capi_driver_get_antifog_lights,
    ),
    (
        "wbu_driver_initialization_is_possible",
        vehicle_capi_driver_initialization_is_possible,
    ),
];

/// The functions without arguments or result: the cleanups and the encoders' switch-off.
pub const ACTIONS: [(&str, extern "C" fn()); 4] = [
    ("wbu_car_cleanup", wbu_car_cleanup),
    ("wbu_driver_cleanup", vehicle_capi_driver_cleanup),
    ("wb_robot_cleanup", wb_robot_cleanup),
    (
        "wb_differential_wheels_disable_encoders",
        wb_differential_wheels_disable_encoders,
    ),
];

/// The initialisers, which end the process in a world whose robot is not a car.
pub const INITS: [(&str, extern "C" fn()); 2] = [
    ("wbu_car_init", wbu_car_init),
    ("wbu_driver_init", vehicle_capi_driver_init),
];

/// Device names for `wb_robot_get_device`: real ones, unknown ones, and bytes that are not
/// UTF-8.
pub const DEVICE_NAMES: [&[u8]; 6] = [
    b"right_steer",
    b"engine_speaker",
    b"left wheel",
    b"",
    b"no such device",
    b"\xff\xfe",
];

/// One call: the table, an index into it (taken modulo its length) and the arguments that
/// table's functions take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Call {
    /// [`F64_SETTERS`].
    F64Setter(usize, f64),
    /// [`F64_PAIR_SETTERS`].
    F64PairSetter(usize, f64, f64),
    /// [`INT_SETTERS`].
    IntSetter(usize, c_int),
    /// [`BOOL_SETTERS`].
    BoolSetter(usize, u8),
    /// [`F64_GETTERS`].
    F64Getter(usize),
    /// [`WHEEL_GETTERS`] with a raw wheel index.
    WheelGetter(usize, c_int),
    /// [`INT_GETTERS`].
    IntGetter(usize),
    /// [`BOOL_GETTERS`].
    BoolGetter(usize),
    /// [`ACTIONS`].
    Action(usize),
    /// [`INITS`] (skipped in a robot world).
    Init(usize),
    /// `wb_robot_step` with a duration (ms).
    RobotStep(c_int),
    /// `wb_robot_get_device` with [`DEVICE_NAMES`] (`None`: a null pointer).
    Device(Option<usize>),
}

/// The worlds the calls run in (`VEHICLE_WORLD`) and whether their robot is a car: the
/// default world (an empty variable), a model name, a car on joints at 100 ms and a
/// DifferentialWheels robot on physics.
pub fn worlds() -> [(String, bool); 4] {
    let seed = |name: &str| {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../fuzz/seeds/world_file")
            .join(name)
            .display()
            .to_string()
    };
    [
        (String::new(), true),
        ("ToyotaPrius".to_string(), true),
        (seed("basic_time_step_100_truck_joints.toml"), true),
        (seed("robot_physics.toml"), false),
    ]
}

/// One session at a time: the library holds one robot per process.
static SESSION: Mutex<()> = Mutex::new(());

/// Set by the panic hook: a panic happened, even one that an entry point's guard caught.
static PANICKED: AtomicBool = AtomicBool::new(false);

/// Installs (once) a panic hook that records every panic before the default report.
fn watch_panics() {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        let default = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            PANICKED.store(true, Ordering::SeqCst);
            default(info);
        }));
    });
}

/// `Err` unless `x` is finite.
fn finite(name: &str, x: f64) -> Result<(), String> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(format!("{name}() returned {x}"))
    }
}

/// Performs `call` in a world whose robot is a car iff `car`.
fn perform(call: Call, car: bool) -> Result<(), String> {
    fn pick<T: Copy>(table: &[T], i: usize) -> T {
        table[i % table.len()]
    }
    match call {
        Call::F64Setter(i, x) => pick(&F64_SETTERS, i).1(x),
        Call::F64PairSetter(i, x, y) => pick(&F64_PAIR_SETTERS, i).1(x, y),
        Call::IntSetter(i, x) => pick(&INT_SETTERS, i).1(x),
        Call::BoolSetter(i, x) => pick(&BOOL_SETTERS, i).1(x),
        Call::F64Getter(i) => {
            let (name, f) = pick(&F64_GETTERS, i);
            finite(name, f())?;
        }
        Call::WheelGetter(i, w) => {
            let (name, f) = pick(&WHEEL_GETTERS, i);
            finite(name, f(w))?;
        }
        Call::IntGetter(i) => {
            pick(&INT_GETTERS, i).1();
        }
        Call::BoolGetter(i) => {
            let (name, f) = pick(&BOOL_GETTERS, i);
            let b = f();
            if b > 1 {
                return Err(format!("{name}() returned {b}"));
            }
        }
        Call::Action(i) => pick(&ACTIONS, i).1(),
        Call::Init(i) if car => pick(&INITS, i).1(),
        Call::Init(_) => {}
        Call::RobotStep(ms) => {
            // Long enough to matter, short enough for a fuzzer: at most 2 s per call.
            wb_robot_step(ms.clamp(-10, 2000));
        }
        Call::Device(name) => {
            let tag = match name {
                Some(i) => {
                    let bytes = pick(&DEVICE_NAMES, i);
                    let c = CString::new(bytes).map_err(|e| e.to_string())?;
                    // SAFETY: a valid NUL-terminated string that outlives the call.
                    unsafe { wb_robot_get_device(c.as_ptr()) }
                }
                // SAFETY: the function accepts a null pointer (it returns 0).
                None => unsafe { wb_robot_get_device(std::ptr::null()) },
            };
            if name.is_none() && tag != 0 {
                return Err(format!("wb_robot_get_device(NULL) returned {tag}"));
            }
        }
    }
    Ok(())
}

/// Runs `body` in world `world` of [`worlds`] (modulo their number), from an uninitialised
/// library to a final cleanup, alone in the process.
///
/// # Errors
/// "panicked" if anything panicked, even inside an entry point's guard; else `body`'s result.
pub fn with_session<R>(
    world: usize,
    body: impl FnOnce(&str, bool) -> Result<R, String>,
) -> Result<R, String> {
    let _one_at_a_time = SESSION.lock().unwrap_or_else(PoisonError::into_inner);
    watch_panics();
    let worlds = worlds();
    let (spec, car) = &worlds[world % worlds.len()];
    wb_robot_cleanup();
    // SAFETY: every caller of the library in this process holds `SESSION`, so nothing reads
    // the environment concurrently.
    unsafe { std::env::set_var(WORLD_VARIABLE, spec) };
    PANICKED.store(false, Ordering::SeqCst);
    let result = body(spec, *car);
    wb_robot_cleanup();
    if PANICKED.swap(false, Ordering::SeqCst) {
        return Err(format!("world {spec:?}: panicked"));
    }
    result
}

/// Runs `calls` in world `world` (see [`with_session`]), checking the invariants of the
/// module documentation after each.
///
/// # Errors
/// The first broken invariant, naming the world and the call.
pub fn run(world: usize, calls: &[Call]) -> Result<(), String> {
    with_session(world, |spec, car| {
        for (i, &call) in calls.iter().enumerate() {
            perform(call, car).map_err(|e| format!("world {spec:?}, call {i} {call:?}: {e}"))?;
            if PANICKED.load(Ordering::SeqCst) {
                return Err(format!("world {spec:?}, call {i} {call:?}: panicked"));
            }
        }
        Ok(())
    })
}
