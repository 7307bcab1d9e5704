//! The integrators' step sizes are unit-free (issue 11, item 1): the initial step, the event
//! tolerances, the minimum steps and the step limits scale with T = √(l/g). The same scene at
//! m, l, g scaled by 1e±30 takes the same number of steps in each phase, evaluates the
//! right-hand side as often, and gives the same θ_s and t_s / T, t_flat / T to rounding.
//!
//! **Why this can fail.** The integrators keep constants that are absolute in the time unit
//! they are run in: the first-step heuristic `initial_step` (Hairer-Nørsett-Wanner's `hinit`)
//! falls back to h0 = 10⁻⁶ when the state barely moves on that unit, and its first step is
//! then at most 100 h0; the fixed-step methods refuse steps below 4 ε max(|t|, 1). The
//! simulator runs every rigid scene in units of T (`sim::scaled`), so those constants mean
//! 10⁻⁶ T and 4 ε T. [`an_absolute_step_scale_is_caught`] is the mutant: the same integrators
//! on the same wall phase, driven in seconds instead (the step scale T replaced by 1 s), fail
//! or take a different number of steps once T is far from 1 s, and the check below rejects
//! them; driven in units of T they pass it.
//!
//! Scales: (m, l, g) ∈ {1e−30, 1e30}³ beside m = l = 1, g = 9.81; and, for the bit-exact
//! mutant test, l = 2^±100 (≈ 1e±30) so that T is an exact power of two.

use sliding_ladder::sim::fall;
use sliding_ladder::sim::integrators::AnyStepper;
use sliding_ladder::sim::integrators::{is_adaptive, names, Control, Stepper};
use sliding_ladder::sim::rigid::WallPhase;

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::scene::output::Output;
use sliding_ladder::sim::scene::{ContactModel, End, Scene};

const U: f64 = f64::EPSILON / 2.0;

/// What must not depend on the scale: (steps of each phase, rhs evaluations, θ_s, t_s / T,
/// the end time / T).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Footprint {
    steps: [u64; 2],
    rhs_evals: u64,
    angle: f64,
    time: f64,
    end: f64,
}

/// Why footprints at several scales are not one, if they are not: step and evaluation counts
/// must be equal, angles and times / T within `ulps` ulps of the first.
fn differ(prints: &[Footprint], ulps: f64) -> Option<String> {
    let first = prints[0];
    let near = |a: f64, b: f64| (a - b).abs() <= ulps * U * b.abs();
    prints.iter().enumerate().find_map(|(i, p)| {
        let same = p.steps == first.steps
            && p.rhs_evals == first.rhs_evals
            && near(p.angle, first.angle)
            && near(p.time, first.time)
            && near(p.end, first.end);
        (!same).then(|| format!("scale {i}: {p:?} against {first:?}"))
    })
}

fn scales() -> Vec<Ladder<f64>> {
    let mut all = vec![Ladder {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    }];
    for k in 0..8 {
        let e = |bit: u32| if k >> bit & 1 == 1 { 1e30 } else { 1e-30 };
        all.push(Ladder {
            m: e(0),
            l: e(1),
            g: e(2),
        });
    }
    all
}

fn scene(ladder: Ladder<f64>, theta0: f64, method: &str, end: End) -> Scene {
    let unit = (ladder.l / ladder.g).sqrt();
    let control = match method {
        "exact" => None,
        m if is_adaptive(m) => Some(Control::Tolerance(1e-10)),
        // A fixed step of 1e-3 T, given in seconds as a scene's `step` is.
        _ => Some(Control::Fixed(1e-3 * unit)),
    };
    Scene {
        file: "(unit-free)".into(),
        ladder,
        theta0,
        phi0: None,
        rate0: 0.0,
        method: method.into(),
        control,
        order: None,
        end,
        outputs: vec![Output::SeparationAngle, Output::SeparationTime],
        contact: ContactModel::Rigid,
    }
}

/// The footprint of `scene` run as `ladder simulate` runs it.
fn simulated(scene: &Scene) -> Footprint {
    let unit = (scene.ladder.l / scene.ladder.g).sqrt();
    let o = fall::run(scene, fall::MAX_STEPS).expect("runs");
    let s = o.separation.expect("separates");
    let floor = o.work.floor.unwrap_or_default();
    Footprint {
        steps: [o.work.wall.steps, floor.steps],
        rhs_evals: o.work.wall.rhs_evals + floor.rhs_evals,
        angle: s.angle,
        time: s.time / unit,
        end: o.last.0 / unit,
    }
}

/// Every method, from rest at an ordinary angle, at a tiny one (the linear lead-in, taken in
/// SI) and next to the floor (the wall phase in the complement), to the separation and to flat:
/// one footprint at every scale.
#[test]
fn every_phase_takes_the_same_steps_at_every_scale() {
    let methods = names().chain(["exact"]);
    let mut checked = 0;
    for method in methods {
        for theta0 in [0.3, 1e-8, std::f64::consts::FRAC_PI_2 - 1e-9] {
            for end in [End::Separation, End::Flat] {
                if method == "exact" && end == End::Flat {
                    continue;
                }
                let prints: Vec<Footprint> = scales()
                    .into_iter()
                    .map(|l| simulated(&scene(l, theta0, method, end)))
                    .collect();
                // Results come back as t T, read here as (t T)/T: two roundings; a fixed step
                // given in seconds goes in as (h T)/T: two more, carried into the times ∝ h.
                if let Some(why) = differ(&prints, 4.0) {
                    panic!("{method} from θ0 = {theta0:e} to {end:?}: {why}");
                }
                checked += 1;
            }
        }
    }
    // Each integrator: 3 starts × 2 ends; the closed form: 3 starts, to the separation only.
    assert_eq!(checked, names().count() * 6 + 3);
}

/// θ and the steps taken when `method` integrates the wall phase of `ladder` from θ0 = 0.3 at
/// rest to t = 2 T (a time in the floor phase: the wall phase's equation continues there),
/// with its steps and the stop time in units of `step_scale` seconds.
fn wall_phase_in(ladder: &Ladder<f64>, method: &str, step_scale: f64) -> Result<Footprint, String> {
    let unit = (ladder.l / ladder.g).sqrt();
    // The model in units of `step_scale`: Ω² s², time running in step_scale seconds.
    let s = step_scale;
    let model = WallPhase::new(&Ladder {
        l: ladder.l / (s * s),
        ..*ladder
    });
    let control = match is_adaptive(method) {
        true => Control::Tolerance(1e-10),
        false => Control::Fixed(1e-3 * unit / s),
    };
    let mut stepper = AnyStepper::new(method, control, 0.0, [0.3, 0.0]).expect("a method");
    let t_end = 2.0 * unit / s;
    while stepper.t() < t_end {
        stepper
            .step(&model, t_end)
            .map_err(|e| format!("T = {unit:e} s: {e}"))?;
    }
    let st = stepper.stats();
    Ok(Footprint {
        steps: [st.steps, 0],
        rhs_evals: st.rhs_evals,
        angle: stepper.y()[0],
        time: stepper.t() * s / unit,
        end: stepper.y()[1] * unit / s,
    })
}

/// The mutant of the step scale: every method's integrator on the wall phase of ladders whose
/// T is 2^−50 s, 1 s and 2^50 s. Run in units of T (as the simulator runs it) the footprints
/// are bit-identical. Run in seconds, each method but Taylor's meets an absolute constant and
/// the check rejects it: the fixed-step methods refuse a step of 10⁻³ T = 9e-19 s as below
/// their floor 4 ε max(|t|, 1 s); dopri5, dop853 and radau5 choose a different first step
/// (`initial_step`'s h0 = 10⁻⁶ and its dimensionally inhomogeneous h1) and take a different
/// number of steps or evaluations.
#[test]
fn an_absolute_step_scale_is_caught() {
    let ladders: Vec<Ladder<f64>> = [-100, 0, 100]
        .map(|e: i32| Ladder {
            m: 1.0,
            l: 2f64.powi(e),
            g: 1.0,
        })
        .to_vec();
    for method in names() {
        let in_units: Vec<Footprint> = ladders
            .iter()
            .map(|l| wall_phase_in(l, method, (l.l / l.g).sqrt()))
            .collect::<Result<_, _>>()
            .unwrap_or_else(|e| panic!("{method} in units of T: {e}"));
        assert_eq!(differ(&in_units, 0.0), None, "{method} in units of T");
        let in_seconds: Result<Vec<Footprint>, String> = ladders
            .iter()
            .map(|l| wall_phase_in(l, method, 1.0))
            .collect();
        let caught = in_seconds.map_or_else(Some, |p| differ(&p, 8.0));
        // The Taylor method's step comes from its own series and its step floor is relative
        // to |t|: it alone is unit-free in any unit.
        assert_eq!(caught.is_some(), method != "taylor", "{method}: {caught:?}");
    }
}
