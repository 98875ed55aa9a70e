//! The small dense linear systems of the contact solve's blocks.

/// Solves an axle's tyre block `m·x = rhs` (unknowns: forward and lateral of one wheel, then
/// of its mirror image) in the wheels' mirror-symmetric and antisymmetric parts: for an axle in
/// a mirror-symmetric state the two parts decouple exactly, so the solution is the mirror image
/// of itself to the last bit and round-off cannot start a turn that the car would amplify (a
/// car whose driven wheels slide is yaw-unstable). Any other state is solved all the same:
/// the change of variables is exact and invertible.
#[inline]
pub(super) fn solve_mirrored(m: &[[f32; 4]; 4], rhs: &[f32; 4]) -> Option<[f32; 4]> {
    // Symmetric forward, symmetric lateral, antisymmetric forward, antisymmetric lateral parts
    // of a row (or a column) ordered forward 0, lateral 0, forward 1, lateral 1; the mirror
    // image of a lateral force is its negative. Each part adds two terms, so a value plus its
    // exact mirror image gives exactly 0.
    let parts = |v: [f32; 4]| [v[0] + v[2], v[1] - v[3], v[0] - v[2], v[1] + v[3]];
    // m·T, where x = T·y maps the parts y back to the forces x.
    let mt = m.map(parts);
    let mut reduced = [[0.0_f32; 4]; 4];
    for c in 0..4 {
        let column = parts([mt[0][c], mt[1][c], mt[2][c], mt[3][c]]);
        for (row, value) in reduced.iter_mut().zip(column) {
            row[c] = value;
        }
    }
    let [sf, sl, af, al] = solve4(reduced, parts(*rhs))?;
    Some([sf + af, sl + al, sf - af, al - sl])
}

/// Solves the 2×2 system `m·x = rhs`; `None` if singular.
#[inline]
pub(super) fn solve2(m: [[f32; 2]; 2], rhs: [f32; 2]) -> Option<[f32; 2]> {
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if !(det.is_finite() && det.abs() > f32::MIN_POSITIVE) {
        return None;
    }
    let x = [
        (rhs[0] * m[1][1] - m[0][1] * rhs[1]) / det,
        (m[0][0] * rhs[1] - m[1][0] * rhs[0]) / det,
    ];
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Solves the 4×4 system `m·x = rhs` by Gaussian elimination with partial pivoting; `None` if
/// singular.
#[inline]
pub(super) fn solve4(mut m: [[f32; 4]; 4], mut rhs: [f32; 4]) -> Option<[f32; 4]> {
    for col in 0..4 {
        let pivot = (col..4).max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs()))?;
        if m[pivot][col].abs() <= f32::MIN_POSITIVE || m[pivot][col].is_nan() {
            return None;
        }
        m.swap(col, pivot);
        rhs.swap(col, pivot);
        let pivot_row = m[col];
        for row in col + 1..4 {
            let factor = m[row][col] / pivot_row[col];
            for (value, p) in m[row].iter_mut().zip(pivot_row).skip(col) {
                *value -= factor * p;
            }
            rhs[row] -= factor * rhs[col];
        }
    }
    let mut x = [0.0_f32; 4];
    for row in (0..4).rev() {
        let tail: f32 = (row + 1..4).map(|k| m[row][k] * x[k]).sum();
        x[row] = (rhs[row] - tail) / m[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}
