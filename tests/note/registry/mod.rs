//! `sliding_ladder::registry`: every display's checks at random states, exact points, proofs and units.

mod check;
mod complete;
mod exact_point;
mod fns;
mod identities;
mod law;
mod markdown_alone;
mod milne;
mod modular;
mod perturbation;
mod prove;
mod sample;
mod source;
mod source_fuzz;
mod twins;
mod units;
