//! LaTeX to MathML, with pulldown-latex.
//!
//! Why pulldown-latex: it is a pure-Rust pull parser that renders MathML Core (what Chromium,
//! Firefox and Safari draw natively, with no JavaScript and no fonts to ship), and it reports
//! every construct it cannot parse as an error event instead of guessing. latex2mathml covers
//! less of amsmath (no `\hat{\mathbf{z}}` accents, no `\left( … \right)` stretch), and KaTeX or
//! MathJax would need a JavaScript engine at build or read time.

use pulldown_latex::config::DisplayMode;
use pulldown_latex::event::{Content, Dimension, DimensionUnit};
use pulldown_latex::{push_mathml, Event, Parser, RenderConfig, Storage};

/// A no-break space (`~`, a control space `\ `) as an explicit space of TeX's interword width.
/// pulldown-latex 0.8.0 parses them as the *text* `&nbsp;`, which its renderer then escapes, so
/// the page would show the characters "&nbsp;"; a `Space` event is drawn as `<mspace>`.
fn no_break_space_as_space(ev: Event<'_>) -> Event<'_> {
    match ev {
        Event::Content(Content::Text("&nbsp;")) => Event::Space {
            width: Some(Dimension::new(0.3333, DimensionUnit::Em)),
            height: None,
            depth: None,
        },
        other => other,
    }
}

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
    let events = events.into_iter().map(|ev| ev.map(no_break_space_as_space));
    push_mathml(&mut out, events, config)
        .map_err(|e| format!("cannot render `{}`: {e}", latex.trim()))?;
    if out.contains("<merror") {
        return Err(format!("LaTeX renders as an error: `{}`", latex.trim()));
    }
    // The renderer keeps a `\text{…}`'s leading or trailing blank as the HTML entity `&nbsp;`,
    // which XML does not define (the pages are polyglot XHTML): write the character reference.
    Ok(space_before_scripted_function(
        out.replace("&nbsp;", "&#160;"),
    ))
}

/// The thin space of TeX's Ord–Op spacing, as pulldown-latex writes it.
pub const FN_SPACE: &str = "<mspace width=\"0.1667em\" />";

/// The thin space pulldown-latex 0.8.0 (the newest release) writes before a function name such
/// as `\sin` when it follows an ordinary atom (TeX's Ord–Op space) is written *inside* the
/// script element when the function is a script's base: `l^2 \sin^2 \theta` comes out as
/// `<msup><mspace/><mi>sin</mi><mn>2</mn></msup>`, three children where `msup` takes two, which
/// Chromium does not draw as a script: the page read "sin2". The renderer checks for a script
/// context only *after* writing the space (`Content::Function` in its `mathml.rs`), and the
/// event stream offers no way to suppress it, so the space is moved here to where TeX puts it:
/// before the scripted operator, `<mspace/><msup><mi>sin</mi><mn>2</mn></msup>`.
pub fn space_before_scripted_function(mut out: String) -> String {
    const SCRIPTS: [&str; 6] = ["msup", "msub", "msubsup", "munder", "mover", "munderover"];
    let mut from = 0;
    while let Some(k) = out[from..].find(FN_SPACE).map(|k| k + from) {
        // The opening tag that ends right before the space, if it is a script element's.
        let open = out[..k]
            .strip_suffix('>')
            .and_then(|head| head.rfind('<'))
            .filter(|&o| {
                let name = out[o + 1..k - 1].split([' ', '>']).next().unwrap_or("");
                SCRIPTS.contains(&name)
            });
        match open {
            Some(o) => {
                out.replace_range(k..k + FN_SPACE.len(), "");
                out.insert_str(o, FN_SPACE);
                // A script that is itself the first child of a script: look again from here.
                from = o;
            }
            None => from = k + FN_SPACE.len(),
        }
    }
    out
}
