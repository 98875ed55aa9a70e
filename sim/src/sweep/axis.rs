//! An axis: a world-file key and the values a sweep gives it, read from the sweep file's
//! `[axes]` table.

use core::ops::Range;

use proto_geom::plausible::Compact;
use toml::de::{DeTable, DeValue};

use crate::report::{METRIC_DIGITS, significant};
use crate::world_file::read::{Section, describe};
use crate::world_file::{KeyPath, WorldFileError, WorldFileErrorKind};

use super::draw;
use super::value::AxisValue;

/// What an axis takes, for messages.
pub(crate) const AXIS_SHAPES: &str = "a list of values, { from, to, steps }, \
     { uniform = [lo, hi], count, seed } or { normal = [mean, sd], count, seed }";

/// The keys of an axis's table (every shape's).
const SHAPE_KEYS: [&str; 7] = ["from", "to", "steps", "uniform", "normal", "count", "seed"];

/// How an axis makes its values.
#[derive(Debug, Clone, PartialEq)]
pub enum AxisValues {
    /// The sweep file's list, in its order.
    List(Vec<AxisValue>),
    /// `steps` evenly spaced numbers from `from` to `to`, both included.
    Range {
        /// The first value.
        from: f64,
        /// The last value.
        to: f64,
        /// How many values, ≥ 2.
        steps: usize,
    },
    /// `count` draws uniform in `[lo, hi)`.
    Uniform {
        /// Lower bound (included).
        lo: f64,
        /// Upper bound (excluded), > `lo`.
        hi: f64,
        /// How many draws, ≥ 1.
        count: usize,
        /// The seed of the draws.
        seed: u64,
    },
    /// `count` draws from the normal distribution of mean `mean` and standard deviation `sd`.
    Normal {
        /// The mean.
        mean: f64,
        /// The standard deviation, ≥ 0.
        sd: f64,
        /// How many draws, ≥ 1.
        count: usize,
        /// The seed of the draws.
        seed: u64,
    },
}

/// One axis of a sweep: a world-file key and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    key: KeyPath,
    values: AxisValues,
}

impl Axis {
    /// An axis over the world-file key `key` (e.g. `ground.friction`).
    pub fn new(key: KeyPath, values: AxisValues) -> Self {
        Axis { key, values }
    }

    /// The world-file key, e.g. `ground.friction` (also the axis's column in the results).
    pub fn key(&self) -> &KeyPath {
        &self.key
    }

    /// How the axis makes its values.
    pub fn values(&self) -> &AxisValues {
        &self.values
    }

    /// The number of values.
    pub fn len(&self) -> usize {
        match &self.values {
            AxisValues::List(v) => v.len(),
            AxisValues::Range { steps, .. } => *steps,
            AxisValues::Uniform { count, .. } | AxisValues::Normal { count, .. } => *count,
        }
    }

    /// True when the axis has no value (a sweep file's axis always has one at least).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Value `k` (from 0), `None` past the last. A range's step and a random draw are rounded
    /// to 6 significant digits (the physics runs in f32, and the results' CSV then holds a
    /// short number) unless the rounding would leave the axis's interval (`[from, to]`,
    /// `[lo, hi)`): a draw from `[0.99999, 1)` may not round to the excluded 1, which a key
    /// valid below 1 refuses, so such a value keeps its full precision. A whole number is an
    /// integer. Every value is finite: a range's values are computed without its span, which
    /// may overflow (`-1e308` to `1e308`).
    pub fn value(&self, k: usize) -> Option<AxisValue> {
        if k >= self.len() {
            return None;
        }
        let key = self.key.as_str();
        let x = match self.values {
            AxisValues::List(ref v) => return v.get(k).cloned(),
            AxisValues::Range { from, to, steps } => {
                let span = to - from;
                let x = if k + 1 == steps {
                    to
                } else if span.is_finite() {
                    from + span * k as f64 / (steps - 1) as f64
                } else {
                    // (1 − t)·from + t·to: each term within the bounds' magnitude, so finite
                    // where the span overflows.
                    let t = k as f64 / (steps - 1) as f64;
                    (1.0 - t) * from + t * to
                };
                let (lo, hi) = (from.min(to), from.max(to));
                rounded_within(x, |r| (lo..=hi).contains(&r))
            }
            AxisValues::Uniform { lo, hi, seed, .. } => {
                let x = draw::uniform(seed, key, k as u64, lo, hi);
                rounded_within(x, |r| (lo..hi).contains(&r))
            }
            AxisValues::Normal { mean, sd, seed, .. } => {
                significant(draw::normal(seed, key, k as u64, mean, sd), METRIC_DIGITS)
            }
        };
        Some(AxisValue::number(x))
    }
}

/// `x` rounded to [`METRIC_DIGITS`] significant digits if `inside` holds for the rounded
/// value, else `x` itself (which the caller made inside).
fn rounded_within(x: f64, inside: impl Fn(f64) -> bool) -> f64 {
    let r = significant(x, METRIC_DIGITS);
    if inside(r) { r } else { x }
}

/// An axis read from the sweep file, with where each of its values is written (for the
/// errors of a value that the world file refuses by its type).
pub(crate) struct ReadAxis {
    pub(crate) axis: Axis,
    /// Where the axis's key is.
    pub(crate) key_span: Range<usize>,
    /// Where each value of a list is (empty for generated values).
    pub(crate) value_spans: Vec<Range<usize>>,
}

/// True for a table that describes an axis (rather than a level of a dotted key).
pub(crate) fn is_shape(t: &DeTable<'_>) -> bool {
    t.iter()
        .any(|(k, _)| SHAPE_KEYS.contains(&k.get_ref().as_ref()))
}

/// The finite number at `key` of `s`, required.
fn finite(s: &Section<'_, '_>, key: &str, what: &str) -> Result<f64, WorldFileError> {
    match s.number(key)? {
        Some(x) if x.is_finite() => Ok(x),
        Some(x) => Err(s.error(
            key,
            WorldFileErrorKind::InvalidValue(format!("{}: must be finite", Compact(x))),
        )),
        None => Err(missing(s, key, what)),
    }
}

fn missing(s: &Section<'_, '_>, key: &str, what: &str) -> WorldFileError {
    s.error(
        key,
        WorldFileErrorKind::Structure(format!(
            "axis '{}': {what} needs '{key}'",
            s.path().trim_start_matches("axes.")
        )),
    )
}

/// A count (≥ 1) at `key`, required.
fn count(s: &Section<'_, '_>, key: &str, what: &str, least: u64) -> Result<usize, WorldFileError> {
    let n = s.unsigned(key)?.ok_or_else(|| missing(s, key, what))?;
    match usize::try_from(n) {
        Ok(n) if n as u64 >= least => Ok(n),
        _ => Err(s.error(
            key,
            WorldFileErrorKind::InvalidValue(format!("{n}: must be an integer >= {least}")),
        )),
    }
}

/// Two finite numbers at `key` (`[lo, hi]`, `[mean, sd]`).
fn pair(s: &Section<'_, '_>, key: &str) -> Result<[f64; 2], WorldFileError> {
    let [a, b] = s.array::<2>(key)?.unwrap_or([f64::NAN; 2]);
    if a.is_finite() && b.is_finite() {
        Ok([a, b])
    } else {
        Err(s.error(
            key,
            WorldFileErrorKind::InvalidValue(format!(
                "[{}, {}]: both must be finite",
                Compact(a),
                Compact(b)
            )),
        ))
    }
}

/// Reads the axis at `key` of the `[axes]` section `axes` over the world-file key
/// `world_key`.
pub(crate) fn read(
    axes: &Section<'_, '_>,
    key: &str,
    world_key: &str,
    value: &DeValue<'_>,
    key_span: Range<usize>,
) -> Result<ReadAxis, WorldFileError> {
    let path = KeyPath::parse(world_key)
        .map_err(|m| axes.error_at(key, key_span.clone(), WorldFileErrorKind::InvalidValue(m)))?;
    let mut value_spans = Vec::new();
    let values = match value {
        DeValue::Array(items) => {
            let mut values = Vec::with_capacity(items.len());
            for item in items.iter() {
                let v = AxisValue::from_toml(item.get_ref()).ok_or_else(|| {
                    axes.error_at(
                        key,
                        item.span(),
                        WorldFileErrorKind::WrongType {
                            expected: "numbers, strings, booleans or lists (set a table's \
                                       keys one by one, e.g. 'vehicle.tyre.model')"
                                .to_string(),
                            found: format!("{} in the list", describe(item.get_ref())),
                        },
                    )
                })?;
                values.push(v);
                value_spans.push(item.span());
            }
            if values.is_empty() {
                return Err(axes.error_at(
                    key,
                    key_span,
                    WorldFileErrorKind::InvalidValue("an axis needs one value at least".into()),
                ));
            }
            AxisValues::List(values)
        }
        DeValue::Table(t) if is_shape(t) => {
            let Some(s) = axes.table(key)? else {
                return Err(axes.error(key, WorldFileErrorKind::Structure(AXIS_SHAPES.into())));
            };
            shape(&s)?
        }
        other => {
            return Err(axes.error_at(
                key,
                key_span,
                WorldFileErrorKind::WrongType {
                    expected: AXIS_SHAPES.to_string(),
                    found: describe(other),
                },
            ));
        }
    };
    Ok(ReadAxis {
        axis: Axis::new(path, values),
        key_span,
        value_spans,
    })
}

/// The generated values of an axis table: a range or random draws.
fn shape(s: &Section<'_, '_>) -> Result<AxisValues, WorldFileError> {
    let has = |k: &str| s.value(k).is_some();
    let range = has("from") || has("to") || has("steps");
    match (range, has("uniform"), has("normal")) {
        (true, false, false) => {
            s.check_keys(&["from", "to", "steps"])?;
            let what = "a range { from, to, steps }";
            Ok(AxisValues::Range {
                from: finite(s, "from", what)?,
                to: finite(s, "to", what)?,
                steps: count(s, "steps", what, 2)?,
            })
        }
        (false, true, false) => {
            s.check_keys(&["uniform", "count", "seed"])?;
            let what = "a uniform draw { uniform = [lo, hi], count, seed }";
            let [lo, hi] = pair(s, "uniform")?;
            if lo >= hi {
                return Err(s.error(
                    "uniform",
                    WorldFileErrorKind::InvalidValue(format!(
                        "[{}, {}]: lo must be < hi",
                        Compact(lo),
                        Compact(hi)
                    )),
                ));
            }
            Ok(AxisValues::Uniform {
                lo,
                hi,
                count: count(s, "count", what, 1)?,
                seed: s
                    .unsigned("seed")?
                    .ok_or_else(|| missing(s, "seed", what))?,
            })
        }
        (false, false, true) => {
            s.check_keys(&["normal", "count", "seed"])?;
            let what = "a normal draw { normal = [mean, sd], count, seed }";
            let [mean, sd] = pair(s, "normal")?;
            if sd < 0.0 {
                return Err(s.error(
                    "normal",
                    WorldFileErrorKind::InvalidValue(format!(
                        "[{}, {}]: the standard deviation must be >= 0",
                        Compact(mean),
                        Compact(sd)
                    )),
                ));
            }
            if !(mean.abs() + draw::NORMAL_REACH * sd).is_finite() {
                return Err(s.error(
                    "normal",
                    WorldFileErrorKind::InvalidValue(format!(
                        "[{}, {}]: the draws would overflow (|mean| + {} standard deviations \
                         must be finite)",
                        Compact(mean),
                        Compact(sd),
                        draw::NORMAL_REACH
                    )),
                ));
            }
            Ok(AxisValues::Normal {
                mean,
                sd,
                count: count(s, "count", what, 1)?,
                seed: s
                    .unsigned("seed")?
                    .ok_or_else(|| missing(s, "seed", what))?,
            })
        }
        (false, false, false) => Err(s.error(
            "count",
            WorldFileErrorKind::Structure(format!(
                "axis '{}': draws need uniform = [lo, hi] or normal = [mean, sd]",
                s.path().trim_start_matches("axes.")
            )),
        )),
        _ => Err(s.src.error(
            s.span(),
            Some(s.path().to_string()),
            WorldFileErrorKind::Structure(format!(
                "axis '{}' mixes {{ from, to, steps }}, uniform and normal: it takes one of them",
                s.path().trim_start_matches("axes.")
            )),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axis(values: AxisValues) -> Axis {
        Axis::new(KeyPath::parse("vehicle.brakeCoefficient").unwrap(), values)
    }

    #[test]
    fn ranges_include_both_ends_rounded() {
        let a = axis(AxisValues::Range {
            from: 1000.0,
            to: 2000.0,
            steps: 5,
        });
        let v: Vec<String> = (0..5).map(|k| a.value(k).unwrap().to_string()).collect();
        assert_eq!(v, ["1000", "1250", "1500", "1750", "2000"]);
        assert_eq!(a.value(0), Some(AxisValue::Integer(1000)));
        assert_eq!(a.value(5), None);
        let thirds = axis(AxisValues::Range {
            from: 0.6,
            to: 1.0,
            steps: 3,
        });
        // 0.6 + 0.4·1/2 is 0.8000000000000002 in f64: 6 significant digits give 0.8.
        assert_eq!(thirds.value(1), Some(AxisValue::Float(0.8)));
        let down = axis(AxisValues::Range {
            from: 1.0,
            to: 0.0,
            steps: 4,
        });
        assert_eq!(down.value(1), Some(AxisValue::Float(0.666667)));
    }

    #[test]
    fn ranges_of_any_span_are_finite_and_exact() {
        // Issue #37: −1e308 + (1e308 − −1e308)·t overflowed to NaN and inf.
        let wide = axis(AxisValues::Range {
            from: -1e308,
            to: 1e308,
            steps: 5,
        });
        let v: Vec<f64> = (0..5)
            .map(|k| wide.value(k).unwrap().as_f64().unwrap())
            .collect();
        assert_eq!(v, [-1e308, -5e307, 0.0, 5e307, 1e308]);
        let max = axis(AxisValues::Range {
            from: f64::MAX,
            to: -f64::MAX,
            steps: 3,
        });
        let v: Vec<f64> = (0..3)
            .map(|k| max.value(k).unwrap().as_f64().unwrap())
            .collect();
        assert_eq!(v, [1.79769e308, 0.0, -1.79769e308]);
    }

    #[test]
    fn rounding_never_leaves_the_interval() {
        // Issue #37: draws over [0.99999, 1) rounded to 6 digits gave the excluded 1.0 in 3
        // of 20 cases; they now keep their full precision there.
        let a = axis(AxisValues::Uniform {
            lo: 0.99999,
            hi: 1.0,
            count: 200,
            seed: 1,
        });
        let xs: Vec<f64> = (0..200)
            .map(|k| a.value(k).unwrap().as_f64().unwrap())
            .collect();
        assert!(xs.iter().all(|x| (0.99999..1.0).contains(x)), "{xs:?}");
        // Some do round, to 6 digits: 0.99999x.
        assert!(xs.iter().any(|&x| x == significant(x, METRIC_DIGITS)));
        assert!(xs.iter().any(|&x| x != significant(x, METRIC_DIGITS)));
        // A range's ends stay themselves when 6 digits would move them out.
        let r = axis(AxisValues::Range {
            from: 0.9999991,
            to: 0.9999999,
            steps: 3,
        });
        let v: Vec<f64> = (0..3)
            .map(|k| r.value(k).unwrap().as_f64().unwrap())
            .collect();
        assert_eq!(v[0], 0.9999991);
        assert_eq!(v[2], 0.9999999);
        assert!((0.9999991..=0.9999999).contains(&v[1]), "{v:?}");
    }

    #[test]
    fn draws_stay_in_their_bounds() {
        let a = axis(AxisValues::Uniform {
            lo: 500.0,
            hi: 1500.0,
            count: 200,
            seed: 1,
        });
        assert_eq!(a.len(), 200);
        for k in 0..200 {
            let x = a.value(k).unwrap().as_f64().unwrap();
            assert!((500.0..=1500.0).contains(&x), "{x}");
        }
        let n = axis(AxisValues::Normal {
            mean: 1.0,
            sd: 0.0,
            count: 3,
            seed: 9,
        });
        assert_eq!(n.value(2), Some(AxisValue::Integer(1)));
    }
}
