//! The Rust side of the displays: every chain function of the registry (generic over the scalar,
//! instantiated in every scalar type), under the name a section writes in its `*Rust:*` list.
//!
//! Each module of checks lists its functions with [`named_fns!`](crate::named_fns), which takes the function's
//! own identifier: the compiler checks that it exists and has the shape of its model, and the
//! name the markdown uses is that identifier, so the two cannot drift. Every name in the
//! markdown must be in this table (else the section is a `file:line` error) and every function
//! in the table must be named by some section (a test).

use super::sample::{LadderSample, ParticleSample, PrintSample};
use super::{Check, Eval, Fns};

/// The states a ladder or floor-phase check is evaluated at, by the name the markdown uses.
pub const LADDER_SAMPLES: &[(&str, LadderSample)] = &[
    ("kinematic", LadderSample::Kinematic),
    ("on-shell", LadderSample::OnShell),
    ("on-shell-from-rest", LadderSample::OnShellFromRest),
];

/// The particle systems a particle check is evaluated on, by the name the markdown uses.
pub const PARTICLE_SAMPLES: &[(&str, ParticleSample)] = &[
    ("general", ParticleSample::General),
    ("p-at-cm", ParticleSample::PAtCm),
    ("p-fixed", ParticleSample::PFixed),
    ("p-at-origin", ParticleSample::PAtOrigin),
    ("cm-at-origin-p-at-cm", ParticleSample::CmAtOriginPAtCm),
    ("force-free", ParticleSample::ForceFree),
    ("torque-free", ParticleSample::TorqueFree),
    ("rolling-about-p", ParticleSample::RollingAboutP),
    ("planar-rigid", ParticleSample::PlanarRigid),
];

/// Every chain function of the registry, by name.
pub fn table() -> impl Iterator<Item = &'static (&'static str, Fns)> {
    super::ladder_eqs::FNS
        .iter()
        .chain(super::general_eqs::FNS)
        .chain(super::jensen_eqs::FNS)
        .chain(super::milne_eqs::MOMENTUM_FNS)
        .chain(super::milne_eqs::MOVING_FNS)
        .chain(super::milne_eqs::RATES_FNS)
        .chain(super::floor_eqs::FNS)
}

/// The chain function named `name`.
pub fn lookup(name: &str) -> Option<Fns> {
    table().find(|(n, _)| *n == name).map(|(_, f)| *f)
}

fn names<T>(list: &[(&str, T)]) -> String {
    list.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
}

/// The check a `*Rust:*` item names: function `function` at states `sample`, called `name`.
pub fn check_of(function: &str, sample: &str, name: &'static str) -> Result<Check, String> {
    let f = lookup(function)
        .ok_or_else(|| format!("`{function}` is not a chain function of the registry"))?;
    let ladder = || LADDER_SAMPLES.iter().find(|s| s.0 == sample).map(|s| s.1);
    let particles = || PARTICLE_SAMPLES.iter().find(|s| s.0 == sample).map(|s| s.1);
    let eval = match f {
        Fns::Ladder(f) => ladder().map(|s| Eval::Ladder(s, f)),
        Fns::Floor(f) => ladder().map(|s| Eval::Floor(s, f)),
        Fns::Particles(f) => particles().map(|s| Eval::Particles(s, f)),
    };
    let allowed = match f {
        Fns::Ladder(_) | Fns::Floor(_) => names(LADDER_SAMPLES),
        Fns::Particles(_) => names(PARTICLE_SAMPLES),
    };
    let eval = eval.ok_or_else(|| {
        format!("`{function}` is evaluated at states {allowed}; '{sample}' is none of them")
    })?;
    Ok(Check { name, eval })
}

/// The states a print alone is evaluated at, by the name of a `*States:*` line.
pub fn print_states(name: &str) -> Result<PrintSample, String> {
    let ladder = LADDER_SAMPLES.iter().find(|s| s.0 == name);
    let particles = PARTICLE_SAMPLES.iter().find(|s| s.0 == name);
    match (ladder, particles) {
        (Some(s), _) => Ok(PrintSample::Ladder(s.1)),
        (_, Some(s)) => Ok(PrintSample::Particles(s.1)),
        _ => Err(format!(
            "*States:* '{name}' is none of {}, {}",
            names(LADDER_SAMPLES),
            names(PARTICLE_SAMPLES)
        )),
    }
}
