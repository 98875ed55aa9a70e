//! The value an axis gives a world-file key in one case.

use core::fmt;

use toml::de::DeValue;

use crate::world_file::read::as_f64;

/// A value set at a world-file key: what the sweep file wrote (a list's element) or what an
/// axis generated (a range's step, a random draw: numbers).
#[derive(Debug, Clone, PartialEq)]
pub enum AxisValue {
    /// A whole number: a list's integer, or a generated number with no fraction (so that a
    /// key that takes an integer, e.g. `basicTimeStep`, takes it).
    Integer(i64),
    /// A number with a fraction.
    Float(f64),
    /// `true` or `false`.
    Bool(bool),
    /// A string, e.g. a model name.
    Text(String),
    /// A list, e.g. a `translation`.
    List(Vec<AxisValue>),
}

/// Largest magnitude below which every integer is exact in an f64 (2⁵³).
const EXACT_INTEGERS: f64 = 9_007_199_254_740_992.0;

impl AxisValue {
    /// A generated number: an [`AxisValue::Integer`] when it has no fraction (and fits),
    /// else an [`AxisValue::Float`].
    pub fn number(x: f64) -> AxisValue {
        if x.is_finite() && x == x.trunc() && x.abs() < EXACT_INTEGERS {
            // Exact: |x| < 2⁵³ and whole.
            AxisValue::Integer(x as i64)
        } else {
            AxisValue::Float(x)
        }
    }

    /// The value as a number, if it is one.
    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            AxisValue::Integer(i) => Some(i as f64),
            AxisValue::Float(x) => Some(x),
            _ => None,
        }
    }

    /// The value of a TOML value of the sweep file; `None` for a table or a date, which no
    /// world-file key takes.
    pub(crate) fn from_toml(v: &DeValue<'_>) -> Option<AxisValue> {
        Some(match v {
            DeValue::Integer(i) => match i64::from_str_radix(i.as_str(), i.radix()) {
                Ok(n) => AxisValue::Integer(n),
                Err(_) => AxisValue::Float(as_f64(v)?),
            },
            DeValue::Float(_) => AxisValue::Float(as_f64(v)?),
            DeValue::Boolean(b) => AxisValue::Bool(*b),
            DeValue::String(s) => AxisValue::Text(s.to_string()),
            DeValue::Array(items) => AxisValue::List(
                items
                    .iter()
                    .map(|item| AxisValue::from_toml(item.get_ref()))
                    .collect::<Option<_>>()?,
            ),
            DeValue::Table(_) | DeValue::Datetime(_) => return None,
        })
    }

    /// The value in TOML's syntax (`1.5`, `1e-7`, `"BmwX5"`, `[0, 0, 0.4]`), as a world
    /// document takes it: a float always with a fraction or exponent, so that it stays a float.
    pub(crate) fn toml_literal(&self) -> String {
        let mut out = String::new();
        self.write_toml(&mut out);
        out
    }

    fn write_toml(&self, out: &mut String) {
        match self {
            AxisValue::Integer(i) => out.push_str(&i.to_string()),
            AxisValue::Float(x) if x.is_nan() => out.push_str("nan"),
            AxisValue::Float(x) if x.is_infinite() => {
                out.push_str(if *x > 0.0 { "inf" } else { "-inf" });
            }
            // `{:?}` writes the shortest text that reads back as `x`, with `.0` or an exponent.
            AxisValue::Float(x) => out.push_str(&format!("{x:?}")),
            AxisValue::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
            AxisValue::Text(s) => {
                out.push('"');
                for c in s.chars() {
                    match c {
                        '"' => out.push_str("\\\""),
                        '\\' => out.push_str("\\\\"),
                        c if c.is_control() => out.push_str(&format!("\\u{:04X}", u32::from(c))),
                        c => out.push(c),
                    }
                }
                out.push('"');
            }
            AxisValue::List(items) => {
                out.push('[');
                for (i, item) in items.iter().enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    item.write_toml(out);
                }
                out.push(']');
            }
        }
    }
}

impl fmt::Display for AxisValue {
    /// As the results' CSV writes it: numbers in their shortest exact decimal form, strings
    /// as they are, lists in TOML's syntax (`[0, 0, 0.4]`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AxisValue::Integer(i) => write!(f, "{i}"),
            AxisValue::Float(x) => write!(f, "{x}"),
            AxisValue::Bool(b) => write!(f, "{b}"),
            AxisValue::Text(s) => f.write_str(s),
            AxisValue::List(items) => {
                f.write_str("[")?;
                for (i, item) in items.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    match item {
                        AxisValue::Text(s) => write!(f, "\"{s}\"")?,
                        other => write!(f, "{other}")?,
                    }
                }
                f.write_str("]")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_read_back_as_the_same_value() {
        let values = [
            AxisValue::Integer(-12),
            AxisValue::Float(0.1),
            AxisValue::Float(1e-7),
            AxisValue::Float(2.0e21),
            AxisValue::Float(-3.5),
            AxisValue::Bool(true),
            AxisValue::Text("a \"quoted\" \\ name\n".into()),
            AxisValue::List(vec![
                AxisValue::Integer(0),
                AxisValue::Float(0.4),
                AxisValue::Text("x".into()),
            ]),
        ];
        for v in values {
            let text = v.toml_literal();
            let parsed = DeValue::parse(&text).unwrap().into_inner();
            assert_eq!(AxisValue::from_toml(&parsed), Some(v.clone()), "{text}");
        }
        // A float stays a float in TOML, whatever its value.
        assert_eq!(AxisValue::Float(2.0).toml_literal(), "2.0");
        assert_eq!(AxisValue::Float(f64::NEG_INFINITY).toml_literal(), "-inf");
    }

    #[test]
    fn generated_whole_numbers_are_integers() {
        assert_eq!(AxisValue::number(1250.0), AxisValue::Integer(1250));
        assert_eq!(AxisValue::number(-0.0), AxisValue::Integer(0));
        assert_eq!(AxisValue::number(0.25), AxisValue::Float(0.25));
        assert_eq!(AxisValue::number(1e300), AxisValue::Float(1e300));
        assert_eq!(
            AxisValue::number(f64::NAN).as_f64().map(f64::is_nan),
            Some(true)
        );
        // The CSV's text: shortest decimals, lists in TOML syntax.
        assert_eq!(AxisValue::Float(0.1).to_string(), "0.1");
        assert_eq!(AxisValue::Float(1e-7).to_string(), "0.0000001");
        let list = AxisValue::List(vec![AxisValue::Integer(1), AxisValue::Text("a".into())]);
        assert_eq!(list.to_string(), "[1, \"a\"]");
    }
}
