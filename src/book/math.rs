//! LaTeX to MathML, with pulldown-latex.
//!
//! Why pulldown-latex: it is a pure-Rust pull parser that renders MathML Core (what Chromium,
//! Firefox and Safari draw natively, with no JavaScript and no fonts to ship), and it reports
//! every construct it cannot parse as an error event instead of guessing. latex2mathml covers
//! less of amsmath (no `\hat{\mathbf{z}}` accents, no `\left( … \right)` stretch), and KaTeX or
//! MathJax would need a JavaScript engine at build or read time.

use pulldown_latex::config::DisplayMode;
use pulldown_latex::{push_mathml, Parser, RenderConfig, Storage};

/// Render `latex` as one `<math>` element (block or inline). Any parse error of the LaTeX is an
/// `Err` naming it: a display that does not typeset is a defect, never shown half-rendered.
pub fn mathml(latex: &str, block: bool) -> Result<String, String> {
    let storage = Storage::new();
    let mut errors = Vec::new();
    let events = Parser::new(latex, &storage)
        .inspect(|ev| {
            if let Err(e) = ev {
                errors.push(e.to_string());
            }
        })
        .collect::<Vec<_>>();
    if !errors.is_empty() {
        return Err(format!(
            "LaTeX does not parse: {} (in `{}`)",
            errors.join("; "),
            latex.trim()
        ));
    }
    let config = RenderConfig {
        display_mode: if block {
            DisplayMode::Block
        } else {
            DisplayMode::Inline
        },
        xml: true,
        ..RenderConfig::default()
    };
    let mut out = String::new();
    push_mathml(&mut out, events.into_iter(), config)
        .map_err(|e| format!("cannot render `{}`: {e}", latex.trim()))?;
    if out.contains("<merror") {
        return Err(format!("LaTeX renders as an error: `{}`", latex.trim()));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_display_of_the_note_renders() {
        for n in crate::registry::equations().iter().map(|e| e.number) {
            let m = mathml(crate::registry::printed_latex(n), true)
                .unwrap_or_else(|e| panic!("({n}): {e}"));
            assert!(
                m.starts_with("<math") && m.contains("display=\"block\""),
                "({n}): {m}"
            );
            assert!(!m.contains('\\'), "({n}) keeps raw LaTeX: {m}");
        }
    }

    #[test]
    fn a_bad_command_or_unbalanced_brace_is_an_error() {
        assert!(mathml(r"\frac{1}{2", true).is_err());
        assert!(mathml(r"\notacommand x", false).is_err());
        assert!(mathml(r"\frac{1}{2}", false).is_ok());
    }
}
