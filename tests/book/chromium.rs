//! The book in a real browser (issue 39): headless Chromium lays out every page of
//! `ladder book` at 1280 px and a measuring script reports, for every display,
//!
//! * whether its formula is wider than its box (clipped, or scrolled, or pushing the equation
//!   number out of the column);
//! * whether its equation number is visible (inside the column);
//! * in a display of several lines (an `mtable`), whether the "=" that open its lines' second
//!   cells stand at one x (aligned, not centred).
//!
//! How: the book is copied, a harness page (`harness.html`, only in the copy) loads each page
//! into a 1280 px iframe, measures it, and writes the findings as JSON into its own DOM, which
//! `chromium --dump-dom` prints once the virtual time budget has run out. No WebDriver and no
//! crate beyond serde_json. Chromium is the Debian package `chromium` (the fonts that make the
//! widths reproducible: `fonts-dejavu-core`, `fonts-dejavu-extra`). Where it is missing the tests
//! say so and pass, except under `CI=true`, where a missing browser is a failure.
//!
//! Shown able to fail: a planted over-wide display, a planted hidden number and a display whose
//! alignment classes are stripped (lines centred again) are each reported.

use crate::built::book;
use crate::common::copy_dir;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The measuring script: for every `.display` of a page, its formula's width against its box,
/// the number's box against the column, and the x of each line-opening "=" of an aligned table.
const MEASURE: &str = r#"
function measure(doc) {
  const out = [];
  const col = doc.querySelector('main').getBoundingClientRect();
  doc.querySelectorAll('.display').forEach((d, k) => {
    const f = d.querySelector('.formula') || d;
    const m = f.querySelector('math');
    if (!m) return;
    const eq = d.closest('[data-number]');
    const no = d.querySelector('.eqno');
    const nr = no ? no.getBoundingClientRect() : null;
    const eqs = [];
    m.querySelectorAll('mtable > mtr > mtd:nth-child(2)').forEach(td => {
      const first = td.firstElementChild;
      if (first && first.localName === 'mo' && first.textContent.trim() === '=')
        eqs.push(first.getBoundingClientRect().left);
    });
    out.push({
      display: eq ? eq.getAttribute('data-number') : 'unnumbered ' + k,
      math: m.getBoundingClientRect().width,
      box: f.clientWidth,
      scroll: f.scrollWidth,
      right: d.getBoundingClientRect().right,
      col_right: col.right,
      number: nr ? [nr.left, nr.right, nr.width] : null,
      equals: eqs,
    });
  });
  return out;
}
async function run(pages) {
  const frame = document.getElementById('f');
  const results = {};
  for (const p of pages) {
    await new Promise(ok => { frame.onload = ok; frame.src = p; });
    try { results[p] = measure(frame.contentDocument); }
    catch (e) { results[p] = 'error: ' + e; }
  }
  document.getElementById('result').textContent = JSON.stringify(results);
}
"#;

/// The width of the window the pages are laid out in (a laptop's).
const WIDTH: u32 = 1280;

/// The Chromium binary, or why there is none.
fn chromium() -> Result<PathBuf, String> {
    let name = std::env::var("CHROMIUM").unwrap_or_else(|_| "chromium".into());
    let found = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|d| d.join(&name))
            .find(|p| p.is_file())
    });
    found.ok_or_else(|| format!("no `{name}` on PATH (Debian: apt-get install chromium)"))
}

/// Chromium, or `None` after saying why the test is skipped; under CI a missing browser fails.
fn browser_or_skip(test: &str) -> Option<PathBuf> {
    match chromium() {
        Ok(p) => Some(p),
        Err(why) if std::env::var("CI").as_deref() == Ok("true") => {
            panic!("{test}: CI=true and {why}")
        }
        Err(why) => {
            eprintln!("{test}: skipped, {why}");
            None
        }
    }
}

/// The book's pages of prose and mathematics (not the Rust source pages), sorted.
fn pages(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().to_string())
        .filter(|n| n.ends_with(".html") && n != "harness.html")
        .collect();
    v.sort();
    v
}

/// Lay out `pages` of the book copy `dir` in Chromium and return the measurements by page.
fn measure(browser: &Path, dir: &Path, pages: &[String]) -> serde_json::Map<String, Value> {
    let list = serde_json::to_string(pages).unwrap();
    let harness = format!(
        "<!DOCTYPE html><html><head><meta charset=\"utf-8\" /></head><body>\
<iframe id=\"f\" style=\"width:{WIDTH}px;height:900px;border:0\"></iframe><pre id=\"result\">pending</pre>\
<script>{MEASURE}\nrun({list});</script></body></html>"
    );
    std::fs::write(dir.join("harness.html"), harness).unwrap();
    let profile = dir.join("chromium-profile");
    let mut child = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--allow-file-access-from-files",
            "--run-all-compositor-stages-before-draw",
            "--virtual-time-budget=120000",
            "--dump-dom",
        ])
        .arg(format!("--window-size={},1000", WIDTH + 40))
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("file://{}", dir.join("harness.html").display()))
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("chromium starts");
    // Read stdout on a thread, so a browser that hangs is killed at the deadline.
    let mut stdout = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut stdout, &mut s).ok();
        s
    });
    let deadline = Instant::now() + Duration::from_secs(240);
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            let _ = child.kill();
            panic!("chromium did not finish in 240 s");
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let dom = reader.join().unwrap();
    let _ = std::fs::remove_dir_all(&profile);
    let start = dom
        .find("<pre id=\"result\">")
        .expect("the harness in the DOM")
        + 17;
    let end = dom[start..].find("</pre>").unwrap() + start;
    let json = dom[start..end]
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    match serde_json::from_str(&json) {
        Ok(Value::Object(m)) => m,
        _ => panic!(
            "the harness did not finish: {}",
            &json[..json.len().min(300)]
        ),
    }
}

/// Half a CSS pixel: layout positions are multiples of 1/64 px, and a formula that fits has
/// scrollWidth = clientWidth exactly (both are integers), so any excess of 1 px is real.
const SLACK: f64 = 0.5;

/// Every problem in the measurements, as `page (N): message`.
fn problems(results: &serde_json::Map<String, Value>) -> Vec<String> {
    let mut out = Vec::new();
    for (page, r) in results {
        let Some(list) = r.as_array() else {
            out.push(format!("{page}: {r}"));
            continue;
        };
        for d in list {
            let f = |k: &str| d[k].as_f64().unwrap_or(f64::NAN);
            let at = format!("{page} ({})", d["display"].as_str().unwrap_or("?"));
            if f("scroll") > f("box") + SLACK || f("math") > f("box") + SLACK {
                out.push(format!(
                    "{at}: formula {:.0} px wide in a box of {:.0} px",
                    f("math").max(f("scroll")),
                    f("box")
                ));
            }
            if f("right") > f("col_right") + SLACK {
                out.push(format!("{at}: display runs past the column"));
            }
            match d["number"].as_array() {
                Some(n)
                    if d["display"]
                        .as_str()
                        .is_some_and(|s| !s.starts_with("unnumbered")) =>
                {
                    let (left, right, width) = (
                        n[0].as_f64().unwrap_or(f64::NAN),
                        n[1].as_f64().unwrap_or(f64::NAN),
                        n[2].as_f64().unwrap_or(0.0),
                    );
                    if !(width > 0.0 && left >= 0.0 && right <= f("col_right") + SLACK) {
                        out.push(format!("{at}: equation number not visible"));
                    }
                }
                _ => {}
            }
            let eqs: Vec<f64> = d["equals"]
                .as_array()
                .map(|a| a.iter().filter_map(Value::as_f64).collect())
                .unwrap_or_default();
            if let (Some(lo), Some(hi)) = (
                eqs.iter().copied().reduce(f64::min),
                eqs.iter().copied().reduce(f64::max),
            ) {
                if hi - lo > SLACK {
                    out.push(format!(
                        "{at}: the lines' \"=\" stand {:.1} px apart (not aligned)",
                        hi - lo
                    ));
                }
            }
        }
    }
    out
}

#[test]
fn every_display_fits_its_box_with_its_number_and_aligned_at_equals() {
    let Some(browser) = browser_or_skip("every_display_fits_its_box") else {
        return;
    };
    let copy = book().with_file_name(format!("book-chromium-all-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&copy);
    copy_dir(book(), &copy);
    let pages = pages(&copy);
    let results = measure(&browser, &copy, &pages);
    assert_eq!(results.len(), pages.len(), "not every page was measured");
    let displays: usize = results
        .values()
        .filter_map(Value::as_array)
        .map(Vec::len)
        .sum();
    let aligned = results
        .values()
        .filter_map(Value::as_array)
        .flatten()
        .filter(|d| d["equals"].as_array().is_some_and(|a| a.len() >= 2))
        .count();
    // Not vacuous: the 95 numbered displays were measured, and aligned ones among them.
    assert!(displays >= 95, "only {displays} displays measured");
    assert!(aligned >= 10, "only {aligned} aligned displays measured");
    let p = problems(&results);
    let _ = std::fs::remove_dir_all(&copy);
    assert!(p.is_empty(), "{}", p.join("\n"));
}

#[test]
fn a_planted_wide_display_hidden_number_or_centred_lines_is_caught() {
    let Some(browser) = browser_or_skip("a_planted_wide_display") else {
        return;
    };
    let copy = book().with_file_name(format!("book-chromium-plant-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&copy);
    copy_dir(book(), &copy);
    let page = std::fs::read_to_string(copy.join("02-point-a.html")).unwrap();
    let plant = |name: &str, from: &str, to: &str| {
        let bad = page.replacen(from, to, 1);
        assert!(bad != page, "{name}: the plant changed nothing");
        std::fs::write(copy.join(name), bad).unwrap();
        name.to_string()
    };
    // (11)'s formula made 60 em wider; (12)'s number hidden; (16)'s alignment classes stripped.
    let wide = plant(
        "plant-wide.html",
        "<msub><mi>τ</mi><mi>A</mi></msub>",
        "<msub><mi>τ</mi><mi>A</mi></msub><mspace width=\"60em\" />",
    );
    let hidden = plant(
        "plant-number.html",
        "<span class=\"eqno\">(12)</span>",
        "<span class=\"eqno\" style=\"position:relative;left:3000px\">(12)</span>",
    );
    let centred = plant(
        "plant-centred.html",
        "<mtable class=\"menv-alignlike menv-align\">",
        "<mtable>",
    );
    let results = measure(&browser, &copy, &[wide, hidden, centred]);
    let p = problems(&results);
    let _ = std::fs::remove_dir_all(&copy);
    let has = |s: &str| p.iter().any(|x| x.contains(s));
    assert!(has("plant-wide.html (11): formula"), "{p:?}");
    assert!(
        has("plant-number.html (12): equation number not visible"),
        "{p:?}"
    );
    assert!(has("plant-centred.html (16): the lines' \"=\""), "{p:?}");
}
