//! The exact phase-one solution against 40-digit mpmath references (tests/sim/exact/mpmath.rs), its
//! scale invariance, its inputs, and proof that a perturbed formula fails the same checks.
use crate::exact::mpmath::{input_condition, ulps, JACOBI, SEPARATION, U};
use sliding_ladder::sim::exact::{separation_cos, Agm, Arg, PhaseOne, Separation};

/// Target of the issue: separation angle, time and rate within 4 ulps of the reference.
const TARGET_ULPS: f64 = 4.0;

fn phase(row: &[f64; 9]) -> PhaseOne {
    PhaseOne::new(row[0], row[1], row[2]).expect("valid start")
}

/// Worst ulp errors (angle, time, rate) of `sep_of` over the table, with the time allowance
/// κu/Ω of the ill-conditioned starts (see `input_condition`) removed before counting ulps.
fn worst_separation_ulps(sep_of: impl Fn(&[f64; 9]) -> Separation) -> [f64; 3] {
    let mut worst = [0.0f64; 3];
    for row in SEPARATION.iter() {
        let s = sep_of(row);
        let allowance = input_condition(row[0], row[1], row[2]) * U / row[2].sqrt();
        let time_err = ((s.time - row[4]).abs() - allowance).max(0.0);
        let errs = [
            ulps(s.angle, row[3]),
            ulps(row[4] + time_err, row[4]),
            ulps(s.rate, row[5]),
        ];
        for (w, e) in worst.iter_mut().zip(errs) {
            *w = w.max(e);
        }
    }
    worst
}

#[test]
fn separation_within_four_ulps_of_mpmath() {
    let worst = worst_separation_ulps(|row| phase(row).separation().expect("moves"));
    println!(
        "max ulps over {} starts: angle {}, time {}, rate {}",
        SEPARATION.len(),
        worst[0],
        worst[1],
        worst[2]
    );
    for (name, w) in ["angle", "time", "rate"].iter().zip(worst) {
        assert!(
            w <= TARGET_ULPS,
            "separation {name}: {w} ulps > {TARGET_ULPS}"
        );
    }
}

#[test]
fn separation_check_fails_for_wrong_omega() {
    // Ω·(1 + 1e-9): times scale by 1/Ω, so the check must see some 4e6 ulps.
    let worst = worst_separation_ulps(|row| {
        let big_omega2 = row[2] * (1.0 + 1e-9) * (1.0 + 1e-9);
        PhaseOne::new(row[0], row[1], big_omega2)
            .unwrap()
            .separation()
            .unwrap()
    });
    assert!(
        worst[1] > TARGET_ULPS,
        "a 1e-9 error in omega went unnoticed: {worst:?}"
    );
}

/// Error model for θ(t), θ̇(t): the phase u₀ + Ωt (or v₀ − Ωt), of size at most 2K plus Ωt, is
/// rounded to a few ulps, i.e. the state is the exact one at a time shifted by at most
/// C·u·(2K/Ω + t), on top of relative errors C·u in the Jacobi recurrence (≤ 4 roundings per
/// Landen level, ≤ 8 levels here, all on positive terms): C = 4·8 + 6 = 38.
fn theta_tolerance(p: &PhaseOne, t: f64, theta: f64, rate: f64, row: &[f64; 9]) -> (f64, f64) {
    const C: f64 = 38.0;
    let omega = row[2].sqrt();
    let shift = C * U * (2.0 * p.quarter_period() / omega + t)
        + input_condition(row[0], row[1], row[2]) * U / omega;
    let accel = row[2] * theta.sin();
    let jerk = row[2] * theta.cos() * rate;
    (
        C * U * theta + rate * shift,
        C * U * rate + (accel + jerk.abs()) * shift,
    )
}

#[test]
fn mid_course_state_matches_mpmath() {
    let (mut worst_theta, mut worst_rate) = (0.0f64, 0.0f64);
    for row in SEPARATION.iter() {
        let p = phase(row);
        let (theta, rate) = p.theta_rate(row[6]);
        let (tol_theta, tol_rate) = theta_tolerance(&p, row[6], row[7], row[8], row);
        assert!(
            (theta - row[7]).abs() <= tol_theta,
            "θ({}) for {row:?}: {theta}",
            row[6]
        );
        assert!(
            (rate - row[8]).abs() <= tol_rate,
            "θ̇({}) for {row:?}: {rate}",
            row[6]
        );
        worst_theta = worst_theta.max(ulps(theta, row[7]));
        worst_rate = worst_rate.max(ulps(rate, row[8]));
    }
    println!("theta(t_mid): max {worst_theta} ulps, rate(t_mid): max {worst_rate} ulps");
}

#[test]
fn mid_course_check_fails_for_wrong_modulus() {
    // k' off by one part in 1e6: the angle moves far beyond the error model, for every start
    // except those whose own condition (input_condition) already swamps 1e-6.
    let resolving = |row: &&[f64; 9]| row[4] > 0.0 && input_condition(row[0], row[1], row[2]) < 1e6;
    assert!(SEPARATION.iter().filter(resolving).count() >= 25);
    let caught = SEPARATION.iter().filter(resolving).all(|row| {
        let p = phase(row).with_modulus_factor(1.0 - 1e-6);
        let (theta, rate) = p.theta_rate(row[6]);
        let (tol_theta, tol_rate) = theta_tolerance(&p, row[6], row[7], row[8], row);
        (theta - row[7]).abs() > tol_theta || (rate - row[8]).abs() > tol_rate
    });
    assert!(
        caught,
        "a wrong modulus passed the mid-course check for some start"
    );
}

#[test]
fn time_to_separation_angle_is_separation_time() {
    for row in SEPARATION.iter().filter(|row| row[4] > 0.0) {
        let p = phase(row);
        let s = p.separation().unwrap();
        // θ_s is within 4 ulps (checked above); t(θ) turns that into 4 ulp(θ_s)/θ̇_s, and the
        // Carlson form adds a few ulps of t: the model is 8u·t + 4 ulp(θ_s)/θ̇_s.
        let ulp = f64::from_bits(s.angle.to_bits() + 1) - s.angle;
        let tol = 8.0 * U * s.time + 4.0 * ulp / s.rate;
        let t = p.time_to_angle(s.angle);
        assert!(
            (t - s.time).abs() <= tol,
            "{row:?}: t(θ_s) = {t}, t_s = {}",
            s.time
        );
    }
}

#[test]
fn jacobi_functions_match_mpmath() {
    let mut worst = 0.0f64;
    for &[kc, arg, quarter, k_ref, sn_ref, cn_ref, dn_ref] in JACOBI.iter() {
        let k2 = (1.0 - kc) * (1.0 + kc);
        let agm = Agm::new(kc, k2);
        let j = agm.eval(if quarter == 0.0 {
            Arg::FromZero(arg)
        } else {
            Arg::FromQuarter(arg)
        });
        // Model: relative error 38u (as above) plus the argument's own condition |arg|·|f'/f|,
        // with f' from DLMF 22.13.1–3 evaluated on the references.
        let k2r = 1.0 - kc * kc;
        let conds = [
            cn_ref * dn_ref / sn_ref,
            sn_ref * dn_ref / cn_ref,
            k2r * sn_ref * cn_ref / dn_ref,
        ];
        for ((got, want), cond) in [(j.sn, sn_ref), (j.cn, cn_ref), (j.dn, dn_ref)]
            .into_iter()
            .zip(conds)
        {
            let tol = (38.0 + 4.0 * arg.abs() * cond.abs()) * U * want.abs();
            assert!(
                (got - want).abs() <= tol,
                "k' = {kc}, arg = {arg}: {got} vs {want}"
            );
            worst = worst.max(ulps(got, want));
        }
        assert!(ulps(agm.quarter_period(), k_ref) <= TARGET_ULPS, "K({kc})");
    }
    println!("Jacobi sn, cn, dn: max {worst} ulps");
}

#[test]
fn scale_invariance_is_exact_for_powers_of_four() {
    // Ω² = 4^j makes Ω = 2^j exact: times must scale as 1/Ω bit for bit, angles not at all.
    for row in SEPARATION.iter().filter(|row| row[2] == 1.0) {
        let base = phase(row);
        let s1 = base.separation().unwrap();
        for j in [-3i32, -1, 1, 3] {
            let omega = 2f64.powi(j);
            let p = PhaseOne::new(row[0], row[1] * omega, omega * omega).unwrap();
            let s = p.separation().unwrap();
            assert_eq!(
                s.angle, s1.angle,
                "angle depends on omega: {row:?}, j = {j}"
            );
            assert_eq!(
                s.time * omega,
                s1.time,
                "time not 1/omega: {row:?}, j = {j}"
            );
            assert_eq!(s.rate / omega, s1.rate, "rate not omega: {row:?}, j = {j}");
            let t = 0.37 * s1.time;
            assert_eq!(
                p.theta(t / omega),
                base.theta(t),
                "theta(t) not scale free: {row:?}"
            );
        }
    }
}

#[test]
fn scale_check_fails_for_perturbed_omega() {
    let row = &SEPARATION[5];
    let s1 = phase(row).separation().unwrap();
    let p = PhaseOne::new(row[0], row[1] * 2.0, 4.0 * (1.0 + 2e-9)).unwrap();
    assert_ne!(p.separation().unwrap().time * 2.0, s1.time);
}

#[test]
fn equilibrium_never_separates_and_fast_starts_separate_at_once() {
    let rest = PhaseOne::new(0.0, 0.0, 1.0).unwrap();
    assert_eq!(rest.separation(), None);
    assert_eq!(rest.theta_rate(5.0), (0.0, 0.0));
    // θ̇₀² ≥ Ω² cos θ₀: the wall force m l sin θ (Ω² cos θ − θ̇²) is ≤ 0 at the start.
    for (theta0, rate0) in [
        (0.0, 1.0),
        (0.0, 1.5),
        (0.5, 0.5f64.cos().sqrt() * 1.0000001),
        (1.2, 3.0),
    ] {
        let s = PhaseOne::new(theta0, rate0, 1.0)
            .unwrap()
            .separation()
            .unwrap();
        assert_eq!(
            s,
            Separation {
                angle: theta0,
                time: 0.0,
                rate: rate0
            }
        );
        assert!(separation_cos(theta0, rate0, 1.0) >= theta0.cos());
    }
    // Just below the threshold the ladder still leans on the wall for a while.
    let s = PhaseOne::new(0.5, 0.5f64.cos().sqrt() * 0.9999999, 1.0)
        .unwrap()
        .separation()
        .unwrap();
    assert!(s.time > 0.0 && s.angle > 0.5);
}

#[test]
fn bad_starts_are_rejected_with_a_message() {
    let bad = [
        (f64::NAN, 0.0, 1.0),
        (-0.1, 0.0, 1.0),
        (std::f64::consts::FRAC_PI_2, 0.0, 1.0),
        (0.3, -1.0, 1.0),
        (0.3, f64::INFINITY, 1.0),
        (0.3, 0.0, 0.0),
        (0.3, 0.0, -1.0),
        (0.3, 0.0, f64::NAN),
        (1e-150, 1e-150, 1.0),
    ];
    for (theta0, rate0, big_omega2) in bad {
        let err = PhaseOne::new(theta0, rate0, big_omega2).expect_err("must be rejected");
        assert!(!err.is_empty() && !err.contains('\n'), "{err}");
    }
    assert!(PhaseOne::new(1e-130, 0.0, 1.0).is_ok());
}

#[test]
fn angle_at_separation_time_is_separation_angle() {
    // The Jacobi inversion (θ(t)) and the Carlson time (t_s) are separate code paths.
    let mut worst = 0.0f64;
    for row in SEPARATION.iter().filter(|row| row[4] > 0.0) {
        let p = phase(row);
        let s = p.separation().unwrap();
        let (theta, rate) = p.theta_rate(s.time);
        let (tol_theta, tol_rate) = theta_tolerance(&p, s.time, s.angle, s.rate, row);
        // plus the 4-ulp errors of θ_s and θ̇_s themselves
        let tol_theta = tol_theta + 4.0 * (f64::from_bits(s.angle.to_bits() + 1) - s.angle);
        let tol_rate = tol_rate + 4.0 * (f64::from_bits(s.rate.to_bits() + 1) - s.rate);
        assert!(
            (theta - s.angle).abs() <= tol_theta,
            "{row:?}: θ(t_s) = {theta} vs {}",
            s.angle
        );
        assert!(
            (rate - s.rate).abs() <= tol_rate,
            "{row:?}: θ̇(t_s) = {rate} vs {}",
            s.rate
        );
        worst = worst.max(ulps(theta, s.angle));
    }
    println!("theta(t_s) vs theta_s: max {worst} ulps");
}

#[test]
fn textbook_legendre_form_loses_the_digits_this_module_keeps() {
    // The conditioning claim of the module docs, measured: t_s = F(ψ_s|m)/Ω with m = 1 − k'²
    // and ψ_s from arcsin, for starts from rest, against the same references.
    let textbook = |theta0: f64| {
        let kp2 = (0.5 * theta0).sin().powi(2);
        let m = 1.0 - kp2;
        let s2 = 0.5 * (1.0 - 2.0 / 3.0 * theta0.cos());
        let psi = ((s2 - kp2) / (m * s2)).sqrt().asin();
        ellip::ellipf(psi, m).unwrap_or(f64::INFINITY)
    };
    for row in SEPARATION
        .iter()
        .filter(|row| row[1] == 0.0 && row[2] == 1.0 && row[0] <= 1e-4)
    {
        let naive = ulps(textbook(row[0]), row[4]);
        let ours = ulps(phase(row).separation().unwrap().time, row[4]);
        println!(
            "θ₀ = {:e}: textbook {naive:e} ulps, this module {ours} ulps",
            row[0]
        );
        assert!(naive > 1e3 && ours <= TARGET_ULPS);
    }
}

#[test]
fn wall_force_pushes_until_separation_and_pulls_after() {
    // F_w = m l sin θ (Ω² cos θ − θ̇²) (eqs. (5), (6), (8)) must be > 0 before t_s and < 0 after:
    // separation is the first and only sign change on the both-contacts motion.
    for row in SEPARATION
        .iter()
        .filter(|row| row[4] > 0.0 && row[0] + row[1] > 0.0)
    {
        let p = phase(row);
        let t_s = p.separation().unwrap().time;
        for frac in [0.01, 0.25, 0.5, 0.75, 0.99] {
            assert!(
                p.wall_force_per_ml(frac * t_s) > 0.0,
                "{row:?} at {frac} t_s"
            );
        }
        assert!(p.wall_force_per_ml(1.01 * t_s) < 0.0, "{row:?} after t_s");
    }
}

/// The wall force's size, not only its sign: from rest, the energy integral (9) gives
/// θ̇² = 2 Ω² (cos θ0 − cos θ), so F_w/(m l) = Ω² sin θ (3 cos θ − 2 cos θ0), eq. (14) over
/// m l. Checked at θ(t) from the closed form, without its rate. Error model: the terms are at
/// most 3 Ω², each with a few roundings (8 u), and the closed form's θ̇² is good to twice its
/// rate's 38 u (module docs of `exact::jacobi`): (8 · 5 + 2 · 38 · 2) u Ω². (Mutation testing:
/// `sin θ · (…)` → `sin θ / (…)`, which keeps the sign, went unseen.)
#[test]
fn wall_force_is_eq_14_on_the_closed_form() {
    for (theta0, big_omega2) in [(0.3, 0.75), (0.05, 7.3575), (1.2, 0.75)] {
        let p = PhaseOne::new(theta0, 0.0, big_omega2).unwrap();
        let t_s = p.separation().unwrap().time;
        for frac in [0.1, 0.4, 0.7, 0.95] {
            let t = frac * t_s;
            let theta = p.theta_rate(t).0;
            let want = big_omega2 * theta.sin() * (3.0 * theta.cos() - 2.0 * theta0.cos());
            let bound = (8.0 * 5.0 + 2.0 * 38.0 * 2.0) * U * big_omega2;
            let got = p.wall_force_per_ml(t);
            assert!(
                (got - want).abs() <= bound,
                "θ0 = {theta0}, t = {frac} t_s: {got} against {want}"
            );
        }
    }
}
