//! The `vehicle-model` control loop as Cortex-M4F firmware: f32, no heap, no panics.
//!
//! A BMW X5 drives a scripted route against a planar car on the `vehicle-model` tyres
//! ([`cortex_m4_drive::plant`]): launch in torque mode through the gears, cruise control, slow
//! down for a junction, turn right with the indicator on (cancelled by steering back), then
//! brake hard to a stop. Each step the firmware reads the sensors, runs [`Driver::step`], and
//! the plant applies the commands, exactly as a host would with the real car. The run prints a
//! summary over semihosting and exits 0 if every check holds, 1 otherwise.

#![no_std]
#![no_main]

mod decimal;
mod stack;

use core::fmt;

use ackermann::{Odometry, PerWheel, Real, SpeedSource};
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};
use panic_semihosting as _;
use vehicle_model::{
    AutoShiftParams, ControlMode, Driver, IndicatorState, Model, TyreError, WheelAngles,
};

use cortex_m4_drive::plant::{Environment, Plant};
use decimal::Fixed;

/// Control period (ms): the world's `basicTimeStep`.
const STEP_MS: u32 = 10;
/// Cruise-control speed on the open road (km/h).
const CRUISE_KMH: f32 = 120.0;
/// Speed for the turn at the junction (km/h).
const TURN_KMH: f32 = 30.0;
/// Central steering angle of the right turn (rad, positive = right).
const TURN_ANGLE: f32 = 0.2;
/// How fast the driver turns the steering (central angle, rad/s).
const STEERING_RATE: f32 = 0.4;
/// Heading change at which the driver starts to unwind the steering (rad, 75°).
const UNWIND_AT_YAW: f32 = 75.0 * DEG;
/// Throttle of the launch (dimensionless).
const LAUNCH_THROTTLE: f32 = 0.8;
/// Brake intensity of the final, hard stop (dimensionless): full brakes, enough to lock the
/// rear wheels, so that the tyres' friction limits the stop.
const BRAKE_INTENSITY: f32 = 1.0;
/// Cruise control must hold the speed within this of its target (km/h).
const SPEED_TOLERANCE_KMH: f32 = 0.5;
/// How far dead reckoning may be from the true position when the final braking begins, as a
/// fraction of the distance travelled (dimensionless). The odometry takes the free rear wheels
/// to roll without slip, but their tyres slip: −0.37 % at 120 km/h, where they carry the
/// wheels' damping and rolling resistance (2 N·m·s/rad × 89 rad/s / 0.374 m + 0.012 × 5854 N
/// = 547 N against a slip stiffness of 25 × 5854 N), and the rear axle drifts outward at
/// 0.23 m/s in the turn. (The hard stop then locks the rear wheels: the odometry misses the
/// few metres they slide.)
const ODOMETRY_TOLERANCE: f32 = 0.005;
/// Yaw rates (rad/s) from which the turn's yaw rate is compared with the kinematic one.
const MIN_KINEMATIC_YAW_RATE: f32 = 0.05;
/// How far the held car may move in the last second of its hold (m), and how fast it may still
/// move then (m/s): it rests on its tyres' carcass springs, not on a rigid rolling constraint,
/// so its speed decays rather than dropping to exactly 0.
const HOLD_TOLERANCE: f32 = 0.001;
/// Standard gravity (m/s²).
const GRAVITY: f32 = 9.81;

const DEG: f32 = core::f32::consts::PI / 180.0;
const DT: f32 = STEP_MS as f32 / 1000.0;

#[entry]
fn main() -> ! {
    stack::paint();
    let log = drive();
    let passed = report(&log);
    debug::exit(if passed {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    // Not reached under QEMU, where `exit` ends the process.
    loop {
        cortex_m::asm::wfi();
    }
}

/// The scripted drive. Each phase sets the driver's controls, then steps until its goal or
/// its time limit.
fn drive() -> Log {
    let (driver, report) = Driver::<f32>::new(Model::BmwX5.params(), STEP_MS);
    let mut car = match Car::new(driver) {
        Ok(car) => car,
        Err(e) => {
            hprintln!("tyre coefficient {} refused", e.field.path());
            // An empty log fails the checks.
            return Log::default();
        }
    };
    car.log.parameter_warnings = report.len();
    hprintln!("BmwX5, f32 on Cortex-M4F, basicTimeStep {} ms", STEP_MS);

    // 1. Launch: first gear, throttle, the automatic gearbox shifts up.
    let engine = *car.driver.powertrain().engine();
    let shift = AutoShiftParams::for_engine(&engine);
    car.log.gearbox_refused = car.driver.set_automatic_gearbox(Some(shift)).is_err();
    car.driver.set_gear(1);
    car.driver.set_throttle(LAUNCH_THROTTLE);
    car.driver.set_dipped_beams(true);
    car.event(format_args!(
        "launch: gear 1, throttle {}, automatic gearbox",
        Fixed(LAUNCH_THROTTLE, 1)
    ));
    car.run_until(40.0, |car| car.speed_kmh() >= CRUISE_KMH);

    // 2. Cruise control at the target speed.
    car.driver.set_cruising_speed(CRUISE_KMH);
    car.event(format_args!("cruise control {} km/h", Fixed(CRUISE_KMH, 0)));
    car.run_for(10.0);
    car.log.cruise_error_kmh = (car.speed_kmh() - CRUISE_KMH).abs();

    // 3. Slow down for the junction.
    car.driver.set_cruising_speed(TURN_KMH);
    car.event(format_args!("slow down to {} km/h", Fixed(TURN_KMH, 0)));
    car.run_until(15.0, |car| {
        car.speed_kmh() <= TURN_KMH + SPEED_TOLERANCE_KMH
    });
    car.run_for(2.0);

    // 4. Turn right: indicator on, steer in, hold until the heading has turned 75°.
    car.driver.set_indicator(IndicatorState::Right);
    car.event(format_args!(
        "indicator right, steer in to {} rad",
        Fixed(TURN_ANGLE, 1)
    ));
    car.run_until(15.0, |car| {
        car.steer_towards(TURN_ANGLE);
        car.compare_yaw_rate();
        car.odometry.pose().yaw <= -UNWIND_AT_YAW
    });

    // 5. Unwind the steering; coming back 0.1 rad from the peak cancels the indicator.
    car.event(format_args!("steer back"));
    car.log.unwind_started = car.plant.time();
    car.run_until(5.0, |car| car.steer_towards(0.0));
    car.run_for(3.0);

    // 6. Brake hard to a stop (torque mode, no throttle), and stay stopped.
    car.driver.set_throttle(0.0);
    car.driver.set_brake_intensity(BRAKE_INTENSITY);
    car.event(format_args!(
        "throttle 0, brake {}",
        Fixed(BRAKE_INTENSITY, 1)
    ));
    let brake_started = car.plant.distance();
    car.log.brake_speed = car.plant.speed();
    car.log.odometry_error_braking = car.odometry_error();
    car.log.distance_braking = brake_started;
    car.run_until(15.0, |car| car.speed_kmh() == 0.0);
    car.log.stop_time = (car.speed_kmh() == 0.0).then(|| car.plant.time());
    car.log.braking_distance = car.plant.distance() - brake_started;
    car.event(format_args!("stopped"));
    // The stop leaves the tyres wound up: the car rocks back on them (about 2 cm) and settles,
    // then must not move.
    car.run_for(1.0);
    let settled_at = car.plant.distance();
    car.run_for(1.0);
    car.log.creep = car.plant.distance() - settled_at;

    car.finish()
}

/// The firmware (driver + dead reckoning) and the car it drives (the plant).
struct Car {
    driver: Driver<f32>,
    plant: Plant,
    /// The ECU's own pose estimate from the measured wheel speeds and steering.
    odometry: Odometry<f32>,
    log: Log,
}

impl Car {
    /// The firmware around `driver`, and the plant built from the same parameters.
    fn new(driver: Driver<f32>) -> Result<Self, TyreError> {
        let environment = Environment::SUV_ON_ASPHALT;
        let plant = Plant::new(driver.params(), environment)?;
        // The tyre's friction per unit load at its nominal load (radius and load 1).
        let tyre = environment.tyres.params(1.0, 1.0).validate()?;
        let road = environment.road_friction;
        let [locked, _] = tyre.force([-1.0, 0.0], 1.0, road);
        let log = Log {
            friction: [
                tyre.params().longitudinal.peak_friction * road,
                tyre.params().lateral.peak_friction * road,
                locked.abs(),
            ],
            ..Log::default()
        };
        let odometry = Odometry::new(
            *driver.geometry(),
            SpeedSource::for_drive(driver.drive_type()),
        );
        Ok(Car {
            driver,
            plant,
            odometry,
            log,
        })
    }

    /// One control period: sense, decide, actuate, then the plant moves.
    fn step(&mut self) {
        let sensors = self.plant.sensors();
        let commands = self.driver.step(&sensors);
        self.log.non_finite |= !commands.is_finite();
        self.log.blink(commands.lights.right_indicator);
        self.plant.step(commands, STEP_MS);

        // Dead reckoning from what the ECU measured (wheel speeds are one step behind).
        let speeds = PerWheel::from_fn(|w| self.driver.wheel_speed(w));
        let measured = WheelAngles::new(
            self.driver.right_steering_angle(),
            self.driver.left_steering_angle(),
        );
        let delta = self
            .driver
            .geometry()
            .central_angle_from_wheel_angles(measured);
        self.log.non_finite |= self.odometry.update(speeds, delta, DT).is_err();

        self.observe();
        self.log.steps = self.log.steps.saturating_add(1);
    }

    /// Records what the summary and the checks need after each step.
    fn observe(&mut self) {
        let speed = self.speed_kmh();
        self.log.non_finite |= !(speed.is_finite() && self.plant.is_finite());
        self.log.top_speed_kmh = self.log.top_speed_kmh.max(speed);
        let [_, lateral] = self.plant.acceleration();
        self.log.peak_lateral = self.log.peak_lateral.max(lateral.abs());
        // The gear exists only in torque mode (asking in speed mode is a warning).
        if self.driver.control_mode() == ControlMode::Torque
            && let Ok(gear) = self.driver.gear()
        {
            let number = gear.number();
            if number != self.log.gear && self.log.gear != 0 {
                self.event(format_args!("gear {} -> {}", self.log.gear, number));
            }
            self.log.gear = number;
            if let Some(bit) = u32::try_from(number)
                .ok()
                .and_then(|n| 1_u32.checked_shl(n))
            {
                self.log.gears |= bit;
            }
        }
        let indicator = self.driver.indicator();
        if self.log.indicator == IndicatorState::Right && indicator == IndicatorState::Off {
            self.log.indicator_cancelled = Some(self.plant.time());
            self.event(format_args!("indicator cancelled"));
        }
        self.log.indicator = indicator;
    }

    /// Steps until `done` returns true (checked after each step) or `timeout` (s) passes.
    /// A timeout is logged and the script goes on.
    fn run_until(&mut self, timeout: f32, mut done: impl FnMut(&mut Self) -> bool) {
        let steps = (timeout / DT) as u32;
        for _ in 0..steps {
            self.step();
            if done(self) {
                return;
            }
        }
        self.log.timeouts = self.log.timeouts.saturating_add(1);
        self.event(format_args!("phase timed out"));
    }

    /// Steps for `duration` (s).
    fn run_for(&mut self, duration: f32) {
        for _ in 0..(duration / DT) as u32 {
            self.step();
        }
    }

    /// Records the car's yaw rate over the kinematic one, `v·tan δ / L` for the rear axle's
    /// speed `v` and the true central steering angle δ: in this 0.46 g turn the tyres' slip
    /// angles make the car turn less than its wheels point (understeer), and later.
    fn compare_yaw_rate(&mut self) {
        let geometry = self.driver.geometry();
        let delta = geometry.central_angle_from_wheel_angles(self.plant.sensors().steering);
        let kinematic = (self.plant.speed() * delta.tan() / geometry.wheelbase()).abs();
        if kinematic >= MIN_KINEMATIC_YAW_RATE {
            let ratio = self.plant.yaw_rate().abs() / kinematic;
            self.log.yaw_ratio = self.log.yaw_ratio.max(ratio);
        }
    }

    /// Moves the steering one step toward `target` (rad) at the driver's rate; true once there.
    fn steer_towards(&mut self, target: f32) -> bool {
        let current = self.driver.commanded_steering_angle();
        let max_step = STEERING_RATE * DT;
        let next = current + Real::clamp(target - current, -max_step, max_step);
        self.driver.set_steering_angle(next);
        next == target
    }

    /// The ECU's speed estimate (km/h).
    fn speed_kmh(&self) -> f32 {
        self.driver.current_speed()
    }

    /// Prints `what` happened, with the time and the ECU's speed.
    fn event(&self, what: fmt::Arguments<'_>) {
        hprintln!(
            "t={:>6} s {:>6} km/h  {}",
            Fixed(self.plant.time(), 2),
            Fixed(self.speed_kmh(), 1),
            what
        );
    }

    /// Distance between the dead-reckoned and the true position (m).
    fn odometry_error(&self) -> f32 {
        let (truth, estimate) = (self.plant.pose(), self.odometry.pose());
        (estimate.x - truth.x).hypot(estimate.y - truth.y)
    }

    fn finish(mut self) -> Log {
        let truth = self.plant.pose();
        let estimate = self.odometry.pose();
        self.log.time = self.plant.time();
        self.log.final_speed = self.plant.speed();
        self.log.final_pose = [truth.x, truth.y, truth.yaw];
        self.log.odometry_error = self.odometry_error();
        self.log.odometry_pose = [estimate.x, estimate.y, estimate.yaw];
        self.log.driver_speed_kmh = self.speed_kmh();
        self.log.driver_warnings = self.driver.warning_count();
        self.log.plant_faults = self.plant.faults();
        self.log.driver_bytes = core::mem::size_of::<Driver<f32>>();
        self.log.plant_bytes = core::mem::size_of::<Plant>();
        self.log
    }
}

/// What the run measured.
#[derive(Debug, Default)]
struct Log {
    steps: u32,
    time: f32,
    top_speed_kmh: f32,
    cruise_error_kmh: f32,
    /// The gear of the last torque-mode step (0 before).
    gear: i32,
    /// Bit n set: forward gear n was engaged in torque mode.
    gears: u32,
    indicator: IndicatorState,
    right_indicator_lit: bool,
    blinks: u32,
    unwind_started: f32,
    indicator_cancelled: Option<f32>,
    /// The tyre's friction coefficients on this road: peak forward, peak sideways, and a locked
    /// wheel's (dimensionless).
    friction: [f32; 3],
    /// The largest yaw rate over the kinematic one while steering into the turn
    /// (dimensionless).
    yaw_ratio: f32,
    /// The largest lateral acceleration (m/s², magnitude).
    peak_lateral: f32,
    /// True speed when the final braking began (m/s).
    brake_speed: f32,
    braking_distance: f32,
    /// How far the car moved in the last second of its hold (m).
    creep: f32,
    stop_time: Option<f32>,
    final_speed: f32,
    driver_speed_kmh: f32,
    final_pose: [f32; 3],
    odometry_pose: [f32; 3],
    odometry_error: f32,
    /// The dead-reckoning error (m) and the distance travelled (m) when the final braking began.
    odometry_error_braking: f32,
    distance_braking: f32,
    non_finite: bool,
    timeouts: u32,
    parameter_warnings: usize,
    gearbox_refused: bool,
    driver_warnings: u32,
    plant_faults: u32,
    driver_bytes: usize,
    plant_bytes: usize,
}

impl Log {
    /// Counts the right indicator's flashes (rising edges of the lamp).
    fn blink(&mut self, lit: bool) {
        if lit && !self.right_indicator_lit {
            self.blinks = self.blinks.saturating_add(1);
        }
        self.right_indicator_lit = lit;
    }
}

/// Prints the summary and the checks; true if all hold.
fn report(log: &Log) -> bool {
    hprintln!("---- summary ----");
    hprintln!(
        "time             {} s, {} steps",
        Fixed(log.time, 2),
        log.steps
    );
    hprintln!("top speed        {} km/h", Fixed(log.top_speed_kmh, 1));
    hprint!("gears used      ");
    for gear in 1..32 {
        if log.gears & (1_u32 << gear) != 0 {
            hprint!(" {}", gear);
        }
    }
    hprintln!();
    match log.indicator_cancelled {
        Some(t) => hprintln!(
            "indicator        cancelled at t={} s after {} flashes",
            Fixed(t, 2),
            log.blinks
        ),
        None => hprintln!("indicator        never cancelled"),
    }
    // The turn's limit: no tyre grips sideways beyond its peak friction.
    let [forward_friction, lateral_friction, locked_friction] = log.friction;
    let max_lateral = lateral_friction * GRAVITY;
    hprintln!(
        "turn             yaw rate <= {} of v tan(d)/L, lateral acceleration {} m/s2 (mu g {})",
        Fixed(log.yaw_ratio, 3),
        Fixed(log.peak_lateral, 2),
        Fixed(max_lateral, 2)
    );
    // The stop's limits: no shorter than at the tyres' peak friction (the air's drag, 0.02
    // m/s² at 30 km/h, is left out), no longer than on four locked wheels.
    let squared_speed = log.brake_speed * log.brake_speed;
    let shortest_stop = squared_speed / (2.0 * forward_friction * GRAVITY);
    let locked_stop = squared_speed / (2.0 * locked_friction * GRAVITY);
    match log.stop_time {
        Some(t) => hprintln!(
            "stopped          t={} s, braking distance {} m (friction: {} to {} m)",
            Fixed(t, 2),
            Fixed(log.braking_distance, 2),
            Fixed(shortest_stop, 2),
            Fixed(locked_stop, 2)
        ),
        None => hprintln!("stopped          never"),
    }
    let [x, y, yaw] = log.final_pose;
    hprintln!(
        "final pose       x={} m y={} m yaw={} deg",
        Fixed(x, 1),
        Fixed(y, 1),
        Fixed(yaw / DEG, 1)
    );
    let [ox, oy, oyaw] = log.odometry_pose;
    hprintln!(
        "odometry         x={} m y={} m yaw={} deg (error {} m; {} m in {} m before braking)",
        Fixed(ox, 1),
        Fixed(oy, 1),
        Fixed(oyaw / DEG, 1),
        Fixed(log.odometry_error, 2),
        Fixed(log.odometry_error_braking, 2),
        Fixed(log.distance_braking, 0)
    );
    match stack::peak() {
        Some(bytes) => hprintln!(
            "memory           Driver {} B, Plant {} B, peak stack {} B",
            log.driver_bytes,
            log.plant_bytes,
            bytes
        ),
        None => hprintln!("memory           stack overflowed the painted window"),
    }

    let cancelled_by_steering = log
        .indicator_cancelled
        .is_some_and(|t| t >= log.unwind_started);
    let checks = [
        (
            "target speed reached and held",
            log.top_speed_kmh >= CRUISE_KMH && log.cruise_error_kmh <= SPEED_TOLERANCE_KMH,
        ),
        (
            "launched through gears 1 to 3",
            log.gears & 0b1110 == 0b1110,
        ),
        (
            "indicator cancelled by steering back",
            cancelled_by_steering && log.blinks > 0,
        ),
        (
            "car stopped and held",
            log.stop_time.is_some()
                && log.final_speed.abs() <= HOLD_TOLERANCE
                && log.creep <= HOLD_TOLERANCE
                && log.driver_speed_kmh == 0.0,
        ),
        (
            "understeer: yaw rate below kinematic in the turn",
            log.yaw_ratio > 0.0 && log.yaw_ratio < 1.0,
        ),
        (
            "lateral acceleration within mu g",
            log.peak_lateral <= max_lateral,
        ),
        (
            "hard stop within the friction's distances",
            (shortest_stop..=locked_stop).contains(&log.braking_distance),
        ),
        ("no NaN anywhere", !log.non_finite && log.plant_faults == 0),
        (
            "no warnings, every phase in time",
            log.driver_warnings == 0
                && log.parameter_warnings == 0
                && !log.gearbox_refused
                && log.timeouts == 0,
        ),
        (
            "dead reckoning within 0.5 % of the distance until braking",
            log.odometry_error_braking <= ODOMETRY_TOLERANCE * log.distance_braking,
        ),
    ];
    let mut passed = true;
    for (name, ok) in checks {
        hprintln!("[{}] {}", if ok { "ok" } else { "FAILED" }, name);
        passed &= ok;
    }
    hprintln!("{}", if passed { "PASS" } else { "FAIL" });
    passed
}
