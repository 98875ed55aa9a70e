//! A world file with numbers set at dotted keys: how a front-end that takes parameters as
//! numbers (the FMU's `vehicle.mass`, `ground.friction` …) makes its world, through the same
//! reader and errors as a world file and a sweep case.

use toml::de::DeValue;

use super::{KeyPath, WorldDescription, WorldFileError, WorldFileErrorKind, parse_with};

/// Parses world-file text with each of `numbers` set at its key first (replacing what the
/// text has there, the tables on the way created), then read as any world file: an invalid
/// value gets the error (or warning) of its key.
///
/// # Errors
/// As [`parse_str`](super::parse_str); a number that is not finite is an
/// [`WorldFileErrorKind::InvalidValue`] at its key (TOML's `nan` and `inf` would reach the
/// reader's own checks, but a front-end should say which number it was given).
pub fn parse_with_numbers(
    file: &str,
    text: &str,
    numbers: &[(KeyPath, f64)],
) -> Result<WorldDescription, WorldFileError> {
    let mut literals = Vec::with_capacity(numbers.len());
    for (key, value) in numbers {
        if !value.is_finite() {
            return Err(WorldFileError {
                file: file.to_string(),
                location: None,
                key: Some(key.to_string()),
                kind: WorldFileErrorKind::InvalidValue(format!("{value}: must be finite")),
            });
        }
        // `{:?}` writes a float with a decimal point or an exponent: a TOML float literal
        // that parses back to the same f64.
        literals.push(format!("{value:?}"));
    }
    let mut overrides = Vec::with_capacity(numbers.len());
    for ((key, _), literal) in numbers.iter().zip(&literals) {
        let value = DeValue::parse(literal).map_err(|e| WorldFileError {
            file: file.to_string(),
            location: None,
            key: Some(key.to_string()),
            kind: WorldFileErrorKind::Syntax(e.message().to_string()),
        })?;
        overrides.push((key, value.into_inner()));
    }
    parse_with(file, text, overrides)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_replace_the_text_s_values_and_bad_ones_are_named() {
        let text = "[ground]\nfriction = 1\n[vehicle]\nmodel = \"BmwX5\"\n";
        let friction = KeyPath::parse("ground.friction").unwrap();
        let mass = KeyPath::parse("vehicle.mass").unwrap();
        let w = parse_with_numbers("w", text, &[(friction.clone(), 0.5), (mass, 1500.0)]).unwrap();
        assert_eq!(w.config.ground_friction, 0.5);
        assert_eq!(w.car().unwrap().params.body.mass, 1500.0);
        let e = parse_with_numbers("w", text, &[(friction.clone(), f64::NAN)]).unwrap_err();
        assert_eq!(e.key.as_deref(), Some("ground.friction"));
        let e = parse_with_numbers("w", text, &[(friction, -1.0)]).unwrap_err();
        assert_eq!(e.key.as_deref(), Some("ground.friction"));
    }
}
