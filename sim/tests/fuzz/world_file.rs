//! The world-file fuzz harness: any text through the loader; a world that loads is built and
//! driven for a few steps.
//!
//! Shared by the property tests of this directory and the coverage-guided target
//! `fuzz/fuzz_targets/world_file.rs` (which includes this file by path). Invariants: nothing
//! panics; an error names the file and, unless it is about a missing section, where (line or
//! key); every message is one short line (apart from what it quotes of the text); a world that loads builds and steps with a finite
//! state (see `simulation.rs`); `parse_all` loads the same world, or reports `parse_str`'s
//! error among its errors, in file order.

use sim::world_file::{WorldFileErrorKind, parse_all, parse_str};

use crate::control_loop::Op;
use crate::simulation::{RobotOp, run};

/// The name the text is given in messages.
pub const FILE: &str = "fuzz.toml";

/// Longest acceptable message (characters): one line with a few suggestions.
const MAX_MESSAGE_LEN: usize = 400;

/// What a loaded world is asked to do: start moving, then three steps.
const STEPS: usize = 3;

/// Loads `text` and, if it loads, builds and drives the world; checks every invariant of the
/// module documentation.
///
/// # Errors
/// The first broken invariant.
pub fn check(text: &str) -> Result<(), String> {
    check_all(text)?;
    match parse_str(FILE, text) {
        Err(e) => {
            let message = e.to_string();
            let located = e.location.is_some()
                || e.key.is_some()
                || matches!(e.kind, WorldFileErrorKind::Structure(_));
            if e.file != FILE || !message.starts_with(FILE) || !located {
                return Err(format!("unlocated error {e:?}"));
            }
            short(&message, text)
        }
        Ok(world) => {
            for w in &world.warnings {
                short(&w.to_string(), text)?;
            }
            let step = Op::Step {
                time: 0.0,
                wheel_angles: [0.0; 4],
                steering: [0.0; 2],
                wiper: None,
            };
            let mut ops = vec![Op::CruisingSpeed(50.0), Op::SteeringAngle(0.2)];
            ops.extend([step; STEPS]);
            let mut robot_ops = vec![RobotOp::SetSpeed(10.0, 5.0)];
            robot_ops.extend([RobotOp::Step; STEPS]);
            run(&world, &ops, &robot_ops)
        }
    }
}

/// `Err` unless `parse_all` loads the world `parse_str` loads, or reports `parse_str`'s error
/// among its errors, in file order, each rendered.
fn check_all(text: &str) -> Result<(), String> {
    match (parse_str(FILE, text), parse_all(FILE, text)) {
        (Ok(a), Ok(b)) if a == b => Ok(()),
        (Err(e), Err(all)) => {
            let lines: Vec<_> = all
                .errors
                .iter()
                .map(|e| e.location.map(|l| l.line))
                .collect();
            if !all.errors.contains(&e) || !lines.is_sorted() || all.to_string().is_empty() {
                return Err(format!("parse_all {all:?} against parse_str {e:?}"));
            }
            Ok(())
        }
        (a, b) => Err(format!("parse_str {a:?} but parse_all {b:?}")),
    }
}

/// `Err` if `message` is not one short line, apart from what it quotes of `text` (a key or a
/// string of the file, which may be long or hold an escaped line break).
fn short(message: &str, text: &str) -> Result<(), String> {
    let may_break = ["\\n", "\\r", "\\u", "\\U", "\"\"\"", "'''"]
        .iter()
        .any(|e| text.contains(e));
    let lines_ok = may_break || !message.contains(['\n', '\r']);
    // A message may quote a word of the text (a key, a name) twice, but never print a short
    // number (`1e300`) long.
    let longest_word = text.split_whitespace().map(|w| w.chars().count()).max();
    if lines_ok && message.chars().count() <= MAX_MESSAGE_LEN + 2 * longest_word.unwrap_or(0) {
        Ok(())
    } else {
        Err(format!("message not one short line: {message}"))
    }
}
