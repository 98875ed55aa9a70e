//! The FMI 3.0 co-simulation entry points (`fmi3Functions.h` of the FMI 3.0.2 standard),
//! `extern "C"` over [`Instance`]: the common functions and those of co-simulation. The same
//! shared library serves FMI 2.0 ([`crate::fmi2`]); the packaged `modelDescription.xml` says
//! which one a tool uses.
//!
//! The FMU is co-simulation without event mode, intermediate updates, clocks or array
//! variables (its description declares none), so the calls for those answer `fmi3Error` with
//! the reason logged, as do Get/Set calls for types it has no variable of. Every entry point
//! runs behind the guard of [`crate::component`] (a panic is `fmi3Fatal`, a NULL instance
//! an error).

// The C ABI of the standard: raw pointers from the tool.
#![allow(unsafe_code)]

use core::ffi::{c_char, c_int, c_void};
use std::path::PathBuf;

use crate::component::{
    ERROR, Fmi3Logger, Logger, OK, Status, catch_null, get_values, guard, instantiate,
    no_variables, set_values, text, unsupported,
};
use crate::instance::{Instance, Phase, Version};
use crate::model_description::guid;
use crate::states;
use crate::variables::Kind;

/// `fmi3Boolean`: C's `bool`, read as a byte so that a tool's stray value is not undefined
/// behaviour in Rust.
type Boolean = u8;

/// `fmi3GetVersion`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetVersion() -> *const c_char {
    c"3.0".as_ptr()
}

/// `fmi3SetDebugLogging`: warnings are logged when on (errors always are).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetDebugLogging(
    c: *mut c_void,
    logging_on: Boolean,
    _n_categories: usize,
    _categories: *const *const c_char,
) -> Status {
    guard(c, |c| {
        c.logging = logging_on != 0;
        OK
    })
}

/// Logs why an interface type this FMU does not offer gives no instance.
fn not_offered(logger: Logger, name: *const c_char, interface: &str) -> *mut c_void {
    // SAFETY: a valid C string or NULL, by the standard's contract with the tool.
    let name = unsafe { text(name) }.unwrap_or("");
    logger.log(
        name,
        ERROR,
        &format!("this FMU offers co-simulation only, not {interface}"),
    );
    core::ptr::null_mut()
}

/// `fmi3InstantiateModelExchange`: not offered (NULL, the reason logged).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3InstantiateModelExchange(
    instance_name: *const c_char,
    _token: *const c_char,
    _resource_path: *const c_char,
    _visible: Boolean,
    _logging_on: Boolean,
    environment: *mut c_void,
    log_message: Option<Fmi3Logger>,
) -> *mut c_void {
    catch_null(|| {
        not_offered(
            Logger::fmi3(log_message, environment),
            instance_name,
            "model exchange",
        )
    })
}

/// `fmi3InstantiateScheduledExecution`: not offered (NULL, the reason logged).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3InstantiateScheduledExecution(
    instance_name: *const c_char,
    _token: *const c_char,
    _resource_path: *const c_char,
    _visible: Boolean,
    _logging_on: Boolean,
    environment: *mut c_void,
    log_message: Option<Fmi3Logger>,
    _clock_update: *const c_void,
    _lock_preemption: *const c_void,
    _unlock_preemption: *const c_void,
) -> *mut c_void {
    catch_null(|| {
        not_offered(
            Logger::fmi3(log_message, environment),
            instance_name,
            "scheduled execution",
        )
    })
}

/// `fmi3InstantiateCoSimulation`: loads `world.toml` from `resourcePath` (a directory path,
/// as FMI 3.0 passes it); NULL (with the reason logged) for another instantiation token, a
/// request for event mode, or a world that cannot be built.
///
/// # Safety
/// As the standard requires of the tool: valid C strings (or NULL) and a valid logger.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
    instance_name: *const c_char,
    instantiation_token: *const c_char,
    resource_path: *const c_char,
    _visible: Boolean,
    logging_on: Boolean,
    event_mode_used: Boolean,
    _early_return_allowed: Boolean,
    _required_intermediate_variables: *const u32,
    _n_required_intermediate_variables: usize,
    environment: *mut c_void,
    log_message: Option<Fmi3Logger>,
    _intermediate_update: *const c_void,
) -> *mut c_void {
    catch_null(|| {
        let logger = Logger::fmi3(log_message, environment);
        // SAFETY: valid C strings or NULL, by the contract above.
        let (name, token, resources) = unsafe {
            (
                text(instance_name).unwrap_or(""),
                text(instantiation_token),
                text(resource_path),
            )
        };
        let built = if token != Some(guid().as_str()) {
            Err(format!(
                "instantiationToken {} does not match this binary's {}",
                token.unwrap_or("(none)"),
                guid()
            ))
        } else if event_mode_used != 0 {
            Err("eventModeUsed: this FMU has no event mode (hasEventMode is false)".to_string())
        } else {
            match resources {
                Some(path) if !path.is_empty() => {
                    Instance::new(name, &PathBuf::from(path), Version::Fmi3)
                }
                _ => Err("no resourcePath: the FMU's world is in its resources".to_string()),
            }
        };
        instantiate(built, logger, name, logging_on != 0)
    })
}

/// `fmi3FreeInstance`.
///
/// # Safety
/// `c` is NULL or an instance not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeInstance(c: *mut c_void) {
    // SAFETY: by the contract.
    unsafe { crate::component::free(c) }
}

/// `fmi3EnterInitializationMode`: a start time other than the world's 0 is refused; the
/// tolerance and stop time are the tool's business (the FMU steps at the world's
/// basicTimeStep).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3EnterInitializationMode(
    c: *mut c_void,
    _tolerance_defined: Boolean,
    _tolerance: f64,
    start_time: f64,
    _stop_time_defined: Boolean,
    _stop_time: f64,
) -> Status {
    guard(c, |c| {
        if start_time != 0.0 && c.instance.phase() == Phase::Instantiated {
            return c.refuse(&format!(
                "fmi3EnterInitializationMode with startTime {start_time} s: the world starts \
                 at 0 s"
            ));
        }
        let r = c.instance.enter_initialisation();
        c.finish(r)
    })
}

/// `fmi3ExitInitializationMode`: into step mode (no event mode).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3ExitInitializationMode(c: *mut c_void) -> Status {
    guard(c, |c| {
        let r = c.instance.exit_initialisation();
        c.finish(r)
    })
}

/// `fmi3Terminate`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3Terminate(c: *mut c_void) -> Status {
    guard(c, |c| {
        let r = c.instance.terminate();
        c.finish(r)
    })
}

/// `fmi3Reset`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3Reset(c: *mut c_void) -> Status {
    guard(c, |c| {
        let r = c.instance.reset();
        c.finish(r)
    })
}

/// The checks every typed Get/Set makes before it touches the arrays: as many values as
/// references (every variable is a scalar), and an array where there are values. `Some` is the
/// refusal, logged through the FMI logger.
fn refuse_arrays(
    c: *mut c_void,
    function: &str,
    nvr: usize,
    n_values: usize,
    values_null: bool,
) -> Option<Status> {
    let problem = if nvr != n_values {
        format!(
            "{function}: {nvr} value references but {n_values} values (every variable is a \
             scalar)"
        )
    } else if nvr > 0 && values_null {
        format!("{function}: values is NULL for {nvr} value references")
    } else {
        return None;
    };
    Some(guard(c, |c| c.refuse(&problem)))
}

/// `fmi3GetFloat64`.
///
/// # Safety
/// `vr` holds `nvr` elements and `values` `n_values`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFloat64(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    values: *mut f64,
    n_values: usize,
) -> Status {
    if let Some(refused) = refuse_arrays(c, "fmi3GetFloat64", nvr, n_values, values.is_null()) {
        return refused;
    }
    // SAFETY: `values` holds `nvr` elements, by the contract.
    get_values(c, vr, nvr, Kind::Real, |i, v| unsafe { *values.add(i) = v })
}

/// `fmi3GetInt32`.
///
/// # Safety
/// `vr` holds `nvr` elements and `values` `n_values`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetInt32(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    values: *mut i32,
    n_values: usize,
) -> Status {
    if let Some(refused) = refuse_arrays(c, "fmi3GetInt32", nvr, n_values, values.is_null()) {
        return refused;
    }
    // SAFETY: as in `fmi3GetFloat64`; integer variables hold whole numbers within i32.
    get_values(c, vr, nvr, Kind::Integer, |i, v| unsafe {
        *values.add(i) = v as i32;
    })
}

/// `fmi3SetFloat64`.
///
/// # Safety
/// `vr` holds `nvr` elements and `values` `n_values`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFloat64(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    values: *const f64,
    n_values: usize,
) -> Status {
    if let Some(refused) = refuse_arrays(c, "fmi3SetFloat64", nvr, n_values, values.is_null()) {
        return refused;
    }
    // SAFETY: as in `fmi3GetFloat64`.
    set_values(c, vr, nvr, Kind::Real, |i| unsafe { *values.add(i) })
}

/// `fmi3SetInt32`.
///
/// # Safety
/// `vr` holds `nvr` elements and `values` `n_values`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetInt32(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    values: *const i32,
    n_values: usize,
) -> Status {
    if let Some(refused) = refuse_arrays(c, "fmi3SetInt32", nvr, n_values, values.is_null()) {
        return refused;
    }
    // SAFETY: as in `fmi3GetFloat64`.
    set_values(c, vr, nvr, Kind::Integer, |i| {
        f64::from(unsafe { *values.add(i) })
    })
}

/// Get and Set of the types the FMU has no variable of: an error unless no variable is named.
macro_rules! no_variables_of {
    ($($get:ident, $set:ident, $t:ty, $name:literal;)*) => {$(
        #[doc = concat!("`", stringify!($get), "`: the FMU has no ", $name, " variables.")]
        #[unsafe(no_mangle)]
        pub extern "C" fn $get(
            c: *mut c_void,
            _vr: *const u32,
            nvr: usize,
            _values: *mut $t,
            _n_values: usize,
        ) -> Status {
            no_variables(c, nvr, $name)
        }

        #[doc = concat!("`", stringify!($set), "`: the FMU has no ", $name, " variables.")]
        #[unsafe(no_mangle)]
        pub extern "C" fn $set(
            c: *mut c_void,
            _vr: *const u32,
            nvr: usize,
            _values: *const $t,
            _n_values: usize,
        ) -> Status {
            no_variables(c, nvr, $name)
        }
    )*};
}

no_variables_of! {
    fmi3GetFloat32, fmi3SetFloat32, f32, "Float32";
    fmi3GetInt8, fmi3SetInt8, i8, "Int8";
    fmi3GetUInt8, fmi3SetUInt8, u8, "UInt8";
    fmi3GetInt16, fmi3SetInt16, i16, "Int16";
    fmi3GetUInt16, fmi3SetUInt16, u16, "UInt16";
    fmi3GetUInt32, fmi3SetUInt32, u32, "UInt32";
    fmi3GetInt64, fmi3SetInt64, i64, "Int64";
    fmi3GetUInt64, fmi3SetUInt64, u64, "UInt64";
    fmi3GetBoolean, fmi3SetBoolean, Boolean, "Boolean";
    fmi3GetString, fmi3SetString, *const c_char, "String";
}

/// `fmi3GetBinary`: the FMU has no Binary variables.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetBinary(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _sizes: *mut usize,
    _values: *mut *const u8,
    _n_values: usize,
) -> Status {
    no_variables(c, nvr, "Binary")
}

/// `fmi3SetBinary`: the FMU has no Binary variables.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetBinary(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _sizes: *const usize,
    _values: *const *const u8,
    _n_values: usize,
) -> Status {
    no_variables(c, nvr, "Binary")
}

/// `fmi3GetClock`: the FMU has no clocks.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetClock(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _values: *mut Boolean,
) -> Status {
    no_variables(c, nvr, "Clock")
}

/// `fmi3SetClock`: the FMU has no clocks.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetClock(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _values: *const Boolean,
) -> Status {
    no_variables(c, nvr, "Clock")
}

/// Calls for capabilities the model description does not declare (dependencies, derivatives,
/// configuration mode, clocks, event mode, output derivatives): `fmi3Error`, the reason
/// logged. Each takes the instance and ignores the rest of its arguments.
macro_rules! unsupported_calls {
    ($($name:ident($($arg:ident: $t:ty),*);)*) => {$(
        #[doc = concat!("`", stringify!($name), "`: not declared by the model description.")]
        #[unsafe(no_mangle)]
        pub extern "C" fn $name(c: *mut c_void, $($arg: $t),*) -> Status {
            $(let _ = $arg;)*
            unsupported(c, stringify!($name))
        }
    )*};
}

unsupported_calls! {
    fmi3GetNumberOfVariableDependencies(_vr: u32, _n: *mut usize);
    fmi3GetVariableDependencies(
        _dependent: u32, _element: *mut usize, _independents: *mut u32,
        _independent_elements: *mut usize, _kinds: *mut c_int, _n: usize
    );
    fmi3GetDirectionalDerivative(
        _unknowns: *const u32, _n_unknowns: usize, _knowns: *const u32, _n_knowns: usize,
        _seed: *const f64, _n_seed: usize, _sensitivity: *mut f64, _n_sensitivity: usize
    );
    fmi3GetAdjointDerivative(
        _unknowns: *const u32, _n_unknowns: usize, _knowns: *const u32, _n_knowns: usize,
        _seed: *const f64, _n_seed: usize, _sensitivity: *mut f64, _n_sensitivity: usize
    );
    fmi3EnterConfigurationMode();
    fmi3ExitConfigurationMode();
    fmi3GetIntervalDecimal(_vr: *const u32, _nvr: usize, _intervals: *mut f64, _q: *mut c_int);
    fmi3GetIntervalFraction(
        _vr: *const u32, _nvr: usize, _counters: *mut u64, _resolutions: *mut u64,
        _q: *mut c_int
    );
    fmi3GetShiftDecimal(_vr: *const u32, _nvr: usize, _shifts: *mut f64);
    fmi3GetShiftFraction(
        _vr: *const u32, _nvr: usize, _counters: *mut u64, _resolutions: *mut u64
    );
    fmi3SetIntervalDecimal(_vr: *const u32, _nvr: usize, _intervals: *const f64);
    fmi3SetIntervalFraction(
        _vr: *const u32, _nvr: usize, _counters: *const u64, _resolutions: *const u64
    );
    fmi3SetShiftDecimal(_vr: *const u32, _nvr: usize, _shifts: *const f64);
    fmi3SetShiftFraction(
        _vr: *const u32, _nvr: usize, _counters: *const u64, _resolutions: *const u64
    );
    fmi3EvaluateDiscreteStates();
    fmi3UpdateDiscreteStates(
        _need_update: *mut Boolean, _terminate: *mut Boolean, _nominals: *mut Boolean,
        _values: *mut Boolean, _next_defined: *mut Boolean, _next: *mut f64
    );
    fmi3EnterEventMode();
    fmi3EnterStepMode();
    fmi3GetOutputDerivatives(
        _vr: *const u32, _nvr: usize, _orders: *const i32, _values: *mut f64, _n_values: usize
    );
    // Model exchange's and scheduled execution's own calls: the interface types are not
    // offered (their instantiation gives NULL), but tools resolve every symbol at load.
    fmi3EnterContinuousTimeMode();
    fmi3CompletedIntegratorStep(
        _no_set_prior_state: Boolean, _enter_event_mode: *mut Boolean, _terminate: *mut Boolean
    );
    fmi3SetTime(_time: f64);
    fmi3SetContinuousStates(_x: *const f64, _nx: usize);
    fmi3GetContinuousStateDerivatives(_derivatives: *mut f64, _nx: usize);
    fmi3GetEventIndicators(_indicators: *mut f64, _ni: usize);
    fmi3GetContinuousStates(_x: *mut f64, _nx: usize);
    fmi3GetNominalsOfContinuousStates(_nominals: *mut f64, _nx: usize);
    fmi3GetNumberOfEventIndicators(_n: *mut usize);
    fmi3GetNumberOfContinuousStates(_n: *mut usize);
    fmi3ActivateModelPartition(_clock: u32, _activation_time: f64);
}

/// `fmi3DoStep`: runs the world from `current` (s) over `step` (s), a whole number of its
/// basicTimeSteps; never returns early, never needs event handling; `terminateSimulation`
/// is set when the physics failed.
///
/// # Safety
/// The four output pointers are NULL or valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3DoStep(
    c: *mut c_void,
    current: f64,
    step: f64,
    _no_set_prior_state: Boolean,
    event_handling_needed: *mut Boolean,
    terminate_simulation: *mut Boolean,
    early_return: *mut Boolean,
    last_successful_time: *mut f64,
) -> Status {
    guard(c, |c| {
        let r = c.instance.do_step(current, step);
        let terminated = c.instance.phase() == Phase::Terminated;
        let time = c.instance.time();
        // SAFETY: NULL or valid, by the contract.
        unsafe {
            if let Some(p) = event_handling_needed.as_mut() {
                *p = 0;
            }
            if let Some(p) = terminate_simulation.as_mut() {
                *p = Boolean::from(terminated);
            }
            if let Some(p) = early_return.as_mut() {
                *p = 0;
            }
            if let Some(p) = last_successful_time.as_mut() {
                *p = time;
            }
        }
        c.finish(r)
    })
}

/// `fmi3GetFMUState`: a new state, or the one `*state` points to overwritten.
///
/// # Safety
/// `state` is valid; `*state` is NULL or a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFMUState(c: *mut c_void, state: *mut *mut c_void) -> Status {
    // SAFETY: by the contract.
    unsafe { states::get(c, state, "fmi3GetFMUState") }
}

/// `fmi3SetFMUState`: back to a state saved or deserialised, in this or another instance of
/// the same world.
///
/// # Safety
/// `state` is a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFMUState(c: *mut c_void, state: *mut c_void) -> Status {
    // SAFETY: by the contract.
    unsafe { states::set(c, state, "fmi3SetFMUState") }
}

/// `fmi3FreeFMUState`: frees `*state` and sets it to NULL.
///
/// # Safety
/// `state` is valid; `*state` is NULL or a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeFMUState(c: *mut c_void, state: *mut *mut c_void) -> Status {
    // SAFETY: by the contract.
    unsafe { states::free(c, state) }
}

/// `fmi3SerializedFMUStateSize`.
///
/// # Safety
/// `state` is a state of this FMU not yet freed; `size` is valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SerializedFMUStateSize(
    c: *mut c_void,
    state: *mut c_void,
    size: *mut usize,
) -> Status {
    // SAFETY: by the contract.
    unsafe { states::size(c, state, size, "fmi3SerializedFMUStateSize") }
}

/// `fmi3SerializeFMUState`: the journal of the run (see [`crate::journal`]).
///
/// # Safety
/// `state` is a state of this FMU not yet freed; `bytes` holds `size` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SerializeFMUState(
    c: *mut c_void,
    state: *mut c_void,
    bytes: *mut u8,
    size: usize,
) -> Status {
    // SAFETY: by the contract.
    unsafe { states::serialise(c, state, bytes, size, "fmi3SerializeFMUState") }
}

/// `fmi3DeserializeFMUState`.
///
/// # Safety
/// `bytes` holds `size` bytes; `state` is valid, `*state` NULL or a state not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3DeserializeFMUState(
    c: *mut c_void,
    bytes: *const u8,
    size: usize,
    state: *mut *mut c_void,
) -> Status {
    // SAFETY: by the contract.
    unsafe { states::deserialise(c, bytes, size, state, "fmi3DeserializeFMUState") }
}
