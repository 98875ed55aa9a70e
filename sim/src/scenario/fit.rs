//! Least-squares circle through a set of points: the turn radius of the `circle` scenario.

/// A fitted circle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Centre (m).
    pub center: [f64; 2],
    /// Radius (m).
    pub radius: f64,
    /// Root-mean-square distance of the points from the circle (m).
    pub rms_residual: f64,
}

/// Solves the 3×3 system `a·x = b` by Gaussian elimination with partial pivoting; `None` if
/// it is singular (to working precision).
fn solve3(mut a: [[f64; 3]; 3], mut b: [f64; 3]) -> Option<[f64; 3]> {
    let scale = a.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    for col in 0..3 {
        let pivot = (col..3).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() <= 1e-14 * scale {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..3 {
            let f = a[row][col] / a[col][col];
            let pivot_row = a[col];
            for (x, p) in a[row].iter_mut().zip(pivot_row).skip(col) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; 3];
    for row in (0..3).rev() {
        let tail: f64 = (row + 1..3).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - tail) / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Adds `w·wᵀ` to `m` and `w·r` to `v` (accumulating normal equations).
fn accumulate(m: &mut [[f64; 3]; 3], v: &mut [f64; 3], w: [f64; 3], r: f64) {
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] += w[i] * w[j];
        }
        v[i] += w[i] * r;
    }
}

/// Fits a circle to `points` (m): the algebraic fit of Kåsa (1976) on centred coordinates as
/// the start, refined by Gauss–Newton on the geometric distances, which removes the algebraic
/// fit's bias on short arcs.
///
/// Returns `None` for fewer than 3 points, non-finite points, or points on a line.
///
/// ```
/// use sim::scenario::fit_circle;
/// let pts: Vec<[f64; 2]> = (0..50)
///     .map(|i| {
///         let a = i as f64 * 0.05;
///         [3.0 + 10.0 * a.cos(), -2.0 + 10.0 * a.sin()]
///     })
///     .collect();
/// let c = fit_circle(&pts).unwrap();
/// assert!((c.radius - 10.0).abs() < 1e-9);
/// ```
pub fn fit_circle(points: &[[f64; 2]]) -> Option<Circle> {
    if points.len() < 3 || points.iter().flatten().any(|v| !v.is_finite()) {
        return None;
    }
    let n = points.len() as f64;
    let mean = [
        points.iter().map(|p| p[0]).sum::<f64>() / n,
        points.iter().map(|p| p[1]).sum::<f64>() / n,
    ];
    // Kåsa: x² + y² + D·x + E·y + F = 0 in least squares (centred coordinates).
    let mut m = [[0.0; 3]; 3];
    let mut v = [0.0; 3];
    for p in points {
        let (x, y) = (p[0] - mean[0], p[1] - mean[1]);
        accumulate(&mut m, &mut v, [x, y, 1.0], -(x * x + y * y));
    }
    let [d, e, f] = solve3(m, v)?;
    let (mut a, mut b) = (-d / 2.0, -e / 2.0);
    let mut r = (a * a + b * b - f).sqrt();
    if !r.is_finite() {
        return None;
    }
    // Gauss–Newton on rᵢ = |pᵢ − c| − R.
    for _ in 0..50 {
        let mut m = [[0.0; 3]; 3];
        let mut v = [0.0; 3];
        for p in points {
            let (dx, dy) = (p[0] - mean[0] - a, p[1] - mean[1] - b);
            let dist = dx.hypot(dy);
            if dist == 0.0 {
                continue;
            }
            let residual = dist - r;
            accumulate(&mut m, &mut v, [-dx / dist, -dy / dist, -1.0], -residual);
        }
        let Some(step) = solve3(m, v) else { break };
        a += step[0];
        b += step[1];
        r += step[2];
        if step.iter().map(|s| s.abs()).fold(0.0, f64::max) <= 1e-12 * r.abs().max(1.0) {
            break;
        }
    }
    let rms = (points
        .iter()
        .map(|p| ((p[0] - mean[0] - a).hypot(p[1] - mean[1] - b) - r).powi(2))
        .sum::<f64>()
        / n)
        .sqrt();
    (r.is_finite() && r > 0.0).then_some(Circle {
        center: [a + mean[0], b + mean[1]],
        radius: r,
        rms_residual: rms,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arc(cx: f64, cy: f64, r: f64, from: f64, to: f64, n: usize) -> Vec<[f64; 2]> {
        (0..n)
            .map(|i| {
                let t = from + (to - from) * i as f64 / (n - 1) as f64;
                [cx + r * t.cos(), cy + r * t.sin()]
            })
            .collect()
    }

    #[test]
    fn exact_circle_far_from_origin() {
        // Full circle of radius 14.78 m (BmwX5 at δ = 0.2 rad: 2.995/tan 0.2) 1 km away.
        let c = fit_circle(&arc(1000.0, -500.0, 14.78, 0.0, 6.2, 400)).unwrap();
        assert!((c.radius - 14.78).abs() < 1e-8, "{c:?}");
        assert!((c.center[0] - 1000.0).abs() < 1e-8 && (c.center[1] + 500.0).abs() < 1e-8);
        assert!(c.rms_residual < 1e-8);
    }

    #[test]
    fn short_noisy_arc_is_unbiased() {
        // A 60° arc with ±2 cm alternating radial noise: the radius comes out within a quarter
        // of the noise, and the residual is the noise.
        let mut pts = arc(0.0, 0.0, 20.0, 0.3, 0.3 + 1.047, 301);
        for (i, p) in pts.iter_mut().enumerate() {
            let s = if i % 2 == 0 { 1.02 } else { 0.98 };
            let k = (20.0 + (s - 1.0)) / 20.0;
            p[0] *= k;
            p[1] *= k;
        }
        let c = fit_circle(&pts).unwrap();
        assert!((c.radius - 20.0).abs() < 5e-3, "{c:?}");
        assert!((c.rms_residual - 0.02).abs() < 1e-3);
    }

    #[test]
    fn degenerate_inputs() {
        assert!(fit_circle(&[[0.0, 0.0], [1.0, 1.0]]).is_none());
        assert!(fit_circle(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]).is_none());
        assert!(fit_circle(&[[0.0, 0.0], [1.0, f64::NAN], [2.0, 0.0]]).is_none());
    }
}
