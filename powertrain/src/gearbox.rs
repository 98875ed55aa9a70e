//! Gears and the fixed-capacity table of total engine-to-wheel ratios.

use ackermann::Real;
use core::fmt;

use crate::error::PowertrainError;

use crate::MAX_GEAR_RATIOS;

/// A gear selection: −1 reverse, 0 neutral, 1 … [`MAX_GEAR_RATIOS`] − 1 forward (Webots: the
/// `int` of `wbu_driver_set_gear` / `wbu_driver_get_gear`).
///
/// A `Gear` is not tied to one gearbox; [`Gearbox::select`] turns an arbitrary Webots gear
/// number into a gear the gearbox has, and [`Gearbox::ratio`] treats a forward gear above the
/// highest one as the highest one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct Gear(i8);

impl Gear {
    /// Reverse (−1): uses the first entry of Webots field `gearRatio`.
    pub const REVERSE: Gear = Gear(-1);
    /// Neutral (0): no torque, engine speed 0 (Webots has no idle model). The initial gear.
    pub const NEUTRAL: Gear = Gear(0);
    /// First forward gear (1).
    pub const FIRST: Gear = Gear(1);

    /// Forward gear `n` (1 = first), or `None` unless `1 ≤ n < MAX_GEAR_RATIOS`.
    #[inline]
    pub const fn forward(n: u8) -> Option<Gear> {
        if n >= 1 && (n as usize) < MAX_GEAR_RATIOS {
            Some(Gear(n as i8))
        } else {
            None
        }
    }

    /// The Webots gear number: −1 reverse, 0 neutral, k ≥ 1 forward gear k.
    #[inline]
    pub const fn number(self) -> i32 {
        self.0 as i32
    }

    /// True for reverse.
    #[inline]
    pub const fn is_reverse(self) -> bool {
        self.0 < 0
    }

    /// True for neutral.
    #[inline]
    pub const fn is_neutral(self) -> bool {
        self.0 == 0
    }

    /// True for a forward gear.
    #[inline]
    pub const fn is_forward(self) -> bool {
        self.0 > 0
    }

    /// The next forward gear up, or `None` from the highest representable gear and from
    /// reverse and neutral.
    #[inline]
    pub(crate) const fn up(self) -> Option<Gear> {
        if self.is_forward() {
            Gear::forward(self.0 as u8 + 1)
        } else {
            None
        }
    }

    /// The next forward gear down, or `None` from first, neutral and reverse.
    #[inline]
    pub(crate) const fn down(self) -> Option<Gear> {
        if self.0 > 1 {
            Gear::forward(self.0 as u8 - 1)
        } else {
            None
        }
    }
}

impl fmt::Display for Gear {
    /// `R`, `N`, or the forward gear number.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            ..0 => f.write_str("R"),
            0 => f.write_str("N"),
            n => write!(f, "{n}"),
        }
    }
}

/// Why a requested gear was changed by [`Gearbox::select`]. `Display` prints the Webots warning
/// text without its `Warning: ` prefix.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GearWarning {
    /// The request was at or above the gear count; the highest forward gear was selected.
    /// Webots: `Warning: this car has only %d gears.` (`%d` = gear count, reverse included).
    AboveHighest {
        /// The requested gear number.
        requested: i32,
        /// Number of entries in the ratio table (Webots `wbu_driver_get_gear_number`).
        gear_count: usize,
    },
    /// The request was below −1; reverse was selected.
    /// Webots: `Warning: Minimum gear value is -1`.
    BelowReverse {
        /// The requested gear number.
        requested: i32,
    },
}

impl fmt::Display for GearWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            GearWarning::AboveHighest { gear_count, .. } => {
                write!(f, "this car has only {gear_count} gears.")
            }
            GearWarning::BelowReverse { .. } => f.write_str("Minimum gear value is -1"),
        }
    }
}

/// The outcome of [`Gearbox::select`]: the gear to engage and the warning to report, if any.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[must_use]
pub struct GearSelection {
    /// The gear the gearbox can actually engage.
    pub gear: Gear,
    /// Set when the request was out of range and clamped.
    pub warning: Option<GearWarning>,
}

/// The table of total engine-to-wheel ratios (dimensionless), reverse first (Webots field
/// `gearRatio`, e.g. `[-12, 10, 6.5, 4.5, 3.5, 2.75]`).
///
/// Holds 2 to [`MAX_GEAR_RATIOS`] finite, non-zero ratios. The reverse ratio is normally
/// negative, which makes reverse torque negative for a positive throttle; like Webots, a
/// positive one is accepted (reverse then drives forward).
///
/// ```
/// use powertrain::{Gear, Gearbox, GearWarning};
/// let bmw = Gearbox::new(&[-12.5_f64, 12.5, 8.0, 5.35, 4.3, 4.0])?;
/// assert_eq!(bmw.gear_count(), 6);
/// assert_eq!(bmw.ratio(Gear::REVERSE), -12.5);
/// assert_eq!(bmw.ratio(Gear::NEUTRAL), 0.0);
/// let s = bmw.select(6); // Webots would read past its table here
/// assert_eq!(s.gear, Gear::forward(5).unwrap());
/// assert_eq!(s.warning, Some(GearWarning::AboveHighest { requested: 6, gear_count: 6 }));
/// # Ok::<(), powertrain::PowertrainError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Gearbox<T: Real> {
    ratios: heapless::Vec<T, MAX_GEAR_RATIOS>,
}

impl<T: Real> Gearbox<T> {
    /// Builds from the total ratios, reverse first (Webots field `gearRatio`).
    ///
    /// # Errors
    /// [`PowertrainError::TooFewGearRatios`] below 2 entries,
    /// [`PowertrainError::TooManyGearRatios`] above [`MAX_GEAR_RATIOS`],
    /// [`PowertrainError::InvalidGearRatio`] for the first zero, NaN or ±∞ entry.
    pub fn new(ratios: &[T]) -> Result<Self, PowertrainError> {
        let count = ratios.len();
        if count < 2 {
            return Err(PowertrainError::TooFewGearRatios { count });
        }
        if let Some((index, &value)) = ratios
            .iter()
            .enumerate()
            .find(|&(_, &r)| !r.is_finite() || r == T::ZERO)
        {
            return Err(PowertrainError::InvalidGearRatio {
                index,
                value: value.to_f64(),
            });
        }
        let ratios = heapless::Vec::from_slice(ratios)
            .map_err(|_| PowertrainError::TooManyGearRatios { count })?;
        Ok(Gearbox { ratios })
    }

    /// The ratios, reverse first.
    #[inline]
    pub fn ratios(&self) -> &[T] {
        &self.ratios
    }

    /// Number of ratios, reverse included (Webots: `wbu_driver_get_gear_number`). The forward
    /// gears are 1 … `gear_count() − 1`.
    #[inline]
    pub fn gear_count(&self) -> usize {
        self.ratios.len()
    }

    /// The highest forward gear (`gear_count() − 1`).
    #[inline]
    pub fn highest_gear(&self) -> Gear {
        // gear_count is in 2..=MAX_GEAR_RATIOS, so this fits an i8 and is ≥ 1.
        Gear((self.ratios.len() - 1) as i8)
    }

    /// True if `gear` is reverse, neutral or a forward gear this gearbox has.
    #[inline]
    pub fn has(&self, gear: Gear) -> bool {
        gear <= self.highest_gear()
    }

    /// The total engine-to-wheel ratio of `gear` (dimensionless; Webots: spec §2.1): the
    /// reverse entry for reverse, 0 for neutral (no transmission), and for a forward gear above
    /// [`Gearbox::highest_gear`] the highest gear's ratio.
    #[inline]
    pub fn ratio(&self, gear: Gear) -> T {
        let index = if gear.is_reverse() {
            0
        } else if gear.is_neutral() {
            return T::ZERO;
        } else {
            (gear.0 as usize).min(self.ratios.len() - 1)
        };
        self.ratios.get(index).copied().unwrap_or(T::ZERO)
    }

    /// Turns a Webots gear number into a gear this gearbox has, as `wbu_driver_set_gear` does:
    /// below −1 gives reverse with [`GearWarning::BelowReverse`], and at or above
    /// [`Gearbox::gear_count`] gives the highest forward gear with
    /// [`GearWarning::AboveHighest`].
    ///
    /// Deliberate fix: Webots only clamps requests *above* the gear count, so a request equal
    /// to it engages a gear past the end of its table; here it engages the highest gear.
    pub fn select(&self, requested: i32) -> GearSelection {
        let highest = self.highest_gear();
        if requested > highest.number() {
            GearSelection {
                gear: highest,
                warning: Some(GearWarning::AboveHighest {
                    requested,
                    gear_count: self.gear_count(),
                }),
            }
        } else if requested < -1 {
            GearSelection {
                gear: Gear::REVERSE,
                warning: Some(GearWarning::BelowReverse { requested }),
            }
        } else {
            GearSelection {
                // −1 ≤ requested ≤ highest < MAX_GEAR_RATIOS: fits an i8.
                gear: Gear(requested as i8),
                warning: None,
            }
        }
    }
}

impl<T: Real> Default for Gearbox<T> {
    /// The Webots `Car` PROTO default table `[-12, 10, 6.5, 4.5, 3.5, 2.75]`.
    fn default() -> Self {
        let mut ratios = heapless::Vec::new();
        for r in [-12.0, 10.0, 6.5, 4.5, 3.5, 2.75] {
            // Six entries always fit the capacity of sixteen.
            let _ = ratios.push(T::from_f64(r));
        }
        Gearbox { ratios }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TRUCK: [f64; 15] = [
        -14.77, 16.0, 13.0, 11.0, 9.0, 7.0, 6.0, 4.5, 3.7, 3.0, 2.4, 1.9, 1.5, 1.2, 1.0,
    ];

    #[test]
    fn default_is_the_car_proto_table() {
        let g = Gearbox::<f64>::default();
        assert_eq!(g.ratios(), &[-12.0, 10.0, 6.5, 4.5, 3.5, 2.75]);
        assert_eq!(
            g,
            Gearbox::new(&[-12.0, 10.0, 6.5, 4.5, 3.5, 2.75]).unwrap()
        );
    }

    #[test]
    fn truck_table_fits() {
        let g = Gearbox::new(&TRUCK).unwrap();
        assert_eq!(g.gear_count(), 15);
        assert_eq!(g.highest_gear(), Gear::forward(14).unwrap());
        assert_eq!(g.ratio(Gear::forward(14).unwrap()), 1.0);
        assert_eq!(g.ratio(Gear::FIRST), 16.0);
    }

    #[test]
    fn bad_tables_are_rejected() {
        assert_eq!(
            Gearbox::<f64>::new(&[]).unwrap_err(),
            PowertrainError::TooFewGearRatios { count: 0 }
        );
        assert_eq!(
            Gearbox::new(&[-6.0]).unwrap_err(),
            PowertrainError::TooFewGearRatios { count: 1 }
        );
        assert_eq!(
            Gearbox::new(&[1.0_f32; 17]).unwrap_err(),
            PowertrainError::TooManyGearRatios { count: 17 }
        );
        assert!(Gearbox::new(&[1.0_f32; 16]).is_ok());
        assert_eq!(
            Gearbox::new(&[-6.0, 6.0, 0.0]).unwrap_err(),
            PowertrainError::InvalidGearRatio {
                index: 2,
                value: 0.0
            }
        );
        let e = Gearbox::new(&[-6.0, f64::NAN]).unwrap_err();
        assert!(matches!(
            e,
            PowertrainError::InvalidGearRatio { index: 1, value } if value.is_nan()
        ));
        assert_eq!(
            Gearbox::new(&[f64::NEG_INFINITY, 6.0]).unwrap_err(),
            PowertrainError::InvalidGearRatio {
                index: 0,
                value: f64::NEG_INFINITY
            }
        );
    }

    #[test]
    fn select_reproduces_webots_bounds_with_the_fix() {
        let g = Gearbox::<f64>::default(); // 6 ratios: R, N, 1..=5
        let top = Gear::forward(5).unwrap();
        for n in -1..=5 {
            let s = g.select(n);
            assert_eq!(s.gear.number(), n);
            assert_eq!(s.warning, None);
        }
        for n in [6, 7, i32::MAX] {
            assert_eq!(
                g.select(n),
                GearSelection {
                    gear: top,
                    warning: Some(GearWarning::AboveHighest {
                        requested: n,
                        gear_count: 6
                    })
                }
            );
        }
        for n in [-2, i32::MIN] {
            assert_eq!(
                g.select(n),
                GearSelection {
                    gear: Gear::REVERSE,
                    warning: Some(GearWarning::BelowReverse { requested: n })
                }
            );
        }
    }

    #[test]
    fn warning_texts_match_webots() {
        extern crate std;
        use std::string::ToString;
        let g = Gearbox::<f64>::default();
        assert_eq!(
            g.select(9).warning.unwrap().to_string(),
            "this car has only 6 gears."
        );
        assert_eq!(
            g.select(-3).warning.unwrap().to_string(),
            "Minimum gear value is -1"
        );
    }

    #[test]
    fn ratio_lookup() {
        let g = Gearbox::new(&[-6.0_f32, 6.0]).unwrap();
        assert_eq!(g.ratio(Gear::REVERSE), -6.0);
        assert_eq!(g.ratio(Gear::NEUTRAL), 0.0);
        assert_eq!(g.ratio(Gear::FIRST), 6.0);
        // A gear from a bigger gearbox falls back to this one's highest gear.
        assert_eq!(g.ratio(Gear::forward(9).unwrap()), 6.0);
        assert!(!g.has(Gear::forward(2).unwrap()));
        assert!(g.has(Gear::REVERSE) && g.has(Gear::NEUTRAL) && g.has(Gear::FIRST));
    }

    #[test]
    fn gear_constructors_and_display() {
        extern crate std;
        use std::string::ToString;
        assert_eq!(Gear::forward(0), None);
        assert_eq!(Gear::forward(16), None);
        assert_eq!(Gear::forward(15).map(Gear::number), Some(15));
        assert_eq!(Gear::default(), Gear::NEUTRAL);
        assert_eq!(Gear::REVERSE.to_string(), "R");
        assert_eq!(Gear::NEUTRAL.to_string(), "N");
        assert_eq!(Gear::forward(3).unwrap().to_string(), "3");
        assert_eq!(Gear::forward(15).unwrap().up(), None);
        assert_eq!(Gear::FIRST.up(), Gear::forward(2));
        assert_eq!(Gear::NEUTRAL.up(), None);
        assert_eq!(Gear::REVERSE.up(), None);
        assert_eq!(Gear::forward(2).unwrap().down(), Some(Gear::FIRST));
        assert_eq!(Gear::FIRST.down(), None);
        assert_eq!(Gear::NEUTRAL.down(), None);
        assert_eq!(Gear::REVERSE.down(), None);
        assert!(Gear::REVERSE.is_reverse() && Gear::NEUTRAL.is_neutral());
        assert!(Gear::FIRST.is_forward() && !Gear::REVERSE.is_forward());
    }
}
