//! The FMU-state calls, the same in FMI 2.0 and 3.0 but for their names: get, set and free a
//! state, and its serialised bytes. A state is a boxed [`State`]; the tool owns it between
//! `Get` and `Free`.

// The C ABI of the standard: raw pointers from the tool.
#![allow(unsafe_code)]

use core::ffi::c_void;

use crate::component::{OK, Status, guard};
use crate::instance::{Instance, State};

/// `GetFMUstate`: a new state in `*state`, or the one it points to overwritten.
///
/// # Safety
/// `state` is NULL or valid; `*state` is NULL or a state of this FMU not yet freed.
pub unsafe fn get(c: *mut c_void, state: *mut *mut c_void, function: &str) -> Status {
    guard(c, |c| {
        if state.is_null() {
            return c.refuse(&format!("{function}: NULL state pointer"));
        }
        let saved = c.instance.state();
        // SAFETY: by the contract, `*state` is NULL or came from `Box::into_raw` here.
        unsafe { store(state, saved) };
        OK
    })
}

/// Puts `saved` in `*state`: a new box, or the existing state overwritten.
///
/// # Safety
/// `state` is valid; `*state` is NULL or a state of this FMU not yet freed.
unsafe fn store(state: *mut *mut c_void, saved: State) {
    // SAFETY: by the contract.
    unsafe {
        match (*state).cast::<State>().as_mut() {
            Some(existing) => *existing = saved,
            None => *state = Box::into_raw(Box::new(saved)).cast::<c_void>(),
        }
    }
}

/// `SetFMUstate`: back to a state this FMU saved or read from bytes.
///
/// # Safety
/// `state` is NULL or a state of this FMU not yet freed.
pub unsafe fn set(c: *mut c_void, state: *mut c_void, function: &str) -> Status {
    guard(c, |c| {
        // SAFETY: by the contract.
        let Some(saved) = (unsafe { state.cast::<State>().as_ref() }) else {
            return c.refuse(&format!("{function}: NULL state"));
        };
        let r = c.instance.set_state(saved);
        c.finish(r)
    })
}

/// `FreeFMUstate`: frees `*state` and sets it to NULL.
///
/// # Safety
/// `state` is NULL or valid; `*state` is NULL or a state of this FMU not yet freed.
pub unsafe fn free(c: *mut c_void, state: *mut *mut c_void) -> Status {
    guard(c, |_| {
        if !state.is_null() {
            // SAFETY: by the contract, from `Box::into_raw` in `store`.
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

/// `SerializedFMUstateSize`: the length of the state's bytes in `*size`.
///
/// # Safety
/// `state` is NULL or a state of this FMU not yet freed; `size` is NULL or valid.
pub unsafe fn size(c: *mut c_void, state: *mut c_void, size: *mut usize, function: &str) -> Status {
    guard(c, |c| {
        // SAFETY: by the contract.
        let (Some(saved), false) = (unsafe { state.cast::<State>().as_ref() }, size.is_null())
        else {
            return c.refuse(&format!("{function}: NULL state or size"));
        };
        // SAFETY: checked non-NULL; valid by the contract.
        unsafe { *size = Instance::serialise(saved).len() };
        OK
    })
}

/// `SerializeFMUstate`: the state's bytes into the tool's buffer of `size` bytes, which
/// must be the length `SerializedFMUstateSize` gave.
///
/// # Safety
/// `state` is NULL or a state of this FMU not yet freed; `bytes` is NULL or holds `size`
/// bytes.
pub unsafe fn serialise(
    c: *mut c_void,
    state: *mut c_void,
    bytes: *mut u8,
    size: usize,
    function: &str,
) -> Status {
    guard(c, |c| {
        // SAFETY: by the contract.
        let Some(saved) = (unsafe { state.cast::<State>().as_ref() }) else {
            return c.refuse(&format!("{function}: NULL state"));
        };
        let out = Instance::serialise(saved);
        if bytes.is_null() || size != out.len() {
            return c.refuse(&format!(
                "{function}: a buffer of {size} bytes for a state of {} bytes",
                out.len()
            ));
        }
        // SAFETY: `bytes` holds `size` = `out.len()` bytes by the contract; the regions are
        // distinct (`out` is ours).
        unsafe { core::ptr::copy_nonoverlapping(out.as_ptr(), bytes, size) };
        OK
    })
}

/// `DeSerializeFMUstate`: a new state from `size` bytes, in `*state`.
///
/// # Safety
/// `bytes` is NULL or holds `size` bytes; `state` is NULL or valid, `*state` NULL or a state
/// of this FMU not yet freed.
pub unsafe fn deserialise(
    c: *mut c_void,
    bytes: *const u8,
    size: usize,
    state: *mut *mut c_void,
    function: &str,
) -> Status {
    guard(c, |c| {
        if bytes.is_null() || state.is_null() {
            return c.refuse(&format!("{function}: NULL bytes or state pointer"));
        }
        // SAFETY: `bytes` holds `size` bytes by the contract.
        let data = unsafe { core::slice::from_raw_parts(bytes, size) };
        match c.instance.deserialise(data) {
            Ok(read) => {
                // SAFETY: by the contract.
                unsafe { store(state, read) };
                c.finish(Ok(()))
            }
            Err(e) => c.finish(Err::<(), _>(e)),
        }
    })
}
