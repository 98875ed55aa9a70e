//! Fixed-point printing of `f32`, in place of core's float formatting: its shortest and exact
//! float-to-decimal algorithms and their tables take about 9 KiB of flash, more than the
//! firmware's 64 KiB allow next to the plant.

use core::fmt;

/// `self.0` printed with `self.1` decimals (at most 4), rounded half away from zero, like
/// `{:.N}` (and `{:W.N}`: the width and alignment of the format are honoured). Values beyond
/// ±4·10⁹ at the given precision print as that bound; non-finite values as `NaN`, `inf`,
/// `-inf`.
#[derive(Debug, Clone, Copy)]
pub struct Fixed(pub f32, pub u8);

/// Powers of ten for 0 to 4 decimals.
const SCALE: [u32; 5] = [1, 10, 100, 1000, 10_000];

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Fixed(value, decimals) = *self;
        if value.is_nan() {
            return f.pad("NaN");
        }
        if value.is_infinite() {
            return f.pad(if value > 0.0 { "inf" } else { "-inf" });
        }
        let scale = SCALE.get(usize::from(decimals)).copied().unwrap_or(1);
        // `as` saturates: no overflow, whatever the value.
        let scaled = (value.abs() * scale as f32 + 0.5) as u32;
        let mut text = Text::default();
        let (mut whole, mut fraction) = (scaled / scale, scaled % scale);
        if scale > 1 {
            for _ in 0..decimals {
                text.push_front(b'0' + (fraction % 10) as u8);
                fraction /= 10;
            }
            text.push_front(b'.');
        }
        loop {
            text.push_front(b'0' + (whole % 10) as u8);
            whole /= 10;
            if whole == 0 {
                break;
            }
        }
        if value.is_sign_negative() {
            text.push_front(b'-');
        }
        f.pad(text.as_str())
    }
}

/// ASCII text built from its end, in a buffer long enough for any [`Fixed`].
#[derive(Debug)]
struct Text {
    bytes: [u8; 16],
    /// Index of the first byte written.
    start: usize,
}

impl Default for Text {
    fn default() -> Self {
        Text {
            bytes: [0; 16],
            start: 16,
        }
    }
}

impl Text {
    /// Writes `byte` before the text (dropped if the buffer is full, which no [`Fixed`] fills).
    fn push_front(&mut self, byte: u8) {
        if let Some(i) = self.start.checked_sub(1)
            && let Some(slot) = self.bytes.get_mut(i)
        {
            *slot = byte;
            self.start = i;
        }
    }

    fn as_str(&self) -> &str {
        self.bytes
            .get(self.start..)
            .and_then(|b| core::str::from_utf8(b).ok())
            .unwrap_or("")
    }
}
