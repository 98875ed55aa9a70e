//! The plan view of a road: its reference line in the xy plane, a chain of segments (straight
//! line, circular arc, clothoid, parametric cubic), each evaluated in closed form at a
//! station `s` (m along the line, in the xy plane as OpenDRIVE measures it).

use core::f64::consts::PI;

use proto_geom::nalgebra::{Point2, Vector2};

use super::fresnel::fresnel;

/// The parameter range of a parametric cubic (OpenDRIVE's `pRange`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamRange {
    /// p runs from 0 to 1 over the segment.
    Normalized,
    /// p runs from 0 to the segment's length (m).
    ArcLength,
}

/// The shape of one segment of a reference line, in its own frame (origin at its start, x
/// along its start heading, y to the left).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Curve {
    /// A straight line.
    Line,
    /// A circular arc of constant curvature (1/m, positive turning left).
    Arc {
        /// Curvature (1/m, positive left).
        curvature: f64,
    },
    /// A clothoid: curvature varying linearly with the station (1/m at either end).
    Spiral {
        /// Curvature at the start (1/m, positive left).
        curvature_start: f64,
        /// Curvature at the end (1/m, positive left).
        curvature_end: f64,
    },
    /// A parametric cubic u(p) = Σ uᵢpⁱ, v(p) = Σ vᵢpⁱ (m), p from 0 at the start to 1 or to
    /// the length at the end, linear in the station (OpenDRIVE's `paramPoly3`; its deprecated
    /// `poly3` is one of these with u(p) = p).
    ParamPoly3 {
        /// u's coefficients (m), constant term first.
        u: [f64; 4],
        /// v's coefficients (m), constant term first.
        v: [f64; 4],
        /// What p runs over.
        range: ParamRange,
    },
}

/// Where a reference line is at a station, and which way it goes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanPose {
    /// The point (m, world x and y).
    pub point: Point2<f64>,
    /// The line's direction (rad, counter-clockwise from +x).
    pub heading: f64,
    /// Its curvature (1/m, positive turning left).
    pub curvature: f64,
}

impl PlanPose {
    /// The unit normal to the left of the line (the +t direction).
    pub fn left(&self) -> Vector2<f64> {
        let (s, c) = self.heading.sin_cos();
        Vector2::new(-s, c)
    }
}

/// One segment of a reference line: a [`Curve`] placed at a station, point and heading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Station of its start along the road (m).
    pub s: f64,
    /// Its start (m, world x and y).
    pub start: Point2<f64>,
    /// Heading at its start (rad, counter-clockwise from +x).
    pub heading: f64,
    /// Its length along the reference line (m, > 0).
    pub length: f64,
    /// Its shape.
    pub curve: Curve,
}

/// Largest clothoid Fresnel argument |u| at which the Fresnel form is used: beyond it (a
/// clothoid whose curvature barely changes, κ₀²/|c| > π·10⁶) the phase πu²/2 would lose its
/// digits, and the segment is an arc plus its first-order correction in c instead.
const FRESNEL_LIMIT: f64 = 1e3;

impl Segment {
    /// The pose at `ds` (m) from the segment's start (clamped to 0..length by the caller).
    pub fn pose_at(&self, ds: f64) -> PlanPose {
        let (local, dheading, curvature) = self.local(ds);
        let (sn, cs) = self.heading.sin_cos();
        PlanPose {
            point: self.start
                + Vector2::new(cs * local.x - sn * local.y, sn * local.x + cs * local.y),
            heading: self.heading + dheading,
            curvature,
        }
    }

    /// The point (m), heading change (rad) and curvature (1/m) at `ds` in the segment's frame.
    fn local(&self, ds: f64) -> (Vector2<f64>, f64, f64) {
        match self.curve {
            Curve::Line => (Vector2::new(ds, 0.0), 0.0, 0.0),
            Curve::Arc { curvature } => (arc(curvature, ds), curvature * ds, curvature),
            Curve::Spiral {
                curvature_start,
                curvature_end,
            } => {
                let c = (curvature_end - curvature_start) / self.length;
                (
                    spiral(curvature_start, c, ds),
                    curvature_start * ds + 0.5 * c * ds * ds,
                    curvature_start + c * ds,
                )
            }
            Curve::ParamPoly3 { u, v, range } => {
                let p = match range {
                    ParamRange::Normalized => ds / self.length,
                    ParamRange::ArcLength => ds,
                };
                let (pu, du, ddu) = cubic(&u, p);
                let (pv, dv, ddv) = cubic(&v, p);
                let speed2 = du * du + dv * dv;
                let curvature = if speed2 > 0.0 {
                    (du * ddv - dv * ddu) / (speed2 * speed2.sqrt())
                } else {
                    0.0
                };
                (Vector2::new(pu, pv), dv.atan2(du), curvature)
            }
        }
    }

    /// The pose at its end.
    pub fn end(&self) -> PlanPose {
        self.pose_at(self.length)
    }
}

/// The value, first and second derivative of Σ cᵢpⁱ at p.
pub(crate) fn cubic(c: &[f64; 4], p: f64) -> (f64, f64, f64) {
    (
        c[0] + p * (c[1] + p * (c[2] + p * c[3])),
        c[1] + p * (2.0 * c[2] + p * 3.0 * c[3]),
        2.0 * c[2] + 6.0 * c[3] * p,
    )
}

/// A point `s` (m) along an arc of curvature `k` (1/m) from the origin heading +x: the chord
/// 2·sin(ks/2)/k at the angle ks/2 (exact, and well conditioned as k → 0).
fn arc(k: f64, s: f64) -> Vector2<f64> {
    let half = 0.5 * k * s;
    let chord = if half.abs() < 1e-8 {
        s
    } else {
        half.sin() / half * s
    };
    let (sn, cs) = half.sin_cos();
    Vector2::new(chord * cs, chord * sn)
}

/// A point `s` (m) along a clothoid from the origin heading +x with curvature k₀ + c·s
/// (k₀ in 1/m, c in 1/m²): ∫₀ˢ e^{i(k₀t + ct²/2)} dt.
fn spiral(k0: f64, c: f64, s: f64) -> Vector2<f64> {
    if c == 0.0 {
        return arc(k0, s);
    }
    if c < 0.0 {
        // The mirror image (y → −y) of the clothoid with (−k₀, −c).
        let m = spiral(-k0, -c, s);
        return Vector2::new(m.x, -m.y);
    }
    // k₀t + ct²/2 = (π/2)u² − k₀²/(2c) with u = (t + k₀/c)/a, a = √(π/c).
    let a = (PI / c).sqrt();
    let (u0, u1) = (k0 / c / a, (s + k0 / c) / a);
    if u0.abs().max(u1.abs()) > FRESNEL_LIMIT {
        return near_arc(k0, c, s);
    }
    let (c0, s0) = fresnel(u0);
    let (c1, s1) = fresnel(u1);
    let (dc, ds) = (a * (c1 - c0), a * (s1 - s0));
    let (sn, cs) = (-k0 * k0 / (2.0 * c)).sin_cos();
    Vector2::new(cs * dc - sn * ds, sn * dc + cs * ds)
}

/// The clothoid of [`spiral`] when c is tiny against k₀²: the arc plus i·(c/2)·∫₀ˢ t²e^{ik₀t}dt,
/// whose neglected second-order term is below c²s⁵/40 (m).
fn near_arc(k0: f64, c: f64, s: f64) -> Vector2<f64> {
    let base = arc(k0, s);
    // I₂ = ∫₀ˢ t² e^{ikt} dt: by its series for small ks (no cancellation), else in closed
    // form e^{iks}(−is²/k + 2s/k² + 2i/k³) − 2i/k³.
    let ks = k0 * s;
    let (re, im) = if ks.abs() < 1.0 {
        let (mut re, mut im) = (0.0, 0.0);
        let mut term = s * s * s; // (iks)ⁿ/n! · s³
        let mut phase = 0usize;
        for n in 0..40 {
            let v = term / (n + 3) as f64;
            match phase {
                0 => re += v,
                1 => im += v,
                2 => re -= v,
                _ => im -= v,
            }
            term *= ks / (n + 1) as f64;
            phase = (phase + 1) % 4;
        }
        (re, im)
    } else {
        let (sn, cs) = ks.sin_cos();
        let (k2, k3) = (k0 * k0, k0 * k0 * k0);
        // (cs + i sn)·(2s/k² + i(2/k³ − s²/k)) − 2i/k³
        let (ar, ai) = (2.0 * s / k2, 2.0 / k3 - s * s / k0);
        (cs * ar - sn * ai, sn * ar + cs * ai - 2.0 / k3)
    };
    // i·(c/2)·(re + i·im) = (−c/2·im, c/2·re)
    Vector2::new(base.x - 0.5 * c * im, base.y + 0.5 * c * re)
}

/// Finds the station offset `ds` (m, in 0..=length) of `segment` nearest to `p`, with the
/// squared distance (m²): a coarse scan, then Newton's method on (p − C(ds))·C'(ds) = 0.
pub(crate) fn nearest(segment: &Segment, p: &Point2<f64>) -> (f64, f64) {
    let n = ((segment.length / 2.0).ceil() as usize).clamp(4, 64);
    let h = segment.length / n as f64;
    let mut best = (0.0, f64::INFINITY);
    for i in 0..=n {
        let ds = i as f64 * h;
        let d2 = (segment.pose_at(ds).point - p).norm_squared();
        if d2 < best.1 {
            best = (ds, d2);
        }
    }
    let mut ds = best.0;
    for _ in 0..20 {
        let pose = segment.pose_at(ds);
        let (sn, cs) = pose.heading.sin_cos();
        // Arc-length speed of the parameter: 1 for all but the parametric cubic, for which
        // the derivative of the point is taken by its own polynomials.
        let (tangent, speed) = tangent_of(segment, ds, Vector2::new(cs, sn));
        let r = p - pose.point;
        let g = r.dot(&tangent);
        let dg = -speed * speed + r.dot(&pose.left()) * pose.curvature * speed * speed;
        if dg >= 0.0 {
            break;
        }
        let next = (ds - g / dg).clamp(0.0, segment.length);
        let done = (next - ds).abs() < 1e-12 * segment.length.max(1.0);
        ds = next;
        if done {
            break;
        }
    }
    let d2 = (segment.pose_at(ds).point - p).norm_squared();
    if d2 < best.1 { (ds, d2) } else { best }
}

/// The derivative of the point by the station (m/m) at `ds`, and its length, given the unit
/// direction `dir`.
fn tangent_of(segment: &Segment, ds: f64, dir: Vector2<f64>) -> (Vector2<f64>, f64) {
    match segment.curve {
        Curve::ParamPoly3 { u, v, range } => {
            let (p, dp) = match range {
                ParamRange::Normalized => (ds / segment.length, 1.0 / segment.length),
                ParamRange::ArcLength => (ds, 1.0),
            };
            let (_, du, _) = cubic(&u, p);
            let (_, dv, _) = cubic(&v, p);
            let speed = (du * du + dv * dv).sqrt() * dp;
            (dir * speed, speed)
        }
        _ => (dir, 1.0),
    }
}

/// The arc length (m) of u(p) = Σ uᵢpⁱ, v(p) = Σ vᵢpⁱ for p from 0 to `p1`, by 8-point
/// Gauss–Legendre quadrature on 16 panels (exact to ~1e-12 relative for the smooth speeds of
/// road cubics).
pub(crate) fn cubic_length(u: &[f64; 4], v: &[f64; 4], p1: f64) -> f64 {
    const NODES: [(f64, f64); 4] = [
        (0.183_434_642_495_649_8, 0.362_683_783_378_362),
        (0.525_532_409_916_329, 0.313_706_645_877_887_3),
        (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
        (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
    ];
    let panels = 16;
    let h = p1 / panels as f64;
    let mut total = 0.0;
    for i in 0..panels {
        let mid = (i as f64 + 0.5) * h;
        for (x, w) in NODES {
            for p in [mid - x * h / 2.0, mid + x * h / 2.0] {
                let (_, du, _) = cubic(u, p);
                let (_, dv, _) = cubic(v, p);
                total += w * h / 2.0 * (du * du + dv * dv).sqrt();
            }
        }
    }
    total
}

#[cfg(test)]
mod tests;
