//! `sim::penalty*`: the penalty (one-sided spring) contact model, its plan, start and confirmation.

mod confirm;
mod convergence;
mod energy;
mod estimate_margin;
mod plan;
mod refusals;
mod retry;
mod start;
mod sweep;
mod verlet_start;

use sliding_ladder::sim::penalty::{contact_forces, preloaded_start, Contact, Law};

/// The clipped law is the switched law's spring-dashpot κ p + γ ṗ where that pushes and the
/// spring is compressed, and zero elsewhere: the two laws' forces compared at states on
/// each side of both kinks, with damping, so the dashpot's sign shows (mutation testing:
/// f − (γ/κ) v in `one_sided` went unseen, no test ran the clipped law with a moving,
/// damped contact and looked at the force).
#[test]
fn the_clipped_law_is_the_switched_law_where_it_pushes() {
    let contact = Contact {
        kappa: 100.0,
        gamma: 3.0,
    };
    let mut active = 0;
    for (p, v) in [
        (0.02, 0.5),
        (0.02, -0.5),
        (0.02, -1.0),
        (-0.01, 0.5),
        (0.0, 2.0),
    ] {
        // y = [θ, f_w, f_f, θ̇, v_w, v_f] with f = κ p, v = κ ṗ (the module docs).
        let (f, rate) = (contact.kappa * p, contact.kappa * v);
        let y = [0.3, f, 0.5 * f, 0.1, rate, 0.5 * rate];
        let switched = contact_forces(&contact, Law::Switched, &y);
        let clipped = contact_forces(&contact, Law::OneSided, &y);
        for (s, c) in [(switched.0, clipped.0), (switched.1, clipped.1)] {
            if f > 0.0 && s > 0.0 {
                active += 1;
                assert_eq!(c, s, "p {p}, v {v}: pushing");
            } else {
                assert_eq!(c, 0.0, "p {p}, v {v}: not pushing ({s})");
            }
        }
    }
    assert!(active >= 4, "both branches are met");
}

/// The pre-loaded start puts the springs on the slow manifold whatever the damping: the
/// dashpot takes its share γ ṗ of the load and the spring the rest, so the force the
/// contact exerts, κ p + γ ṗ, and its rate κ ṗ are those of the undamped start (the rigid
/// motion's slow forces, set by the ladder and not by the contact law). Each force is a
/// sum of two terms, so they agree to a few ulps of |F| + (γ/κ)|Ḟ|. A moving start is
/// needed: at rest Ḟ = 0 and the split is empty (mutation testing: `f − (γ/κ) v` →
/// `f + (γ/κ) v` went unseen, every damped start was at rest).
#[test]
fn damping_splits_the_preloaded_force_but_does_not_change_it() {
    let undamped = Contact {
        kappa: 1e6,
        gamma: 0.0,
    };
    for (theta0, rate0, gamma) in [(0.6, 0.4, 1e3), (0.2, 0.1, 2e3), (1.1, 0.3, 50.0)] {
        let damped = Contact { gamma, ..undamped };
        let (y0, y1) = (
            preloaded_start(&undamped, theta0, rate0),
            preloaded_start(&damped, theta0, rate0),
        );
        let want = contact_forces(&undamped, Law::Switched, &y0);
        let got = contact_forces(&damped, Law::Switched, &y1);
        let split = gamma / damped.kappa;
        for (i, (w, g)) in [(want.0, got.0), (want.1, got.1)].into_iter().enumerate() {
            let rate = y0[4 + i];
            let tol = 4.0 * f64::EPSILON * (w.abs() + split * rate.abs());
            assert!(
                (g - w).abs() <= tol,
                "θ0 {theta0}, force {i}: {g} against {w} (tol {tol:e})"
            );
            assert_eq!(y1[4 + i], rate, "the spring's rate κ ṗ = Ḟ");
            // The check can fail: the dashpot's share is far above the tolerance.
            assert!(split * rate.abs() > 1e3 * tol, "force {i}: Ḟ = {rate}");
        }
    }
}
