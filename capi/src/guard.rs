//! The panic boundary of every entry point.
//!
//! A Rust panic must never unwind into C (since Rust 1.81 it would abort the controller). Every
//! exported function is defined with [`entry_points!`], which runs its body inside
//! [`std::panic::catch_unwind`]: a panic prints an error naming the function and the call
//! returns the type's neutral value (0, 0.0, false) instead. This needs `panic = "unwind"`, the
//! default of every profile of this workspace.

use std::panic::{AssertUnwindSafe, catch_unwind};

/// Runs `body` for the C function `name`; a panic prints an error and gives `R::default()`.
pub(crate) fn call<R: Default>(name: &str, body: impl FnOnce() -> R) -> R {
    // The state behind the entry points stays usable after a panic (its lock recovers from
    // poisoning), so observing it afterwards cannot break memory safety.
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(value) => value,
        Err(payload) => {
            let reason = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown cause".to_string());
            crate::message::error(format_args!(
                "internal error in {name}(): {reason}; the call was ignored."
            ));
            R::default()
        }
    }
}

/// As [`call`] for a function whose C result is a pointer: `None` and a panic give NULL.
pub(crate) fn call_pointer<T>(name: &str, body: impl FnOnce() -> Option<*const T>) -> *const T {
    call(name, body).unwrap_or(std::ptr::null())
}

/// Defines `#[unsafe(no_mangle)] pub extern "C"` functions whose bodies run behind
/// [`call`]. Syntax: doc comments, then `fn name(arg: Type, ...) -> Ret { body }`.
macro_rules! entry_points {
    ($(
        $(#[$attr:meta])*
        fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? $body:block
    )*) => {$(
        $(#[$attr])*
        #[unsafe(no_mangle)]
        pub extern "C" fn $name($($arg: $ty),*) $(-> $ret)? {
            $crate::guard::call(stringify!($name), move || $body)
        }
    )*};
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_becomes_the_neutral_value() {
        let r: f64 = call("test_function", || panic!("boom"));
        assert_eq!(r, 0.0);
        let r: i32 = call("test_function", || 7);
        assert_eq!(r, 7);
    }
}
