//! Cutting a pixel polyline to the plotting area: the parts inside are drawn, the parts outside
//! are not (pinning outside points to the edges would draw lines along the frame that are no
//! data). Both backends draw what this keeps.

use super::draw::PixelBox;

/// The pieces of `points` inside `area`, each a polyline of two or more points; a segment
/// crossing the boundary is cut where it crosses. Non-finite points break the line.
pub(super) fn clip(points: &[(f64, f64)], area: &PixelBox) -> Vec<Vec<(f64, f64)>> {
    let mut pieces = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let finish = |current: &mut Vec<(f64, f64)>, pieces: &mut Vec<Vec<(f64, f64)>>| {
        if current.len() > 1 {
            pieces.push(std::mem::take(current));
        } else {
            current.clear();
        }
    };
    for w in points.windows(2) {
        match clip_segment(w[0], w[1], area) {
            Some((a, b)) => {
                if current.last() != Some(&a) {
                    finish(&mut current, &mut pieces);
                    current.push(a);
                }
                current.push(b);
            }
            None => finish(&mut current, &mut pieces),
        }
    }
    finish(&mut current, &mut pieces);
    pieces
}

/// The part of the segment `a`-`b` inside `area` (Liang-Barsky), if any.
fn clip_segment(a: (f64, f64), b: (f64, f64), area: &PixelBox) -> Option<((f64, f64), (f64, f64))> {
    if ![a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite()) {
        return None;
    }
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    // Each edge as (p, q): the segment is inside where p t <= q.
    let edges = [
        (-dx, a.0 - area.left),
        (dx, area.right - a.0),
        (-dy, a.1 - area.top),
        (dy, area.bottom - a.1),
    ];
    for (p, q) in edges {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (a.0 + t * dx, a.1 + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    const AREA: PixelBox = PixelBox {
        left: 0.0,
        right: 10.0,
        top: 0.0,
        bottom: 10.0,
    };

    #[test]
    fn inside_points_are_kept_whole() {
        let line = vec![(1.0, 1.0), (5.0, 9.0), (9.0, 2.0)];
        assert_eq!(clip(&line, &AREA), vec![line]);
    }

    #[test]
    fn a_line_leaving_and_coming_back_is_cut_at_the_edge() {
        let line = [(5.0, 5.0), (5.0, 15.0), (8.0, 15.0), (8.0, 5.0)];
        assert_eq!(
            clip(&line, &AREA),
            vec![vec![(5.0, 5.0), (5.0, 10.0)], vec![(8.0, 10.0), (8.0, 5.0)]]
        );
    }

    #[test]
    fn a_segment_crossing_the_whole_area_keeps_its_inside() {
        let line = [(-10.0, 5.0), (20.0, 5.0)];
        assert_eq!(clip(&line, &AREA), vec![vec![(0.0, 5.0), (10.0, 5.0)]]);
        assert!(clip(&[(-5.0, -5.0), (-1.0, 20.0)], &AREA).is_empty());
    }

    #[test]
    fn non_finite_points_break_the_line() {
        let line = [
            (1.0, 1.0),
            (2.0, 2.0),
            (f64::INFINITY, 3.0),
            (4.0, 4.0),
            (5.0, 5.0),
        ];
        assert_eq!(
            clip(&line, &AREA),
            vec![vec![(1.0, 1.0), (2.0, 2.0)], vec![(4.0, 4.0), (5.0, 5.0)]]
        );
    }
}
