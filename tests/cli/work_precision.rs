//! `ladder work-precision` takes a list of scenes and draws one panel per scene (issue 13,
//! item 3): two scene files give two panels titled by their starts, `runs.csv` rows of both,
//! and an observed-order block per scene with the fitted range and the slope's standard error
//! (or why none is fitted) and the slope of error against tolerance.

use std::process::Command;

#[test]
fn a_list_of_scenes_gives_one_panel_each() {
    let dir = crate::common::tmp_dir("wp-scenes", "two");
    let o = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "work-precision",
            "scenes/steep.toml",
            "scenes/from-rest-0.1.toml",
        ])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = std::fs::read_to_string(dir.join("work_precision.svg")).unwrap();
    let csv = std::fs::read_to_string(dir.join("runs.csv")).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    // Panel titles are the bold texts, one per scene, in the order given.
    let titles: Vec<&str> = svg
        .split("font-weight=\"bold\">")
        .skip(1)
        .map(|t| t.split('<').next().unwrap())
        .collect();
    assert_eq!(titles.len(), 2, "{titles:?}");
    assert!(
        titles[0].contains("θ0 = 1.4") && titles[1].contains("θ0 = 0.1"),
        "{titles:?}"
    );
    for scene in ["scenes/steep.toml", "scenes/from-rest-0.1.toml"] {
        let quoted = format!("\"{scene}\",");
        assert!(
            csv.lines().any(|l| l.starts_with(&quoted)),
            "{scene} not in runs.csv"
        );
    }
    // One observed-order line for dop853 per scene, with its standard error and range.
    let fits: Vec<&str> = stdout
        .lines()
        .filter(|l| l.trim_start().starts_with("dop853") && l.contains("classical"))
        .collect();
    assert_eq!(fits.len(), 2, "{stdout}");
    assert!(
        fits.iter()
            .any(|l| l.contains(" ± ") && l.contains("rhs ") && l.contains("floor")),
        "{fits:?}"
    );
    assert!(
        fits.iter().any(|l| l.contains("not fitted (")),
        "steep (θ0 = 1.4) reaches the floor in fewer than 10 steps: {fits:?}"
    );
    // Each of the four adaptive methods has its tolerance line, on each scene.
    assert!(
        stdout.matches("tolerance slope").count() >= 2 * 4,
        "{stdout}"
    );
}
