//! `ladder simulate`: bad scenes, random scenes, every method, the summary.

mod random_scenes;
mod scene_errors;
mod summary_digits;
mod taylor_every_scene;

use sliding_ladder::cli::simulate::run_error_code;
use sliding_ladder::sim::run::RunError;

/// The step limit is not bad input (it was exit 2): exit 1 like a run short of its end.
#[test]
fn the_step_limit_exits_1_and_an_unresolved_contact_2() {
    let limit = RunError::TooManySteps { limit: 10, t: 1.0 };
    assert_eq!(run_error_code(&limit), 1);
    assert_eq!(run_error_code(&RunError::LiftOff { t: 1.0, theta: 1.0 }), 1);
    assert_eq!(run_error_code(&RunError::Start("not resolved".into())), 2);
}
