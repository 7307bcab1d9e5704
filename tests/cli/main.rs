//! The `ladder` command as a user runs it: exit codes, stderr, files (`cargo test --test cli`).

mod animate;
mod broken_pipe;
#[path = "../common/mod.rs"]
mod common;
mod show;
mod simulate;
mod stability;
mod units;
mod work_precision;

/// Tests of `sliding_ladder::cli::reads_note`: the commands that read the note, and only those,
/// parse it at start-up.
mod reads_note {
    use clap::Parser;
    use sliding_ladder::cli::{reads_note, Cli};

    fn reads(args: &[&str]) -> bool {
        let cli = Cli::try_parse_from(args).expect("arguments parse");
        reads_note(&cli.command)
    }

    #[test]
    fn reads_note_for_the_note_commands_only() {
        for args in [
            &["ladder"][..],
            &["ladder", "verify"],
            &["ladder", "show", "25"],
            &["ladder", "errata"],
            &["ladder", "book", "--out", "b"],
        ] {
            assert!(reads(args), "{args:?} reads the note");
        }
        for args in [
            &["ladder", "simulate", "s.toml"][..],
            &["ladder", "stability"],
            &["ladder", "work-precision"],
            &["ladder", "animate", "s.toml", "--out", "a.svg"],
            &["ladder", "diagram"],
        ] {
            assert!(!reads(args), "{args:?} needs no note");
        }
    }
}
