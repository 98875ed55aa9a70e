//! Webots' keyboard (spec §11) for headless runs: the keys a car's programme presses
//! (`[[vehicle.programme]] at = 2.0, key = "A"`), read by the controller with
//! `wb_keyboard_get_key`.
//!
//! A press at time `t` is a tap: the keyboard's first sample at or after `t` holds it. Each
//! sample (every `period` ms, with the sampling rules of every device) holds the keys pressed
//! since the previous sample, at most [`MAX_KEYS`]; successive reads in one step return them in
//! turn, then −1; the next step end clears them. A disabled keyboard holds nothing and costs
//! nothing.

use crate::error::ParamError;
use crate::sampling::Schedule;

/// The most keys one sample holds (Webots' library keeps 7).
pub const MAX_KEYS: usize = 7;
/// `WB_KEYBOARD_KEY`: the mask of the key code without its modifiers.
pub const KEY: i32 = 0xFFFF;
/// `WB_KEYBOARD_SHIFT`.
pub const SHIFT: i32 = 0x0001_0000;
/// `WB_KEYBOARD_CONTROL`.
pub const CONTROL: i32 = 0x0002_0000;
/// `WB_KEYBOARD_ALT`.
pub const ALT: i32 = 0x0004_0000;

/// The special keys by their Webots names (`WB_KEYBOARD_<NAME>`), with their codes.
pub const SPECIAL_KEYS: [(&str, i32); 14] = [
    ("END", 312),
    ("HOME", 313),
    ("LEFT", 314),
    ("UP", 315),
    ("RIGHT", 316),
    ("DOWN", 317),
    ("PAGEUP", 366),
    ("PAGEDOWN", 367),
    ("NUMPAD_HOME", 375),
    ("NUMPAD_LEFT", 376),
    ("NUMPAD_UP", 377),
    ("NUMPAD_RIGHT", 378),
    ("NUMPAD_DOWN", 379),
    ("NUMPAD_END", 382),
];

/// The code of a key written as Webots names it: a single printable ASCII character (a
/// letter is taken upper-case, as Webots sends letters), a special key name (`"UP"`,
/// `"PAGEDOWN"` … [`SPECIAL_KEYS`]), optionally after modifiers `"SHIFT+"`, `"CONTROL+"`,
/// `"ALT+"` (e.g. `"CONTROL+SHIFT+A"`). `None` if it is none of these.
pub fn parse_key(text: &str) -> Option<i32> {
    let mut code = 0;
    let mut rest = text;
    while let Some((modifier, tail)) = rest
        .split_once('+')
        .filter(|(m, t)| !m.is_empty() && !t.is_empty())
    {
        code |= match modifier {
            "SHIFT" => SHIFT,
            "CONTROL" => CONTROL,
            "ALT" => ALT,
            _ => return None,
        };
        rest = tail;
    }
    let mut chars = rest.chars();
    let key = match (chars.next(), chars.next()) {
        (Some(c), None) if c.is_ascii_graphic() => i32::from(c.to_ascii_uppercase() as u8),
        _ => SPECIAL_KEYS.iter().find(|(n, _)| *n == rest)?.1,
    };
    Some(code | key)
}

/// Checks a key code given as a number: a key in 1..=0xFFFF with any of the three modifiers.
///
/// # Errors
/// A [`ParamError`] naming `key`.
pub fn check_code(code: i64) -> Result<i32, ParamError> {
    let ok = |c: f64| {
        let c = c as i64;
        c & i64::from(KEY) != 0 && c & !i64::from(KEY | SHIFT | CONTROL | ALT) == 0
    };
    ParamError::check(
        "key",
        code as f64,
        "a key code 1 to 0xFFFF with SHIFT, CONTROL or ALT bits",
        ok,
    )
    .map(|c| c as i32)
}

/// One key pressed by a programme.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KeyPress {
    /// When (ms of simulated time).
    pub at_ms: u64,
    /// The Webots key code, modifiers included.
    pub code: i32,
}

/// A controller's keyboard: its sampling and the keys of its last sample.
#[derive(Debug, Clone, Default)]
pub struct Keyboard {
    /// The programme's presses, by time.
    presses: Vec<KeyPress>,
    /// The first press not yet sampled.
    next_press: usize,
    schedule: Schedule,
    /// The keys of the last sample.
    held: Vec<i32>,
    /// How many of them were read.
    read: usize,
}

impl Keyboard {
    /// A keyboard whose keys are `presses` (sorted here by time; equal times keep their order).
    pub fn new(mut presses: Vec<KeyPress>) -> Self {
        presses.sort_by_key(|p| p.at_ms);
        Keyboard {
            presses,
            ..Keyboard::default()
        }
    }

    /// Its sampling period (ms), 0 when disabled.
    pub fn period_ms(&self) -> u32 {
        self.schedule.period_ms()
    }

    /// Enables it with a period of `period_ms` (0 disables) at `now_ms`: presses before now
    /// are never seen.
    pub fn enable(&mut self, period_ms: u32, now_ms: u64) {
        if self.schedule.enable(period_ms, now_ms) {
            self.skip_until(now_ms);
        }
    }

    fn skip_until(&mut self, now_ms: u64) {
        while self
            .presses
            .get(self.next_press)
            .is_some_and(|p| p.at_ms <= now_ms)
        {
            self.next_press += 1;
        }
    }

    /// The step end at `now_ms`: clears the held keys and, if a sample is due, holds the keys
    /// pressed since the previous one.
    pub fn refresh(&mut self, now_ms: u64) {
        self.held.clear();
        self.read = 0;
        if !self.schedule.is_enabled() {
            self.skip_until(now_ms);
            return;
        }
        if !self.schedule.due(now_ms) {
            return;
        }
        self.schedule.sampled(now_ms);
        while let Some(p) = self
            .presses
            .get(self.next_press)
            .filter(|p| p.at_ms <= now_ms)
        {
            if self.held.len() < MAX_KEYS {
                self.held.push(p.code);
            }
            self.next_press += 1;
        }
    }

    /// The next key of the last sample, −1 when none is left (Webots: `wb_keyboard_get_key`).
    pub fn next_key(&mut self) -> i32 {
        match self.held.get(self.read) {
            Some(&k) => {
                self.read += 1;
                k
            }
            None => -1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_parse_as_webots_codes() {
        assert_eq!(parse_key("A"), Some(65));
        assert_eq!(parse_key("a"), Some(65));
        assert_eq!(parse_key("UP"), Some(315));
        assert_eq!(parse_key("CONTROL+SHIFT+B"), Some(CONTROL | SHIFT | 66));
        assert_eq!(parse_key("+"), Some(43));
        assert_eq!(parse_key("ALT++"), Some(ALT | 43));
        assert_eq!(parse_key("UPP"), None);
        assert_eq!(parse_key("META+A"), None);
        assert_eq!(parse_key(""), None);
        assert_eq!(check_code(65), Ok(65));
        assert!(check_code(0).is_err());
        assert!(check_code(0x0008_0041).is_err());
    }

    #[test]
    fn a_press_is_held_by_one_sample_and_read_once() {
        let mut k = Keyboard::new(vec![
            KeyPress {
                at_ms: 25,
                code: 65,
            },
            KeyPress {
                at_ms: 25,
                code: 66,
            },
            KeyPress { at_ms: 5, code: 67 },
        ]);
        k.enable(20, 10); // the press at 5 ms came before enabling: never seen
        k.refresh(20);
        assert_eq!(k.next_key(), -1);
        k.refresh(30); // sample at 30 ms: the two presses at 25 ms
        assert_eq!((k.next_key(), k.next_key(), k.next_key()), (65, 66, -1));
        assert_eq!(k.next_key(), -1);
        k.refresh(40);
        assert_eq!(k.next_key(), -1);
    }
}
