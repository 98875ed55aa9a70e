//! A world file with values set at dotted keys: how a front-end that takes parameters as
//! numbers and names (the FMU's `vehicle.mass`, `ground.friction`, `vehicle.tyre.model` …)
//! makes its world, through the same reader and errors as a world file and a sweep case.

use std::borrow::Cow;

use toml::de::DeValue;

use super::{KeyPath, WorldDescription, WorldFileError, WorldFileErrorKind, parse_with};

/// A value a front-end sets at a world-file key.
#[derive(Debug, Clone, PartialEq)]
pub enum Setting {
    /// A number (a TOML float).
    Number(f64),
    /// A name (a TOML string), e.g. `"webots"` at `vehicle.tyre.model`.
    Text(String),
}

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
    let settings: Vec<(KeyPath, Setting)> = numbers
        .iter()
        .map(|(key, value)| (key.clone(), Setting::Number(*value)))
        .collect();
    parse_with_settings(file, text, &settings)
}

/// [`parse_with_numbers`] for numbers and names.
///
/// # Errors
/// As [`parse_with_numbers`].
pub fn parse_with_settings(
    file: &str,
    text: &str,
    settings: &[(KeyPath, Setting)],
) -> Result<WorldDescription, WorldFileError> {
    let mut literals = Vec::with_capacity(settings.len());
    for (key, setting) in settings {
        let Setting::Number(value) = setting else {
            literals.push(String::new());
            continue;
        };
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
    let mut overrides = Vec::with_capacity(settings.len());
    for ((key, setting), literal) in settings.iter().zip(&literals) {
        let value = match setting {
            Setting::Text(name) => DeValue::String(Cow::Borrowed(name.as_str())),
            Setting::Number(_) => DeValue::parse(literal)
                .map_err(|e| WorldFileError {
                    file: file.to_string(),
                    location: None,
                    key: Some(key.to_string()),
                    kind: WorldFileErrorKind::Syntax(e.message().to_string()),
                })?
                .into_inner(),
        };
        overrides.push((key, value));
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

    #[test]
    fn names_are_set_as_strings_and_bad_ones_are_named() {
        let text = "[vehicle]\nmodel = \"BmwX5\"\n";
        let model = KeyPath::parse("vehicle.tyre.model").unwrap();
        let w = parse_with_settings(
            "w",
            text,
            &[(model.clone(), Setting::Text("webots".into()))],
        )
        .unwrap();
        assert!(matches!(
            w.car().unwrap().tyre,
            crate::TyreChoice::Webots(_)
        ));
        let e =
            parse_with_settings("w", text, &[(model, Setting::Text("slick".into()))]).unwrap_err();
        assert_eq!(e.key.as_deref(), Some("vehicle.tyre.model"));
    }
}
