//! The book (`equations/*.md` and `ladder book`): its pages, its doc-as-test checks, the errata
//! and units pages held against the code (`cargo test --test book`).

mod built;
mod check;
mod chromium;
#[path = "../common/mod.rs"]
mod common;
mod docs;
mod errata_doc;
mod harness;
mod mathml;
mod pages;
mod problems;
mod units_doc;
