//! Adding a method from outside the crate: torque analyses about two points the note never uses,
//! checked exactly like the note's own (random float states within an error bound, exact
//! rational points, on-shell and off-shell).
//!
//! Run: `cargo run --release --example midpoint_derivation` (exit code 1 if a check fails).

use sliding_ladder::derivation::{check_derivation, Derivation};
use sliding_ladder::ladder::analysis::{torque_equation, AngularMomentum, ReferencePoint};
use sliding_ladder::ladder::geometry::{corner_position, Corner};
use sliding_ladder::ladder::{Ladder, State};
use sliding_ladder::registry::check::Config;
use sliding_ladder::scalar::Scalar;
use sliding_ladder::vector::Vec3;
use std::process::ExitCode;

/// The midpoint of B (the centre of mass) and E (the instantaneous centre of rotation).
struct MidpointOfBAndE;

impl ReferencePoint for MidpointOfBAndE {
    fn position<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
        let b = corner_position(Corner::B, ladder, st);
        let e = corner_position(Corner::E, ladder, st);
        (b + e).scale(&T::ratio(1, 2))
    }
}

/// The foot of the perpendicular from the corner A to the ladder: C + ((A − C)·u) u with u the
/// unit vector from C to D. It slides along the ladder as the ladder falls.
struct FootOfPerpendicularFromA;

impl ReferencePoint for FootOfPerpendicularFromA {
    fn position<T: Scalar>(&self, ladder: &Ladder<T>, st: &State<T>) -> Vec3<T> {
        let c = corner_position(Corner::C, ladder, st);
        let u = Vec3::planar(st.sin.clone(), -st.cos.clone());
        let along = (Vec3::zero() - c.clone()).dot(&u);
        c + u.scale(&along)
    }
}

/// Torque analysis about the midpoint of B and E, with L_P and eq. (38).
#[derive(Default)]
struct AboutMidpointOfBAndE;

impl Derivation for AboutMidpointOfBAndE {
    const NAME: &'static str = "about the midpoint of B and E, L_P and (38)";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        let (lhs, rhs) = torque_equation(&MidpointOfBAndE, AngularMomentum::Absolute, l, s);
        lhs - rhs
    }
}

/// Torque analysis about the foot of the perpendicular from A, with L'_P and eq. (40).
#[derive(Default)]
struct AboutFootOfPerpendicular;

impl Derivation for AboutFootOfPerpendicular {
    const NAME: &'static str = "about the foot of the perpendicular from A, L'_P and (40)";
    fn residual<T: Scalar>(&self, l: &Ladder<T>, s: &State<T>) -> T {
        let (lhs, rhs) =
            torque_equation(&FootOfPerpendicularFromA, AngularMomentum::Relative, l, s);
        lhs - rhs
    }
}

fn report<M: Derivation>(cfg: &Config) -> bool {
    let mut ok = true;
    for r in check_derivation::<M>(cfg) {
        println!(
            "{:<58} {:<48} {} float cases (worst {:.3} error bounds), {} exact points, degree {} (Schwartz-Zippel ≤ {:.1e}){}: {}",
            M::NAME,
            r.name,
            r.float_cases,
            r.max_scaled_residual,
            r.exact_points,
            r.degree,
            r.sz_bound,
            match r.off_shell_fails {
                Some(true) => ", fails off shell",
                Some(false) => ", HOLDS OFF SHELL",
                None => "",
            },
            if r.passed() { "ok" } else { "FAILED" }
        );
        ok &= r.passed();
    }
    ok
}

fn main() -> ExitCode {
    let cfg = Config::default();
    let a = report::<AboutMidpointOfBAndE>(&cfg);
    let b = report::<AboutFootOfPerpendicular>(&cfg);
    if a && b {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
