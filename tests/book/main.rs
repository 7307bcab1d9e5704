//! The book (`equations/*.md` and `ladder book`): its pages, its doc-as-test checks, the errata
//! and units pages held against the code (`cargo test --test book`).

mod about;
mod built;
mod check;
mod chromium;
mod code;
#[path = "../common/mod.rs"]
mod common;
mod derivations;
mod docs;
mod errata_doc;
mod harness;
mod markdown;
mod math;
mod mathml;
mod pages;
mod problems;
mod reader;
mod refs;
mod terms;
mod units_doc;
mod write;
