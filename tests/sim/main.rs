//! The simulator (`sliding_ladder::sim`): integrators, events, the exact reference, the rigid,
//! constrained and penalty models, scenes and whole falls (`cargo test --test sim`).

#[path = "../common/mod.rs"]
mod common;
mod complement;
mod constrained;
mod event;
mod exact;
mod extreme;
mod fall;
mod floor;
mod impact;
mod integrators;
mod minimum;
mod near_release;
mod outcome;
mod penalty;
mod rigid;
mod run;
mod scaled;
mod scene;
mod start_margin;
mod trace;
mod units;
