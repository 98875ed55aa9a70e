//! What an FMI instance handle points to, for both versions: the [`Instance`], the tool's
//! logger, and the guard every entry point runs behind.
//!
//! A Rust panic never unwinds into the tool (it becomes `Fatal` with a logged message), and a
//! NULL component is refused without touching memory. The two versions differ in their logger
//! only: FMI 2.0's is printf-like and variadic, FMI 3.0's takes the finished message.

// The C ABI of the standard: raw pointers from the tool, variadic logger calls.
#![allow(unsafe_code)]

use core::ffi::{c_char, c_int, c_void};
use std::ffi::{CStr, CString};
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::instance::{Instance, LOG_CATEGORIES, Severity};
use crate::variables::Kind;

/// `fmi2Status` / `fmi3Status` (the same values).
pub type Status = c_int;
/// `fmi2OK` / `fmi3OK`.
pub const OK: Status = 0;
/// `fmi2Warning` / `fmi3Warning`.
pub const WARNING: Status = 1;
/// `fmi2Discard` / `fmi3Discard`.
pub const DISCARD: Status = 2;
/// `fmi2Error` / `fmi3Error`.
pub const ERROR: Status = 3;
/// `fmi2Fatal` / `fmi3Fatal`.
pub const FATAL: Status = 4;

/// `fmi2CallbackLogger`.
pub type Fmi2Logger = unsafe extern "C" fn(
    component_environment: *mut c_void,
    instance_name: *const c_char,
    status: Status,
    category: *const c_char,
    message: *const c_char,
    ...
);

/// `fmi3LogMessageCallback`.
pub type Fmi3Logger = unsafe extern "C" fn(
    instance_environment: *mut c_void,
    status: Status,
    category: *const c_char,
    message: *const c_char,
);

/// The tool's logger and the environment pointer it gets back.
#[derive(Clone, Copy)]
pub struct Logger {
    sink: Sink,
    environment: *mut c_void,
}

#[derive(Clone, Copy)]
enum Sink {
    None,
    Fmi2(Fmi2Logger),
    Fmi3(Fmi3Logger),
}

impl Logger {
    /// An FMI 2.0 logger (or none).
    pub fn fmi2(logger: Option<Fmi2Logger>, environment: *mut c_void) -> Logger {
        Logger {
            sink: logger.map_or(Sink::None, Sink::Fmi2),
            environment,
        }
    }

    /// An FMI 3.0 logger (or none).
    pub fn fmi3(logger: Option<Fmi3Logger>, environment: *mut c_void) -> Logger {
        Logger {
            sink: logger.map_or(Sink::None, Sink::Fmi3),
            environment,
        }
    }

    /// Sends `text` for instance `name` in the category of `status`. FMI 2.0's logger gets it
    /// as its format string with every `%` doubled: tools that cannot read C varargs (FMPy's
    /// ctypes logger) show the format itself, so the text must be the format, made safe.
    pub fn log(&self, name: &str, status: Status, text: &str) {
        let category = if status >= ERROR {
            LOG_CATEGORIES[1]
        } else {
            LOG_CATEGORIES[0]
        };
        let clean = |s: &str| CString::new(s.replace('\0', " ")).unwrap_or_default();
        match self.sink {
            Sink::None => {}
            Sink::Fmi2(logger) => {
                let (name, category, format) = (
                    clean(name),
                    clean(category),
                    clean(&text.replace('%', "%%")),
                );
                // SAFETY: the tool gave this logger for this environment; every string is a
                // valid C string for the call, and the format has no conversion (each `%` is
                // doubled), so it reads no variadic argument.
                unsafe {
                    logger(
                        self.environment,
                        name.as_ptr(),
                        status,
                        category.as_ptr(),
                        format.as_ptr(),
                    );
                }
            }
            Sink::Fmi3(logger) => {
                let (category, message) = (clean(category), clean(text));
                // SAFETY: the tool gave this logger for this environment; the strings are
                // valid C strings for the call.
                unsafe {
                    logger(
                        self.environment,
                        status,
                        category.as_ptr(),
                        message.as_ptr(),
                    );
                }
            }
        }
    }
}

/// What an instance handle (`fmi2Component`, `fmi3Instance`) points to.
pub struct Component {
    /// The instance.
    pub instance: Instance,
    /// The tool's logger.
    pub logger: Logger,
    /// `SetDebugLogging`: warnings are logged only when on; errors always are.
    pub logging: bool,
}

impl Component {
    /// Sends the instance's messages to the logger; the status of a call that `result`
    /// ended with (a warning makes `OK` a `WARNING`).
    pub fn finish<T>(&mut self, result: Result<T, String>) -> Status {
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
            self.logger.log(&self.instance.name, level, &text);
        }
        status
    }

    /// Logs `text` as an error of this instance and answers `Error`: for the calls the entry
    /// points refuse before they reach the instance (NULL arrays, absent types, undeclared
    /// capabilities), which the instance's own messages do not carry.
    pub fn refuse(&self, text: &str) -> Status {
        self.logger.log(&self.instance.name, ERROR, text);
        ERROR
    }
}

/// Runs `body` on the component `c`; NULL is refused and a panic is `Fatal`.
pub(crate) fn guard(c: *mut c_void, body: impl FnOnce(&mut Component) -> Status) -> Status {
    if c.is_null() {
        return ERROR;
    }
    // SAFETY: a non-NULL component is one an instantiation function returned and the free
    // function has not freed (the standard's contract with the tool); the tool calls an
    // instance from one thread at a time.
    let component = unsafe { &mut *c.cast::<Component>() };
    let logger = component.logger;
    let name = component.instance.name.clone();
    match catch_unwind(AssertUnwindSafe(|| body(component))) {
        Ok(status) => status,
        Err(_) => {
            logger.log(
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
pub(crate) unsafe fn text<'a>(p: *const c_char) -> Option<&'a str> {
    if p.is_null() {
        return None;
    }
    // SAFETY: by the function's contract.
    unsafe { CStr::from_ptr(p) }.to_str().ok()
}

/// The `n` value references at `vr` (empty for `n` = 0).
///
/// # Safety
/// `vr` holds `n` elements when `n` > 0 and is not NULL.
unsafe fn references<'a>(vr: *const u32, n: usize) -> &'a [u32] {
    if n == 0 {
        &[]
    } else {
        // SAFETY: by the function's contract.
        unsafe { core::slice::from_raw_parts(vr, n) }
    }
}

/// Reads `n` values of `kind` into `write(i, value)`.
pub(crate) fn get_values(
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
        let refs = unsafe { references(vr, n) };
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
pub(crate) fn set_values(
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
        let refs = unsafe { references(vr, n) };
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

/// Refuses a call on variables of a type the FMU has none of, unless it names none.
pub(crate) fn no_variables(c: *mut c_void, nvr: usize, kind: &str) -> Status {
    guard(c, |c| {
        if nvr == 0 {
            OK
        } else {
            c.refuse(&format!("the FMU has no {kind} variables"))
        }
    })
}

/// Refuses an optional capability the model description does not declare.
pub(crate) fn unsupported(c: *mut c_void, what: &str) -> Status {
    guard(c, |c| {
        c.refuse(&format!(
            "{what} is not supported by this FMU (see its modelDescription.xml)"
        ))
    })
}

/// Boxes a new instance for the tool (NULL with the reason logged when it cannot be built).
pub(crate) fn instantiate(
    built: Result<Instance, String>,
    logger: Logger,
    name: &str,
    logging: bool,
) -> *mut c_void {
    match built {
        Ok(instance) => Box::into_raw(Box::new(Component {
            instance,
            logger,
            logging,
        }))
        .cast::<c_void>(),
        Err(why) => {
            logger.log(name, ERROR, &why);
            core::ptr::null_mut()
        }
    }
}

/// Frees what [`instantiate`] returned.
///
/// # Safety
/// `c` is NULL or an instance not yet freed.
pub(crate) unsafe fn free(c: *mut c_void) {
    if !c.is_null() {
        // SAFETY: `c` came from `Box::into_raw` in `instantiate` and is freed once.
        drop(unsafe { Box::from_raw(c.cast::<Component>()) });
    }
}

/// Catches a panic of an entry point that returns no status (instantiation), as NULL.
pub(crate) fn catch_null(body: impl FnOnce() -> *mut c_void) -> *mut c_void {
    catch_unwind(AssertUnwindSafe(body)).unwrap_or(core::ptr::null_mut())
}
