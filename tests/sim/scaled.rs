//! A run fails in the scene's own units (`sim::scaled`); the error a user reads gives its times
//! and steps in seconds: times scene-unit values by T = √(l/g). Every kind of error is converted
//! (mutation testing of `src/sim`: NewtonFailed's time divided by T went unseen, since no run of
//! the tests makes radau5's Newton iteration fail on a scaled scene).

use sliding_ladder::ladder::Ladder;
use sliding_ladder::sim::integrators::StepError;
use sliding_ladder::sim::run::RunError;
use sliding_ladder::sim::scaled::Units;

/// l = 4 m, g = 1 m/s²: T = 2 s exactly, so each conversion is exact (a power of two).
fn units() -> Units {
    Units::of(&Ladder {
        m: 3.0,
        l: 4.0,
        g: 1.0,
    })
}

#[test]
fn every_run_error_gives_its_times_in_seconds() {
    let u = units();
    assert_eq!(u.time, 2.0);
    let step = |e| u.error_to_si(RunError::Step(e));
    assert_eq!(
        step(StepError::StepTooSmall { t: 3.0, h: 0.25 }),
        RunError::Step(StepError::StepTooSmall { t: 6.0, h: 0.5 })
    );
    assert_eq!(
        step(StepError::NotFinite { t: 3.0 }),
        RunError::Step(StepError::NotFinite { t: 6.0 })
    );
    assert_eq!(
        step(StepError::NewtonFailed { t: 3.0 }),
        RunError::Step(StepError::NewtonFailed { t: 6.0 })
    );
    assert_eq!(
        step(StepError::NoTaylorSeries { t: 3.0 }),
        RunError::Step(StepError::NoTaylorSeries { t: 6.0 })
    );
    assert_eq!(
        u.error_to_si(RunError::TooManySteps { limit: 7, t: 3.0 }),
        RunError::TooManySteps { limit: 7, t: 6.0 }
    );
    // An angle has no unit: only the time changes.
    assert_eq!(
        u.error_to_si(RunError::LiftOff { t: 3.0, theta: 0.5 }),
        RunError::LiftOff { t: 6.0, theta: 0.5 }
    );
    let start = RunError::Start("at equilibrium".into());
    assert_eq!(u.error_to_si(start.clone()), start);
}
