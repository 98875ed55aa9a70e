//! One axle's rows in a sweep of the contact solve: the brakes, then the two suspension rows
//! as one 2×2 block and the tyre rows as one 4×4 block (or wheel by wheel on Webots' contact),
//! so that neither wheel of an axle is favoured by the order of the solve.

use rapier3d::prelude::Vector;
use vehicle_model::actuator::coulomb_torque;

use super::body::Body;
use super::linear::{solve_mirrored, solve2};
use super::rows::{Grip, Spin, WheelRow};

/// The per-step constants of one axle (wheels `2·a` and `2·a + 1`).
#[derive(Debug, Clone, Copy)]
pub(super) struct Axle {
    /// Suspension rows' inverse effective masses (1/kg), 2×2: the compression rate of wheel
    /// `i`'s spring per unit normal impulse of wheel `j`.
    k_normal: [[f32; 2]; 2],
    /// `n/(n·up)` per wheel: the spring compresses at the hard point's velocity toward the
    /// ground along this (m/s per m/s). The wheel stays on the ground, so the compression is
    /// the hard point's height over the ground over `n·up`; moving along the ground leaves it
    /// unchanged, however the chassis pitches or rolls (a rate along `up` would see a BmwX5's
    /// 0.5° of pitch at 20 m/s as 0.17 m/s of compression, 660 N of damper force per wheel).
    compression_direction: [Vector; 2],
    /// `n·up` per wheel: the share of its normal impulse that its spring carries.
    axis_cosine: [f32; 2],
    /// `[forward·up, lateral·up]` per wheel: the shares of its tyre impulses that its spring
    /// carries when the chassis leans on the ground, limited by [`MAX_FRICTION_FEEDBACK`].
    tyre_along_axis: [[f32; 2]; 2],
    /// `dt·k·x` (N·s) per wheel: the spring's impulse at the current compression.
    spring_impulse: [f32; 2],
    /// `dt·(k·dt + c)` (kg) per wheel: the implicit spring-damper's impulse per m/s of
    /// compression rate.
    softness: [f32; 2],
    /// Tyre rows' inverse effective masses (1/kg), 4×4 in the order forward 0, lateral 0,
    /// forward 1, lateral 1, with each free wheel's spin on its forward diagonal.
    k_tyre: [[f32; 4]; 4],
}

/// The most the tyre's friction may feed back into its own normal load through the leaning
/// suspension axis (dimensionless, < 1).
///
/// Why a limit: the spring carries `N·(n·up) + P_t·up`, and the tyre impulse `P_t` can reach
/// `μ·N`, so the normal impulse solves `N·(n·up − μ·|t·up|) ≤ P_spring` at worst (`t` the
/// tyre force's direction in the ground plane). Once the suspension axis leans from the
/// ground's normal past `atan(1/μ)` (45° at μ = 1, 18° at μ = 3, 6° at μ = 10, a car rolling
/// over), the factor is ≤ 0 and a rigid slider with Coulomb friction has no bounded solution:
/// the wedging of Painlevé's paradox. The solve then found normal loads of meganewtons whose
/// friction threw a rolled BmwX5 76 m up (issue #37). A real suspension yields there (bump stop,
/// arm compliance, the tyre's sidewall). The spring's share of the tyre impulse is scaled
/// down so that the gain `μ·|t·up| / (n·up)` is at most this: the normal impulse is then at
/// most `P_spring / ((1 − 0.5)·(n·up))`. A car on its wheels never reaches it (the gain is
/// `μ·tan(lean)`: 0.09 at μ = 1 and 5° of roll), so its handling is unchanged.
pub(super) const MAX_FRICTION_FEEDBACK: f32 = 0.5;

/// The peak friction coefficient of `grip` in any direction of the ground plane.
#[inline]
fn peak_friction(grip: &Grip) -> f32 {
    match *grip {
        Grip::Slip(law) => law.friction[0].max(law.friction[1]),
        Grip::Coulomb { friction, .. } => friction,
    }
}

impl Axle {
    #[inline]
    pub(super) fn new(body: &Body, wheels: &[WheelRow], dt: f32) -> Axle {
        let contacts = [wheels[0].contact, wheels[1].contact];
        let mut axle = Axle {
            k_normal: [[0.0; 2]; 2],
            compression_direction: [Vector::ZERO; 2],
            axis_cosine: [1.0; 2],
            tyre_along_axis: [[0.0; 2]; 2],
            spring_impulse: [0.0; 2],
            softness: [0.0; 2],
            k_tyre: [[0.0; 4]; 4],
        };
        for (i, ci) in contacts.iter().enumerate() {
            let Some(ci) = ci else { continue };
            if let Some(si) = ci.spring() {
                axle.axis_cosine[i] = ci.axis_cosine(si);
                axle.compression_direction[i] = ci.normal / axle.axis_cosine[i];
                let along = [ci.forward.dot(si.up), ci.lateral.dot(si.up)];
                // Each axis of the Coulomb pyramid reaches μ·N on its own: the worst case adds them.
                let reach = match wheels[i].grip {
                    Grip::Slip(_) => along[0].hypot(along[1]),
                    Grip::Coulomb { .. } => along[0].abs() + along[1].abs(),
                };
                let gain = peak_friction(&wheels[i].grip) * reach / axle.axis_cosine[i];
                let share = if gain > MAX_FRICTION_FEEDBACK {
                    MAX_FRICTION_FEEDBACK / gain
                } else {
                    1.0
                };
                axle.tyre_along_axis[i] = along.map(|a| a * share);
                axle.spring_impulse[i] = dt * si.stiffness * si.compression;
                axle.softness[i] = dt * (si.stiffness * dt + si.damping);
            }
            for (j, cj) in contacts.iter().enumerate() {
                let Some(cj) = cj else { continue };
                if let (Some(si), Some(_)) = (ci.spring(), cj.spring()) {
                    axle.k_normal[i][j] = body.coupling(
                        si.hardpoint_arm,
                        axle.compression_direction[i],
                        cj.contact_arm,
                        cj.normal,
                    );
                }
                for (m, dm) in [ci.forward, ci.lateral].into_iter().enumerate() {
                    for (n, dn) in [cj.forward, cj.lateral].into_iter().enumerate() {
                        axle.k_tyre[2 * i + m][2 * j + n] =
                            body.coupling(ci.contact_arm, dm, cj.contact_arm, dn);
                    }
                }
            }
            axle.k_tyre[2 * i][2 * i] += ci.radius * ci.radius * wheels[i].spin.inv_inertia();
        }
        axle
    }
}

/// The brake: drives the spin toward 0 with an impulse within `±brake_impulse`.
#[inline]
pub(super) fn brake_row(w: &mut WheelRow) {
    let Spin::Free {
        inv_inertia,
        brake_impulse,
    } = w.spin
    else {
        return;
    };
    if brake_impulse <= 0.0 || inv_inertia <= 0.0 {
        return;
    }
    let old = w.impulses.brake;
    // The Coulomb rule on impulses: the impulse that stops the wheel, within the capacity.
    let new = coulomb_torque(old - w.omega / inv_inertia, brake_impulse);
    w.impulses.brake = new;
    w.omega += (new - old) * inv_inertia;
}

/// The implicit spring-dampers of an axle: `N·(n·up) + P_t·up = dt·k·x + dt·(k·dt + c)·ẋ`
/// for each wheel's normal impulse `N ≥ 0` (along the ground's normal at the contact point),
/// with `P_t` its tyre impulse (the sweep's latest) and `ẋ` the spring's compression rate
/// after both normal impulses (the hard point's approach to the ground over `n·up`).
#[inline]
pub(super) fn suspension_block(body: &mut Body, pair: &mut [WheelRow], axle: &Axle) {
    let springs = [0, 1].map(|i| {
        let c = pair[i].contact?;
        Some((c, *c.spring()?))
    });
    let mut m = [[1.0, 0.0], [0.0, 1.0]];
    let mut rhs = [0.0; 2];
    for i in 0..2 {
        let Some((_, s)) = springs[i] else { continue };
        let rate = -axle.compression_direction[i].dot(body.velocity_at(s.hardpoint_arm));
        let soft = axle.softness[i];
        let cosine = axle.axis_cosine[i];
        for (j, (out, k)) in m[i].iter_mut().zip(axle.k_normal[i]).enumerate() {
            *out = if i == j { cosine } else { 0.0 } + soft * k;
        }
        let tyre = pair[i].impulses;
        let [along_forward, along_lateral] = axle.tyre_along_axis[i];
        rhs[i] = axle.spring_impulse[i] + soft * rate
            - cosine * tyre.normal
            - along_forward * tyre.forward
            - along_lateral * tyre.lateral;
    }
    let Some(delta) = solve2(m, rhs) else { return };
    for (i, c) in springs.iter().enumerate() {
        let Some((c, _)) = c else { continue };
        let old = pair[i].impulses.normal;
        let new = (old + delta[i]).max(0.0);
        pair[i].impulses.normal = new;
        c.apply_normal(body, new - old);
    }
}

/// The tyres of an axle in sweep number `sweep`.
///
/// Slip-based tyres: each direction's force law at the end-of-step slip velocities of both
/// wheels, solved together, then each wheel's force kept within its friction ellipse. The
/// tyres' compliance determines how the two wheels share a lateral load; Webots' rigid contact
/// leaves that undetermined (two lateral rows on one line of a rigid chassis), so its wheels
/// are solved one at a time, as ODE's solver does, alternating which goes first.
#[inline]
pub(super) fn tyre_block(body: &mut Body, pair: &mut [WheelRow], axle: &Axle, sweep: usize) {
    if pair.iter().any(|w| matches!(w.grip, Grip::Coulomb { .. })) {
        let order = if sweep.is_multiple_of(2) {
            [0, 1]
        } else {
            [1, 0]
        };
        for i in order {
            wheel_tyre(body, &mut pair[i], axle, i);
        }
        return;
    }
    let mut m = [[0.0_f32; 4]; 4];
    let mut rhs = [0.0_f32; 4];
    for (i, w) in pair.iter().enumerate() {
        let Some(rows) = tyre_rows(body, w) else {
            m[2 * i][2 * i] = 1.0;
            m[2 * i + 1][2 * i + 1] = 1.0;
            continue;
        };
        for (d, (alpha, beta, b)) in rows.into_iter().enumerate() {
            let r = 2 * i + d;
            for (col, k) in axle.k_tyre[r].iter().enumerate() {
                m[r][col] = beta * k;
            }
            m[r][r] += alpha;
            rhs[r] = b;
        }
    }
    let Some(delta) = solve_mirrored(&m, &rhs) else {
        return;
    };
    for (i, w) in pair.iter_mut().enumerate() {
        apply_tyre(body, w, [delta[2 * i], delta[2 * i + 1]]);
    }
}

/// Wheel `i` of an axle's tyre rows alone, the other wheel's impulses held.
#[inline]
fn wheel_tyre(body: &mut Body, w: &mut WheelRow, axle: &Axle, i: usize) {
    let Some(rows) = tyre_rows(body, w) else {
        return;
    };
    let mut m = [[0.0_f32; 2]; 2];
    let mut rhs = [0.0_f32; 2];
    for (d, (alpha, beta, b)) in rows.into_iter().enumerate() {
        for (e, out) in m[d].iter_mut().enumerate() {
            *out = beta * axle.k_tyre[2 * i + d][2 * i + e];
        }
        m[d][d] += alpha;
        rhs[d] = b;
    }
    if let Some(delta) = solve2(m, rhs) {
        apply_tyre(body, w, delta);
    }
}

/// The forward and lateral tyre rows of a wheel on the ground, `α·ΔP + β·(K·ΔP) = b` as
/// `(α, β, b)` with the current slip velocities; `None` in the air.
#[inline]
fn tyre_rows(body: &Body, w: &WheelRow) -> Option<[(f32, f32, f32); 2]> {
    let c = w.contact?;
    let v = c.slip_velocity(body, w.omega);
    let current = [w.impulses.forward, w.impulses.lateral];
    Some([0, 1].map(|d| {
        let (alpha, beta, c0) = w.grip.row(d, w.impulses.normal, current[d]);
        (alpha, beta, c0 - beta * v[d])
    }))
}

/// Adds `delta` (N·s, forward and lateral) to the wheel's tyre impulses within its friction
/// limits, and applies what was added to the chassis and the spin.
#[inline]
fn apply_tyre(body: &mut Body, w: &mut WheelRow, delta: [f32; 2]) {
    let Some(c) = w.contact else { return };
    let (f0, l0) = (w.impulses.forward, w.impulses.lateral);
    let [f, l] = w
        .grip
        .clamp(f0 + delta[0], l0 + delta[1], w.impulses.normal);
    w.impulses.forward = f;
    w.impulses.lateral = l;
    body.apply(c.contact_arm, c.forward * (f - f0) + c.lateral * (l - l0));
    w.omega -= c.radius * (f - f0) * w.spin.inv_inertia();
}
