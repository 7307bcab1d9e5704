//! The floor phase's duration by quadrature of its conservation laws: an independent reference
//! for the flat time (the floor phase itself is beyond the note; `sim::floor`).
//!
//! In the scene's own units (m = l = g = 1, Ω² = 3/4) the floor phase keeps the centre's
//! horizontal velocity Ẋ = cos θ_s θ̇_s and the energy ½ Ẋ² + ½ (sin² θ + 1/3) θ̇² + cos θ, so
//! θ̇(θ)² = 2 (E' − cos θ)/(sin² θ + 1/3) with E' = ½ (sin² θ_s + 1/3) θ̇_s² + cos θ_s, and the
//! time from separation to flat is ∫ dθ/θ̇ over [θ_s, π/2]. With θ̇_s² = Ω² cos θ_s (the wall
//! force's zero) it depends on c = cos θ_s alone.
//!
//! The integral is taken in φ = π/2 − θ ∈ [0, φ_s], sin φ_s = c, where a start near the floor
//! keeps its relative precision (see `sim::complement`); the difference
//! E' − cos θ = ½ (cos² φ_s + 1/3) θ̇_s² plus 2 cos((φ_s + φ)/2) sin((φ_s − φ)/2) has no
//! cancellation. The integrand is smooth and
//! positive on the closed interval (θ̇ ≥ θ̇_s > 0), so adaptive Gauss-Legendre converges to
//! rounding. Written by hand: twenty lines of a textbook rule, where a quadrature crate would
//! be a dependency for one integral.

/// Ω² in the scene's units.
pub const OMEGA2: f64 = 0.75;
/// Points of the Gauss-Legendre rule.
const POINTS: usize = 10;

/// Nodes and weights of the `POINTS`-point Gauss-Legendre rule on [−1, 1] (Newton on P_n).
pub fn rule() -> ([f64; POINTS], [f64; POINTS]) {
    let n = POINTS;
    let (mut x, mut w) = ([0.0; POINTS], [0.0; POINTS]);
    for i in 0..n {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let k = k as f64;
                (p0, p1) = (p1, ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k);
            }
            dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() <= 1e-17 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// The Gauss-Legendre rule `r` (nodes, weights on [−1, 1], from [`rule`]) applied to `f` on [a, b].
pub fn gauss(f: &impl Fn(f64) -> f64, a: f64, b: f64, r: &([f64; POINTS], [f64; POINTS])) -> f64 {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    r.0.iter()
        .zip(&r.1)
        .map(|(x, w)| w * f(c + h * x))
        .sum::<f64>()
        * h
}

fn adaptive(
    f: &impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    whole: f64,
    depth: u32,
    r: &([f64; POINTS], [f64; POINTS]),
) -> f64 {
    let m = 0.5 * (a + b);
    let (left, right) = (gauss(f, a, m, r), gauss(f, m, b, r));
    let halves = left + right;
    if depth == 0 || (halves - whole).abs() <= 4.0 * f64::EPSILON * halves.abs() {
        return halves;
    }
    adaptive(f, a, m, left, depth - 1, r) + adaptive(f, m, b, right, depth - 1, r)
}

/// Time from separation to flat in units of √(l/g), for cos θ_s = `cos_s` in (0, 1].
pub fn floor_duration(cos_s: f64) -> f64 {
    let phi_s = cos_s.asin();
    let rate_s2 = OMEGA2 * cos_s;
    duration(phi_s, 0.5 * (1.0 - cos_s * cos_s + 1.0 / 3.0) * rate_s2)
}

/// Time to flat in units of √(l/g) of a floor phase that starts at φ = π/2 − θ = `phi_s` with
/// θ̇ = `rate_s` (per √(l/g)): a start at or past the release push leaves the wall at once with
/// its own rate, not the separation's θ̇_s² = Ω² cos θ_s (`sim::fall::wall_phase`).
pub fn floor_duration_from(phi_s: f64, rate_s: f64) -> f64 {
    let c = phi_s.cos();
    duration(phi_s, 0.5 * (c * c + 1.0 / 3.0) * rate_s * rate_s)
}

/// ∫ dφ/φ̇ over [0, φ_s] with the floor phase's kinetic energy ½ (sin² θ + 1/3) θ̇² = `kinetic`
/// at φ_s (module docs).
fn duration(phi_s: f64, kinetic: f64) -> f64 {
    let inverse_rate = |phi: f64| {
        let drop = 2.0 * (0.5 * (phi_s + phi)).cos() * (0.5 * (phi_s - phi)).sin();
        let c = phi.cos();
        ((c * c + 1.0 / 3.0) / (2.0 * (kinetic + drop))).sqrt()
    };
    let r = rule();
    adaptive(
        &inverse_rate,
        0.0,
        phi_s,
        gauss(&inverse_rate, 0.0, phi_s, &r),
        30,
        &r,
    )
}
