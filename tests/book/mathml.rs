//! The book's MathML, read back as XML from every page that `ladder book` writes (issue 39):
//!
//! * every script, fraction and root has the number of child elements its MathML element takes
//!   (`msup`, `msub`, `mfrac`, `munder`, `mover`, `mroot`: 2; `msubsup`, `munderover`: 3). A
//!   three-child `msup` is how "sin² θ" came out drawn as "sin2";
//! * no text a reader sees is markup or an entity: `<!--`, `-->`, a tag such as `<b>`, or an
//!   entity left escaped (`&nbsp;`, `&amp;`, `&#160;` in the text after one round of XML
//!   unescaping), outside `<code>`/`<pre>` and the pages of Rust source.
//!
//! Both checks are shown to fail on a planted three-child `msup` and a planted visible `<!--`.

use crate::built::book;
use quick_xml::events::Event;
use quick_xml::Reader;
use std::path::{Path, PathBuf};

/// How many child elements a MathML element takes, for those with a fixed count.
fn arity(name: &str) -> Option<usize> {
    match name {
        "msup" | "msub" | "mfrac" | "munder" | "mover" | "mroot" => Some(2),
        "msubsup" | "munderover" => Some(3),
        _ => None,
    }
}

/// Markup or an entity in text that a reader sees (already unescaped once by the parser).
fn visible_markup(text: &str) -> Option<String> {
    for m in ["<!--", "-->"] {
        if text.contains(m) {
            return Some(format!("the comment marker `{m}`"));
        }
    }
    for (i, c) in text.char_indices() {
        let rest = &text[i + c.len_utf8()..];
        if c == '<' && rest.starts_with(|n: char| n.is_ascii_alphabetic() || n == '/') {
            let tag: String = text[i..].chars().take(12).collect();
            return Some(format!("a tag `{tag}`"));
        }
        if c == '&' {
            let name: String = rest
                .chars()
                .take_while(|n| n.is_ascii_alphanumeric() || *n == '#')
                .collect();
            if !name.is_empty() && rest[name.len()..].starts_with(';') {
                return Some(format!("the entity `&{name};`"));
            }
        }
    }
    None
}

/// Every problem of one page (`name` for the messages), as `name: (N): message` where the
/// problem sits inside numbered display N.
fn check_page(name: &str, src: &str, code_page: bool) -> (Vec<String>, usize) {
    let mut problems = Vec::new();
    let mut reader = Reader::from_str(src);
    reader.config_mut().check_end_names = true;
    // Open elements: (name, child elements so far, the display number it opens, if any).
    let mut stack: Vec<(String, usize, Option<String>)> = Vec::new();
    let mut maths = 0;
    let mut text = String::new();
    let here = |stack: &[(String, usize, Option<String>)]| {
        stack
            .iter()
            .rev()
            .find_map(|(_, _, n)| n.as_ref())
            .map(|n| format!("({n}): "))
            .unwrap_or_default()
    };
    loop {
        let ev = match reader.read_event() {
            Ok(ev) => ev,
            Err(e) => {
                problems.push(format!("{name}: not well-formed: {e}"));
                break;
            }
        };
        if !matches!(ev, Event::Text(_) | Event::GeneralRef(_)) && !text.is_empty() {
            let in_code = stack.iter().any(|(n, _, _)| n == "code" || n == "pre");
            if let Some(what) = visible_markup(&text).filter(|_| !code_page && !in_code) {
                let snippet: String = text.trim().chars().take(50).collect();
                problems.push(format!(
                    "{name}: {}visible markup, {what}: `{snippet}`",
                    here(&stack)
                ));
            }
            text.clear();
        }
        match ev {
            Event::Eof => break,
            Event::Start(ref e) | Event::Empty(ref e) => {
                let tag = String::from_utf8_lossy(e.name().as_ref()).to_string();
                if let Some(parent) = stack.last_mut() {
                    parent.1 += 1;
                }
                maths += usize::from(tag == "math");
                if matches!(ev, Event::Empty(_)) {
                    if arity(&tag).is_some() {
                        problems.push(format!("{name}: {}empty <{tag}/>", here(&stack)));
                    }
                    continue;
                }
                let number = e
                    .try_get_attribute("data-number")
                    .ok()
                    .flatten()
                    .map(|a| String::from_utf8_lossy(&a.value).to_string());
                stack.push((tag, 0, number));
            }
            Event::End(_) => {
                let Some((tag, children, _)) = stack.pop() else {
                    break;
                };
                if let Some(want) = arity(&tag).filter(|&w| w != children) {
                    problems.push(format!(
                        "{name}: {}<{tag}> with {children} children, takes {want}",
                        here(&stack)
                    ));
                }
            }
            // quick-xml reports `&name;` apart from the text around it: join them into the text
            // the reader sees, checked when the run ends (at the next tag).
            Event::Text(t) => match t.decode() {
                Ok(d) => text.push_str(&d),
                Err(e) => problems.push(format!("{name}: text not UTF-8: {e}")),
            },
            Event::GeneralRef(r) => {
                let entity = String::from_utf8_lossy(&r).to_string();
                match quick_xml::escape::unescape(&format!("&{entity};")) {
                    Ok(c) => text.push_str(&c),
                    Err(_) => problems.push(format!(
                        "{name}: {}undefined entity &{entity};",
                        here(&stack)
                    )),
                }
            }
            _ => {}
        }
    }
    (problems, maths)
}

/// Every page of the book in `dir`: the problems and the number of `<math>` elements read.
fn check_book(dir: &Path) -> (Vec<String>, usize) {
    fn walk(dir: &Path, base: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, base, out);
            } else if p.extension().is_some_and(|x| x == "html") {
                out.push(p.strip_prefix(base).unwrap().to_path_buf());
            }
        }
    }
    let mut files = Vec::new();
    walk(dir, dir, &mut files);
    files.sort();
    let (mut problems, mut maths) = (Vec::new(), 0);
    for f in files {
        let src = std::fs::read_to_string(dir.join(&f)).unwrap();
        let (p, m) = check_page(&f.display().to_string(), &src, f.starts_with("code"));
        problems.extend(p);
        maths += m;
    }
    (problems, maths)
}

#[test]
fn every_script_has_its_children_and_no_markup_shows_as_text() {
    let (problems, maths) = check_book(book());
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // Not vacuous: the 95 numbered displays and the errata forms at least were read.
    assert!(maths > 95 + 3 * 5, "only {maths} <math> elements read");
}

/// The squares of the torque expansions, e.g. `l^2 \sin^2 \theta` in (16), are two-child
/// scripts with "sin" as the base.
#[test]
fn the_squared_sines_of_the_torque_expansions_are_scripts_of_sin() {
    let page = std::fs::read_to_string(book().join("02-point-a.html")).unwrap();
    for f in ["sin", "cos"] {
        assert!(
            page.contains(&format!("<msup><mi>{f}</mi><mn>2</mn></msup>")),
            "no {f}² drawn as a script of {f}"
        );
    }
}

#[test]
fn a_planted_three_child_msup_or_visible_comment_fails_the_check() {
    let src = std::fs::read_to_string(book().join("02-point-a.html")).unwrap();
    assert!(check_page("02-point-a.html", &src, false).0.is_empty());
    let plant = |from: &str, to: &str| {
        let bad = src.replacen(from, to, 1);
        assert!(bad != src, "the plant `{from}` changed nothing");
        check_page("02-point-a.html", &bad, false).0
    };
    // The defect as the renderer made it: a thin space as the first child of the msup.
    let p = plant(
        "<msup><mi>sin</mi>",
        "<msup><mspace width=\"0.1667em\" /><mi>sin</mi>",
    );
    assert!(
        p.iter()
            .any(|p| p.contains("<msup> with 3 children, takes 2")),
        "{p:?}"
    );
    // A harness marker shown as text, as the pages of 2.2-2.6 had it.
    let p = plant("<p>", "<p>&lt;!-- worked-example 16 --&gt; ");
    assert!(
        p.iter().any(|p| p.contains("comment marker `<!--`")),
        "{p:?}"
    );
    // An entity escaped twice, as (68)'s difference had it, and an undefined entity.
    let p = plant("<mo>=</mo>", "<mtext>&amp;nbsp;</mtext><mo>=</mo>");
    assert!(p.iter().any(|p| p.contains("`&nbsp;`")), "{p:?}");
    let p = plant("<mo>=</mo>", "<mtext>&nbsp;</mtext><mo>=</mo>");
    assert!(p.iter().any(|p| p.contains("undefined entity")), "{p:?}");
    // A fraction with one child.
    let p = plant("<mfrac><mrow>", "<mfrac><mrow></mrow><mrow>");
    assert!(
        p.iter().any(|p| p.contains("<mfrac> with 3 children")),
        "{p:?}"
    );
}
