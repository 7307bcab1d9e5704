//! Random bytes and random mutations of valid scenes through the built `ladder simulate`
//! (issue 11, item 4): every run is either a success (exit 0) or bad input named where it is
//! (exit 2, one line on stderr `error: FILE:LINE: ...` with a line inside the file, nothing on
//! stdout, nothing in `--out`). Never a panic (exit 101), another exit code, or a hang (a run
//! is killed after [`HANG`]).
//!
//! The mutations are the ones a user makes by hand: delete a line, duplicate one (a key or a
//! section given twice), swap two (a key in the wrong section), change a value to a random
//! token (numbers of every size and form, NaN, inf, strings, arrays, tables, dates, names of
//! methods, ends and outputs), insert bytes that are not UTF-8, insert lines of garbage; one
//! to three of them on one of the shipped scenes or the tests' base scenes. A tenth of the
//! cases are random bytes. The draw is seeded (ChaCha8, [`SEED`]): a failure names its case,
//! and `LADDER_CASES=N` runs more (default [`CASES`], a few seconds).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const SEED: u64 = 11;
const CASES: u32 = 300;
/// A run longer than this is a hang (the longest valid scene here takes well under a second).
const HANG: Duration = Duration::from_secs(60);

/// Values a key may be given: every TOML type, numbers out of every range, names the scene
/// format knows in the wrong place.
const TOKENS: [&str; 40] = [
    "nan",
    "inf",
    "-inf",
    "+nan",
    "0",
    "0.0",
    "-0.0",
    "-1",
    "1",
    "1e308",
    "1e-308",
    "5e-324",
    "1e-320",
    "1.7976931348623157e308",
    "9223372036854775807",
    "-9223372036854775808",
    "99999999999999999999",
    "0x10",
    "0o7",
    "0b1",
    "1_000.5",
    ".5",
    "1.",
    "1e",
    "\"\"",
    "\"x\"",
    "'literal'",
    "\"\"\"two\nlines\"\"\"",
    "true",
    "[]",
    "[1, \"a\"]",
    "[[1]]",
    "{}",
    "{ a = 1 }",
    "1979-05-27T07:32:00Z",
    "\"dop853\"",
    "\"taylor\"",
    "\"time\"",
    "\"flat\"",
    "[\"trajectory\", \"forces\", \"flat_time\"]",
];

/// A random value: a token, a number 10^U(−400, 400) with a random sign, or printable junk.
fn random_value(rng: &mut ChaCha8Rng) -> String {
    match rng.gen_range(0..4) {
        0 | 1 => TOKENS[rng.gen_range(0..TOKENS.len())].to_string(),
        2 => {
            let x = 10f64.powf(rng.gen_range(-400.0..400.0));
            let sign = if rng.gen_bool(0.3) { "-" } else { "" };
            format!("{sign}{x:e}")
        }
        _ => junk_line(rng),
    }
}

/// Printable ASCII weighted toward TOML's own punctuation.
fn junk_line(rng: &mut ChaCha8Rng) -> String {
    const PUNCT: &[u8] = b"[]{}=\"'#.,-_ ";
    (0..rng.gen_range(0..30))
        .map(|_| match rng.gen_bool(0.4) {
            true => PUNCT[rng.gen_range(0..PUNCT.len())] as char,
            false => rng.gen_range(b' '..=b'~') as char,
        })
        .collect()
}

/// One random mutation of `text` (bytes, since some make it invalid UTF-8).
fn mutate(rng: &mut ChaCha8Rng, text: &[u8]) -> Vec<u8> {
    let mut lines: Vec<Vec<u8>> = text.split(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    let n = lines.len();
    let k = rng.gen_range(0..n);
    match rng.gen_range(0..6) {
        0 => {
            lines.remove(k);
        }
        1 => {
            let line = lines[k].clone();
            lines.insert(rng.gen_range(0..=n), line);
        }
        2 => lines.swap(k, rng.gen_range(0..n)),
        3 => {
            // A key's value (or the whole line, when it has no `=`) becomes a random value.
            let v = random_value(rng).into_bytes();
            match lines[k].iter().position(|&b| b == b'=') {
                Some(eq) => {
                    lines[k].truncate(eq + 1);
                    lines[k].push(b' ');
                    lines[k].extend(v);
                }
                None => lines[k] = v,
            }
        }
        4 => {
            let at = rng.gen_range(0..=lines[k].len());
            let bytes: Vec<u8> = (0..rng.gen_range(1..4))
                .map(|_| rng.gen_range(0x80..=0xff))
                .collect();
            lines[k].splice(at..at, bytes);
        }
        _ => {
            for _ in 0..rng.gen_range(1..5) {
                lines.insert(rng.gen_range(0..=lines.len()), junk_line(rng).into_bytes());
            }
        }
    }
    lines.join(&b'\n')
}

/// The valid scenes the mutations start from: the shipped ones and the tests' bases.
fn valid_scenes() -> Vec<Vec<u8>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scenes: Vec<Vec<u8>> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| std::fs::read(e.unwrap().path()).unwrap())
        .collect();
    scenes.sort();
    scenes.push(crate::common::BASE.as_bytes().to_vec());
    scenes.push(crate::common::PENALTY.as_bytes().to_vec());
    scenes
}

/// What a run of `ladder simulate` did.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    files: usize,
}

/// `ladder simulate DIR/scene.toml --out DIR/out` on `bytes`, killed after [`HANG`].
fn simulate(dir: &Path, bytes: &[u8], json: bool) -> Run {
    let scene = dir.join("scene.toml");
    let out = dir.join("out");
    let _ = std::fs::remove_dir_all(&out);
    std::fs::write(&scene, bytes).unwrap();
    let (so, se) = (dir.join("stdout"), dir.join("stderr"));
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_ladder"));
    cmd.arg("simulate").arg(&scene).arg("--out").arg(&out);
    if json {
        cmd.arg("--json");
    }
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&so).unwrap())
        .stderr(std::fs::File::create(&se).unwrap())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break Some(s);
        }
        if start.elapsed() > HANG {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let read = |p: &Path| String::from_utf8_lossy(&std::fs::read(p).unwrap()).into_owned();
    Run {
        code: status.map(|s| s.code().unwrap_or(-1)),
        stdout: read(&so),
        stderr: read(&se),
        files: std::fs::read_dir(&out).map_or(0, |d| d.count()),
    }
}

/// Why `run` of scene `bytes` (at `path`) breaks the promise, if it does.
fn broken_promise(path: &str, bytes: &[u8], run: &Run) -> Option<String> {
    let lines_in_file = bytes.split(|&b| b == b'\n').count();
    match run.code {
        None => Some(format!("no answer after {HANG:?}")),
        Some(0) => None,
        Some(2) => {
            let err = run.stderr.trim_end();
            let line = err
                .strip_prefix(&format!("error: {path}:"))
                .and_then(|rest| rest.split_once(": "))
                .and_then(|(l, _)| l.parse::<usize>().ok());
            if err.lines().count() != 1 {
                Some("not one line on stderr".into())
            } else if !line.is_some_and(|l| (1..=lines_in_file).contains(&l)) {
                Some("stderr does not name file:line with a line in the file".into())
            } else if !run.stdout.is_empty() {
                Some("output on stdout".into())
            } else if run.files > 0 {
                Some("files written to --out".into())
            } else {
                None
            }
        }
        Some(c) => Some(format!("exit {c}")),
    }
}

#[test]
fn random_and_mutated_scenes_succeed_or_are_named_never_panic() {
    let dir = crate::common::tmp_dir("random", "scenes");
    let path = dir.join("scene.toml").display().to_string();
    let scenes = valid_scenes();
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let (mut ok, mut refused, mut broken) = (0, 0, Vec::new());
    for case in 0..crate::common::cases(CASES) {
        let bytes: Vec<u8> = if rng.gen_range(0..10) == 0 {
            (0..rng.gen_range(0..300)).map(|_| rng.gen()).collect()
        } else {
            let mut b = scenes[rng.gen_range(0..scenes.len())].clone();
            for _ in 0..rng.gen_range(1..=3) {
                b = mutate(&mut rng, &b);
            }
            b
        };
        let run = simulate(&dir, &bytes, rng.gen_bool(0.5));
        match broken_promise(&path, &bytes, &run) {
            Some(why) => broken.push(format!(
                "case {case}: {why}\n  exit {:?}\n  stderr: {}\n  stdout: {:.200}\n  scene: {:?}",
                run.code,
                run.stderr.trim_end(),
                run.stdout,
                String::from_utf8_lossy(&bytes)
            )),
            None if run.code == Some(0) => ok += 1,
            None => refused += 1,
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    eprintln!(
        "{ok} ran, {refused} refused, {} broke the promise",
        broken.len()
    );
    assert!(broken.is_empty(), "{}", broken.join("\n"));
    // The draw reaches both outcomes (a mutation is often harmless: a comment, a blank line).
    assert!(ok >= 10 && refused >= 10, "{ok} ran, {refused} refused");
}

/// The judge of a run can fail: a panic's exit, a second stderr line, a missing or wrong line
/// number, output on stdout and a written file are each caught.
#[test]
fn the_promise_can_be_broken() {
    let scene = b"a\nb\nc\n";
    let run = |code: i32, stderr: &str, stdout: &str, files: usize| Run {
        code: Some(code),
        stdout: stdout.into(),
        stderr: stderr.into(),
        files,
    };
    let good = run(2, "error: s.toml:2: [ladder] mass: wrong\n", "", 0);
    assert_eq!(broken_promise("s.toml", scene, &good), None);
    for (bad, why) in [
        (run(101, "thread 'main' panicked", "", 0), "exit 101"),
        (run(1, "error: s.toml: stopped short\n", "", 0), "exit 1"),
        (run(2, "error: s.toml:2: a\nerror: b\n", "", 0), "one line"),
        (
            run(2, "error: s.toml: [ladder] mass: x\n", "", 0),
            "file:line",
        ),
        (
            run(2, "error: s.toml:9: [ladder] mass: x\n", "", 0),
            "file:line",
        ),
        (
            run(2, "error: t.toml:2: [ladder] mass: x\n", "", 0),
            "file:line",
        ),
        (run(2, "error: s.toml:2: x\n", "{}", 0), "stdout"),
        (run(2, "error: s.toml:2: x\n", "", 1), "--out"),
    ] {
        let got = broken_promise("s.toml", scene, &bad);
        assert!(got.as_deref().is_some_and(|g| g.contains(why)), "{got:?}");
    }
    let hung = Run { code: None, ..good };
    assert!(broken_promise("s.toml", scene, &hung).is_some());
}
