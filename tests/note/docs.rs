//! Tests of `sliding_ladder::docs`.

mod pages;
