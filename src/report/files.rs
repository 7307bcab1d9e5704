//! Output files, written all-or-nothing: each goes to a hidden temporary name in the target
//! directory first and is renamed into place only when every file has been written.

use super::plot::{chart_plot, line_plot, panel_plot, Chart, PlotSpec, Series};
use std::path::Path;

/// A file to write.
#[derive(Clone, Debug, PartialEq)]
pub enum Content {
    /// Text (CSV, JSON).
    Text(String),
    /// An SVG line plot.
    Plot(PlotSpec, Vec<Series>),
    /// An SVG figure of several line plots (panels).
    Panels(Vec<(Chart, Vec<Series>)>),
    /// An SVG chart (log axes, markers, events).
    Chart(Chart, Vec<Series>),
}

/// A named output file.
#[derive(Clone, Debug, PartialEq)]
pub struct OutFile {
    /// File name inside the output directory.
    pub name: String,
    /// What goes in it.
    pub content: Content,
}

impl OutFile {
    /// A text file.
    pub fn text(name: &str, text: String) -> Self {
        OutFile {
            name: name.into(),
            content: Content::Text(text),
        }
    }
    /// An SVG figure with one panel per entry.
    pub fn panels<C: Into<Chart>>(name: &str, panels: Vec<(C, Vec<Series>)>) -> Self {
        OutFile {
            name: name.into(),
            content: Content::Panels(panels.into_iter().map(|(c, s)| (c.into(), s)).collect()),
        }
    }
    /// An SVG chart.
    pub fn chart(name: &str, chart: Chart, series: Vec<Series>) -> Self {
        OutFile {
            name: name.into(),
            content: Content::Chart(chart, series),
        }
    }
    /// An SVG plot.
    pub fn plot(name: &str, spec: PlotSpec, series: Vec<Series>) -> Self {
        OutFile {
            name: name.into(),
            content: Content::Plot(spec, series),
        }
    }
}

/// Write `files` into `dir` (created if missing); on any failure remove what was written.
pub fn write_all(dir: &Path, files: &[OutFile]) -> Result<(), String> {
    if files.is_empty() {
        return Ok(());
    }
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("{}: cannot create the output directory: {e}", dir.display()))?;
    let mut temps = Vec::new();
    let result = (|| {
        for f in files {
            let tmp = dir.join(format!(".{}.tmp-{}", f.name, std::process::id()));
            temps.push(tmp.clone());
            match &f.content {
                Content::Text(t) => std::fs::write(&tmp, t)
                    .map_err(|e| format!("{}: cannot write: {e}", tmp.display()))?,
                Content::Plot(spec, series) => line_plot(&tmp, spec, series)?,
                Content::Panels(panels) => panel_plot(&tmp, panels)?,
                Content::Chart(chart, series) => chart_plot(&tmp, chart, series)?,
            }
        }
        for (f, tmp) in files.iter().zip(&temps) {
            let dest = dir.join(&f.name);
            std::fs::rename(tmp, &dest)
                .map_err(|e| format!("{}: cannot write: {e}", dest.display()))?;
        }
        Ok(())
    })();
    if result.is_err() {
        for t in &temps {
            let _ = std::fs::remove_file(t);
        }
    }
    result
}
