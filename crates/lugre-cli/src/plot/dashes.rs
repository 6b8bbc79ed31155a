//! Dash patterns in pixel space (plotters has no dash-dot, and dashing in data space would
//! stretch with the axes' aspect ratio), and the thinning of polylines before they are cut.

use super::LineStyle;

impl LineStyle {
    /// On/off lengths in pixels at scale `s`.
    pub(super) fn pattern(self, s: f64) -> Vec<f64> {
        let base: &[f64] = match self {
            LineStyle::Solid => &[],
            LineStyle::Dashed => &[11.0, 6.0],
            LineStyle::Dotted => &[2.0, 4.0],
            LineStyle::DashDot => &[11.0, 4.0, 2.0, 4.0],
        };
        base.iter().map(|v| v * s).collect()
    }
}

/// Points of a drawn polyline closer than this (pixels) to the previous one are dropped: the
/// bitmap backend rounds to whole pixels, and runs of sub-pixel steps draw as jagged lines.
pub(super) const MIN_PIXEL_STEP: f64 = 2.5;

/// `points` without those closer than `step` to the last kept one (the last point is kept).
pub(super) fn thin(points: &[(f64, f64)], step: f64) -> Vec<(f64, f64)> {
    let mut kept: Vec<(f64, f64)> = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        let far = kept
            .last()
            .is_none_or(|q| (p.0 - q.0).hypot(p.1 - q.1) >= step);
        if far || i + 1 == points.len() {
            kept.push(p);
        }
    }
    kept
}

/// Splits a pixel polyline into the "on" pieces of a dash pattern (solid: one piece).
pub(super) fn dash(points: &[(f64, f64)], pattern: &[f64]) -> Vec<Vec<(f64, f64)>> {
    if pattern.is_empty() || points.len() < 2 {
        return vec![points.to_vec()];
    }
    let mut pieces = Vec::new();
    let mut current: Vec<(f64, f64)> = vec![points[0]];
    let (mut idx, mut left, mut on) = (0usize, pattern[0], true);
    for w in points.windows(2) {
        let (mut a, b) = (w[0], w[1]);
        let mut seg = ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
        while seg > left {
            let t = left / seg;
            let cut = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            if on {
                current.push(cut);
                pieces.push(std::mem::take(&mut current));
            } else {
                current = vec![cut];
            }
            seg -= left;
            a = cut;
            idx = (idx + 1) % pattern.len();
            left = pattern[idx];
            on = !on;
        }
        left -= seg;
        if on {
            current.push(b);
        }
    }
    if on && current.len() > 1 {
        pieces.push(current);
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dashes_cover_the_pattern() {
        let line = [(0.0, 0.0), (34.0, 0.0)];
        let pieces = dash(&line, &[10.0, 5.0]);
        let spans: Vec<(f64, f64)> = pieces.iter().map(|p| (p[0].0, p[p.len() - 1].0)).collect();
        assert_eq!(spans, vec![(0.0, 10.0), (15.0, 25.0), (30.0, 34.0)]);
        assert_eq!(dash(&line, &[]).len(), 1);
    }
}
