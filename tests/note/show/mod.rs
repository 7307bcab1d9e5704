//! `sliding_ladder::show`: one display evaluated at a user's state.

mod states;
