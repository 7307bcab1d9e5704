//! The axes of a line chart ([`super::svg_chart`]): linear axes with round ticks, and real
//! logarithmic axes whose ticks sit at whole decades, labelled 10⁻¹², 10⁻⁸, ….

/// `10` to the integer power `k`, as text with Unicode superscripts: 10⁻¹².
pub fn decade_label(k: i32) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for d in k.unsigned_abs().to_string().bytes() {
        s.push(SUP[(d - b'0') as usize]);
    }
    s
}

/// One axis: its range in plotted units (log10 of the data on a log axis) and its ticks.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// Lower end, plotted units.
    pub lo: f64,
    /// Upper end, plotted units.
    pub hi: f64,
    /// Ticks: (position in plotted units, label).
    pub ticks: Vec<(f64, String)>,
    /// Logarithmic.
    pub log: bool,
}

impl Axis {
    /// The axis through `values` (data units; non-positive values are left out on a log axis).
    pub fn fit(values: impl Iterator<Item = f64>, log: bool) -> Axis {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.filter(|v| v.is_finite() && (!log || *v > 0.0)) {
            let v = if log { v.log10() } else { v };
            lo = lo.min(v);
            hi = hi.max(v);
        }
        if !lo.is_finite() {
            (lo, hi) = (0.0, 1.0);
        }
        if log {
            let (a, b) = (lo.floor(), hi.ceil().max(lo.floor() + 1.0));
            let every = ((b - a) / 8.0).ceil().max(1.0);
            let first = (a / every).ceil() * every;
            let ticks = (0..)
                .map(|i| first + i as f64 * every)
                .take_while(|&k| k <= b + 1e-9)
                .map(|k| (k, decade_label(k as i32)))
                .collect();
            return Axis {
                lo: a,
                hi: b,
                ticks,
                log,
            };
        }
        if hi - lo < 1e-300 {
            let pad = 0.5 * lo.abs().max(1.0);
            (lo, hi) = (lo - pad, hi + pad);
        }
        let pad = 0.04 * (hi - lo);
        let (lo, hi) = (lo - pad, hi + pad);
        let raw = (hi - lo) / 6.0;
        let mag = 10f64.powf(raw.log10().floor());
        let step = [1.0, 2.0, 5.0, 10.0]
            .iter()
            .map(|m| m * mag)
            .find(|s| *s >= raw)
            .unwrap_or(10.0 * mag);
        let decimals = (-step.log10().floor()).max(0.0) as usize;
        let first = (lo / step).ceil();
        let ticks = (0..)
            .map(|i| (first + i as f64) * step)
            .take_while(|&v| v <= hi)
            .map(|v| {
                let v = if v.abs() < step * 1e-9 { 0.0 } else { v };
                (v, format!("{v:.decimals$}").replace('-', "−"))
            })
            .collect();
        Axis { lo, hi, ticks, log }
    }

    /// A data value in plotted units (None when it cannot be shown on this axis).
    pub fn map(&self, v: f64) -> Option<f64> {
        match (self.log, v.is_finite()) {
            (true, true) if v > 0.0 => Some(v.log10()),
            (false, true) => Some(v),
            _ => None,
        }
    }
}
