//! Time over long runs (issue 38, item 4): a fixed-step method's time is t0 + n h, rounded
//! once (`integrators::fixed`), and the adaptive methods carry their time's rounding
//! (`integrators::adaptive::advance_time`). Before, both summed t + h, rounding at every step:
//! rk4's separation time from θ0 = 1e-4 at rest (g = l = 1) at h = 1e-4 T (112,529 steps) was
//! off by 1.15e-12 relative, radau5's at tolerance 1e-16 (27,758 steps) by 4.1e-13, while
//! both angles were within 7e-16 (measured on main's `ladder simulate`).
//!
//! **Error model.** At h = 1e-4 T rk4's truncation error, (h Ω)⁴ ≈ 6e-17, and at τ = 1e-16 ≈ u
//! radau5's local error, are at the rounding level: each step adds a few ulps of error that
//! leans no way, a random walk of n steps, 8 u √n relative (3e-13 and 1.5e-13 here). A time
//! summed step by step adds up to n half-ulps that lean one way.
use sliding_ladder::sim::exact::PhaseOne;
use sliding_ladder::sim::fall;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{Control, Stepper};
use sliding_ladder::sim::rigid::WallPhase;
use sliding_ladder::sim::scene;
use sliding_ladder::sim::units::UNIT_LADDER;

const U: f64 = f64::EPSILON / 2.0;

/// After n whole steps a fixed-step method's time is t0 + n h, rounded once: bit for bit. The
/// running sum is not (the check can fail): after 1e5 steps of 1e-4 it is hundreds of ulps off.
#[test]
fn a_fixed_step_time_is_on_its_grid() {
    let wall = WallPhase::new(&UNIT_LADDER);
    let (t0, h, n) = (0.25, 1e-4, 100_000u32);
    for method in ["rk4", "euler", "verlet", "symplectic-euler"] {
        let mut st = AnyStepper::new(method, Control::Fixed(h), t0, [1e-4, 0.0]).unwrap();
        let mut plain = t0;
        for k in 1..=n {
            st.step(&wall, 1e6).unwrap();
            plain += h;
            assert_eq!(st.t(), t0 + k as f64 * h, "{method}, step {k}");
        }
        let ulp = f64::EPSILON * st.t();
        assert!((plain - st.t()).abs() > 100.0 * ulp, "{method}: {plain}");
    }
}

fn separation_error(method: &str, control: &str) -> (f64, u64) {
    let text = format!(
        "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = 1.0\n[start]\nangle = 1e-4\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"{method}\"\n{control}\n[end]\nat = \"separation\"\n[outputs]\nwant = [\"separation_time\"]\n"
    );
    let sc = scene::parse("long.toml", &text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    let t_ref = PhaseOne::new(1e-4, 0.0, 0.75)
        .unwrap()
        .separation()
        .unwrap()
        .time;
    let t = o.separation.unwrap().time;
    ((t - t_ref).abs() / t_ref, o.work.wall.steps)
}

/// rk4 at h = 1e-4 T and radau5 at τ = 1e-16 from θ0 = 1e-4 at rest: the separation time
/// within the random walk 8 u √n of the closed form (`sim::exact`, 2 ulps).
#[test]
fn a_long_run_s_time_carries_no_drift() {
    for (method, control) in [("rk4", "step = 1e-4"), ("radau5", "tolerance = 1e-16")] {
        let (err, n) = separation_error(method, control);
        let bound = 8.0 * U * (n as f64).sqrt();
        assert!(n > 20_000, "{method}: {n} steps");
        assert!(
            err <= bound,
            "{method}: {err:.2e} over {n} steps, bound {bound:.2e}"
        );
    }
}
