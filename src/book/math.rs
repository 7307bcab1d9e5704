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
const FN_SPACE: &str = "<mspace width=\"0.1667em\" />";

/// The thin space pulldown-latex 0.8.0 (the newest release) writes before a function name such
/// as `\sin` when it follows an ordinary atom (TeX's Ord–Op space) is written *inside* the
/// script element when the function is a script's base: `l^2 \sin^2 \theta` comes out as
/// `<msup><mspace/><mi>sin</mi><mn>2</mn></msup>`, three children where `msup` takes two, which
/// Chromium does not draw as a script: the page read "sin2". The renderer checks for a script
/// context only *after* writing the space (`Content::Function` in its `mathml.rs`), and the
/// event stream offers no way to suppress it, so the space is moved here to where TeX puts it:
/// before the scripted operator, `<mspace/><msup><mi>sin</mi><mn>2</mn></msup>`.
fn space_before_scripted_function(mut out: String) -> String {
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

    /// The first child elements of the first `tag` element of `m` (by a plain tag count: the
    /// renderer's output has no comments or CDATA).
    fn children_of_first(m: &str, tag: &str) -> Vec<String> {
        let start = m.find(&format!("<{tag}>")).expect(tag) + tag.len() + 2;
        let (mut depth, mut names, mut i) = (0, Vec::new(), start);
        while let Some(o) = m[i..].find('<').map(|o| o + i) {
            let end = m[o..].find('>').unwrap() + o;
            let t = &m[o + 1..end];
            if let Some(closing) = t.strip_prefix('/') {
                if depth == 0 {
                    assert_eq!(closing, tag);
                    return names;
                }
                depth -= 1;
            } else {
                if depth == 0 {
                    names.push(t.split([' ', '/']).next().unwrap().to_string());
                }
                if !t.ends_with('/') {
                    depth += 1;
                }
            }
            i = end + 1;
        }
        panic!("unclosed <{tag}> in {m}")
    }

    #[test]
    fn a_squared_function_after_an_ordinary_atom_is_a_two_child_script() {
        // After an Ord (l²) the renderer adds the thin space; it must stand before the msup.
        for (latex, tag) in [
            (r"l^2 \sin^2 \theta", "msup"),
            (r"m \cos_1 \theta", "msub"),
            (r"x \cos_1^2 \theta", "msubsup"),
        ] {
            let m = mathml(latex, true).unwrap();
            let kids = children_of_first(&m, tag);
            let want = if tag == "msubsup" { 3 } else { 2 };
            assert_eq!(kids.len(), want, "{latex}: {kids:?} in {m}");
            assert_eq!(kids[0], "mi", "{latex}: {m}");
            assert!(m.contains(&format!("{FN_SPACE}<{tag}>")), "{latex}: {m}");
        }
        // At the start (no Ord before it) there is no space to move, and none is added.
        let m = mathml(r"\sin^2 \theta", true).unwrap();
        assert_eq!(children_of_first(&m, "msup"), ["mi", "mn"], "{m}");
        assert!(!m.contains("<mspace width=\"0.1667em\" /><msup>"), "{m}");
    }

    #[test]
    fn the_unfixed_renderer_output_has_three_children_so_the_test_can_fail() {
        let bad = "<math><mi>l</mi><msup><mspace width=\"0.1667em\" /><mi>sin</mi><mn>2</mn></msup></math>";
        assert_eq!(children_of_first(bad, "msup").len(), 3);
        let fixed = space_before_scripted_function(bad.to_string());
        assert_eq!(children_of_first(&fixed, "msup"), ["mi", "mn"], "{fixed}");
        // A space that is not a script's first child stays where it is.
        let plain = "<math><mi>a</mi><mspace width=\"0.1667em\" /><mi>b</mi></math>";
        assert_eq!(space_before_scripted_function(plain.to_string()), plain);
    }

    #[test]
    fn a_no_break_space_is_a_space_not_the_text_nbsp() {
        for latex in [r"a,\ b", "a~b"] {
            let m = mathml(latex, false).unwrap();
            assert!(!m.contains("nbsp"), "{latex}: {m}");
            assert!(m.contains("<mspace width=\"0.3333em\""), "{latex}: {m}");
        }
        // Without the mapping the renderer shows the entity as text: the mapping is needed.
        let storage = Storage::new();
        let mut raw = String::new();
        push_mathml(
            &mut raw,
            Parser::new("a~b", &storage),
            RenderConfig::default(),
        )
        .unwrap();
        assert!(raw.contains("&amp;nbsp;"), "{raw}");
        // A text's trailing blank is kept, as a character reference XML knows.
        let m = mathml(r"x, \text{Milne: } y", false).unwrap();
        assert!(
            m.contains("Milne:&#160;</mtext>") && !m.contains("&nbsp;"),
            "{m}"
        );
    }

    #[test]
    fn a_bad_command_or_unbalanced_brace_is_an_error() {
        assert!(mathml(r"\frac{1}{2", true).is_err());
        assert!(mathml(r"\notacommand x", false).is_err());
        assert!(mathml(r"\frac{1}{2}", false).is_ok());
    }
}
