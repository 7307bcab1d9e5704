//! `sliding_ladder::registry::source::parse::parse_file` on generated markdown: files of display
//! sections with every field the format has (kind, code, checks, law, erratum, premises,
//! states), some written wrong, repeated or missing, in a random order, under chapter headings.
//! The test writes each file from a plan and knows, from the plan alone, every section that must
//! come back (each field as put in) and every error (file, line and reason), in order.
//!
//! The note's own files hold few of the shapes an extender can write (a second `*Kind:*` line,
//! a `*Misprint:*` whose `*Corrected:*` comes a paragraph later, a premise with no source):
//! this is where those shapes are held to what the format promises.

use proptest::prelude::*;
use sliding_ladder::registry::source::parse::parse_file;
use sliding_ladder::registry::source::{
    CheckSpec, ErratumSpec, LawSpec, PremiseSource, PremiseSpec, Section,
};
use sliding_ladder::registry::Kind;

const FILE: &str = "equations/gen.md";
const SHAPE_CHECK: &str = "a check reads - `function` (states): what it compares";
const SHAPE_LAW: &str =
    "the *Law:* line reads \"the 2nd `=` is the law of motion: the law in words\"";

/// A heading's number as written.
#[derive(Clone, Debug)]
enum Number {
    /// `(n)`, 1 ≤ n < 1000.
    Note(u32),
    /// `(Pk)`, an extension.
    Extension(u32),
    /// `(0)`, refused.
    Zero,
    /// `(n)`, n ≥ 1000, refused.
    TooBig(u32),
}

/// One `*Kind:*` field: a kind by its index in `Kind::ALL`, or a word that names none.
#[derive(Clone, Debug)]
enum KindLine {
    Named(usize),
    Unknown,
}

/// How the section records an erratum.
#[derive(Clone, Debug)]
enum Erratum {
    None,
    /// Misprint, Corrected and Why in one paragraph.
    Whole,
    /// Misprint alone; Corrected in a later paragraph (a field paragraph of its own).
    Split,
    /// Misprint with no Corrected anywhere.
    NoCorrected,
    /// A whole erratum, then a second Misprint.
    SecondMisprint,
}

/// One premise item: its source (0-3 bar, implies, stated, prose; 4 a word that is none) and
/// whether it has a `$condition$`.
#[derive(Clone, Debug)]
struct Premise {
    source: usize,
    condition: bool,
}

#[derive(Clone, Debug)]
struct Plan {
    /// A `# Sec. a.b — …` heading before the section (the section label changes), or a
    /// `## Notes` heading (it closes the section before, the label stays).
    chapter: Option<Option<(u8, u8)>>,
    number: Number,
    titled: bool,
    /// The display's forms (`None`: no `$$` block).
    forms: Option<usize>,
    kinds: Vec<KindLine>,
    code: usize,
    /// The `*Rust:*` items: well formed or not.
    checks: Vec<bool>,
    /// The `*Law:*` lines' `=` numbers (0: a line that does not read).
    laws: Vec<u32>,
    erratum: Erratum,
    premises: Vec<Premise>,
    states: bool,
    /// Kind, Code and States share one paragraph, joined by ` · `.
    joined: bool,
    /// The order of the field paragraphs (a permutation seed).
    order: u64,
    /// Prose paragraphs between fields.
    prose: usize,
    /// An empty `*Rust:*` then a code block, then a list in the shape of checks that no field
    /// announces (the code block ends what `*Rust:*` announced).
    aside: bool,
}

fn number() -> impl Strategy<Value = Number> {
    prop_oneof![
        12 => (1u32..1000).prop_map(Number::Note),
        6 => (1u32..1000).prop_map(Number::Extension),
        1 => Just(Number::Zero),
        1 => (1000u32..5000).prop_map(Number::TooBig),
    ]
}

fn kind_line() -> impl Strategy<Value = KindLine> {
    prop_oneof![5 => (0usize..6).prop_map(KindLine::Named), 1 => Just(KindLine::Unknown)]
}

fn erratum() -> impl Strategy<Value = Erratum> {
    prop_oneof![
        8 => Just(Erratum::None),
        4 => Just(Erratum::Whole),
        1 => Just(Erratum::Split),
        1 => Just(Erratum::NoCorrected),
        1 => Just(Erratum::SecondMisprint),
    ]
}

prop_compose! {
    fn plan()(
        chapter in prop::option::weighted(0.4, prop::option::of((1u8..9, 1u8..9))),
        number in number(),
        titled in prop::bool::weighted(0.95),
        forms in prop::option::weighted(0.95, 1usize..5),
        kinds in prop_oneof![
            8 => (0usize..6).prop_map(|i| vec![KindLine::Named(i)]),
            2 => prop::collection::vec(kind_line(), 0..3),
        ],
        code in 0usize..3,
        checks in prop::collection::vec(prop::bool::weighted(0.95), 0..3),
        laws in prop_oneof![
            8 => prop::collection::vec(1u32..3, 0..2),
            1 => prop::collection::vec(0u32..6, 0..3),
        ],
        erratum in erratum(),
        premises in prop::collection::vec(
            (prop_oneof![12 => 0usize..4, 1 => Just(4usize)], prop::bool::weighted(0.9))
                .prop_map(|(source, condition)| Premise { source, condition }),
            0..3,
        ),
        states in any::<bool>(),
        joined in any::<bool>(),
        order in any::<u64>(),
        prose in 0usize..3,
        aside in prop::bool::weighted(0.2),
    ) -> Plan {
        Plan { chapter, number, titled, forms, kinds, code, checks, laws, erratum, premises,
               states, joined, order, prose, aside }
    }
}

/// The file being written, line by line, and what the parser must return for it.
#[derive(Default)]
struct Expected {
    lines: Vec<String>,
    sections: Vec<Section>,
    errors: Vec<(usize, String)>,
}

impl Expected {
    /// The line number the next pushed line will have.
    fn next(&self) -> usize {
        self.lines.len() + 1
    }
    fn push(&mut self, line: impl Into<String>) -> usize {
        self.lines.push(line.into());
        self.lines.len()
    }
    /// A paragraph: its lines, then a blank line; its first line's number.
    fn paragraph(&mut self, lines: &[String]) -> usize {
        let at = self.next();
        for l in lines {
            self.push(l.clone());
        }
        self.push("");
        at
    }
}

fn label(n: u32) -> String {
    if n > 1000 {
        format!("(P{})", n - 1000)
    } else {
        format!("({n})")
    }
}

fn ordinal(k: u32) -> String {
    let suffix = match (k % 10, k % 100) {
        (1, x) if x != 11 => "st",
        (2, x) if x != 12 => "nd",
        (3, x) if x != 13 => "rd",
        _ => "th",
    };
    format!("{k}{suffix}")
}

/// A deterministic shuffle of `n` items from a seed (the plan's order).
fn permutation(n: usize, mut seed: u64) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let j = usize::try_from((seed >> 33) % (i as u64 + 1)).unwrap_or(0);
        idx.swap(i, j);
    }
    idx
}

/// What the section's field paragraphs say, gathered as the parser must gather them.
#[derive(Default)]
struct Gathered {
    kind: Option<Kind>,
    kind_written: bool,
    functions: Vec<String>,
    checks: Vec<CheckSpec>,
    law: Option<(LawSpec, usize)>,
    erratum: Option<ErratumSpec>,
    erratum_line: usize,
    states: Option<(String, usize)>,
    premises: Vec<PremiseSpec>,
    errors: Vec<(usize, String)>,
}

/// One field paragraph of a section, with its list if it has one.
enum Para {
    Kind(usize),
    Code,
    States,
    /// Kind (if any), Code and States in one paragraph.
    Joined,
    Checks,
    Law(u32, usize),
    /// Misprint, Corrected and Why in one paragraph.
    Erratum,
    /// Corrected alone.
    Corrected,
    /// Misprint alone.
    Misprint,
    Premises,
    /// `*Rust:*`, a code block, then a list no field announces.
    Aside,
}

const SOURCES: [&str; 5] = ["bar", "implies", "stated", "prose", "assumed"];

fn write_kind(plan: &Plan, k: usize, g: &mut Gathered, line: usize) -> String {
    g.kind_written = true;
    match plan.kinds[k] {
        KindLine::Named(i) => {
            let kind = Kind::ALL[i];
            if g.kind.is_some() {
                g.errors.push((line, "a second *Kind:* line".into()));
            } else {
                g.kind = Some(kind);
            }
            format!("*Kind:* {}", kind.name())
        }
        KindLine::Unknown => {
            let names: Vec<&str> = Kind::ALL.iter().map(|k| k.name()).collect();
            g.errors.push((
                line,
                format!("unknown kind 'sideways' (one of {})", names.join(", ")),
            ));
            "*Kind:* sideways".into()
        }
    }
}

fn write_code(plan: &Plan, g: &mut Gathered) -> String {
    let spans: Vec<String> = (0..plan.code)
        .map(|i| {
            let f = format!("ladder::gen::function_{i}");
            g.functions.push(f.clone());
            format!("[`{f}`](../src/ladder/gen.rs)")
        })
        .collect();
    format!("*Code:* {}", spans.join(", "))
}

fn write_states(g: &mut Gathered, line: usize) -> String {
    g.states = Some(("p-at-cm".into(), line));
    "*States:* p-at-cm. (P rides on the centre of mass.)".into()
}

fn write_checks(plan: &Plan, e: &mut Expected, g: &mut Gathered) {
    e.push("*Rust:*");
    for (i, ok) in plan.checks.iter().enumerate() {
        let line = e.next();
        if *ok {
            e.push(format!(
                "- `gen_{i}` (general): form {i}   against  a model"
            ));
            g.checks.push(CheckSpec {
                function: format!("gen_{i}"),
                sample: "general".into(),
                name: format!("form {i} against a model"),
                line,
            });
        } else {
            e.push(format!("- `gen_{i}` (general) with no colon"));
            g.errors.push((line, SHAPE_CHECK.into()));
        }
    }
    e.push("");
}

fn write_premises(plan: &Plan, e: &mut Expected, g: &mut Gathered) {
    e.push("*Premises:*");
    let shape = "a premise reads - bar|implies|stated|prose: $condition$ words";
    for (i, p) in plan.premises.iter().enumerate() {
        let line = e.next();
        let name = SOURCES[p.source];
        let condition = if p.condition {
            format!("$x_P  = {i}$ ")
        } else {
            String::new()
        };
        e.push(format!("- {name}: {condition}(premise {i})."));
        let source = [
            PremiseSource::Bar,
            PremiseSource::Implies,
            PremiseSource::Stated,
            PremiseSource::Prose,
        ]
        .get(p.source)
        .copied();
        match source {
            None => g.errors.push((
                line,
                format!("*Premises:* '{name}' is not a source: {shape}"),
            )),
            Some(s) if !p.condition && s != PremiseSource::Prose => g.errors.push((
                line,
                format!("*Premises:* a {name} premise needs its $condition$"),
            )),
            Some(source) => g.premises.push(PremiseSpec {
                source,
                latex: p.condition.then(|| format!("x_P = {i}")),
                words: format!("premise {i}"),
                line,
            }),
        }
    }
    e.push("");
}

fn write_law(step: u32, k: usize, e: &mut Expected, g: &mut Gathered) {
    let line = e.next();
    let text = format!(
        "*Law:* the {} `=` is the law of motion: law  {k}. Every other `=` holds.",
        ordinal(step)
    );
    e.paragraph(&[text]);
    if step == 0 {
        g.errors.push((line, SHAPE_LAW.into()));
    } else if g.law.is_some() {
        g.errors.push((line, "a second *Law:* line".into()));
    } else {
        let statement = format!("law {k}");
        g.law = Some((LawSpec { step, statement }, line));
    }
}

fn write_erratum(which: &Para, e: &mut Expected, g: &mut Gathered) {
    let line = e.next();
    let misprint = "*Misprint:* $a_1  = b$";
    let (text, fields): (String, &[&str]) = match which {
        Para::Erratum => (
            format!("{misprint} · *Corrected:* $a_1 = c$ · *Why:* a  typo"),
            &["Misprint", "Corrected", "Why"],
        ),
        Para::Corrected => ("*Corrected:* $a_1 = c$".into(), &["Corrected"]),
        _ => (misprint.into(), &["Misprint"]),
    };
    e.paragraph(&[text]);
    if g.erratum.is_none() {
        g.erratum_line = line;
    }
    let er = g.erratum.get_or_insert_with(|| ErratumSpec {
        printed: String::new(),
        corrected: String::new(),
        why: String::new(),
    });
    for f in fields {
        let (slot, value) = match *f {
            "Misprint" => (&mut er.printed, "a_1 = b"),
            "Corrected" => (&mut er.corrected, "a_1 = c"),
            _ => (&mut er.why, "a typo"),
        };
        if slot.is_empty() {
            *slot = value.into();
        } else {
            g.errors.push((line, format!("a second *{f}:*")));
        }
    }
}

/// The field paragraphs of a plan, in the plan's order (a Corrected that completes a split
/// erratum, or a second Misprint, always after the erratum's first paragraph).
fn paragraphs(plan: &Plan) -> Vec<Para> {
    let mut paras: Vec<Para> = Vec::new();
    if plan.joined {
        paras.push(Para::Joined);
        paras.extend((1..plan.kinds.len()).map(Para::Kind));
    } else {
        paras.extend((0..plan.kinds.len()).map(Para::Kind));
        paras.push(Para::Code);
        if plan.states {
            paras.push(Para::States);
        }
    }
    if !plan.checks.is_empty() {
        paras.push(Para::Checks);
    }
    paras.extend(plan.laws.iter().enumerate().map(|(k, s)| Para::Law(*s, k)));
    if !plan.premises.is_empty() {
        paras.push(Para::Premises);
    }
    if plan.aside {
        paras.push(Para::Aside);
    }
    let first = match plan.erratum {
        Erratum::None => None,
        Erratum::Whole | Erratum::SecondMisprint => Some(Para::Erratum),
        Erratum::Split | Erratum::NoCorrected => Some(Para::Misprint),
    };
    paras.extend(first);
    let mut order: Vec<Para> = Vec::new();
    let perm = permutation(paras.len(), plan.order);
    let mut slots: Vec<Option<Para>> = paras.into_iter().map(Some).collect();
    for i in perm {
        order.extend(slots[i].take());
    }
    match plan.erratum {
        Erratum::Split => order.push(Para::Corrected),
        Erratum::SecondMisprint => order.push(Para::Misprint),
        _ => {}
    }
    order
}

/// Write one section of `plan` into `e`, and what the parser must make of it.
fn write_section(plan: &Plan, chapter: &mut String, e: &mut Expected) {
    match plan.chapter {
        Some(Some((a, b))) => {
            e.paragraph(&[format!("# Sec. {a}.{b} — Chapter {a}")]);
            *chapter = format!("{a}.{b}");
        }
        Some(None) => {
            e.paragraph(&["## Notes".to_string()]);
        }
        None => {}
    }
    let (written, number) = match plan.number {
        Number::Note(n) => (format!("({n})"), Ok(n)),
        Number::Extension(k) => (format!("(P{k})"), Ok(1000 + k)),
        Number::Zero => (
            "(0)".into(),
            Err("(0): displays are numbered from 1".to_string()),
        ),
        Number::TooBig(n) => (
            format!("({n})"),
            Err(format!(
                "({n}): numbers run below 1000 (an extension is (P1), (P2), ...)"
            )),
        ),
    };
    let title = if plan.titled {
        "A generated display"
    } else {
        ""
    };
    let heading = e.paragraph(&[format!("### {written} {title}")]);
    let mut latex = None;
    if let Some(k) = plan.forms {
        let forms: Vec<String> = (0..=k).map(|i| format!("a_{i}")).collect();
        let at = e.next();
        e.paragraph(&[
            "$$".into(),
            forms[..1].join(" = "),
            format!("= {}", forms[1..].join("  =  ")),
            "$$".into(),
        ]);
        latex = Some((forms.join(" = "), at));
    }
    let mut g = Gathered::default();
    for (i, para) in paragraphs(plan).iter().enumerate() {
        if i < plan.prose {
            e.paragraph(&[format!(
                "**Prose {i}.** Words, *emphasis* and $x = y$ inline."
            )]);
        }
        write_para(plan, para, e, &mut g);
    }
    close(plan, heading, number, latex, chapter, g, e);
}

fn write_para(plan: &Plan, para: &Para, e: &mut Expected, g: &mut Gathered) {
    let line = e.next();
    match para {
        Para::Kind(k) => {
            let text = write_kind(plan, *k, g, line);
            e.paragraph(&[text]);
        }
        Para::Code => {
            let text = write_code(plan, g);
            e.paragraph(&[text]);
        }
        Para::States => {
            let text = write_states(g, line);
            e.paragraph(&[text]);
        }
        Para::Joined => {
            let mut parts = Vec::new();
            if !plan.kinds.is_empty() {
                parts.push(write_kind(plan, 0, g, line));
            }
            parts.push(write_code(plan, g));
            if plan.states {
                parts.push(write_states(g, line));
            }
            e.paragraph(&[parts.join(" · ")]);
        }
        Para::Checks => write_checks(plan, e, g),
        Para::Aside => {
            e.paragraph(&["*Rust:*".into()]);
            e.paragraph(&["```text".into(), "an example".into(), "```".into()]);
            e.paragraph(&["- `gen_9` (general): a remark in the shape of a check".into()]);
        }
        Para::Premises => write_premises(plan, e, g),
        Para::Law(step, k) => write_law(*step, *k, e, g),
        Para::Erratum | Para::Corrected | Para::Misprint => write_erratum(para, e, g),
    }
}

/// What the parser makes of a finished section: the section itself, or its errors.
fn close(
    plan: &Plan,
    heading: usize,
    number: Result<u32, String>,
    latex: Option<(String, usize)>,
    chapter: &str,
    mut g: Gathered,
    e: &mut Expected,
) {
    let number = match number {
        Ok(n) => n,
        Err(reason) => return e.errors.push((heading, reason)),
    };
    let label = label(number);
    if g.erratum.as_ref().is_some_and(|er| er.corrected.is_empty()) {
        let reason = "a *Misprint:* needs its *Corrected:* form".to_string();
        g.errors.push((g.erratum_line, reason));
    }
    g.errors.sort_by_key(|(l, _)| *l);
    let mut errors: Vec<(usize, String)> = g
        .errors
        .iter()
        .map(|(l, r)| (*l, format!("{label}: {r}")))
        .collect();
    let Some((latex, latex_line)) = latex else {
        let reason = format!("{label} has no display (the LaTeX between two `$$` lines)");
        errors.push((heading, reason));
        return e.errors.extend(errors);
    };
    let Some(kind) = g.kind else {
        if !g.kind_written {
            let reason =
                format!("{label} does not state its kind (a line `*Kind:* on-shell`, ...)");
            errors.push((heading, reason));
        }
        return e.errors.extend(errors);
    };
    if !plan.titled {
        errors.push((heading, format!("{label} has no title after its number")));
    }
    let signs = u32::try_from(plan.forms.unwrap_or(0)).unwrap_or(0);
    if let Some((law, line)) = &g.law {
        if law.step > signs {
            let step = law.step;
            let reason = format!("{label}: *Law:* names `=` no. {step}, the display has {signs}");
            errors.push((*line, reason));
        }
    }
    if !errors.is_empty() {
        return e.errors.extend(errors);
    }
    e.sections.push(Section {
        number,
        file: FILE.into(),
        line: heading,
        title: "A generated display".into(),
        section: chapter.to_string(),
        latex,
        latex_line,
        kind,
        functions: g.functions,
        checks: g.checks,
        law: g.law.map(|l| l.0),
        erratum: g.erratum,
        continues: None,
        states: g.states,
        premises: g.premises,
    });
}

fn expected(plans: &[Plan]) -> Expected {
    let mut e = Expected::default();
    e.paragraph(&["Opening prose of a generated file.".to_string()]);
    let mut chapter = "gen".to_string();
    for p in plans {
        write_section(p, &mut chapter, &mut e);
    }
    e
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(crate::common::cases(256)))]

    /// Every generated file reads back as planned: the sections without a problem, field by
    /// field, and each problem at its line with its reason, in order.
    #[test]
    fn parse_file_reads_generated_sections_as_written(
        plans in prop::collection::vec(plan(), 1..5)
    ) {
        let e = expected(&plans);
        let src = e.lines.join("\n");
        let parsed = parse_file(FILE, &src);
        let errors: Vec<(usize, String)> =
            parsed.errors.iter().map(|x| (x.line, x.reason.clone())).collect();
        prop_assert!(parsed.errors.iter().all(|x| x.file == FILE));
        prop_assert_eq!(errors, e.errors, "{}", src);
        prop_assert_eq!(parsed.sections, e.sections, "{}", src);
    }
}

/// The generator's own reach: over a fixed run of plans, each shape it exists for occurs, as a
/// clean section and as each error the format names.
#[test]
fn generated_plans_reach_every_shape() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let strategy = prop::collection::vec(plan(), 1..5);
    let mut reasons: Vec<String> = Vec::new();
    let mut clean = Vec::new();
    let mut plans_with_aside = 0;
    for _ in 0..400 {
        let plans = strategy.new_tree(&mut runner).expect("a plan").current();
        let e = expected(&plans);
        plans_with_aside += plans.iter().filter(|p| p.aside).count();
        reasons.extend(e.errors.into_iter().map(|x| x.1));
        clean.extend(e.sections);
    }
    for shape in [
        "a second *Kind:* line",
        "unknown kind 'sideways'",
        "a check reads",
        "the *Law:* line reads",
        "a second *Law:* line",
        "*Law:* names `=` no.",
        "a *Misprint:* needs its *Corrected:* form",
        "a second *Misprint:*",
        "*Premises:* 'assumed' is not a source",
        "premise needs its $condition$",
        "numbers run below 1000",
        "displays are numbered from 1",
        "has no display",
        "does not state its kind",
        "has no title",
    ] {
        assert!(
            reasons.iter().any(|r| r.contains(shape)),
            "never generated: {shape}"
        );
    }
    let has = |f: &dyn Fn(&Section) -> bool| clean.iter().any(f);
    assert!(clean.len() > 100, "{} clean sections", clean.len());
    assert!(has(&|s| s.number > 1000 && s.section != "gen"));
    assert!(has(&|s| s.erratum.is_some()
        && s.law.is_some()
        && !s.checks.is_empty()));
    assert!(has(&|s| s.premises.len() > 1 && s.states.is_some()));
    assert!(has(&|s| s.premises.iter().any(|p| p.latex.is_none())));
    assert!(plans_with_aside > 0);
}
