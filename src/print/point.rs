//! Points named by id in the markdown and in quantity ids: a point of the ladder by the
//! fraction of the way from C to D (`ladder:1/4`) or a point fixed in the lab in units of l
//! (`lab:1/2,3/2`), as `ladder diagram --about` names them. Read exactly (no float), so the
//! point is the same in every scalar type.

use crate::ladder::analysis::Reference;

/// An exact fraction written as `3`, `-1/4` or `0.25`, as (numerator, denominator).
pub fn fraction(text: &str) -> Option<(i64, i64)> {
    let t = text.trim();
    if let Some((p, q)) = t.split_once('/') {
        let (p, q): (i64, i64) = (p.trim().parse().ok()?, q.trim().parse().ok()?);
        return (q > 0).then_some((p, q));
    }
    let (int, dec) = t.split_once('.').unwrap_or((t, ""));
    if dec.len() > 12 || !dec.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    let den = 10i64.checked_pow(dec.len() as u32)?;
    let whole: i64 = int.parse().ok()?;
    let part: i64 = if dec.is_empty() { 0 } else { dec.parse().ok()? };
    let sign = if int.trim_start().starts_with('-') {
        -1
    } else {
        1
    };
    Some((whole.checked_mul(den)?.checked_add(sign * part)?, den))
}

/// A point of the ladder or the lab by its id: `ladder:1/4` (a quarter of the way from C to D,
/// between 0 and 1) or `lab:1/2,3/2` (fixed at x = l/2, y = 3l/2); `None` for anything else.
pub fn parse_point(id: &str) -> Option<Reference> {
    if let Some(f) = id.strip_prefix("ladder:") {
        let (n, d) = fraction(f)?;
        return (0..=d).contains(&n).then_some(Reference::OnLadder(n, d));
    }
    let (x, y) = id.strip_prefix("lab:")?.split_once(',')?;
    let ((xn, xd), (yn, yd)) = (fraction(x)?, fraction(y)?);
    Some(Reference::Lab(
        xn.checked_mul(yd)?,
        yn.checked_mul(xd)?,
        xd.checked_mul(yd)?,
    ))
}
