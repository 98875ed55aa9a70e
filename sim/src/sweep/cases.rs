//! How the axes' values make the cases: every combination (product) or side by side (zip).

use super::axis::Axis;

/// How the axes combine into cases (`combine` in the sweep file).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Combine {
    /// Every combination of the axes' values (the default): as many cases as the product of
    /// the axes' lengths. Case 0 takes every axis's first value; the last axis varies
    /// fastest, as nested loops in the file's order.
    #[default]
    Product,
    /// Value `k` of every axis in case `k`: the axes have one length, the number of cases.
    Zip,
}

impl Combine {
    /// The names in the sweep file.
    pub const NAMES: [&'static str; 2] = ["product", "zip"];

    /// The combination named `name`.
    pub fn from_name(name: &str) -> Option<Combine> {
        match name {
            "product" => Some(Combine::Product),
            "zip" => Some(Combine::Zip),
            _ => None,
        }
    }

    /// Its name in the sweep file.
    pub const fn name(self) -> &'static str {
        match self {
            Combine::Product => "product",
            Combine::Zip => "zip",
        }
    }
}

/// Why the axes make no set of cases.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum CountError {
    /// The product of the lengths does not fit a `usize`.
    TooMany,
    /// Zipped axes of different lengths: the first axis's key and length, and the first that
    /// differs.
    Lengths([(String, usize); 2]),
}

/// The number of cases of `axes` combined by `combine` (1 without axes: the base world).
pub(crate) fn count(axes: &[Axis], combine: Combine) -> Result<usize, CountError> {
    match combine {
        Combine::Product => axes.iter().try_fold(1usize, |n, a| {
            n.checked_mul(a.len()).ok_or(CountError::TooMany)
        }),
        Combine::Zip => {
            let Some(first) = axes.first() else {
                return Ok(1);
            };
            match axes.iter().find(|a| a.len() != first.len()) {
                Some(other) => Err(CountError::Lengths([
                    (first.key().to_string(), first.len()),
                    (other.key().to_string(), other.len()),
                ])),
                None => Ok(first.len()),
            }
        }
    }
}

/// The index of each axis's value in case `case` (< the number of cases).
pub(crate) fn positions(axes: &[Axis], combine: Combine, case: usize) -> Vec<usize> {
    match combine {
        Combine::Zip => vec![case; axes.len()],
        Combine::Product => {
            let mut rest = case;
            let mut out = vec![0; axes.len()];
            for (slot, axis) in out.iter_mut().zip(axes).rev() {
                let n = axis.len().max(1);
                *slot = rest % n;
                rest /= n;
            }
            out
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::{AxisValue, AxisValues};
    use crate::world_file::KeyPath;

    fn axis(key: &str, n: i64) -> Axis {
        let values = (0..n).map(AxisValue::Integer).collect();
        Axis::new(KeyPath::parse(key).unwrap(), AxisValues::List(values))
    }

    #[test]
    fn product_varies_the_last_axis_fastest() {
        let axes = [axis("a", 2), axis("b", 3)];
        assert_eq!(count(&axes, Combine::Product), Ok(6));
        let all: Vec<Vec<usize>> = (0..6)
            .map(|c| positions(&axes, Combine::Product, c))
            .collect();
        assert_eq!(
            all,
            [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2]].map(Vec::from)
        );
        assert_eq!(count(&[], Combine::Product), Ok(1));
    }

    #[test]
    fn zip_needs_one_length() {
        let axes = [axis("a", 3), axis("b", 3)];
        assert_eq!(count(&axes, Combine::Zip), Ok(3));
        assert_eq!(positions(&axes, Combine::Zip, 2), [2, 2]);
        assert_eq!(
            count(&[axis("a", 3), axis("b", 4)], Combine::Zip),
            Err(CountError::Lengths([("a".into(), 3), ("b".into(), 4)]))
        );
        assert_eq!(count(&[], Combine::Zip), Ok(1));
    }
}
