//! The pages made from the checks rather than from `equations/`: the summary table of the
//! index, the errata, the derivations (methods) and the figures.

use super::math::mathml;
use super::pages::esc;
use super::panel::{anchor, status_name};
use super::BookData;
use std::collections::BTreeMap;
use std::path::Path;

fn eq_link(home: &BTreeMap<u32, String>, number: u32, label: &str) -> String {
    match home.get(&number) {
        Some(p) => format!("<a href=\"{p}#{}\">{}</a>", anchor(label), esc(label)),
        None => esc(label),
    }
}

/// The index: the opening for a student (`opening`: the problem, the figure, the answer, where
/// to go next), then `README.md` (how the book checks the note), then every display's status.
pub fn index_page(
    data: &BookData,
    home: &BTreeMap<u32, String>,
    opening: &str,
    readme: &str,
) -> String {
    use super::reader::{badge, term};
    let mut rows = String::new();
    for r in data.results.iter().chain(&data.extensions) {
        let s = status_name(r.status);
        rows.push_str(&format!(
            "<tr data-number=\"{n}\" data-status=\"{s}\" data-proved=\"{p}\"><td>{link}</td><td>{sec}</td><td>{title}</td>\
<td>{kind}</td><td>{badge}</td><td>{proved}</td><td>{units}</td><td>{res:.3}</td><td>{exact}</td></tr>\n",
            n = r.number,
            p = r.proved,
            link = eq_link(home, r.number, &r.label),
            sec = esc(r.section),
            title = esc(r.title),
            kind = r.kind.name(),
            badge = badge(r.status),
            proved = if r.proved { "yes" } else { "no" },
            units = esc(r.units.name()),
            res = r.max_residual,
            exact = if r.exact { "zero" } else { "no" },
        ));
    }
    let (v, e, d, f) = crate::verify::counts(&data.results);
    let readme = readme
        .replacen("<h1>", "<h2>", 1)
        .replacen("</h1>", "</h2>", 1);
    format!(
        "{opening}\n{readme}\n<h2 id=\"summary\">Every display, checked</h2>\n\
<p class=\"summary\"><strong>{v} {checked}, {e} {misprint}, {d} {definition}, {f} failed</strong> of the note's {} displays. \
{}</p>\n<p>{resb}: the worst float residual in units of its running error bound \
(pass ≤ 4); {exact}: the residual at random exact points (the first in rationals, the rest {modp}).</p>\n\
<table><thead><tr><th>eq</th><th>sec</th><th>title</th><th>kind</th><th>status</th><th>{proved}</th><th>units</th>\
<th>{resb}</th><th>{exact}</th></tr></thead>\n<tbody>\n{rows}</tbody></table>\n",
        data.results.len(),
        esc(&data.summary),
        checked = term("checked", "checked"),
        misprint = term("misprint", "misprints in the note"),
        definition = term("definition", "definitions"),
        resb = term("residual", "res/bound"),
        exact = term("exact", "exact"),
        modp = term("modp", "modulo p = 2<sup>61</sup> − 1"),
        proved = term("proved", "proved"),
    )
}

fn block(latex: &str, what: &str, problems: &mut Vec<String>) -> String {
    match mathml(latex, true) {
        Ok(m) => format!("<div class=\"display\"><div class=\"formula\">{m}</div></div>"),
        Err(e) => {
            problems.push(format!("errata.html: {what}: {e}"));
            "<p class=\"math-error\">[did not typeset]</p>".into()
        }
    }
}

/// The errata: each misprint live from `ladder errata`, the prose claims, then `ERRATA.md`.
pub fn errata_page(
    data: &BookData,
    home: &BTreeMap<u32, String>,
    notes: &str,
    problems: &mut Vec<String>,
) -> String {
    let mut claims = String::new();
    for c in &data.claims {
        claims.push_str(&claim_row(c, problems));
    }
    let mut out = String::from(
        "<h1>Errata of the note</h1>\n<p>Each misprint below is computed when the book is built: \
the printed form fails exactly, the corrected form holds, and their difference is simplified \
symbolically (with s = sin θ, c = cos θ, s² + c² = 1).</p>\n",
    );
    for e in &data.errata {
        out.push_str(&erratum_section(data, home, e, problems));
    }
    out.push_str("<h2>Claims of the prose</h2>\n<table><thead><tr><th>where</th><th>claim</th><th>verdict</th></tr></thead><tbody>\n");
    out.push_str(&claims);
    out.push_str("</tbody></table>\n<h2>Notes (equations/ERRATA.md)</h2>\n");
    out.push_str(
        &notes
            .replacen("<h1>", "<h2>", 1)
            .replacen("</h1>", "</h2>", 1),
    );
    out
}

/// A prose erratum's wording: MathML when it holds a TeX command, words otherwise.
fn prose(s: &str, problems: &mut Vec<String>) -> String {
    if !s.contains('\\') {
        return esc(s);
    }
    mathml(s, false).unwrap_or_else(|e| {
        problems.push(format!("errata.html: {e}"));
        "[did not typeset]".into()
    })
}

/// One claim of the prose as a table row: where, what, and its verdict (holds, a prose erratum
/// with printed and corrected wording, a slip of wording, or FAILED).
fn claim_row(c: &crate::verify::claims::Claim, problems: &mut Vec<String>) -> String {
    let verdict = match (c.holds, c.printed_fails, c.erratum) {
        (true, Some(true), Some((p, k))) => format!(
            "prose erratum{}: printed {} fails, corrected {} holds{}",
            if c.imprecise { " (imprecise)" } else { "" },
            prose(p, problems),
            prose(k, problems),
            c.reading_latex
                .as_deref()
                .and_then(|r| super::panel::markdown_math(r).ok())
                .map(|r| format!("; {r}"))
                .unwrap_or_default()
        ),
        (true, None, Some((p, k))) => format!(
            "prose slip (the formula is right): printed {}, meant {}",
            prose(p, problems),
            prose(k, problems)
        ),
        (true, None, None) => "holds".into(),
        _ => "<strong>FAILED</strong>".into(),
    };
    format!(
        "<tr><td>{}</td><td>{}</td><td>{verdict}</td></tr>\n",
        esc(c.location),
        esc(&c.claim)
    )
}

/// One misprint's section: printed and corrected forms, their difference, the residuals at an
/// exact point, the units verdict and why.
fn erratum_section(
    data: &BookData,
    home: &BTreeMap<u32, String>,
    e: &crate::verify::errata::ErratumReport,
    problems: &mut Vec<String>,
) -> String {
    let label = format!("({})", e.number);
    let title = data
        .results
        .iter()
        .find(|r| r.number == e.number)
        .map(|r| format!(" {}", esc(r.title)))
        .unwrap_or_default();
    format!(
        "<section class=\"erratum\" id=\"erratum-{n}\" data-erratum=\"{n}\"><h2>{link}{title}</h2>\n<dl>\
<dt>Printed</dt><dd>{p}</dd><dt>Corrected</dt><dd>{c}</dd><dt>{dl}</dt><dd>{d}</dd>\
<dt>Residual at an exact point (SI units)</dt><dd>printed {pr} {ru}, corrected {cr}</dd><dt>Units</dt><dd>{u}</dd>\
<dt>Why</dt><dd>{why}</dd></dl></section>\n",
        n = e.number,
        link = eq_link(home, e.number, &label),
        p = block(e.printed, &label, problems),
        c = block(e.corrected, &label, problems),
        dl = super::panel::misprint_label(e),
        d = super::panel::misprint(e).unwrap_or_else(|x| {
            problems.push(format!("errata.html: {label}: {x}"));
            "<p class=\"math-error\">[did not typeset]</p>".into()
        }),
        ru = esc(&e.residual_unit),
        pr = esc(&e.printed_residual_exact),
        cr = esc(&e.corrected_residual),
        u = esc(e.units.doc_line().trim_start_matches("- ")),
        why = esc(e.why),
    )
}

/// The derivations of the equation of motion, checked.
pub fn methods_page(data: &BookData) -> String {
    let mut rows = String::new();
    for m in &data.methods {
        rows.push_str(&format!(
            "<tr data-method=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td>{:.3}</td><td>{}</td></tr>\n",
            esc(m.name),
            esc(m.name),
            if m.passed { "<span class=\"badge verified\">passed</span>" } else { "<span class=\"badge failed\">failed</span>" },
            m.cases,
            m.max_residual,
            esc(&m.problems.join("; "))
        ));
    }
    format!(
        "<h1>Methods: every derivation of the equation of motion</h1>\n\
<p>The note derives θ̈ = (3g/4l) sin θ by Lagrange's method and by torque analyses about five \
points; its appendices add Jensen's methods and Milne's. Each derivation is written as a residual \
affine in θ̈; the check solves it for θ̈, compares with (5) at random states (tolerance from the \
running error bound) and shows that the residual vanishes on the motion only. \
<a href=\"{extending}\">Adding a method</a> explains how to add one.</p>\n\
<table><thead><tr><th>method</th><th>verdict</th><th>float states</th><th>res/bound</th><th>problems</th></tr></thead>\
<tbody>\n{rows}</tbody></table>\n",
        extending = super::about::page_name("docs/EXTENDING.md")
    )
}

/// The SVG figures of `equations/figures/`, sorted by name.
pub fn figure_files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir.join("figures"))
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .filter(|e| e.file_name().to_string_lossy().ends_with(".svg"))
                .filter_map(|e| {
                    Some((
                        e.file_name().to_string_lossy().to_string(),
                        std::fs::read(e.path()).ok()?,
                    ))
                })
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files
}

/// The full fall of `scenes/full-fall.toml`, simulated now: its scene and outcome.
pub fn full_fall(
    root: &Path,
) -> Result<(crate::sim::scene::Scene, crate::sim::outcome::Outcome), String> {
    let path = root.join("scenes/full-fall.toml");
    let scene = crate::sim::scene::load(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let o = crate::sim::fall::run(&scene, crate::sim::fall::MAX_STEPS)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok((scene, o))
}

/// The figures of the full fall: trajectory and contact forces with the separation, the flat
/// landing and F_w reaching zero marked.
pub fn fall_figures(
    scene: &crate::sim::scene::Scene,
    o: &crate::sim::outcome::Outcome,
) -> Vec<(String, Vec<u8>)> {
    use crate::report::files::Content;
    crate::report::fall_figures::files(scene, o)
        .into_iter()
        .filter_map(|f| match f.content {
            Content::Chart(c, s) => Some((
                format!("fall-{}", f.name.replace('_', "-")),
                crate::report::svg_chart::document(&[(c, s)], 960.0, 600.0).into_bytes(),
            )),
            _ => None,
        })
        .collect()
}

fn caption(name: &str) -> String {
    if let Some(what) = name.strip_prefix("fall-") {
        let what = match what.trim_end_matches(".svg") {
            "trajectory" => "θ and θ̇ against t; the separation from the wall and the flat landing are marked",
            "forces-t" => "the contact forces against t; the separation, the flat landing and the wall force reaching zero are marked",
            "forces-theta" => "the contact forces against θ; the separation angle of footnote 4 and the wall force reaching zero are marked (they coincide)",
            other => other,
        };
        return format!(
            "The full fall of scenes/full-fall.toml, simulated when this book was built: {what}."
        );
    }
    match name.strip_prefix("forces-").and_then(|n| n.strip_suffix(".svg")) {
        Some(p) => format!(
            "The forces of the torque analysis about {}: F_w at C, F_f at D, m g at B, each lever arm dashed (drawn by report::diagram).",
            p.to_uppercase()
        ),
        None => name.to_string(),
    }
}

/// The work-precision figure of `docs/simulator.md` (a picture of `docs/`, kept beside the
/// about pages), with its caption.
pub const WORK_PRECISION: (&str, &str) = (
    "work-precision.png",
    "Work against precision of every integrator on the six built-in scenes, one panel per scene: \
the error of the separation (or flat) time against the work, the peers (ode_solvers' DOP853 and \
Dopri5) dashed in the colour of the method they match, the Pareto front as a grey band \
(docs/simulator.md says how it was made and on which machine).",
);

/// The figures page: every figure with its caption, then `pictures` (file, caption) of the
/// book's root.
pub fn figures_page(files: &[(String, Vec<u8>)], pictures: &[(&str, &str)]) -> String {
    let mut out = String::from("<h1>Figures</h1>\n");
    for (name, _) in files {
        out.push_str(&format!(
            "<figure id=\"{id}\"><img src=\"figures/{n}\" alt=\"{c}\" /><figcaption>{c}</figcaption></figure>\n",
            id = esc(name.trim_end_matches(".svg")),
            n = esc(name),
            c = esc(&caption(name)),
        ));
    }
    for (file, cap) in pictures {
        out.push_str(&format!(
            "<figure id=\"{id}\"><img src=\"{f}\" alt=\"{c}\" /><figcaption>{c}</figcaption></figure>\n",
            id = esc(file.trim_end_matches(".png")),
            f = esc(file),
            c = esc(cap),
        ));
    }
    out
}
