//! Two refusals of penalty scenes and the sweeps that set their thresholds:
//! * explicit methods whose tolerance exceeds the starting wall force (`sim::scene::work`,
//!   [`RESOLVED_WALL_FORCE`]): below it a run can end at a spurious zero of the wall force,
//!   above it none was seen;
//!   and its companion for θ0 = 0 with a push, where that force is 0 and only its rate
//!   Ḟ_w0 counts (`resolved_wall_force_rates`);
//! * springs softer than [`SOFTEST_CONTACT`] (`sim::scene::checks`): the foot lifts off first.
//!
//! The fast test shows runs on each side of the first (`tests/sim/scene/work.rs` of the second);
//! the sweeps run with `LADDER_SLOW=1 cargo test --profile test --test sim penalty::refusals`
//! (about a minute each on a quiet machine; the θ0 = 0 sweep took 457 s at a load of 11).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sliding_ladder::sim::integrators::Control;
use sliding_ladder::sim::penalty::confirm::{rigid_separation_angle, separation_bound};
use sliding_ladder::sim::penalty::run::separation;
use sliding_ladder::sim::penalty::{Contact, Law, OMEGA2};
use sliding_ladder::sim::scene::work::{
    resolved_wall_force_rates, starting_wall_force, wall_force_rate, RESOLVED_WALL_FORCE,
};
use sliding_ladder::sim::scene::SOFTEST_CONTACT;
use std::f64::consts::FRAC_PI_2;

/// What became of a run: separated within the bound, a spurious zero (the run's own check
/// against the rigid separation), the foot lifted off, or another stop (the step cap).
#[derive(Debug, PartialEq)]
enum Seen {
    Fine,
    Spurious,
    LiftOff,
    Other,
}

fn run(method: &str, contact: Contact, theta0: f64, rate0: f64, tol: f64, cap: u64) -> Seen {
    let r = separation(
        contact,
        Law::Switched,
        theta0,
        rate0,
        method,
        Control::Tolerance(tol),
        cap,
    );
    match r.result {
        Ok(_) => Seen::Fine,
        Err(e) if format!("{e:?}").contains("not resolved") => Seen::Spurious,
        Err(e) if format!("{e:?}").contains("LiftOff") => Seen::LiftOff,
        Err(_) => Seen::Other,
    }
}

/// dopri5 from θ0 = 1e-20 (F_w0 = 7e-10 m g at the lead-in's hand-over): at τ = 100 F_w0 the
/// wall force crosses zero within the first steps, far from the rigid separation, and again
/// at the second try's τ/10 = 10 F_w0 (`penalty::confirm::retry_control`; at τ = 10 F_w0 the
/// second try, at F_w0, resolves κ = 100); at the plan's limit τ = F_w0/40 each run separates
/// within the bound.
#[test]
fn a_tolerance_above_the_starting_wall_force_gives_a_spurious_zero_and_the_limit_does_not() {
    let (_, fw0) = starting_wall_force(1e-20, 0.0);
    for kappa in [1e2, 1e3, 1e4] {
        let contact = Contact { kappa, gamma: 0.0 };
        let seen = |tol| run("dopri5", contact, 1e-20, 0.0, tol, 100_000);
        assert_eq!(seen(100.0 * fw0), Seen::Spurious, "κ = {kappa}");
        assert_eq!(seen(fw0 / RESOLVED_WALL_FORCE), Seen::Fine, "κ = {kappa}");
    }
}

/// The sweep (module docs of `sim::scene::work`): random κ, γ, starts and pushes with τ around
/// F_w0; the largest F_w0/τ with a spurious zero must stay a factor 3 below the plan's limit.
#[test]
fn no_spurious_zero_within_a_factor_3_of_the_limit() {
    if std::env::var("LADDER_SLOW").is_err() {
        eprintln!("skipped: set LADDER_SLOW=1");
        return;
    }
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let (mut worst, mut above, mut fine) = (0.0f64, 0, 0);
    for _ in 0..3000 {
        let method = ["dopri5", "dop853"][rng.gen_range(0..2)];
        let kappa = 10f64.powf(rng.gen_range(0.5..9.0));
        let gamma = match rng.gen_bool(0.5) {
            true => 0.0,
            false => 10f64.powf(rng.gen_range(-3.0..1.0)) * kappa.sqrt(),
        };
        let theta0 = match rng.gen_range(0..3) {
            0 => 10f64.powf(rng.gen_range(-300.0..-9.0)),
            1 => 10f64.powf(rng.gen_range(-9.0..-1.0)),
            _ => FRAC_PI_2 - 10f64.powf(rng.gen_range(-9.0..-1.0)),
        };
        let rate0 = match rng.gen_bool(0.7) {
            true => 0.0,
            false => rng.gen_range(0.0..1.0) * (OMEGA2 * theta0.cos()).sqrt(),
        };
        let (_, fw0) = starting_wall_force(theta0, rate0);
        let ratio = 10f64.powf(rng.gen_range(-1.5..3.0));
        let tol = (fw0 / ratio).min(0.1);
        if tol < 1e-16 {
            continue;
        }
        let seen = run(
            method,
            Contact { kappa, gamma },
            theta0,
            rate0,
            tol,
            100_000,
        );
        if seen == Seen::Spurious {
            worst = worst.max(fw0 / tol);
        }
        if fw0 / tol >= RESOLVED_WALL_FORCE / 3.0 {
            above += 1;
            fine += usize::from(seen == Seen::Fine);
        }
    }
    eprintln!("largest F_w0/τ with a spurious zero: {worst:.2}; {fine} of {above} runs above the limit/3 separated");
    assert!(
        worst > 1.0,
        "the sweep found no spurious zero: it shows nothing"
    );
    assert!(worst < RESOLVED_WALL_FORCE / 3.0, "{worst}");
    assert!(fine * 10 >= above * 8, "{fine} of {above}");
}

/// The sweep of θ0 = 0 with a push (module docs of `sim::scene::work`, the campaign's F8):
/// random method, κ, γ and push, τ = Ḟ_w0/10^U(−1, 3.5); only starts whose separation is far
/// (the rule's own condition). For each method the largest Ḟ_w0/τ with a spurious zero must
/// stay a factor 3 below its [`RESOLVED_WALL_FORCE_RATE`]; it prints how many runs below the
/// limit (which the plan refuses) would have been fine: the rule's cost. Last run (seed 8):
/// dopri5 114 spurious zeros in 1,828 runs, the largest at 10.5; dop853 87 in 1,769, the
/// largest at 7.1 (its tail up to 1,164 needs the longer sweeps of the module docs).
#[test]
fn pushes_from_zero_give_no_spurious_zero_within_a_factor_3_of_the_limit() {
    if std::env::var("LADDER_SLOW").is_err() {
        eprintln!("skipped: set LADDER_SLOW=1");
        return;
    }
    let rates = resolved_wall_force_rates();
    assert_eq!(
        rates.len(),
        2,
        "the sweep below was set for dopri5 and dop853: {rates:?}"
    );
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    // Per method: (largest Ḟ_w0/τ with a spurious zero, spurious, runs, refused but fine).
    let mut seen = [(0.0f64, 0, 0, 0); 2];
    for _ in 0..4000 {
        let m = rng.gen_range(0..2);
        let (method, need) = rates[m];
        let kappa = 10f64.powf(rng.gen_range(0.7..10.0));
        let gamma = match rng.gen_bool(0.5) {
            true => 0.0,
            false => 10f64.powf(rng.gen_range(-3.0..1.0)) * kappa.sqrt(),
        };
        let rate0 = match rng.gen_bool(0.8) {
            true => 10f64.powf(rng.gen_range(-9.0..-0.3)),
            false => rng.gen_range(0.0..0.866),
        };
        let growth = wall_force_rate(0.0, rate0);
        let tol = growth / 10f64.powf(rng.gen_range(-1.0..3.5));
        let rigid = rigid_separation_angle(0.0, rate0);
        if !(1e-16..=0.1).contains(&tol) || rigid <= separation_bound(kappa, rigid, 1, tol) {
            continue;
        }
        let r = run(method, Contact { kappa, gamma }, 0.0, rate0, tol, 200_000);
        let s = &mut seen[m];
        s.2 += 1;
        if r == Seen::Spurious {
            s.0 = s.0.max(growth / tol);
            s.1 += 1;
        }
        s.3 += usize::from(r == Seen::Fine && growth / tol < need);
    }
    for (m, (worst, spurious, runs, fine_refused)) in seen.into_iter().enumerate() {
        let (method, need) = rates[m];
        eprintln!("{method}: {runs} runs, {spurious} spurious zeros, the largest at Ḟ_w0/τ = {worst:.3}; {fine_refused} runs below the limit {need} were fine");
        assert!(
            spurious > 0,
            "{method}: no spurious zero: the sweep shows nothing"
        );
        assert!(worst < need / 3.0, "{method}: {worst}");
    }
}

/// Random soft springs (κ = 1..10, γ = 0 or 1e-3..10 √κ) from tiny, ordinary and near-π/2
/// starts with pushes up to the wall's limit, radau5 at 1e-10: the foot lifts off at some
/// (κ ≤ 2.5 when the threshold was set), never above half of [`SOFTEST_CONTACT`].
#[test]
fn soft_springs_lift_the_foot_only_well_below_the_least_stiffness() {
    if std::env::var("LADDER_SLOW").is_err() {
        eprintln!("skipped: set LADDER_SLOW=1");
        return;
    }
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let (mut stiffest, mut lifted) = (0.0f64, 0);
    for _ in 0..6000 {
        let kappa = 10f64.powf(rng.gen_range(0.0..1.0));
        let gamma = match rng.gen_bool(0.7) {
            true => 0.0,
            false => 10f64.powf(rng.gen_range(-3.0..1.0)) * kappa.sqrt(),
        };
        let theta0 = match rng.gen_range(0..3) {
            0 => 10f64.powf(rng.gen_range(-300.0..-2.0)),
            1 => rng.gen_range(0.0..FRAC_PI_2),
            _ => FRAC_PI_2 - 10f64.powf(rng.gen_range(-9.0..-1.0)),
        };
        let rate0 = match rng.gen_bool(0.4) {
            true => 0.0,
            false => rng.gen_range(0.0..1.0f64).sqrt() * (OMEGA2 * theta0.cos()).sqrt(),
        };
        if run(
            "radau5",
            Contact { kappa, gamma },
            theta0,
            rate0,
            1e-10,
            1_000_000,
        ) == Seen::LiftOff
        {
            stiffest = stiffest.max(kappa);
            lifted += 1;
        }
    }
    eprintln!("{lifted} of 6000 runs lifted the foot, the stiffest at κ = {stiffest:.3}");
    assert!(lifted > 0, "no lift-off: the sweep shows nothing");
    assert!(stiffest < SOFTEST_CONTACT / 2.0, "{stiffest}");
}

/// `penalty::run::separation` itself refuses a stiffness that is not a positive finite number
/// (NaN, ∞, 0, negative) and the equilibrium θ0 = θ̇0 = 0, before any step, as a start error
/// naming the cause; the same start with a usable κ runs to its separation. (Mutation
/// testing: the stiffness guard's `&&` → `||` went unseen: scenes refuse such κ earlier, so
/// only a direct call reaches the run's own guard.)
#[test]
fn the_run_refuses_an_unusable_stiffness_and_the_equilibrium() {
    use sliding_ladder::sim::run::RunError;
    let start_error = |kappa: f64, theta0: f64| {
        let contact = Contact { kappa, gamma: 0.0 };
        let r = separation(
            contact,
            Law::Switched,
            theta0,
            0.0,
            "radau5",
            Control::Tolerance(1e-8),
            100_000,
        );
        match r.result {
            Err(RunError::Start(m)) => Some(m),
            _ => None,
        }
    };
    for kappa in [f64::NAN, f64::INFINITY, 0.0, -1e4] {
        let m = start_error(kappa, 0.3).unwrap_or_else(|| panic!("κ = {kappa} was run"));
        assert!(m.contains("is not usable"), "κ = {kappa}: {m}");
    }
    let m = start_error(1e4, 0.0).expect("the equilibrium was run");
    assert!(m.contains("equilibrium"), "{m}");
    assert_eq!(start_error(1e4, 0.3), None, "a usable κ runs");
}
