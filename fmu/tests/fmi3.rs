//! The FMI 3.0 entry points driven as a tool drives them: the same run as the native engine
//! to the bit, states saved, serialised and restored in a second instance, the logger, and
//! the refusals of the state machine.
#![allow(unsafe_code, clippy::unwrap_used, clippy::expect_used)]

use std::ffi::{CStr, CString, c_char};
use std::os::raw::c_void;
use std::path::Path;
use std::sync::Mutex;

use sim::Simulation;
use sim::world_file;
use vehicle_fmu::fmi3::*;
use vehicle_fmu::model_description::guid;
use vehicle_fmu::variables::{GEAR, STEERING_ANGLE, THROTTLE, TIME};

const OK: i32 = 0;
const ERROR: i32 = 3;
const WORLD: &str = "basicTimeStep = 10\n[vehicle]\nmodel = \"TeslaModel3\"\n";

/// Messages the logger received, by instance environment (each test its own key).
static LOG: Mutex<Vec<(usize, i32, String)>> = Mutex::new(Vec::new());

unsafe extern "C" fn logger(
    env: *mut c_void,
    status: i32,
    _category: *const c_char,
    m: *const c_char,
) {
    // SAFETY: the FMU passes a valid C string.
    let text = unsafe { CStr::from_ptr(m) }.to_string_lossy().into_owned();
    LOG.lock().unwrap().push((env as usize, status, text));
}

fn messages(env: usize) -> Vec<(i32, String)> {
    LOG.lock()
        .unwrap()
        .iter()
        .filter(|(e, _, _)| *e == env)
        .map(|(_, s, t)| (*s, t.clone()))
        .collect()
}

/// An instance of the world `text`, logging under `env`.
fn instantiate_with(name: &str, text: &str, token: &str, env: usize) -> *mut c_void {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("fmu3-tests")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("world.toml"), text).unwrap();
    let path = CString::new(format!("{}/", dir.display())).unwrap();
    let instance = CString::new(name).unwrap();
    let token = CString::new(token).unwrap();
    // SAFETY: valid C strings and logger.
    unsafe {
        fmi3InstantiateCoSimulation(
            instance.as_ptr(),
            token.as_ptr(),
            path.as_ptr(),
            0,
            1,
            0,
            0,
            std::ptr::null(),
            0,
            env as *mut c_void,
            Some(logger),
            std::ptr::null(),
        )
    }
}

fn instantiate(name: &str, env: usize) -> *mut c_void {
    instantiate_with(name, WORLD, &guid(), env)
}

fn initialise(c: *mut c_void) {
    assert!(!c.is_null());
    assert_eq!(fmi3EnterInitializationMode(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(fmi3ExitInitializationMode(c), OK);
}

fn set_f64(c: *mut c_void, vr: u32, v: f64) -> i32 {
    // SAFETY: one reference, one value.
    unsafe { fmi3SetFloat64(c, &vr, 1, &v, 1) }
}

fn set_i32(c: *mut c_void, vr: u32, v: i32) -> i32 {
    // SAFETY: one reference, one value.
    unsafe { fmi3SetInt32(c, &vr, 1, &v, 1) }
}

fn get_f64(c: *mut c_void, vr: u32) -> f64 {
    let mut v = f64::NAN;
    // SAFETY: one reference, one value.
    assert_eq!(unsafe { fmi3GetFloat64(c, &vr, 1, &mut v, 1) }, OK);
    v
}

fn do_step(c: *mut c_void, t: f64, h: f64) -> (i32, f64) {
    let (mut event, mut terminate, mut early, mut last) = (9u8, 9u8, 9u8, f64::NAN);
    // SAFETY: valid output pointers.
    let status = unsafe {
        fmi3DoStep(
            c,
            t,
            h,
            1,
            &mut event,
            &mut terminate,
            &mut early,
            &mut last,
        )
    };
    if status == OK {
        assert_eq!((event, terminate, early), (0, 0, 0));
    }
    (status, last)
}

#[test]
fn fmi3_reproduces_the_native_run_to_the_bit() {
    let c = instantiate("native3", 1);
    initialise(c);
    let (mut sim, _) =
        Simulation::from_description(&world_file::parse_str("w", WORLD).unwrap()).unwrap();
    let id = sim.car_ids().next().unwrap();
    let mut t = 0.0;
    for k in 0..30 {
        let (throttle, steering) = if k < 15 { (1.0, 0.0) } else { (0.3, -0.1) };
        assert_eq!(set_f64(c, THROTTLE, throttle), OK);
        assert_eq!(set_f64(c, STEERING_ANGLE, steering), OK);
        assert_eq!(set_i32(c, GEAR, 1), OK);
        let (status, last) = do_step(c, t, 0.05);
        assert_eq!(status, OK);
        t += 0.05;
        if k == 0 || k == 15 {
            let d = sim.driver_mut(id).unwrap();
            d.set_throttle(throttle);
            d.set_gear(1);
            d.set_steering_angle(steering);
        }
        for _ in 0..5 {
            sim.step().unwrap();
        }
        let native = sim.telemetry(id).unwrap();
        assert_eq!(last.to_bits(), native.time.to_bits());
        assert_eq!(get_f64(c, TIME).to_bits(), native.time.to_bits());
        assert_eq!(get_f64(c, 100).to_bits(), native.state.position.x.to_bits());
        assert_eq!(get_f64(c, 101).to_bits(), native.state.position.y.to_bits());
        assert_eq!(
            get_f64(c, 120).to_bits(),
            native.state.tyres[vehicle_model::Wheel::RearRight]
                .slip_ratio
                .to_bits()
        );
    }
    assert_eq!(fmi3Terminate(c), OK);
    // SAFETY: freed once.
    unsafe { fmi3FreeInstance(c) };
}

#[test]
fn a_state_round_trips_through_bytes_into_a_second_instance() {
    let drive = |c: *mut c_void, from: u32, to: u32| {
        (from..to)
            .map(|k| {
                let t = f64::from(k) * 0.1;
                assert_eq!(set_f64(c, THROTTLE, if t < 6.0 { 0.9 } else { 0.0 }), OK);
                assert_eq!(set_f64(c, STEERING_ANGLE, 0.02 * (t - 5.0).max(0.0)), OK);
                assert_eq!(do_step(c, t, 0.1).0, OK);
                [99, 100, 101, 105, 106, 116].map(|vr| get_f64(c, vr).to_bits())
            })
            .collect::<Vec<_>>()
    };
    let a = instantiate("serial3-a", 2);
    initialise(a);
    drive(a, 0, 50);
    let mut state = std::ptr::null_mut();
    let mut size = 0usize;
    // SAFETY: valid pointers.
    let bytes = unsafe {
        assert_eq!(fmi3GetFMUState(a, &mut state), OK);
        assert_eq!(fmi3SerializedFMUStateSize(a, state, &mut size), OK);
        let mut bytes = vec![0u8; size];
        assert_eq!(
            fmi3SerializeFMUState(a, state, bytes.as_mut_ptr(), size),
            OK
        );
        bytes
    };
    let first = drive(a, 50, 100);
    // Back in the same instance, from the snapshot.
    // SAFETY: the state saved above.
    assert_eq!(unsafe { fmi3SetFMUState(a, state) }, OK);
    assert_eq!(drive(a, 50, 100), first);
    // In a second instance, from the bytes.
    let b = instantiate("serial3-b", 3);
    initialise(b);
    let mut read = std::ptr::null_mut();
    // SAFETY: `bytes` holds `size` bytes; a valid pointer to NULL.
    unsafe {
        assert_eq!(
            fmi3DeserializeFMUState(b, bytes.as_ptr(), size, &mut read),
            OK
        );
        assert_eq!(fmi3SetFMUState(b, read), OK);
    }
    assert_eq!(drive(b, 50, 100), first);
    // SAFETY: each freed once.
    unsafe {
        assert_eq!(fmi3FreeFMUState(a, &mut state), OK);
        assert_eq!(fmi3FreeFMUState(b, &mut read), OK);
        assert!(state.is_null() && read.is_null());
        fmi3FreeInstance(a);
        fmi3FreeInstance(b);
    }
}

#[test]
fn wrong_order_and_bad_values_are_logged_errors() {
    let c = instantiate("order3", 4);
    assert!(!c.is_null());
    assert_eq!(do_step(c, 0.0, 0.01).0, ERROR);
    assert!(
        messages(4)
            .iter()
            .any(|(s, t)| *s == ERROR && t.contains("fmi3DoStep is not allowed")),
        "{:?}",
        messages(4)
    );
    initialise(c);
    assert_eq!(do_step(c, 0.0, 0.015).0, ERROR);
    assert_eq!(set_f64(c, 100, 1.0), ERROR);
    assert_eq!(set_f64(c, THROTTLE, f64::INFINITY), ERROR);
    // An Int32 reference read as Float64, and mismatched counts.
    let mut v = 0.0;
    // SAFETY: one reference, one value.
    assert_eq!(unsafe { fmi3GetFloat64(c, &GEAR, 1, &mut v, 1) }, ERROR);
    // SAFETY: one reference; the count mismatch is refused before any value is read.
    assert_eq!(unsafe { fmi3GetFloat64(c, &THROTTLE, 1, &mut v, 2) }, ERROR);
    // SAFETY: one reference; the NULL array is refused before anything is written.
    assert_eq!(
        unsafe { fmi3GetFloat64(c, &THROTTLE, 1, std::ptr::null_mut(), 1) },
        ERROR
    );
    // Types and capabilities the FMU does not have.
    let mut b = 0u8;
    assert_eq!(fmi3GetBoolean(c, &GEAR, 1, &mut b, 1), ERROR);
    assert_eq!(fmi3GetBoolean(c, std::ptr::null(), 0, &mut b, 0), OK);
    assert_eq!(fmi3EnterEventMode(c), ERROR);
    assert_eq!(do_step(c, 0.0, 0.01).0, OK);
    let log = messages(4);
    for needle in [
        "communication step 0.015 s",
        "x is an output",
        "throttle = inf",
        "1 value references but 2 values",
        "fmi3GetFloat64: values is NULL for 1 value references",
        "no Boolean variables",
        "fmi3EnterEventMode is not supported",
    ] {
        assert!(
            log.iter().any(|(_, t)| t.contains(needle)),
            "{needle}: {log:?}"
        );
    }
    // SAFETY: freed once.
    unsafe { fmi3FreeInstance(c) };
}

#[test]
fn a_wrong_token_event_mode_or_model_exchange_give_no_instance() {
    assert!(instantiate_with("token3", WORLD, "{nope}", 5).is_null());
    assert!(
        messages(5)
            .iter()
            .any(|(_, t)| t.contains("instantiationToken {nope}")),
        "{:?}",
        messages(5)
    );
    let name = CString::new("me").unwrap();
    let token = CString::new(guid()).unwrap();
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmu3-tests/token3/");
    let path = CString::new(dir.display().to_string()).unwrap();
    // SAFETY: valid C strings and logger.
    let c = unsafe {
        fmi3InstantiateCoSimulation(
            name.as_ptr(),
            token.as_ptr(),
            path.as_ptr(),
            0,
            1,
            1,
            0,
            std::ptr::null(),
            0,
            6 as *mut c_void,
            Some(logger),
            std::ptr::null(),
        )
    };
    assert!(c.is_null());
    assert!(messages(6).iter().any(|(_, t)| t.contains("no event mode")));
    let me = fmi3InstantiateModelExchange(
        name.as_ptr(),
        token.as_ptr(),
        path.as_ptr(),
        0,
        1,
        7 as *mut c_void,
        Some(logger),
    );
    assert!(me.is_null());
    assert!(
        messages(7)
            .iter()
            .any(|(_, t)| t.contains("co-simulation only"))
    );
}
