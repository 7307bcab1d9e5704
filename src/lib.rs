//! sliding-ladder: the equations of "Torque Analyses of a Sliding Ladder" as checked code.
//!
//! # Map
//! * [`scalar`], [`vector`]: the number types every equation is evaluated in (f64 with num-dual
//!   derivatives, running error bounds, exact rationals, jets, degrees, physical dimensions) and 3-vectors over them.
//! * [`system`]: systems of particles and moving reference points, Appendix A (29)-(41).
//! * [`ladder`]: the note's ladder: geometry, energy, forces, torque analyses about A-E and any
//!   point, Jensen's methods; plus the three-particle model used as the independent reference.
//! * [`milne`]: Appendix B, Milne's names for ours.
//! * [`registry`]: one entry per display of the note, built from its section of the markdown
//!   `equations/*.md` (embedded in the binary), with its checks; [`verify`] runs them and lists
//!   the errata; [`docs`] holds the book's files, examples and figures against the code.
//! * [`derivation`]: the trait a new derivation of the equation of motion implements to be checked.
//! * [`sim`], [`report`]: the simulator (scenes, models, integrators, exact reference) and its
//!   reports (work-precision, plots).
//! * [`show`]: one display in depth (`ladder show N`); [`book`]: the note as verified, as a static
//!   HTML book (`ladder book`).
//! * [`cli`]: the `ladder` command, one file per subcommand; it calls into verify, sim and report.
//!
//! Dependencies flow one way, bottom to top (ARCHITECTURE.md, checked by `tests/architecture/main.rs`):
//! scalar → vector → system → ladder, milne, sim → print → registry → method, docs, verify →
//! report → show, book → cli; no two modules import each other. The physics modules know nothing of tests,
//! markdown or the command line.

pub mod book;
pub mod cli;
pub mod derivation;
pub mod docs;
pub mod ladder;
pub mod milne;
pub mod print;
pub mod registry;
pub mod report;
pub mod scalar;
pub mod show;
pub mod sim;
pub mod system;
pub mod vector;
pub mod verify;
