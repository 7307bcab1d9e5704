//! Tests of `sliding_ladder::show::state` (src/show/state.rs).

use sliding_ladder::scalar::Rational;
use sliding_ladder::show::at::parse_at;
use sliding_ladder::show::state::build;

#[test]
fn the_energy_and_the_motion_complete_the_state() {
    let p = build(&parse_at("m=2, l=3/4, g=10, sin_theta=3/5").unwrap());
    // θ̇² = (3·10/1.5)(1 − 4/5) = 4.
    let (_, s) = p.exact.clone().expect("exact");
    assert_eq!(s.rate, Rational::from_integer(2.into()));
    // θ̈ = (3g/4l) sin θ = 10 · 3/5 = 6.
    assert_eq!(s.accel, Rational::from_integer(6.into()));
    assert_eq!(p.float.1.accel, 6.0);
    // From rest at 10°: θ̇ smaller than from upright.
    let up = build(&parse_at("theta=40deg").unwrap());
    let ten = build(&parse_at("theta=40deg, theta0=10deg").unwrap());
    assert!(ten.float.1.rate < up.float.1.rate && ten.float.1.rate > 0.0);
    assert!(up.exact.is_none() && up.summary.why_not_exact.is_some());
    // A given θ̈ is kept (off the motion).
    let off = build(&parse_at("theta=40deg, theta_ddot=0").unwrap());
    assert_eq!(off.float.1.accel, 0.0);
    assert!(!off.summary.on_motion);
}

#[test]
fn past_separation_the_state_warns_that_the_wall_would_pull() {
    // From rest upright the top leaves the wall at cos θ = 2/3, θ = 48.19°.
    let sep = (2.0f64 / 3.0).acos().to_degrees();
    let before = build(&parse_at("theta=40deg").unwrap()).summary.phase;
    assert!(before.warnings.is_empty(), "{:?}", before.warnings);
    assert!(before.phase.starts_with("phase 1"), "{}", before.phase);
    let past = build(&parse_at("theta=60deg").unwrap()).summary.phase;
    assert!(past.wall_force < 0.0);
    assert!(past.phase.starts_with("past separation"), "{}", past.phase);
    assert!(past.phase.contains("θ = 48.19°"), "{}", past.phase);
    assert!((past.separation.unwrap().to_degrees() - sep).abs() < 1e-9);
    assert_eq!(past.warnings.len(), 1);
    assert!(
        past.warnings[0].starts_with("F_w = -"),
        "{:?}",
        past.warnings
    );
    // Released at 30°, 48.19° is still on the wall (separation at acos((2/3) cos 30°) = 54.7°).
    let later = build(&parse_at("theta=50deg, theta0=30deg").unwrap())
        .summary
        .phase;
    assert!(
        later.warnings.is_empty() && later.phase.contains("θ = 54.74°"),
        "{}",
        later.phase
    );
    // A θ̇ given on the motion is traced back to its release: θ̇² = (3g/2l)(1 − cos θ) is
    // the release from upright, so 60° is past separation again.
    let w = (1.5f64 * 9.81 * (1.0 - 60f64.to_radians().cos())).sqrt();
    let given = build(&parse_at(&format!("theta=60deg, theta_dot={w}")).unwrap());
    assert!(
        given.summary.phase.phase.contains("θ0 = 0°"),
        "{}",
        given.summary.phase.phase
    );
    // A θ̈ that needs the floor to pull: θ̈ large and positive at a low angle.
    let pull = build(&parse_at("theta=80deg, theta_dot=0, theta_ddot=100").unwrap());
    assert!(pull
        .summary
        .phase
        .warnings
        .iter()
        .any(|w| w.starts_with("F_f = -")));
}
