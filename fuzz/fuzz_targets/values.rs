//! Numbers from fuzz bytes, weighted like the property tests' strategies towards the values
//! that broke things before.

use libfuzzer_sys::arbitrary::{Result, Unstructured};

#[path = "../../vehicle-model/tests/fuzz/special.rs"]
mod special;

use special::SPECIAL;

/// A special value (half of the time), a small integer in −100…100, or any bit pattern.
pub fn hostile(u: &mut Unstructured<'_>) -> Result<f64> {
    Ok(match u.int_in_range(0..=3u8)? {
        0 | 1 => *u.choose(&SPECIAL)?,
        2 => f64::from(u.int_in_range(-100..=100i32)?),
        _ => f64::from_bits(u.arbitrary()?),
    })
}

/// A small integer around the gears, enum values and wheel indices, or any i32.
pub fn hostile_int(u: &mut Unstructured<'_>) -> Result<i32> {
    Ok(if u.arbitrary()? {
        u.int_in_range(-3..=8)?
    } else {
        u.arbitrary()?
    })
}
