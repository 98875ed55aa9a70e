//! The keyboard of a car's controller: keys pressed by the world file's programme arrive at
//! the first keyboard sample at or after their time, are read once each, then −1.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::keyboard::{CONTROL, SHIFT};
use sim::{Simulation, world_file};

const WORLD: &str = r#"
[vehicle]
model = "BmwX5"
[[vehicle.programme]]
at = 0.05
key = "a"
[[vehicle.programme]]
at = 0.05
key = "CONTROL+UP"
[[vehicle.programme]]
at = 0.1
key = 66
cruising_speed = 10
[[vehicle.programme]]
at = 0.2
key = "SHIFT+PAGEDOWN"
"#;

#[test]
fn programmed_keys_arrive_at_their_times() {
    let description = world_file::parse_str("keys.toml", WORLD).unwrap();
    // The key-only steps drive nothing: only the step with a cruising speed is a command.
    assert_eq!(description.cars[0].programme.steps().len(), 1);
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.enable_keyboard(id, 20).unwrap();
    assert_eq!(sim.keyboard(id).unwrap().period_ms(), 20);
    // Keys read at the end of each 10 ms step, until 250 ms.
    let mut seen: Vec<(u64, i32)> = Vec::new();
    for _ in 0..25 {
        sim.step().unwrap();
        loop {
            let k = sim.next_key(id).unwrap();
            if k == -1 {
                break;
            }
            seen.push((sim.world().time_ms(), k));
        }
    }
    // Samples every 20 ms from enabling at 0: 20, 40, 60 ... The presses at 50 ms arrive at
    // 60 ms, the one at 100 ms at 100 ms, the one at 200 ms at 200 ms; each once.
    assert_eq!(
        seen,
        vec![(60, 65), (60, CONTROL | 315), (100, 66), (200, SHIFT | 367)]
    );
}

#[test]
fn a_disabled_keyboard_holds_nothing_and_bad_keys_are_refused() {
    let description = world_file::parse_str("keys.toml", WORLD).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    for _ in 0..25 {
        sim.step().unwrap();
        assert_eq!(sim.next_key(id).unwrap(), -1);
    }
    for bad in [
        "key = \"UPP\"",
        "key = \"META+A\"",
        "key = 0",
        "key = 1.5",
        "key = true",
    ] {
        let text = format!("[vehicle]\n[[vehicle.programme]]\nat = 1\n{bad}\n");
        let e = world_file::parse_str("keys.toml", &text)
            .unwrap_err()
            .to_string();
        assert!(e.contains("key") && e.contains("keys.toml"), "{bad}: {e}");
    }
}
