//! The exact reference for phase one of the sliding ladder: both contacts hold, the ladder obeys
//! eq. (5) of the note, θ̈ = Ω² sin θ with Ω² = 3g/(4l), until the wall force vanishes.
//!
//! # Overview
//! [`PhaseOne::new`] takes a start (θ₀, θ̇₀) and Ω²; [`PhaseOne::separation`] returns the angle,
//! time and rate at which the wall lets go (footnote 4 of the note, generalised to a moving
//! start); [`PhaseOne::theta`] / [`PhaseOne::rate`] give θ(t), θ̇(t) and
//! [`PhaseOne::time_to_angle`] the inverse t(θ); [`PhaseOne::wall_force_per_ml`] the wall force
//! along the motion. Everything is closed form: Carlson's integral R_F
//! (from the `ellip` crate) for times, Jacobi's sn, cn, dn (hand-written in [`jacobi`], no crate
//! has them) for angles. All of it keeps full relative accuracy near the separatrix, where the
//! ladder starts almost upright and almost at rest (see the table below).
//!
//! # Derivation
//! **Energy.** Multiplying (5) by θ̇ and integrating from the start gives
//! θ̇² = θ̇₀² + 2Ω²(cos θ₀ − cos θ) (the note's (10) is the case θ₀ = θ̇₀ = 0). With half angles
//! s = sin(θ/2), c = cos(θ/2) and cos θ₀ − cos θ = 2(s² − s₀²),
//!
//!   θ̇² = 4Ω²(s² − a),   a = s₀² − ρ²,   ρ = θ̇₀/(2Ω).
//!
//! In pendulum terms (φ = π − θ, the ladder upright is the pendulum on top) a > 0 is a libration
//! whose turning point sin(θ_min/2) = √a lies at or before the start, a < 0 a rotation that passed
//! the top θ = 0 with θ̇ = 2Ω√(−a), and a = 0 the separatrix.
//!
//! **Separation.** From (6) and (8), F_w = m a_x = m l (cos θ θ̈ − sin θ θ̇²), and with (5) and the
//! energy, F_w = m l sin θ (Ω² cos θ − θ̇²) = m l sin θ (3Ω² cos θ − 2Ω² cos θ₀ − θ̇₀²). The bracket
//! falls as θ grows, so the wall lets go at
//!
//!   cos θ_s = (2/3) cos θ₀ + θ̇₀²/(3Ω²)        ([`separation_cos`]; footnote 4 when θ̇₀ = 0),
//!
//! unless the bracket is already ≤ 0 at the start (θ̇₀² ≥ Ω² cos θ₀: separation at t = 0, the start
//! returned as is). θ₀ = θ̇₀ = 0 is the equilibrium: no separation, `None`. In half angles
//! s_s² − s₀² = δ := (cos θ₀ − θ̇₀²/Ω²)/6 > 0, and at separation θ̇_s² = Ω² cos θ_s.
//!
//! **Time.** dt = dθ/θ̇ and dθ = 2 ds/c turn t(θ) into ∫ ds/(Ω√((1 − s²)(s² − a))), a cubic
//! elliptic integral in x = s². The reduction of DLMF §19.29(i) writes it between any two points
//! as one R_F with non-negative arguments ([`carlson_rf`], formula in the `carlson` submodule).
//!
//! **Angle.** Invert with Jacobi functions of modulus k (DLMF 22.2; derivatives DLMF 22.13.1–3).
//! For a > 0 put k'² = a, k² = 1 − a = c₀² + ρ² and u = Ω·(time since the turning point); then
//! sin(θ/2) = k'/dn(u), cos(θ/2) = k cn(u)/dn(u), θ̇ = 2Ω k k' sn(u)/dn(u). (Check: with
//! dn' = −k² sn cn, (ds/du)² = k'²k⁴sn²cn²/dn⁴ = (1 − s²)(s² − a).) For a < 0 put
//! k² = 1/(1 − a), k' = k√(−a), w = (Ω/k)·(time since θ = 0); then sin(θ/2) = k' sn(w)/dn(w),
//! cos(θ/2) = cn(w)/dn(w), θ̇ = 2Ω (k'/k)/dn(w) (same check with sd' = cn/dn²). In both cases the
//! quarter period K is reached at θ = π. The phase at the start (u₀, from the origin) and the
//! phase still to go to θ = π (v₀) are both R_F values, so at time t the code knows u = u₀ + Ωt and
//! v = v₀ − Ωt = K − u and evaluates the Jacobi functions from the nearer end. For a = 0,
//! tan(θ/4) = tan(θ₀/4) e^{Ωt}.
//!
//! # Conditioning: where naive formulas lose digits, and what is done instead
//! * **k from k'.** Near the separatrix k' ~ θ₀/2 or θ̇₀/(2Ω); for θ₀ = 1e-8 the parameter
//!   m = k² = 1 − 2.5e-17 rounds to 1 and K(m) = ∞: every digit of the time is gone. Here k' is
//!   the input of the AGM (DLMF 22.20(ii) with b₀ = k') and k² = c₀² + ρ² is a sum, never 1 − k'².
//! * **a itself** is formed as (s₀ − ρ)(s₀ + ρ), not s₀² − ρ².
//! * **Legendre's F.** t = [F(ψ|k) − F(ψ₀|k)]/Ω with sin²ψ = (s² − k'²)/(k² s²) takes arcsin near 1
//!   (error √u in ψ) and subtracts two logarithmically large integrals. Carlson's two-point form
//!   has only sums of products of positive numbers, and R_F's relative condition is at most ½ in
//!   each argument: the time carries the relative errors of s, c, ρ, δ plus a few ulps.
//! * **The separation angle.** acos((2/3)cos θ₀ + …) loses half the digits when θ_s is small
//!   (near-immediate separation). Instead s_s² = s₀² + δ, θ_s = 2 atan2(s_s, c_s), and δ, the only
//!   small difference, is formed in double-double ([`twofold`]); θ̇_s = √(Ω² cos θ_s) with cos θ_s
//!   a sum of positive terms.
//! * **Jacobi functions.** Near the separatrix cn(u) and dn(u) fall to ~k' while u approaches K ~
//!   ln(4/k'); the amplitude method returns cn = cos φ with φ ≈ π/2 and loses the ratio u/cn. The
//!   ratio form of the descending Landen transformation (see [`jacobi`]) keeps relative accuracy,
//!   with the argument passed from the nearer end of [0, K].
//!
//! What remains is the conditioning of the problem itself. (i) θ(t) as a function of t has
//! relative condition t θ̇/θ, about ln(1/θ₀) near the separatrix: a 1-ulp change of t moves θ by
//! that many ulps. The error model of the tests is a time shift of at most 38u(2K/Ω + t) plus
//! relative errors 38u. (ii) With both θ₀ > 0 and θ̇₀ > 0 near the separatrix, a = s₀² − ρ² is a
//! small difference of inputs: the ½-ulp rounding of sin(θ₀/2) moves the times by about
//! (s₀²/|a|)·u/Ω. The code is exact for inputs perturbed by a few ulps (backward stable) but
//! cannot beat that condition. (iii) Starts with s₀ and ρ both below 1e-140 are rejected: their
//! squares would leave the normal range of f64.
//!
//! # Measured accuracy (tests/sim/exact/reference.rs, 31 starts, references from mpmath at 40 digits)
//! Ulps between f64 values: the reference rounded to f64 against the result (the time less the
//! allowance κu/Ω of the ill-conditioned starts); in parentheses, the distance from the
//! unrounded 25-digit reference in ulps (`tests/sim/exact/ulps.rs`, no allowance).
//! | quantity | max error | where |
//! |---|---|---|
//! | separation angle θ_s | 1 ulp (1.04 of the unrounded reference) | all starts |
//! | separation time t_s | 2 ulps (1.53 of the unrounded reference) | all starts, incl. θ₀ = 1e-12, θ̇₀/Ω = 1e-15, 0.999999 |
//! | separation rate θ̇_s | 1 ulp | all starts |
//! | θ(t_s/2), θ̇(t_s/2) | 12 ulps | condition t θ̇/θ ≤ 17.5 |
//! | θ(t_s/2), θ̇(t_s/2) | 56 ulps | θ₀ = θ̇₀ = 1e-6 (a cancels: κ = 2.4e13) |
//! | sn, cn, dn | 86 ulps | k' = 1e-100, u = 100 (condition u·sn·dn/cn = 100) |
//!
//! The textbook form F(ψ_s|1 − k'²)/Ω is off by 1.2e6 ulps at θ₀ = 1e-4, 7e13 ulps at 1e-8 and
//! infinite at 1e-12 (same test file).
//!
//! # References
//! * NIST DLMF, ch. 19 (19.2.4 Legendre's F, 19.8 AGM, 19.16.1 R_F, 19.26.18 duplication,
//!   §19.29(i) reduction to R_F) and ch. 22 (22.2, 22.6, 22.7.1–4 Landen, 22.13 derivatives,
//!   22.20(ii) AGM method).
//! * M. Abramowitz, I. A. Stegun, Handbook of Mathematical Functions (1964), 16.4 (AGM method for
//!   Jacobi functions) and 17.6.
//! * R. Bulirsch, Numerical calculation of elliptic integrals and elliptic functions, Numer.
//!   Math. 7 (1965) 78–90 (the ratio form of the Gauss transformation).
//! * B. C. Carlson, Numerical computation of real or complex elliptic integrals, Numer.
//!   Algorithms 10 (1995) 13–26 (the duplication algorithm `ellip` implements).
mod carlson;
pub mod flat;
pub mod jacobi;
pub mod near_flat;
mod phase_one;
pub mod twofold;

pub use carlson::carlson_rf;
pub use jacobi::{Agm, Arg, Jacobi};
pub use phase_one::{separation_cos, PhaseOne, Separation};
