//! The FMI 2.0 entry points driven as a tool drives them, against the same world run natively:
//! identical outputs, the state machine's refusals, parameters, and instances that do not
//! share state.
#![allow(unsafe_code, clippy::unwrap_used, clippy::expect_used)]

use std::ffi::CString;
use std::os::raw::c_void;
use std::path::Path;

use sim::Simulation;
use sim::world_file;
use vehicle_fmu::fmi2::*;
use vehicle_fmu::model_description::guid;
use vehicle_fmu::variables::{BRAKE_INTENSITY, GEAR, STEERING_ANGLE, THROTTLE};

const OK: i32 = 0;
const ERROR: i32 = 3;

/// A resources directory holding `text` as the world, under the target's temporary directory.
fn resources(name: &str, text: &str) -> std::path::PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("fmu-tests")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("world.toml"), text).unwrap();
    dir
}

/// An instance of the world `text` (no logger: the tests read the statuses).
fn instantiate(name: &str, text: &str) -> *mut c_void {
    let dir = resources(name, text);
    let uri = CString::new(format!("file://{}", dir.display())).unwrap();
    let instance = CString::new(name).unwrap();
    let id = CString::new(guid()).unwrap();
    // SAFETY: valid C strings; NULL callbacks are accepted (nothing is logged).
    unsafe {
        fmi2Instantiate(
            instance.as_ptr(),
            1,
            id.as_ptr(),
            uri.as_ptr(),
            std::ptr::null(),
            0,
            0,
        )
    }
}

fn set_real(c: *mut c_void, vr: u32, v: f64) -> i32 {
    // SAFETY: one reference, one value.
    unsafe { fmi2SetReal(c, &vr, 1, &v) }
}

fn set_integer(c: *mut c_void, vr: u32, v: i32) -> i32 {
    // SAFETY: one reference, one value.
    unsafe { fmi2SetInteger(c, &vr, 1, &v) }
}

fn get_real(c: *mut c_void, vr: u32) -> f64 {
    let mut v = f64::NAN;
    // SAFETY: one reference, one value.
    assert_eq!(unsafe { fmi2GetReal(c, &vr, 1, &mut v) }, OK);
    v
}

fn initialise(c: *mut c_void) {
    assert!(!c.is_null());
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK);
}

const WORLD: &str = "basicTimeStep = 10\n[vehicle]\nmodel = \"TeslaModel3\"\n";

#[test]
fn the_fmu_reproduces_the_native_run_of_the_same_commands_to_the_bit() {
    let c = instantiate("native", WORLD);
    initialise(c);
    let (mut sim, _) =
        Simulation::from_description(&world_file::parse_str("w", WORLD).unwrap()).unwrap();
    let id = sim.car_ids().next().unwrap();
    // Full throttle in first gear for 1 s, then 0.1 rad of steering and half brake for 1 s,
    // in communication steps of 50 ms (5 basic steps).
    let mut t = 0.0;
    for k in 0..40 {
        let (throttle, steering, brake) = if k < 20 {
            (1.0, 0.0, 0.0)
        } else {
            (0.0, 0.1, 0.5)
        };
        assert_eq!(set_real(c, THROTTLE, throttle), OK);
        assert_eq!(set_real(c, STEERING_ANGLE, steering), OK);
        assert_eq!(set_real(c, BRAKE_INTENSITY, brake), OK);
        assert_eq!(set_integer(c, GEAR, 1), OK);
        assert_eq!(fmi2DoStep(c, t, 0.05, 1), OK);
        t += 0.05;
        let d = sim.driver_mut(id).unwrap();
        if k == 0 || k == 20 {
            d.set_throttle(throttle);
            d.set_gear(1);
            d.set_steering_angle(steering);
            d.set_brake_intensity(brake);
        }
        for _ in 0..5 {
            sim.step().unwrap();
        }
        let native = sim.telemetry(id).unwrap();
        assert_eq!(
            get_real(c, 100).to_bits(),
            native.state.position.x.to_bits(),
            "x at {t} s"
        );
        assert_eq!(
            get_real(c, 105).to_bits(),
            native.state.roll_pitch_yaw.yaw.to_bits()
        );
        assert_eq!(
            get_real(c, 116).to_bits(),
            native.rpm.unwrap_or(0.0).to_bits()
        );
    }
    assert!(get_real(c, 100) > 1.0, "the car moved");
    assert_eq!(fmi2Terminate(c), OK);
    // SAFETY: freed once.
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn bad_call_order_and_bad_values_are_errors_not_crashes() {
    let c = instantiate("order", WORLD);
    assert!(!c.is_null());
    // doStep before initialisation.
    assert_eq!(fmi2DoStep(c, 0.0, 0.01, 1), ERROR);
    initialise(c);
    // Not a multiple of the 10 ms step; not the FMU's time; an output set; a NaN.
    assert_eq!(fmi2DoStep(c, 0.0, 0.015, 1), ERROR);
    assert_eq!(fmi2DoStep(c, 1.0, 0.01, 1), ERROR);
    assert_eq!(set_real(c, 100, 1.0), ERROR);
    assert_eq!(set_real(c, THROTTLE, f64::NAN), ERROR);
    assert_eq!(set_real(c, 999, 1.0), ERROR);
    // A parameter after initialisation.
    assert_eq!(set_real(c, 1000, 1500.0), ERROR);
    assert_eq!(fmi2DoStep(c, 0.0, 0.01, 1), OK);
    // Unsupported capabilities answer an error; a NULL state too.
    assert_eq!(fmi2CancelStep(c), ERROR);
    let mut size = 0usize;
    // SAFETY: a NULL state is refused before it is read.
    assert_eq!(
        unsafe { fmi2SerializedFMUstateSize(c, std::ptr::null_mut(), &mut size) },
        ERROR
    );
    // Bytes that are not a state are refused.
    let mut state = std::ptr::null_mut();
    let junk = [7u8; 40];
    // SAFETY: 40 valid bytes, a valid pointer to NULL.
    assert_eq!(
        unsafe { fmi2DeSerializeFMUstate(c, junk.as_ptr(), junk.len(), &mut state) },
        ERROR
    );
    assert!(state.is_null());
    // NULL component.
    assert_eq!(fmi2DoStep(std::ptr::null_mut(), 0.0, 0.01, 1), ERROR);
    // SAFETY: freed once.
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn a_wrong_guid_a_missing_world_or_two_cars_give_no_instance() {
    let dir = resources("guid", WORLD);
    let uri = CString::new(format!("file://{}", dir.display())).unwrap();
    let name = CString::new("x").unwrap();
    let wrong = CString::new("{00000000-0000-0000-0000-000000000000}").unwrap();
    // SAFETY: valid C strings.
    let c = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            1,
            wrong.as_ptr(),
            uri.as_ptr(),
            std::ptr::null(),
            0,
            0,
        )
    };
    assert!(c.is_null());
    let id = CString::new(guid()).unwrap();
    let nowhere = CString::new("file:///nonexistent/resources").unwrap();
    // SAFETY: valid C strings.
    let c = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            1,
            id.as_ptr(),
            nowhere.as_ptr(),
            std::ptr::null(),
            0,
            0,
        )
    };
    assert!(c.is_null());
    let two = "[[vehicle]]\nmodel = \"BmwX5\"\n[[vehicle]]\nmodel = \"Bus\"\ntranslation = [0, 10, 0.5]\n";
    assert!(instantiate("two", two).is_null());
    // Model exchange is not offered.
    // SAFETY: valid C strings.
    let c = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            0,
            id.as_ptr(),
            uri.as_ptr(),
            std::ptr::null(),
            0,
            0,
        )
    };
    assert!(c.is_null());
}

#[test]
fn parameters_reach_the_world_and_instances_do_not_interfere() {
    let grippy = instantiate("grippy", WORLD);
    let icy = instantiate("icy", WORLD);
    assert_eq!(get_real(grippy, 1005), 1.0);
    assert_eq!(fmi2SetupExperiment(icy, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(fmi2EnterInitializationMode(icy), OK);
    assert_eq!(set_real(icy, 1005, 0.1), OK);
    assert_eq!(fmi2ExitInitializationMode(icy), OK);
    initialise(grippy);
    assert_eq!(get_real(icy, 1005), 0.1);
    assert_eq!(get_real(grippy, 1005), 1.0);
    for c in [grippy, icy] {
        assert_eq!(set_real(c, THROTTLE, 1.0), OK);
        assert_eq!(set_integer(c, GEAR, 1), OK);
        assert_eq!(fmi2DoStep(c, 0.0, 2.0, 1), OK);
    }
    // On ice (μ = 0.1) the driven wheels cannot pass more than 0.1·g of the car's weight:
    // after 2 s it goes at most 0.1 · 9.81 · 2 = 1.96 m/s, the other well above.
    assert!(get_real(icy, 106) < 1.97, "{}", get_real(icy, 106));
    assert!(get_real(grippy, 106) > 3.0, "{}", get_real(grippy, 106));
    // An invalid parameter is refused at the end of initialisation, naming it.
    let bad = instantiate("bad", WORLD);
    assert_eq!(fmi2EnterInitializationMode(bad), OK);
    assert_eq!(set_real(bad, 1005, -1.0), OK);
    assert_eq!(fmi2ExitInitializationMode(bad), ERROR);
    // SAFETY: each freed once.
    unsafe {
        fmi2FreeInstance(grippy);
        fmi2FreeInstance(icy);
        fmi2FreeInstance(bad);
    }
}

#[test]
fn a_state_saved_at_5_s_and_set_back_replays_to_10_s_identically() {
    let c = instantiate("state", WORLD);
    initialise(c);
    // Communication steps of 0.1 s, numbered from 0 (k·0.1 s).
    let drive = |c: *mut c_void, from: u32, to: u32| {
        let mut trace = Vec::new();
        for k in from..to {
            let t = f64::from(k) * 0.1;
            // A command that changes over time, so the replay must restore the inputs too.
            let throttle = if t < 7.0 { 0.8 } else { 0.0 };
            assert_eq!(set_real(c, THROTTLE, throttle), OK);
            assert_eq!(set_real(c, STEERING_ANGLE, 0.05 * (t - 5.0).max(0.0)), OK);
            assert_eq!(set_integer(c, GEAR, 1), OK);
            assert_eq!(fmi2DoStep(c, t, 0.1, 1), OK);
            trace.push([100, 101, 105, 106, 116].map(|vr| get_real(c, vr).to_bits()));
        }
        trace
    };
    drive(c, 0, 50);
    let mut state = std::ptr::null_mut();
    // SAFETY: a valid pointer to NULL: a new state.
    assert_eq!(unsafe { fmi2GetFMUstate(c, &mut state) }, OK);
    assert!(!state.is_null());
    let first = drive(c, 50, 100);
    // SAFETY: the state saved above.
    assert_eq!(unsafe { fmi2SetFMUstate(c, state) }, OK);
    let again = drive(c, 50, 100);
    assert_eq!(first, again);
    // Another instance of the same world takes the state by replaying its journal, and goes
    // on exactly as the first did.
    let other = instantiate("state-other", WORLD);
    initialise(other);
    // SAFETY: a state of this FMU, not yet freed.
    assert_eq!(unsafe { fmi2SetFMUstate(other, state) }, OK);
    assert_eq!(drive(other, 50, 100), first);
    // An instance of another world refuses it and is left as it was.
    let elsewhere = instantiate(
        "state-elsewhere",
        "basicTimeStep = 10\n[vehicle]\nmodel = \"Bus\"\n",
    );
    initialise(elsewhere);
    // SAFETY: a state of this FMU, not yet freed.
    assert_eq!(unsafe { fmi2SetFMUstate(elsewhere, state) }, ERROR);
    assert_eq!(get_real(elsewhere, 99), 0.0);
    // SAFETY: freed once; the pointer is cleared.
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut state) }, OK);
    assert!(state.is_null());
    // SAFETY: each freed once.
    unsafe {
        fmi2FreeInstance(c);
        fmi2FreeInstance(other);
        fmi2FreeInstance(elsewhere);
    }
}

#[test]
fn a_serialised_state_restores_in_a_second_instance_to_the_bit() {
    let drive = |c: *mut c_void, from: u32, to: u32| {
        let mut trace = Vec::new();
        for k in from..to {
            let t = f64::from(k) * 0.1;
            assert_eq!(set_real(c, THROTTLE, if t < 3.0 { 1.0 } else { 0.2 }), OK);
            assert_eq!(
                set_real(c, STEERING_ANGLE, 0.1 * (t - 4.0).clamp(0.0, 1.0)),
                OK
            );
            assert_eq!(set_integer(c, GEAR, 1), OK);
            assert_eq!(fmi2DoStep(c, t, 0.1, 1), OK);
            trace.push([99, 100, 101, 105, 106, 116, 118].map(|vr| get_real(c, vr).to_bits()));
        }
        trace
    };
    // Parameters are part of the state: the second instance is built without them.
    let c = instantiate("serial-a", WORLD);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(set_real(c, 1000, 2100.0), OK);
    assert_eq!(set_real(c, 1005, 0.7), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    drive(c, 0, 50);
    let mut state = std::ptr::null_mut();
    let mut size = 0usize;
    // SAFETY: valid pointers; the state is this FMU's.
    let bytes = unsafe {
        assert_eq!(fmi2GetFMUstate(c, &mut state), OK);
        assert_eq!(fmi2SerializedFMUstateSize(c, state, &mut size), OK);
        let mut bytes = vec![0u8; size];
        assert_eq!(
            fmi2SerializeFMUstate(c, state, bytes.as_mut_ptr(), size),
            OK
        );
        // A buffer of the wrong size is refused.
        assert_eq!(
            fmi2SerializeFMUstate(c, state, bytes.as_mut_ptr(), size - 1),
            ERROR
        );
        bytes
    };
    let first = drive(c, 50, 80);
    let b = instantiate("serial-b", WORLD);
    initialise(b);
    let mut read = std::ptr::null_mut();
    // SAFETY: `bytes` holds `size` bytes; a valid pointer to NULL.
    unsafe {
        assert_eq!(
            fmi2DeSerializeFMUstate(b, bytes.as_ptr(), size, &mut read),
            OK
        );
        assert_eq!(fmi2SetFMUstate(b, read), OK);
    }
    assert_eq!(get_real(b, 1000), 2100.0);
    assert_eq!(get_real(b, 1005), 0.7);
    assert_eq!(get_real(b, 99), 5.0);
    assert_eq!(drive(b, 50, 80), first);
    // SAFETY: each freed once.
    unsafe {
        assert_eq!(fmi2FreeFMUstate(c, &mut state), OK);
        assert_eq!(fmi2FreeFMUstate(b, &mut read), OK);
        fmi2FreeInstance(c);
        fmi2FreeInstance(b);
    }
}

#[test]
fn tyre_parameters_reach_the_world() {
    // The longitudinal peak friction bounds the drive force: 0.2 of the car's weight at most
    // (less on the driven axle alone), so at most 0.2 · 9.81 · 2 = 3.92 m/s after 2 s.
    let slippery = instantiate("tyre-mu", WORLD);
    assert_eq!(
        get_real(slippery, 1007),
        1.0,
        "the passenger-car class's default"
    );
    assert_eq!(fmi2EnterInitializationMode(slippery), OK);
    assert_eq!(set_real(slippery, 1007, 0.2), OK);
    assert_eq!(fmi2ExitInitializationMode(slippery), OK);
    assert_eq!(get_real(slippery, 1007), 0.2);
    // Webots' contact instead of the slip tyre, set on a world that names the tyre by a
    // string: the parameter replaces it.
    let webots = instantiate(
        "tyre-webots",
        "basicTimeStep = 10\n[vehicle]\nmodel = \"TeslaModel3\"\ntyre = \"magic-formula\"\n",
    );
    let mut model = 0;
    // SAFETY: one reference, one value.
    assert_eq!(unsafe { fmi2GetInteger(webots, &1006, 1, &mut model) }, OK);
    assert_eq!(model, 0);
    assert_eq!(fmi2EnterInitializationMode(webots), OK);
    assert_eq!(set_integer(webots, 1006, 1), OK);
    assert_eq!(fmi2ExitInitializationMode(webots), OK);
    // SAFETY: one reference, one value.
    assert_eq!(unsafe { fmi2GetInteger(webots, &1006, 1, &mut model) }, OK);
    assert_eq!(model, 1);
    for c in [slippery, webots] {
        assert_eq!(set_real(c, THROTTLE, 1.0), OK);
        assert_eq!(set_integer(c, GEAR, 1), OK);
        assert_eq!(fmi2DoStep(c, 0.0, 2.0, 1), OK);
    }
    assert!(
        get_real(slippery, 106) < 3.93,
        "{}",
        get_real(slippery, 106)
    );
    assert!(get_real(webots, 106) > 3.93, "{}", get_real(webots, 106));
    // A tyre model that is neither is refused at the end of initialisation.
    let bad = instantiate("tyre-bad", WORLD);
    assert_eq!(fmi2EnterInitializationMode(bad), OK);
    assert_eq!(set_integer(bad, 1006, 7), OK);
    assert_eq!(fmi2ExitInitializationMode(bad), ERROR);
    // SAFETY: each freed once.
    unsafe {
        fmi2FreeInstance(slippery);
        fmi2FreeInstance(webots);
        fmi2FreeInstance(bad);
    }
}
