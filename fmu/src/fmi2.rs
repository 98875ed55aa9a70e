//! The FMI 2.0 co-simulation entry points (`fmi2Functions.h` of the FMI 2.0.3 standard),
//! `extern "C"` over [`Instance`].
//!
//! Every entry point runs behind the guard of [`crate::component`]: a Rust panic never
//! unwinds into the tool (it becomes `fmi2Fatal` with a logged message), and a NULL component
//! is refused without touching memory. The instance's messages go to the tool's logger with the status of the
//! call ([`crate::component::Logger`] says how).

// The C ABI of the standard: raw pointers from the tool, variadic logger calls.
#![allow(unsafe_code)]

use core::ffi::{c_char, c_int, c_void};
use std::path::PathBuf;

use crate::component::{
    DISCARD, ERROR, Fmi2Logger, Logger, OK, Status, catch_null, get_values, guard, instantiate,
    no_variables, set_values, text, unsupported,
};
use crate::instance::{Instance, Phase, Version};
use crate::model_description::guid;
use crate::states;
use crate::variables::Kind;

/// `fmi2CoSimulation` of `fmi2Type`.
const CO_SIMULATION: c_int = 1;

/// `fmi2CallbackFunctions`.
#[repr(C)]
pub struct CallbackFunctions {
    logger: Option<Fmi2Logger>,
    allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    step_finished: Option<unsafe extern "C" fn(*mut c_void, Status)>,
    component_environment: *mut c_void,
}

/// The directory of a `file:` URI (`file:///a/b`, `file:/a/b`, `file://localhost/a/b`),
/// percent-decoded.
fn directory_of(uri: &str) -> Option<PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let path = rest
        .strip_prefix("//localhost")
        .or_else(|| rest.strip_prefix("//"))
        .unwrap_or(rest);
    let bytes = path.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            if i + 2 >= bytes.len() {
                return None;
            }
            let hex = std::str::from_utf8(&bytes[i + 1..i + 3]).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    Some(PathBuf::from(String::from_utf8(out).ok()?))
}

/// `fmi2GetTypesPlatform`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

/// `fmi2GetVersion`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

/// `fmi2Instantiate`: loads `resources/world.toml` below `fmuResourceLocation`; NULL (with
/// the reason logged) for another FMU type, another GUID or a world that cannot be built.
///
/// # Safety
/// As the standard requires of the tool: valid C strings (or NULL) and callback functions.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Instantiate(
    instance_name: *const c_char,
    fmu_type: c_int,
    fmu_guid: *const c_char,
    fmu_resource_location: *const c_char,
    functions: *const CallbackFunctions,
    _visible: c_int,
    logging_on: c_int,
) -> *mut c_void {
    catch_null(|| {
        // SAFETY: the tool passes valid callback functions or NULL.
        let callbacks = unsafe { functions.as_ref() };
        let logger = Logger::fmi2(
            callbacks.and_then(|f| f.logger),
            callbacks.map_or(core::ptr::null_mut(), |f| f.component_environment),
        );
        // SAFETY: valid C strings or NULL, by the contract above.
        let (name, id, location) = unsafe {
            (
                text(instance_name).unwrap_or(""),
                text(fmu_guid),
                text(fmu_resource_location),
            )
        };
        let built = if fmu_type != CO_SIMULATION {
            Err("this FMU is for co-simulation only (fmuType 1)".to_string())
        } else if id != Some(guid().as_str()) {
            Err(format!(
                "GUID {} does not match this binary's {}",
                id.unwrap_or("(none)"),
                guid()
            ))
        } else {
            match location.and_then(directory_of) {
                Some(resources) => Instance::new(name, &resources, Version::Fmi2),
                None => Err(format!(
                    "fmuResourceLocation {:?} is not a file: URI",
                    location.unwrap_or("(none)")
                )),
            }
        };
        instantiate(built, logger, name, logging_on != 0)
    })
}

/// `fmi2FreeInstance`.
///
/// # Safety
/// `c` is NULL or an instance not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: *mut c_void) {
    // SAFETY: by the contract.
    unsafe { crate::component::free(c) }
}

/// `fmi2SetDebugLogging`: warnings are logged when on (errors always are).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetDebugLogging(
    c: *mut c_void,
    logging_on: c_int,
    _n_categories: usize,
    _categories: *const *const c_char,
) -> Status {
    guard(c, |c| {
        c.logging = logging_on != 0;
        OK
    })
}

/// `fmi2SetupExperiment`: a start time other than the world's 0 is refused; the tolerance
/// and stop time are the tool's business (the FMU steps at the world's basicTimeStep).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetupExperiment(
    c: *mut c_void,
    _tolerance_defined: c_int,
    _tolerance: f64,
    start_time: f64,
    _stop_time_defined: c_int,
    _stop_time: f64,
) -> Status {
    guard(c, |c| {
        if start_time == 0.0 && c.instance.phase() == Phase::Instantiated {
            OK
        } else {
            c.refuse(&format!(
                "fmi2SetupExperiment with startTime {start_time} s in the {:?} state: the \
                 world starts at 0 s, before initialisation",
                c.instance.phase()
            ))
        }
    })
}

/// `fmi2EnterInitializationMode`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2EnterInitializationMode(c: *mut c_void) -> Status {
    guard(c, |c| {
        let r = c.instance.enter_initialisation();
        c.finish(r)
    })
}

/// `fmi2ExitInitializationMode`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2ExitInitializationMode(c: *mut c_void) -> Status {
    guard(c, |c| {
        let r = c.instance.exit_initialisation();
        c.finish(r)
    })
}

/// `fmi2Terminate`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2Terminate(c: *mut c_void) -> Status {
    guard(c, |c| {
        let r = c.instance.terminate();
        c.finish(r)
    })
}

/// `fmi2Reset`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2Reset(c: *mut c_void) -> Status {
    guard(c, |c| {
        let r = c.instance.reset();
        c.finish(r)
    })
}

/// `fmi2GetReal`.
///
/// # Safety
/// `vr` and `value` hold `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    value: *mut f64,
) -> Status {
    if nvr > 0 && value.is_null() {
        return ERROR;
    }
    // SAFETY: `value` holds `nvr` elements, by the contract.
    get_values(c, vr, nvr, Kind::Real, |i, v| unsafe { *value.add(i) = v })
}

/// `fmi2GetInteger`.
///
/// # Safety
/// `vr` and `value` hold `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetInteger(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    value: *mut c_int,
) -> Status {
    if nvr > 0 && value.is_null() {
        return ERROR;
    }
    // SAFETY: as in `fmi2GetReal`; integer variables hold whole numbers within i32.
    get_values(c, vr, nvr, Kind::Integer, |i, v| unsafe {
        *value.add(i) = v as c_int;
    })
}

/// `fmi2SetReal`.
///
/// # Safety
/// `vr` and `value` hold `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    value: *const f64,
) -> Status {
    if nvr > 0 && value.is_null() {
        return ERROR;
    }
    // SAFETY: as in `fmi2GetReal`.
    set_values(c, vr, nvr, Kind::Real, |i| unsafe { *value.add(i) })
}

/// `fmi2SetInteger`.
///
/// # Safety
/// `vr` and `value` hold `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetInteger(
    c: *mut c_void,
    vr: *const u32,
    nvr: usize,
    value: *const c_int,
) -> Status {
    if nvr > 0 && value.is_null() {
        return ERROR;
    }
    // SAFETY: as in `fmi2GetReal`.
    set_values(c, vr, nvr, Kind::Integer, |i| {
        f64::from(unsafe { *value.add(i) })
    })
}

/// `fmi2GetBoolean`: the FMU has no Boolean variables.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetBoolean(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _v: *mut c_int,
) -> Status {
    no_variables(c, nvr, "Boolean")
}

/// `fmi2SetBoolean`: the FMU has no Boolean variables.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetBoolean(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _v: *const c_int,
) -> Status {
    no_variables(c, nvr, "Boolean")
}

/// `fmi2GetString`: the FMU has no String variables.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetString(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _v: *mut *const c_char,
) -> Status {
    no_variables(c, nvr, "String")
}

/// `fmi2SetString`: the FMU has no String variables.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetString(
    c: *mut c_void,
    _vr: *const u32,
    nvr: usize,
    _v: *const *const c_char,
) -> Status {
    no_variables(c, nvr, "String")
}

/// `fmi2DoStep`: runs the world from `current` (s) over `step` (s), a whole number of its
/// basicTimeSteps; synchronous.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2DoStep(
    c: *mut c_void,
    current: f64,
    step: f64,
    _no_set_prior_state: c_int,
) -> Status {
    guard(c, |c| {
        let r = c.instance.do_step(current, step);
        c.finish(r)
    })
}

/// `fmi2CancelStep`: steps are synchronous, there is nothing to cancel.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2CancelStep(c: *mut c_void) -> Status {
    unsupported(c, "fmi2CancelStep")
}

/// `fmi2GetStatus`: no asynchronous step ever pends.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetStatus(c: *mut c_void, _kind: c_int, _value: *mut Status) -> Status {
    guard(c, |_| DISCARD)
}

/// `fmi2GetRealStatus`: no asynchronous step ever pends.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetRealStatus(c: *mut c_void, _kind: c_int, _value: *mut f64) -> Status {
    guard(c, |_| DISCARD)
}

/// `fmi2GetIntegerStatus`: no asynchronous step ever pends.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetIntegerStatus(c: *mut c_void, _kind: c_int, _value: *mut c_int) -> Status {
    guard(c, |_| DISCARD)
}

/// `fmi2GetBooleanStatus`: no asynchronous step ever pends.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetBooleanStatus(c: *mut c_void, _kind: c_int, _value: *mut c_int) -> Status {
    guard(c, |_| DISCARD)
}

/// `fmi2GetStringStatus`: no asynchronous step ever pends.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetStringStatus(
    c: *mut c_void,
    _kind: c_int,
    _value: *mut *const c_char,
) -> Status {
    guard(c, |_| DISCARD)
}

/// `fmi2SetRealInputDerivatives`: `canInterpolateInputs` is false.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetRealInputDerivatives(
    c: *mut c_void,
    _vr: *const u32,
    _nvr: usize,
    _order: *const c_int,
    _value: *const f64,
) -> Status {
    unsupported(c, "fmi2SetRealInputDerivatives")
}

/// `fmi2GetRealOutputDerivatives`: `maxOutputDerivativeOrder` is 0.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetRealOutputDerivatives(
    c: *mut c_void,
    _vr: *const u32,
    _nvr: usize,
    _order: *const c_int,
    _value: *mut f64,
) -> Status {
    unsupported(c, "fmi2GetRealOutputDerivatives")
}

/// `fmi2GetDirectionalDerivative`: `providesDirectionalDerivative` is false.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetDirectionalDerivative(
    c: *mut c_void,
    _unknown: *const u32,
    _n_unknown: usize,
    _known: *const u32,
    _n_known: usize,
    _dv_known: *const f64,
    _dv_unknown: *mut f64,
) -> Status {
    unsupported(c, "fmi2GetDirectionalDerivative")
}

/// `fmi2GetFMUstate`: a new state, or the one `*state` points to overwritten.
///
/// # Safety
/// `state` is valid; `*state` is NULL or a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(c: *mut c_void, state: *mut *mut c_void) -> Status {
    // SAFETY: by the contract.
    unsafe { states::get(c, state, "fmi2GetFMUstate") }
}

/// `fmi2SetFMUstate`: back to a state `fmi2GetFMUstate` saved or `fmi2DeSerializeFMUstate`
/// read, in this or another instance of the same world.
///
/// # Safety
/// `state` is a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: *mut c_void, state: *mut c_void) -> Status {
    // SAFETY: by the contract.
    unsafe { states::set(c, state, "fmi2SetFMUstate") }
}

/// `fmi2FreeFMUstate`: frees `*state` and sets it to NULL.
///
/// # Safety
/// `state` is valid; `*state` is NULL or a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: *mut c_void, state: *mut *mut c_void) -> Status {
    // SAFETY: by the contract.
    unsafe { states::free(c, state) }
}

/// `fmi2SerializedFMUstateSize`.
///
/// # Safety
/// `state` is a state of this FMU not yet freed; `size` is valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: *mut c_void,
    state: *mut c_void,
    size: *mut usize,
) -> Status {
    // SAFETY: by the contract.
    unsafe { states::size(c, state, size, "fmi2SerializedFMUstateSize") }
}

/// `fmi2SerializeFMUstate`: the journal of the run, which any instance of the same world
/// replays to the same bits (see [`crate::journal`]).
///
/// # Safety
/// `state` is a state of this FMU not yet freed; `bytes` holds `size` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: *mut c_void,
    state: *mut c_void,
    bytes: *mut u8,
    size: usize,
) -> Status {
    // SAFETY: by the contract.
    unsafe { states::serialise(c, state, bytes, size, "fmi2SerializeFMUstate") }
}

/// `fmi2DeSerializeFMUstate`.
///
/// # Safety
/// `bytes` holds `size` bytes; `state` is valid, `*state` NULL or a state not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: *mut c_void,
    bytes: *const u8,
    size: usize,
    state: *mut *mut c_void,
) -> Status {
    // SAFETY: by the contract.
    unsafe { states::deserialise(c, bytes, size, state, "fmi2DeSerializeFMUstate") }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resource_uris_become_directories() {
        assert_eq!(
            directory_of("file:///a/b%20c/resources"),
            Some(PathBuf::from("/a/b c/resources"))
        );
        assert_eq!(directory_of("file:/a/b"), Some(PathBuf::from("/a/b")));
        assert_eq!(
            directory_of("file://localhost/a"),
            Some(PathBuf::from("/a"))
        );
        assert_eq!(directory_of("http://x/a"), None);
        assert_eq!(directory_of("file:///a%2"), None);
    }
}
