//! The momentum output measures something (issue 17, item 4): the horizontal momentum balance
//! m Ẋ_end − m Ẋ_0 = ∫F_w dt of the whole fall (the wall force (14) is the only horizontal
//! force), evaluated on the integrated motion. It used to be |Ẋ_end − Ẋ_s| / |Ẋ_s| over the floor
//! phase, which every method reports as exactly 0 (Ẍ = 0 is built into the floor equations).
//!
//! **Error model:** the state is good to 10 N τ relative (N steps, tolerance τ), and Ẋ, the
//! impulse are of size m √(g l) (m = l = 1, g = 9.81 here: √g), so the balance is within
//! 10 N τ √g · 4 (Ẋ_end, Ẋ_0, the impulse, and the quadrature on the dense output) + rounding.
//! **It can fail:** explicit Euler at step 1e-3 (first order, energy error 1e-3) breaks the
//! balance by far more than DOP853's bound, and a balance with the wall's impulse left out is
//! off by the whole momentum at separation.

use sliding_ladder::sim::fall;
use sliding_ladder::sim::scene;

const G: f64 = 9.81;

fn run(theta0: f64, method: &str, control: &str) -> fall::Outcome {
    let text = format!(
        "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = {G}\n[start]\nangle = {theta0}\nangular_velocity = 0.0\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"{method}\"\n{control}\n[end]\nat = \"flat\"\n[outputs]\nwant = [\"momentum_error\", \"flat_state\"]\n"
    );
    let sc = scene::parse("momentum.toml", &text).unwrap();
    fall::run(&sc, fall::MAX_STEPS).unwrap()
}

#[test]
fn the_momentum_balance_holds_to_the_error_model_and_catches_a_first_order_method() {
    for theta0 in [0.3, 1.2] {
        let o = run(theta0, "dop853", "tolerance = 1e-14");
        let n = (o.work.wall.steps + o.work.floor.unwrap().steps) as f64;
        let bound = 4.0 * (10.0 * n * 1e-14 + 4.0 * f64::EPSILON) * G.sqrt();
        let e = o.momentum_error.unwrap();
        println!("dop853 θ0 = {theta0}: {e:e} (bound {bound:e})");
        assert!(e <= bound, "{e:e} > {bound:e}");
        // The same check on explicit Euler fails, by orders of magnitude.
        let euler = run(theta0, "euler", "step = 1e-3").momentum_error.unwrap();
        println!("euler θ0 = {theta0}: {euler:e}");
        assert!(euler > 1e3 * bound, "{euler:e}");
        // Without the wall's impulse the balance would be off by m Ẋ_end itself.
        let vx = o.flat.unwrap().centre_velocity_x;
        assert!(vx.abs() > 1e6 * bound, "{vx}");
    }
}

/// Campaign seed 1, scene 995 (the Taylor method at tolerance 3.4e-16 on a subnormal start with
/// a push, to flat): its few long wall-phase steps (up to three times other methods' cap) once
/// took the wall's impulse by one 5-point rule each and missed it by 2.9e-13, above the judge's
/// bound of 2.0e-13 (`sim::fall::observer::impulse_pieces` now resolves the quadrature by the
/// motion). The judge's own check, on the outcome as the campaign makes it.
#[test]
fn the_taylor_method_meets_the_judges_momentum_bound_on_campaign_scene_995() {
    use sliding_ladder::report::campaign::judge::out_of_tolerance;
    let text = "[ladder]\nmass = 9.747692118443467e-8\nhalf_length = 2.1347904560355113e18\ngravity = 9.57698820050432e-7\n[start]\nangle = 2.2675337567e-314\nangular_velocity = 2.53723876632668e-13\n[contact]\nmodel = \"rigid\"\n[integrator]\nmethod = \"taylor\"\ntolerance = 3.4403496339676883e-16\n[end]\nat = \"flat\"\n[outputs]\nwant = [\"separation_time\", \"momentum_error\", \"final_state\"]\n";
    let sc = scene::parse("campaign-1-995.toml", text).unwrap();
    let o = fall::run(&sc, fall::MAX_STEPS).unwrap();
    println!("momentum error {:e}", o.momentum_error.unwrap());
    let bad = out_of_tolerance(&sc, &o);
    assert!(bad.is_empty(), "{bad:?}");
}
