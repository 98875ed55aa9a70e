//! Wheel identifiers and per-wheel storage, in the Webots wheel order (0 FR, 1 FL, 2 RR, 3 RL).

use core::ops::{Index, IndexMut};

/// One of the four wheels of an Ackermann vehicle.
///
/// The discriminant is the Webots wheel index (Webots: `WbuCarWheelIndex`,
/// `WBU_CAR_WHEEL_FRONT_RIGHT` = 0 … `WBU_CAR_WHEEL_REAR_LEFT` = 3).
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Wheel {
    /// Front-right wheel (index 0, Webots device prefix `right_front`).
    FrontRight = 0,
    /// Front-left wheel (index 1, Webots device prefix `left_front`).
    FrontLeft = 1,
    /// Rear-right wheel (index 2, Webots device prefix `right_rear`).
    RearRight = 2,
    /// Rear-left wheel (index 3, Webots device prefix `left_rear`).
    RearLeft = 3,
}

impl Wheel {
    /// All four wheels in index order: FR, FL, RR, RL.
    pub const ALL: [Wheel; 4] = [
        Wheel::FrontRight,
        Wheel::FrontLeft,
        Wheel::RearRight,
        Wheel::RearLeft,
    ];

    /// The Webots wheel index, 0..=3.
    #[inline]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The wheel with Webots index `i`, or `None` if `i > 3`.
    #[inline]
    pub const fn from_index(i: usize) -> Option<Wheel> {
        match i {
            0 => Some(Wheel::FrontRight),
            1 => Some(Wheel::FrontLeft),
            2 => Some(Wheel::RearRight),
            3 => Some(Wheel::RearLeft),
            _ => None,
        }
    }

    /// True for the two steered front wheels.
    #[inline]
    pub const fn is_front(self) -> bool {
        matches!(self, Wheel::FrontRight | Wheel::FrontLeft)
    }

    /// True for the two wheels on the right side (negative y).
    #[inline]
    pub const fn is_right(self) -> bool {
        matches!(self, Wheel::FrontRight | Wheel::RearRight)
    }

    /// The wheel on the other side of the same axle (FR ↔ FL, RR ↔ RL).
    #[inline]
    pub const fn mirror(self) -> Wheel {
        match self {
            Wheel::FrontRight => Wheel::FrontLeft,
            Wheel::FrontLeft => Wheel::FrontRight,
            Wheel::RearRight => Wheel::RearLeft,
            Wheel::RearLeft => Wheel::RearRight,
        }
    }

    /// The Webots device-name prefix of this wheel: `right_front`, `left_front`, `right_rear`,
    /// `left_rear` (Webots motors are `<prefix>_wheel`, sensors `<prefix>_sensor`, brakes
    /// `<prefix>_brake`).
    #[inline]
    pub const fn webots_prefix(self) -> &'static str {
        match self {
            Wheel::FrontRight => "right_front",
            Wheel::FrontLeft => "left_front",
            Wheel::RearRight => "right_rear",
            Wheel::RearLeft => "left_rear",
        }
    }
}

/// One value per wheel, stored in Webots wheel order `[FR, FL, RR, RL]` and indexed by [`Wheel`].
///
/// ```
/// use ackermann::{PerWheel, Wheel};
/// let mut speeds = PerWheel::new(1.0_f64, 2.0, 3.0, 4.0); // rad/s
/// speeds[Wheel::RearLeft] += 1.0;
/// assert_eq!(speeds.as_array(), &[1.0, 2.0, 3.0, 5.0]);
/// assert_eq!(speeds.map(|w| w * 2.0)[Wheel::FrontLeft], 4.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct PerWheel<T>(pub [T; 4]);

impl<T> PerWheel<T> {
    /// Builds from the four values in wheel order.
    #[inline]
    pub const fn new(front_right: T, front_left: T, rear_right: T, rear_left: T) -> Self {
        PerWheel([front_right, front_left, rear_right, rear_left])
    }

    /// Builds by calling `f` for each wheel in index order.
    #[inline]
    pub fn from_fn(mut f: impl FnMut(Wheel) -> T) -> Self {
        PerWheel::new(
            f(Wheel::FrontRight),
            f(Wheel::FrontLeft),
            f(Wheel::RearRight),
            f(Wheel::RearLeft),
        )
    }

    /// The same value for all four wheels.
    #[inline]
    pub const fn splat(v: T) -> Self
    where
        T: Copy,
    {
        PerWheel([v; 4])
    }

    /// Applies `f` to each value.
    #[inline]
    pub fn map<U>(self, f: impl FnMut(T) -> U) -> PerWheel<U> {
        PerWheel(self.0.map(f))
    }

    /// Applies `f` to each wheel and its value.
    #[inline]
    pub fn map_with_wheel<U>(self, mut f: impl FnMut(Wheel, T) -> U) -> PerWheel<U> {
        let [fr, fl, rr, rl] = self.0;
        PerWheel::new(
            f(Wheel::FrontRight, fr),
            f(Wheel::FrontLeft, fl),
            f(Wheel::RearRight, rr),
            f(Wheel::RearLeft, rl),
        )
    }

    /// Pairs each value with the other's value for the same wheel.
    #[inline]
    pub fn zip<U>(self, other: PerWheel<U>) -> PerWheel<(T, U)> {
        let [a0, a1, a2, a3] = self.0;
        let [b0, b1, b2, b3] = other.0;
        PerWheel([(a0, b0), (a1, b1), (a2, b2), (a3, b3)])
    }

    /// Combines each value with the other's value for the same wheel.
    #[inline]
    pub fn zip_with<U, V>(self, other: PerWheel<U>, mut f: impl FnMut(T, U) -> V) -> PerWheel<V> {
        self.zip(other).map(|(a, b)| f(a, b))
    }

    /// Iterates over the values in wheel order.
    #[inline]
    pub fn iter(&self) -> core::slice::Iter<'_, T> {
        self.0.iter()
    }

    /// Iterates mutably over the values in wheel order.
    #[inline]
    pub fn iter_mut(&mut self) -> core::slice::IterMut<'_, T> {
        self.0.iter_mut()
    }

    /// Iterates over `(wheel, &value)` pairs in wheel order.
    #[inline]
    pub fn iter_wheels(&self) -> impl Iterator<Item = (Wheel, &T)> + '_ {
        Wheel::ALL.into_iter().zip(self.0.iter())
    }

    /// The values as an array `[FR, FL, RR, RL]`.
    #[inline]
    pub const fn as_array(&self) -> &[T; 4] {
        &self.0
    }

    /// The values as a mutable array `[FR, FL, RR, RL]`.
    #[inline]
    pub const fn as_mut_array(&mut self) -> &mut [T; 4] {
        &mut self.0
    }

    /// Consumes into the array `[FR, FL, RR, RL]`.
    #[inline]
    pub fn into_array(self) -> [T; 4] {
        self.0
    }

    /// The value of wheel index `i` (Webots index), or `None` if `i > 3`.
    #[inline]
    pub fn get(&self, i: usize) -> Option<&T> {
        self.0.get(i)
    }

    /// The value of wheel index `i` (Webots index) mutably, or `None` if `i > 3`.
    #[inline]
    pub fn get_mut(&mut self, i: usize) -> Option<&mut T> {
        self.0.get_mut(i)
    }
}

impl<T> Index<Wheel> for PerWheel<T> {
    type Output = T;
    #[inline]
    fn index(&self, w: Wheel) -> &T {
        // Constant indices: checked at compile time, so no panic path exists.
        match w {
            Wheel::FrontRight => &self.0[0],
            Wheel::FrontLeft => &self.0[1],
            Wheel::RearRight => &self.0[2],
            Wheel::RearLeft => &self.0[3],
        }
    }
}

impl<T> IndexMut<Wheel> for PerWheel<T> {
    #[inline]
    fn index_mut(&mut self, w: Wheel) -> &mut T {
        match w {
            Wheel::FrontRight => &mut self.0[0],
            Wheel::FrontLeft => &mut self.0[1],
            Wheel::RearRight => &mut self.0[2],
            Wheel::RearLeft => &mut self.0[3],
        }
    }
}

impl<T> From<[T; 4]> for PerWheel<T> {
    #[inline]
    fn from(a: [T; 4]) -> Self {
        PerWheel(a)
    }
}

impl<T> From<PerWheel<T>> for [T; 4] {
    #[inline]
    fn from(p: PerWheel<T>) -> Self {
        p.0
    }
}

impl<T> IntoIterator for PerWheel<T> {
    type Item = T;
    type IntoIter = core::array::IntoIter<T, 4>;
    #[inline]
    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

impl<'a, T> IntoIterator for &'a PerWheel<T> {
    type Item = &'a T;
    type IntoIter = core::slice::Iter<'a, T>;
    #[inline]
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

impl<'a, T> IntoIterator for &'a mut PerWheel<T> {
    type Item = &'a mut T;
    type IntoIter = core::slice::IterMut<'a, T>;
    #[inline]
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter_mut()
    }
}

#[cfg(test)]
mod tests {
    use super::{PerWheel, Wheel};

    #[test]
    fn index_round_trip_and_webots_order() {
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            assert_eq!(w.index(), i);
            assert_eq!(Wheel::from_index(i), Some(w));
            assert_eq!(w.mirror().mirror(), w);
            assert_eq!(w.mirror().is_front(), w.is_front());
            assert_ne!(w.mirror().is_right(), w.is_right());
        }
        assert_eq!(Wheel::from_index(4), None);
        assert_eq!(Wheel::from_index(usize::MAX), None);
        assert_eq!(
            Wheel::ALL.map(|w| (w.is_front(), w.is_right())),
            [(true, true), (true, false), (false, true), (false, false)]
        );
        assert_eq!(Wheel::RearLeft.webots_prefix(), "left_rear");
    }

    #[test]
    fn per_wheel_indexing_and_combinators() {
        let mut p = PerWheel::new(1, 2, 3, 4);
        assert_eq!(Wheel::ALL.map(|w| p[w]), [1, 2, 3, 4]);
        p[Wheel::FrontLeft] = 20;
        assert_eq!(p.as_array(), &[1, 20, 3, 4]);
        assert_eq!(p.get(3), Some(&4));
        assert_eq!(p.get(4), None);
        assert_eq!(p.map(|x| x * 10), PerWheel([10, 200, 30, 40]));
        assert_eq!(
            p.zip_with(PerWheel::splat(1), |a, b| a - b).0,
            [0, 19, 2, 3]
        );
        assert_eq!(
            p.map_with_wheel(|w, x| w.index() as i32 + x).0,
            [1, 21, 5, 7]
        );
        assert_eq!(PerWheel::from_fn(Wheel::index).0, [0, 1, 2, 3]);
        assert_eq!(p.iter().sum::<i32>(), 28);
        assert_eq!(
            p.iter_wheels().find(|(_, x)| **x == 3).map(|(w, _)| w),
            Some(Wheel::RearRight)
        );
        for x in &mut p {
            *x = -*x;
        }
        assert_eq!(<[i32; 4]>::from(p), [-1, -20, -3, -4]);
        assert_eq!(PerWheel::<f32>::default().0, [0.0; 4]);
    }
}
