//! An independent reader of the book written by `ladder book`, for the tests: it parses every
//! page as XML (quick-xml: the pages are polyglot XHTML, so a page that is not well-formed is
//! itself a defect) and reports, as `file: message`,
//!
//! * a numbered display missing, doubled, without block MathML, or with a status, proof verdict
//!   or units verdict other than the one `ladder verify --json` gives (status and proof also in
//!   every summary-table row);
//! * an erratum listed on the errata page that `ladder verify` does not call an erratum, or the
//!   reverse;
//! * raw LaTeX left in the text of a page (a backslash command, `$$`, `^{`, `_{`), outside code;
//! * a `<merror>` (a formula the renderer could not read);
//! * a link or image that does not resolve: a missing file or a missing `id` for its fragment,
//!   and any stylesheet or image fetched from the network (the book must open offline).

use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// What `ladder verify --json` says: number → (status, proved), number → units, and the errata.
pub struct Expected {
    pub displays: BTreeMap<u32, (String, bool)>,
    pub units: BTreeMap<u32, String>,
    pub errata: BTreeSet<u32>,
}

/// Read the expectations from the JSON of `ladder verify --json`.
pub fn expected(verify: &serde_json::Value) -> Expected {
    let (mut displays, mut units) = (BTreeMap::new(), BTreeMap::new());
    for list in ["equations", "extensions"] {
        for e in verify[list].as_array().expect("a list of equations") {
            let n = e["number"].as_u64().expect("a number") as u32;
            units.insert(n, e["units"].as_str().expect("units").to_string());
            let s = e["status"].as_str().expect("a status").to_string();
            displays.insert(n, (s, e["proved"].as_bool().expect("proved")));
        }
    }
    let errata = displays
        .iter()
        .filter(|(n, (s, _))| **n < 1000 && s == "erratum")
        .map(|(n, _)| *n)
        .collect();
    Expected {
        displays,
        units,
        errata,
    }
}

#[derive(Default)]
struct Page {
    ids: BTreeSet<String>,
    /// (attribute, target, is a stylesheet or image)
    refs: Vec<(String, bool)>,
    /// (number, status, proved, has block math) of each display, and of each table row.
    displays: Vec<(u32, String, bool, bool)>,
    /// (number, data-units) of each display.
    units: Vec<(u32, Option<String>)>,
    rows: Vec<(u32, String, bool)>,
    errata: Vec<u32>,
    problems: Vec<String>,
}

fn attrs(e: &BytesStart) -> BTreeMap<String, String> {
    e.attributes()
        .filter_map(|a| a.ok())
        .map(|a| {
            let v = String::from_utf8_lossy(&a.value)
                .replace("&quot;", "\"")
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&amp;", "&");
            (String::from_utf8_lossy(a.key.as_ref()).to_string(), v)
        })
        .collect()
}

fn raw_latex(text: &str) -> Option<&'static str> {
    let b = text.as_bytes();
    if b.windows(2)
        .any(|w| w[0] == b'\\' && w[1].is_ascii_alphabetic())
    {
        return Some("a backslash command");
    }
    ["$$", "^{", "_{"].into_iter().find(|p| text.contains(p))
}

fn read_page(src: &str, code_page: bool) -> Page {
    let mut page = Page::default();
    let mut reader = Reader::from_str(src);
    reader.config_mut().check_end_names = true;
    // Open elements: (name, index into page.displays when it is a display).
    let mut stack: Vec<(String, Option<usize>)> = Vec::new();
    loop {
        let ev = match reader.read_event() {
            Ok(ev) => ev,
            Err(e) => {
                page.problems.push(format!(
                    "not well-formed at byte {}: {e}",
                    reader.buffer_position()
                ));
                break;
            }
        };
        match ev {
            Event::Eof => break,
            Event::Start(ref e) | Event::Empty(ref e) => {
                let name = String::from_utf8_lossy(e.name().as_ref()).to_string();
                let a = attrs(e);
                if let Some(id) = a.get("id") {
                    if !page.ids.insert(id.clone()) {
                        page.problems.push(format!("id {id} used twice"));
                    }
                }
                for key in ["href", "src"] {
                    if let Some(t) = a.get(key) {
                        let fetched = name == "img" || name == "link" || key == "src";
                        page.refs.push((t.clone(), fetched));
                    }
                }
                if name == "merror" {
                    page.problems
                        .push("a formula did not typeset (<merror>)".into());
                }
                if name == "math" && a.get("display").map(String::as_str) == Some("block") {
                    for (_, d) in stack.iter().rev() {
                        if let Some(i) = d {
                            page.displays[*i].3 = true;
                        }
                    }
                }
                if let Some(n) = a.get("data-erratum").and_then(|n| n.parse().ok()) {
                    page.errata.push(n);
                }
                let mut display = None;
                if let (Some(n), Some(s)) = (a.get("data-number"), a.get("data-status")) {
                    let n: u32 = n.parse().unwrap_or(0);
                    let proved = a.get("data-proved").map(String::as_str) == Some("true");
                    if name == "tr" {
                        page.rows.push((n, s.clone(), proved));
                    } else {
                        page.displays.push((n, s.clone(), proved, false));
                        page.units.push((n, a.get("data-units").cloned()));
                        display = Some(page.displays.len() - 1);
                    }
                }
                if matches!(ev, Event::Start(_)) {
                    stack.push((name, display));
                }
            }
            Event::End(_) => {
                stack.pop();
            }
            Event::Text(t) => {
                let in_code = stack.iter().any(|(n, _)| n == "code" || n == "pre");
                if !code_page && !in_code {
                    let text = String::from_utf8_lossy(&t).to_string();
                    if let Some(what) = raw_latex(&text) {
                        let snippet: String = text.trim().chars().take(60).collect();
                        page.problems
                            .push(format!("raw LaTeX left ({what}): `{snippet}`"));
                    }
                }
            }
            _ => {}
        }
    }
    page
}

fn html_files(dir: &Path, base: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let p = e.path();
        if p.is_dir() {
            html_files(&p, base, out);
        } else if p.extension().is_some_and(|x| x == "html") {
            out.push(p.strip_prefix(base).unwrap().to_path_buf());
        }
    }
}

/// Every problem of the book in `dir` against `expect`.
pub fn check(dir: &Path, expect: &Expected) -> Vec<String> {
    let mut files = Vec::new();
    html_files(dir, dir, &mut files);
    files.sort();
    let mut pages: BTreeMap<PathBuf, Page> = BTreeMap::new();
    let mut problems = Vec::new();
    for f in &files {
        let src = std::fs::read_to_string(dir.join(f)).unwrap_or_default();
        pages.insert(f.clone(), read_page(&src, f.starts_with("code")));
    }
    let mut seen: BTreeMap<u32, PathBuf> = BTreeMap::new();
    let mut errata = BTreeSet::new();
    for (f, page) in &pages {
        let name = f.display();
        problems.extend(page.problems.iter().map(|p| format!("{name}: {p}")));
        for (target, fetched) in &page.refs {
            if target.starts_with("http://")
                || target.starts_with("https://")
                || target.starts_with("//")
            {
                if *fetched {
                    problems.push(format!("{name}: {target} needs the network"));
                }
                continue;
            }
            let (path, frag) = target.split_once('#').unwrap_or((target, ""));
            let dest = if path.is_empty() {
                f.clone()
            } else {
                normalize(&f.parent().unwrap_or(Path::new("")).join(path))
            };
            if !dir.join(&dest).is_file() {
                problems.push(format!("{name}: link to {target}: no such file"));
            } else if !frag.is_empty() && !pages.get(&dest).is_some_and(|p| p.ids.contains(frag)) {
                problems.push(format!("{name}: link to {target}: no id {frag} there"));
            }
        }
        for (n, s, proved, math) in &page.displays {
            if let Some(first) = seen.insert(*n, f.clone()) {
                problems.push(format!(
                    "{name}: display {n} appears twice (also in {})",
                    first.display()
                ));
            }
            if !math {
                problems.push(format!("{name}: display {n} has no block MathML"));
            }
            match expect.displays.get(n) {
                Some((es, ep)) if es == s && ep == proved => {}
                Some((es, ep)) => problems.push(format!(
                    "{name}: display {n} says {s} (proved {proved}), ladder verify says {es} (proved {ep})"
                )),
                None => problems.push(format!("{name}: display {n} is not an equation ladder verify knows")),
            }
        }
        for (n, u) in &page.units {
            if expect.units.get(n) != u.as_ref() {
                problems.push(format!(
                    "{name}: display {n} says units {u:?}, ladder verify says {:?}",
                    expect.units.get(n)
                ));
            }
        }
        for (n, s, proved) in &page.rows {
            if expect.displays.get(n) != Some(&(s.clone(), *proved)) {
                problems.push(format!(
                    "{name}: table row {n} says {s} (proved {proved}), ladder verify disagrees"
                ));
            }
        }
        errata.extend(page.errata.iter().copied());
    }
    for n in expect.displays.keys() {
        if !seen.contains_key(n) {
            problems.push(format!("equation {n}: no display in the book"));
        }
    }
    if errata != expect.errata {
        problems.push(format!(
            "errata page lists {errata:?}, ladder verify says {:?}",
            expect.errata
        ));
    }
    problems
}

fn normalize(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            std::path::Component::ParentDir => {
                out.pop();
            }
            std::path::Component::CurDir => {}
            other => out.push(other),
        }
    }
    out
}
