//! The FMI 2.0 co-simulation entry points (`fmi2Functions.h` of the FMI 2.0.3 standard),
//! `extern "C"` over [`Instance`].
//!
//! Every entry point runs behind `guard`: a Rust panic never unwinds into the tool (it
//! becomes `fmi2Fatal` with a logged message), and a NULL or dangling component is refused
//! without touching memory where the pointer can be checked. The instance's messages go to the
//! tool's logger with the status of the call, as its format string with every `%` doubled:
//! the logger is printf-like, and tools that cannot read C varargs (FMPy's ctypes logger)
//! show the format string itself, so the text must be the format, made safe.

// The C ABI of the standard: raw pointers from the tool, variadic logger calls.
#![allow(unsafe_code)]

use core::ffi::{c_char, c_int, c_void};
use std::ffi::{CStr, CString};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

use crate::instance::{Instance, LOG_CATEGORIES, Phase, Severity, State};
use crate::model_description::guid;
use crate::variables::Kind;

/// `fmi2Status`.
type Status = c_int;
const OK: Status = 0;
const WARNING: Status = 1;
const DISCARD: Status = 2;
const ERROR: Status = 3;
const FATAL: Status = 4;

/// `fmi2CoSimulation` of `fmi2Type`.
const CO_SIMULATION: c_int = 1;

/// `fmi2CallbackLogger`.
type Logger = unsafe extern "C" fn(
    component_environment: *mut c_void,
    instance_name: *const c_char,
    status: Status,
    category: *const c_char,
    message: *const c_char,
    ...
);

/// `fmi2CallbackFunctions`.
#[repr(C)]
pub struct CallbackFunctions {
    logger: Option<Logger>,
    allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    step_finished: Option<unsafe extern "C" fn(*mut c_void, Status)>,
    component_environment: *mut c_void,
}

/// What `fmi2Component` points to.
struct Component {
    instance: Instance,
    logger: Option<Logger>,
    environment: *mut c_void,
    /// `fmi2SetDebugLogging`: warnings are logged only when on; errors always are.
    logging: bool,
}

impl Component {
    /// Sends the instance's messages to the logger; the status of a call that `result`
    /// ended with (a warning makes `OK` a `WARNING`).
    fn finish(&mut self, result: Result<(), String>) -> Status {
        let messages = self.instance.take_messages();
        let mut status = if result.is_ok() { OK } else { ERROR };
        for (severity, text) in messages {
            let level = match severity {
                Severity::Warning => {
                    status = status.max(WARNING);
                    if !self.logging {
                        continue;
                    }
                    WARNING
                }
                Severity::Error => ERROR,
            };
            log(
                self.logger,
                self.environment,
                &self.instance.name,
                level,
                &text,
            );
        }
        status
    }
}

impl Component {
    /// Logs `text` as an error of this instance and answers `fmi2Error`: for the calls the
    /// entry points refuse before they reach the instance (NULL arrays, absent types,
    /// undeclared capabilities), which the instance's own messages do not carry.
    fn refuse(&self, text: &str) -> Status {
        log(
            self.logger,
            self.environment,
            &self.instance.name,
            ERROR,
            text,
        );
        ERROR
    }
}

/// Calls `logger` with `text` (its `%` doubled) as the format, in the category of `status`.
fn log(logger: Option<Logger>, environment: *mut c_void, name: &str, status: Status, text: &str) {
    let Some(logger) = logger else {
        return;
    };
    let category = if status >= ERROR {
        LOG_CATEGORIES[1]
    } else {
        LOG_CATEGORIES[0]
    };
    let clean = |s: &str| CString::new(s.replace('\0', " ")).unwrap_or_default();
    let (name, category, format) = (
        clean(name),
        clean(category),
        clean(&text.replace('%', "%%")),
    );
    // SAFETY: the tool gave this logger for this environment; every string is a valid C
    // string for the call, and the format has no conversion (each `%` is doubled), so it
    // reads no variadic argument.
    unsafe {
        logger(
            environment,
            name.as_ptr(),
            status,
            category.as_ptr(),
            format.as_ptr(),
        );
    }
}

/// Runs `body` on the component `c`; NULL is refused and a panic is `fmi2Fatal`.
fn guard(c: *mut c_void, body: impl FnOnce(&mut Component) -> Status) -> Status {
    if c.is_null() {
        return ERROR;
    }
    // SAFETY: a non-NULL component is one `fmi2Instantiate` returned and `fmi2FreeInstance`
    // has not freed (the standard's contract with the tool); the tool calls an instance from
    // one thread at a time.
    let component = unsafe { &mut *c.cast::<Component>() };
    let logger = component.logger;
    let environment = component.environment;
    let name = component.instance.name.clone();
    match catch_unwind(AssertUnwindSafe(|| body(component))) {
        Ok(status) => status,
        Err(_) => {
            log(
                logger,
                environment,
                &name,
                FATAL,
                "internal error (a panic in the FMU); the instance must be freed",
            );
            FATAL
        }
    }
}

/// The string behind `p`, `None` for NULL or invalid UTF-8.
///
/// # Safety
/// `p` is NULL or a NUL-terminated string valid for the call.
unsafe fn text<'a>(p: *const c_char) -> Option<&'a str> {
    if p.is_null() {
        return None;
    }
    // SAFETY: by the function's contract.
    unsafe { CStr::from_ptr(p) }.to_str().ok()
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
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: the tool passes valid callback functions or NULL.
        let callbacks = unsafe { functions.as_ref() };
        let logger = callbacks.and_then(|f| f.logger);
        let environment = callbacks.map_or(core::ptr::null_mut(), |f| f.component_environment);
        // SAFETY: valid C strings or NULL, by the contract above.
        let (name, id, location) = unsafe {
            (
                text(instance_name).unwrap_or(""),
                text(fmu_guid),
                text(fmu_resource_location),
            )
        };
        let refuse = |why: String| {
            log(logger, environment, name, ERROR, &why);
            core::ptr::null_mut()
        };
        if fmu_type != CO_SIMULATION {
            return refuse("this FMU is for co-simulation only (fmuType 1)".to_string());
        }
        let ours = guid();
        if id != Some(ours.as_str()) {
            return refuse(format!(
                "GUID {} does not match this binary's {ours}",
                id.unwrap_or("(none)")
            ));
        }
        let Some(resources) = location.and_then(directory_of) else {
            return refuse(format!(
                "fmuResourceLocation {:?} is not a file: URI",
                location.unwrap_or("(none)")
            ));
        };
        match Instance::new(name, &resources) {
            Ok(instance) => Box::into_raw(Box::new(Component {
                instance,
                logger,
                environment,
                logging: logging_on != 0,
            }))
            .cast::<c_void>(),
            Err(why) => refuse(why),
        }
    }));
    outcome.unwrap_or(core::ptr::null_mut())
}

/// `fmi2FreeInstance`.
///
/// # Safety
/// `c` is NULL or an instance not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: *mut c_void) {
    if !c.is_null() {
        // SAFETY: `c` came from `Box::into_raw` in `fmi2Instantiate` and is freed once.
        drop(unsafe { Box::from_raw(c.cast::<Component>()) });
    }
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

/// Reads `n` values of `kind` into `write(i, value)`.
fn get_values(
    c: *mut c_void,
    vr: *const u32,
    n: usize,
    kind: Kind,
    mut write: impl FnMut(usize, f64),
) -> Status {
    guard(c, |c| {
        if n > 0 && vr.is_null() {
            return c.refuse("NULL value references");
        }
        // SAFETY: the tool passes `n` value references (checked non-NULL above when n > 0).
        let refs = if n == 0 {
            &[][..]
        } else {
            unsafe { core::slice::from_raw_parts(vr, n) }
        };
        let mut result = Ok(());
        for (i, &r) in refs.iter().enumerate() {
            match c.instance.get(r, kind) {
                Ok(v) => write(i, v),
                Err(e) => {
                    result = Err(e);
                    break;
                }
            }
        }
        c.finish(result)
    })
}

/// Sets `n` values of `kind` read by `read(i)`.
fn set_values(
    c: *mut c_void,
    vr: *const u32,
    n: usize,
    kind: Kind,
    read: impl Fn(usize) -> f64,
) -> Status {
    guard(c, |c| {
        if n > 0 && vr.is_null() {
            return c.refuse("NULL value references");
        }
        // SAFETY: as in `get_values`.
        let refs = if n == 0 {
            &[][..]
        } else {
            unsafe { core::slice::from_raw_parts(vr, n) }
        };
        let mut result = Ok(());
        for (i, &r) in refs.iter().enumerate() {
            if let Err(e) = c.instance.set(r, kind, read(i)) {
                result = Err(e);
                break;
            }
        }
        c.finish(result)
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

/// Refuses a call on variables of a type the FMU has none of (Boolean, String), unless it
/// names none.
fn no_variables(c: *mut c_void, nvr: usize, kind: &str) -> Status {
    guard(c, |c| {
        if nvr == 0 {
            OK
        } else {
            c.refuse(&format!("the FMU has no {kind} variables"))
        }
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

/// Refuses an optional capability the model description does not declare.
fn unsupported(c: *mut c_void, what: &str) -> Status {
    guard(c, |c| {
        c.refuse(&format!(
            "{what} is not supported by this FMU (see its modelDescription.xml)"
        ))
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
    guard(c, |c| {
        if state.is_null() {
            return c.refuse("fmi2GetFMUstate: NULL state pointer");
        }
        let saved = c.instance.state();
        // SAFETY: by the contract, `*state` is NULL or came from `Box::into_raw` below.
        unsafe {
            match (*state).cast::<State>().as_mut() {
                Some(existing) => *existing = saved,
                None => *state = Box::into_raw(Box::new(saved)).cast::<c_void>(),
            }
        }
        OK
    })
}

/// `fmi2SetFMUstate`: back to a state `fmi2GetFMUstate` saved.
///
/// # Safety
/// `state` is a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: *mut c_void, state: *mut c_void) -> Status {
    guard(c, |c| {
        // SAFETY: by the contract.
        let Some(saved) = (unsafe { state.cast::<State>().as_ref() }) else {
            return c.refuse("fmi2SetFMUstate: NULL state");
        };
        let r = c.instance.set_state(saved);
        c.finish(r)
    })
}

/// `fmi2FreeFMUstate`: frees `*state` and sets it to NULL.
///
/// # Safety
/// `state` is valid; `*state` is NULL or a state of this FMU not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: *mut c_void, state: *mut *mut c_void) -> Status {
    guard(c, |_| {
        if !state.is_null() {
            // SAFETY: by the contract, from `Box::into_raw` in `fmi2GetFMUstate`.
            unsafe {
                let p = (*state).cast::<State>();
                if !p.is_null() {
                    drop(Box::from_raw(p));
                }
                *state = core::ptr::null_mut();
            }
        }
        OK
    })
}

/// `fmi2SerializedFMUstateSize`: `canSerializeFMUstate` is false.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SerializedFMUstateSize(
    c: *mut c_void,
    _state: *mut c_void,
    _size: *mut usize,
) -> Status {
    unsupported(c, "fmi2SerializedFMUstateSize")
}

/// `fmi2SerializeFMUstate`: `canSerializeFMUstate` is false.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SerializeFMUstate(
    c: *mut c_void,
    _state: *mut c_void,
    _bytes: *mut u8,
    _size: usize,
) -> Status {
    unsupported(c, "fmi2SerializeFMUstate")
}

/// `fmi2DeSerializeFMUstate`: `canSerializeFMUstate` is false.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2DeSerializeFMUstate(
    c: *mut c_void,
    _bytes: *const u8,
    _size: usize,
    _state: *mut *mut c_void,
) -> Status {
    unsupported(c, "fmi2DeSerializeFMUstate")
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
