//! What the libraries print on stderr: Webots' texts, and C's `%g` number format they use.

use std::fmt::Display;

use vehicle_model::Warning;

/// Prints a warning of the driver or car library exactly as Webots does (one line, except
/// `Warning: Minimum gear value is -1`, which Webots prints without a newline).
pub(crate) fn warning(w: &Warning) {
    if w.ends_with_newline() {
        eprintln!("{w}");
    } else {
        eprint!("{w}");
    }
}

/// Prints the warning a setter returned, if any.
pub(crate) fn report(returned: Option<Warning>) {
    if let Some(w) = returned {
        warning(&w);
    }
}

/// Prints `Warning: '<init>' should be called before to use '<function>'.`
pub(crate) fn not_initialised(init: &'static str, function: &'static str) {
    warning(&Warning::NotInitialised { init, function });
}

/// Prints `Error: <text>` on one line.
pub(crate) fn error(text: impl Display) {
    eprintln!("Error: {text}");
}

/// A device's sampling period (ms) from the C argument; a negative one is refused with
/// Webots' error naming `function` (`None`: nothing is to be enabled).
pub(crate) fn sampling_period(period_ms: std::os::raw::c_int, function: &str) -> Option<u32> {
    let period = u32::try_from(period_ms).ok();
    if period.is_none() {
        error(format_args!(
            "{function}() called with negative sampling period."
        ));
    }
    period
}

/// Formats `x` as C's `printf("%g", x)` does: 6 significant digits, trailing zeros removed,
/// exponent form (`1e-05`, `1.5e+07`) below 1e-4 and from 1e6 on, `inf`, `-inf`, `nan`.
pub(crate) fn format_g(x: f64) -> String {
    if x.is_nan() {
        return if x.is_sign_negative() { "-nan" } else { "nan" }.to_string();
    }
    if x.is_infinite() {
        return if x < 0.0 { "-inf" } else { "inf" }.to_string();
    }
    if x == 0.0 {
        return if x.is_sign_negative() { "-0" } else { "0" }.to_string();
    }
    // The decimal exponent after rounding to 6 significant digits decides the form.
    let scientific = format!("{x:.5e}");
    let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if (-4..6).contains(&exponent) {
        let decimals = usize::try_from(5 - exponent).unwrap_or(0);
        strip_zeros(&format!("{x:.decimals$}")).to_string()
    } else {
        let sign = if exponent < 0 { '-' } else { '+' };
        format!(
            "{}e{sign}{:02}",
            strip_zeros(mantissa),
            exponent.unsigned_abs()
        )
    }
}

/// `1.500` → `1.5`, `2.000` → `2`; integers are left alone.
fn strip_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percent_g_like_c() {
        // Expected strings from glibc's printf("%g", x).
        let cases: [(f64, &str); 17] = [
            (6.25, "6.25"),
            (10.0, "10"),
            (1.0, "1"),
            (-3.0, "-3"),
            (0.5, "0.5"),
            (100000.0, "100000"),
            (999999.4, "999999"),
            (999999.5, "1e+06"),
            (1e6, "1e+06"),
            (123456789.0, "1.23457e+08"),
            (0.0001, "0.0001"),
            (0.00001, "1e-05"),
            (0.000123456789, "0.000123457"),
            (1.0 / 3.0, "0.333333"),
            (-2.5e-300, "-2.5e-300"),
            (1e100, "1e+100"),
            (0.1 + 0.2, "0.3"),
        ];
        for (x, expected) in cases {
            assert_eq!(format_g(x), expected, "{x:e}");
        }
        assert_eq!(format_g(f64::INFINITY), "inf");
        assert_eq!(format_g(f64::NEG_INFINITY), "-inf");
        assert_eq!(format_g(f64::NAN), "nan");
        assert_eq!(format_g(0.0), "0");
        assert_eq!(format_g(-0.0), "-0");
    }
}
