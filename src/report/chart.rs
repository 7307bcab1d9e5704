//! The data of a line chart: named series, titles and labels, and the options beyond them (log
//! axes, markers, dashed references, labelled events). Shared by the writers in
//! [`super::plot`] and the drawing in [`super::svg_chart`].

/// One named line.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// (x, y) points in drawing order; non-finite points are dropped.
    pub points: Vec<(f64, f64)>,
}

/// Titles, labels and markers of a plot.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlotSpec {
    /// Caption.
    pub title: String,
    /// x-axis label (with units).
    pub x_label: String,
    /// y-axis label (with units).
    pub y_label: String,
    /// Vertical marker lines at these x values.
    pub vlines: Vec<f64>,
    /// Horizontal marker lines at these y values.
    pub hlines: Vec<f64>,
}

/// A labelled vertical event line (separation, flat, a force crossing zero).
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// Where, in data units of x.
    pub x: f64,
    /// What happens there.
    pub label: String,
}

/// A plot with the options beyond [`PlotSpec`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chart {
    /// Titles, labels, plain marker lines.
    pub spec: PlotSpec,
    /// Logarithmic x axis (data > 0; ticks at decades).
    pub log_x: bool,
    /// Logarithmic y axis (data > 0; ticks at decades).
    pub log_y: bool,
    /// Labelled event lines.
    pub marks: Vec<Mark>,
    /// A marker on every point (measured data rather than a sampled curve).
    pub markers: bool,
    /// Names of the series drawn dashed (references, peers, fronts).
    pub dashed: Vec<String>,
    /// Peers: (series, the series it is a peer of). A peer is drawn dashed, with markers, in
    /// the colour and marker of the series it compares with (same method, another code).
    pub peers: Vec<(String, String)>,
}

impl From<PlotSpec> for Chart {
    fn from(spec: PlotSpec) -> Chart {
        Chart {
            spec,
            ..Chart::default()
        }
    }
}
