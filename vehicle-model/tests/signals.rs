//! Lights, indicators, wipers, sounds and the steering read-back (spec §2–§3) against the
//! Webots rules (the arithmetic is in the comments, evaluated with python3 in f64).

mod common;

use common::Plant;
use common::golden::{close, driver, sensors_at};
use vehicle_model::{
    ControlMode, IndicatorState, Model, PerWheel, Sensors, WheelAngles, WiperMode,
};

#[test]
fn steering_read_back_is_the_measured_mean() {
    let mut d = driver(Model::BmwX5);
    assert_eq!(d.steering_angle(), 0.0);
    d.set_steering_angle(0.5);
    // Not the commanded angle: the measured one, still 0 until the sensors report.
    assert_eq!(d.steering_angle(), 0.0);
    let mut s = Sensors::unsampled(0.0);
    d.step(&s);
    assert_eq!(d.steering_angle(), 0.0);
    s.steering = WheelAngles::new(0.6, 0.4);
    d.step(&s);
    assert!(close(d.steering_angle(), 0.5, 1e-15));
    assert_eq!(d.right_steering_angle(), 0.6);
    assert_eq!(d.left_steering_angle(), 0.4);
    // A lost sample keeps the previous reading.
    s.steering = WheelAngles::new(f64::NAN, 0.2);
    d.step(&s);
    assert_eq!(
        (d.right_steering_angle(), d.left_steering_angle()),
        (0.6, 0.2)
    );
}

#[test]
fn blink_timeline_indicators_and_hazard() {
    let mut d = driver(Model::BmwX5);
    d.set_indicator(IndicatorState::Right);
    // Period 0.34 s: on in [0, 0.34), off in [0.34, 0.68), on in [0.68, 1.02).
    for (t, on) in [
        (0.0, true),
        (0.2, true),
        (0.335, true),
        (0.345, false),
        (0.6, false),
        (0.685, true),
        (1.0, true),
        (1.03, false),
    ] {
        let l = d.step(&sensors_at(t)).lights;
        assert_eq!(
            (l.right_indicator, l.interior_right_indicator),
            (on, on),
            "t = {t}"
        );
        assert!(!l.left_indicator && !l.interior_left_indicator);
    }
    assert!(d.commands().sound.blinker);
    assert_eq!(d.commands().cockpit.indicator_lever, IndicatorState::Right);
    assert_eq!(
        d.commands().cockpit.indicator_lever_position(-0.3, 0.3),
        0.3
    );
    d.set_indicator(IndicatorState::Left);
    let l = d.step(&sensors_at(0.1)).lights;
    assert!(l.left_indicator && !l.right_indicator);
    // Hazard flashers: both, whatever the indicator.
    d.set_hazard_flashers(true);
    let l = d.step(&sensors_at(0.1)).lights;
    assert!(l.left_indicator && l.right_indicator);
    let l = d.step(&sensors_at(0.4)).lights;
    assert!(!l.left_indicator && !l.right_indicator);
    d.set_indicator(IndicatorState::Off);
    assert!(d.step(&sensors_at(0.1)).sound.blinker); // hazards still on
    d.set_hazard_flashers(false);
    let c = d.step(&sensors_at(0.1));
    assert!(!c.sound.blinker && !c.lights.right_indicator);
    // Another period: 0.5 s.
    assert_eq!(d.set_indicator_period(0.5), None);
    d.set_indicator(IndicatorState::Right);
    assert!(d.step(&sensors_at(0.45)).lights.right_indicator);
    assert!(!d.step(&sensors_at(0.55)).lights.right_indicator);
    assert_eq!(d.indicator_period(), 0.5);
}

#[test]
fn indicator_auto_cancel_after_0_1_rad_back() {
    let mut d = driver(Model::BmwX5);
    d.set_indicator(IndicatorState::Right);
    d.set_steering_angle(0.5); // tracks the extreme
    d.set_steering_angle(0.45); // 0.05 back: still on
    assert_eq!(d.indicator(), IndicatorState::Right);
    d.set_steering_angle(0.375); // 0.125 back
    assert_eq!(d.indicator(), IndicatorState::Off);
    assert_eq!(
        d.step(&sensors_at(0.0)).cockpit.indicator_lever,
        IndicatorState::Off
    );
    assert!(!d.commands().sound.blinker);

    // Left: mirrored, relative to the angle when the indicator was set (no zero crossing
    // needed).
    d.set_steering_angle(0.25);
    d.set_indicator(IndicatorState::Left);
    d.set_steering_angle(0.3); // 0.05 the other way: still on
    assert_eq!(d.indicator(), IndicatorState::Left);
    d.set_steering_angle(-0.25); // new extreme
    d.set_steering_angle(-0.125); // 0.125 back
    assert_eq!(d.indicator(), IndicatorState::Off);

    // Auto-disabling off, and hazards are never cancelled.
    d.enable_indicator_auto_disabling(false);
    assert!(!d.indicator_auto_disabling());
    d.set_indicator(IndicatorState::Right);
    d.set_hazard_flashers(true);
    d.set_steering_angle(-0.5);
    assert_eq!(d.indicator(), IndicatorState::Right);
    assert!(d.hazard_flashers());
}

#[test]
fn wiper_cycles_normal_and_slow() {
    let mut d = driver(Model::BmwX5);
    let mut plant = Plant::new(&d);
    assert_eq!(plant.wiper, Some(0.0));
    d.set_wiper_mode(WiperMode::Normal);
    // Sweeps 0 → 1.6 → 0 at 2 rad/s (0.8 s per stroke): two tops in 4 s.
    let mut tops = 0;
    let mut last_target = 0.0;
    for _ in 0..400 {
        plant.run(&mut d);
        let target = d.commands().cockpit.wipers.unwrap().target;
        if target != last_target && target == 0.0 {
            tops += 1;
        }
        last_target = target;
    }
    assert_eq!(tops, 2, "one top per 1.6 s");
    assert_eq!(d.wiper_mode(), WiperMode::Normal);

    // Slow: only sweeps while floor(t) mod 4 == 0. (The clock is set from the step number so
    // that t = 4 is exact.)
    let mut d = driver(Model::BmwX5);
    let mut plant = Plant::new(&d);
    d.set_wiper_mode(WiperMode::Slow);
    for k in 100..400 {
        plant.time = f64::from(k) / 100.0; // t in [1, 4): held down
        plant.run(&mut d);
        assert_eq!(d.commands().cockpit.wipers.unwrap().target, 0.0, "k = {k}");
    }
    assert_eq!(plant.wiper, Some(0.0));
    plant.time = 4.0; // start of a window
    plant.run(&mut d);
    assert_eq!(d.commands().cockpit.wipers.unwrap().target, 1.6);
    // 0.02 rad per step: the sensor reads 1.6 at k = 480 (0.8 s at 2 rad/s), then down again.
    for k in 401..480 {
        plant.time = f64::from(k) / 100.0;
        plant.run(&mut d);
        assert_eq!(d.commands().cockpit.wipers.unwrap().target, 1.6, "k = {k}");
    }
    plant.time = 4.8;
    plant.run(&mut d);
    assert_eq!(d.commands().cockpit.wipers.unwrap().target, 0.0);

    // Fast mode velocity, and cars without wipers ignore the mode.
    d.set_wiper_mode(WiperMode::Fast);
    assert_eq!(d.commands().cockpit.wipers.unwrap().velocity, 2.0); // until the next step
    assert_eq!(
        d.step(&plant.sensors()).cockpit.wipers.unwrap().velocity,
        4.0
    );
    let mut prius = driver(Model::ToyotaPrius);
    prius.set_wiper_mode(WiperMode::Fast);
    assert_eq!(prius.wiper_mode(), WiperMode::Down);
    assert_eq!(prius.step(&sensors_at(0.0)).cockpit.wipers, None);
}

#[test]
fn backwards_lights_in_both_modes() {
    let mut d = driver(Model::BmwX5);
    assert!(!d.step(&sensors_at(0.0)).lights.backwards);
    d.set_gear(-1); // reverse alone does nothing outside torque mode
    assert!(!d.step(&sensors_at(0.01)).lights.backwards);
    d.set_throttle(0.0);
    assert!(!d.backwards_lights()); // updated by the step
    assert!(d.step(&sensors_at(0.02)).lights.backwards);
    assert!(d.backwards_lights());
    d.set_gear(1);
    assert!(!d.step(&sensors_at(0.03)).lights.backwards);
    d.set_cruising_speed(-5.0);
    assert!(d.step(&sensors_at(0.04)).lights.backwards);
    d.set_cruising_speed(0.0);
    assert!(!d.step(&sensors_at(0.05)).lights.backwards);
}

#[test]
fn brake_lights_and_brake_torque() {
    let mut d = driver(Model::BmwX5);
    assert_eq!(d.set_brake_intensity(0.5), None);
    assert!(d.brake_lights()); // immediately, like the LED
    let c = *d.step(&sensors_at(0.0));
    assert!(c.lights.brake);
    // 0.5 · brakeCoefficient 1800 on every wheel, driven or not, even at standstill.
    assert_eq!(c.brake_torque, PerWheel::splat(900.0));
    assert_eq!(d.control_mode(), ControlMode::Undefined); // braking chooses no mode
    d.set_brake_intensity(0.0);
    assert!(!d.brake_lights());
    let c = *d.step(&sensors_at(0.01));
    assert_eq!(c.brake_torque, PerWheel::splat(0.0));
    assert!(!c.lights.brake);
    assert_eq!(d.brake_intensity(), 0.0);
}

#[test]
fn lights_switches() {
    let mut d = driver(Model::BmwX5);
    d.set_dipped_beams(true);
    d.set_antifog_lights(true);
    let l = d.step(&sensors_at(0.0)).lights;
    assert!(l.front && l.rear && l.antifog);
    assert!(d.dipped_beams() && d.antifog_lights());
    d.set_dipped_beams(false);
    let l = d.step(&sensors_at(0.0)).lights;
    assert!(!l.front && !l.rear && l.antifog);
}

#[test]
fn engine_sound_torque_mode_and_none() {
    // BmwX5, torque mode, first gear, throttle 0.5, wheels at 10 rad/s:
    // rpm = 10·60/(2π)·12.5 = 1193.662073189215;
    // volume = (0.8 + 0.2·0.5)·(0.5 + 0.5·rpm/6500); pitch = rpm/1000.
    let mut d = driver(Model::BmwX5);
    let mut plant = Plant::new(&d);
    d.set_gear(1);
    d.set_throttle(0.5);
    plant.roll(&mut d, PerWheel::splat(10.0), 3);
    let s = d.commands().sound.engine;
    let rpm = 1193.662073189215;
    assert!(s.playing);
    assert!(close(s.volume, 0.9 * (0.5 + 0.5 * rpm / 6500.0), 1e-12));
    assert!(close(s.pitch, rpm / 1000.0, 1e-12));
    // Undefined mode: idle at engineMinRPM, volume 1.
    let mut d = driver(Model::BmwX5);
    let s = d.step(&sensors_at(0.0)).sound.engine;
    assert!(s.playing && s.volume == 1.0 && s.pitch == 1.0);
    // Electric cars here have no engine sound.
    let mut tesla = driver(Model::TeslaModel3);
    tesla.set_throttle(1.0);
    assert!(!tesla.step(&sensors_at(0.0)).sound.engine.playing);
}

#[test]
fn engine_sound_speed_mode_uses_min() {
    // BmwX5 at 20 km/h target, wheels at 10 rad/s (13.464 km/h measured):
    // n = 95.4929658551372 rev/min; virtual gear: the first with |n·k| < (2·1000 + 6500)/3
    // = 2833.3 → first gear (1193.66 rpm); deficit 20 − 13.464 = 6.536 km/h;
    // volume = (0.8 + 0.2·6.536/25)·(0.5 + 0.5·min(1193.66, 6500)/6500).
    let mut d = driver(Model::BmwX5);
    let mut plant = Plant::new(&d);
    d.set_cruising_speed(20.0);
    plant.roll(&mut d, PerWheel::splat(10.0), 1);
    // Wheel speeds not measurable yet: the sound is left as it was (stopped).
    assert!(!d.commands().sound.engine.playing);
    plant.roll(&mut d, PerWheel::splat(10.0), 2);
    let s = d.commands().sound.engine;
    let rpm = 1193.662073189215;
    let volume = (0.8 + 0.2 * (20.0 - 13.464) / 25.0) * (0.5 + 0.5 * rpm / 6500.0);
    assert!(s.playing);
    assert!(close(s.volume, volume, 1e-9), "{} vs {volume}", s.volume);
    assert!(close(s.pitch, rpm / 1000.0, 1e-9));
}

#[test]
fn prius_power_split_sound_stops_below_min_rpm() {
    let mut d = driver(Model::ToyotaPrius);
    d.set_gear(1);
    d.set_throttle(1.0);
    let mut plant = Plant::new(&d);
    plant.roll(&mut d, PerWheel::splat(1.0), 3); // 57.3 rpm < 1200
    assert!(!d.commands().sound.engine.playing);
    // 30 rad/s · 60/(2π) · 6 = 1718.9 rpm > 1200: plays at hybridPowerSplitRPM 3000 → pitch 3.
    plant.roll(&mut d, PerWheel::splat(30.0), 3);
    let s = d.commands().sound.engine;
    assert!(s.playing && close(s.pitch, 3.0, 1e-12));
}
