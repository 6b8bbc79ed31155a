//! Figs. 6-13: the simulated responses of Examples 2 and 3 converging to the hysteresis loop.

use anyhow::Result;
use lugre::simulate::{merge_times, uniform_times};
use lugre::{Gamma, HysteresisLoop, LuGre, PiecewiseLinear, Simulator, Trajectory, TurningPoints};

use super::examples::{paper_model, LoopExample, PaperInput};
use super::figures::PaperFigure;
use crate::fmt::sig;
use crate::hysteresis::arc_points;
use crate::plot::{Curve, Figure, LineStyle, RGBColor, BLACK, BLUE, GREEN, ORANGE, RED};

/// Output times per period of the time plots (kinks and the instants just before them are
/// added: the output of eq. 5 jumps at a kink when `sigma1 > 0`).
const SAMPLES_PER_PERIOD: usize = 400;

/// A jump at a kink is drawn from the value this fraction of a period before it.
const BEFORE_KINK: f64 = 1e-9;

/// Output times over `periods` periods: a uniform grid, every kink, and the instant just
/// before each kink (so that jumps of the output draw as vertical steps); the run ends just
/// before its end.
fn plot_times(pl: &PiecewiseLinear, periods: u32) -> Vec<f64> {
    let start = pl.times()[0];
    let period = pl.period();
    let knots = pl.knot_times(periods);
    let before: Vec<f64> = knots
        .iter()
        .filter(|&&t| t > start)
        .map(|&t| t - BEFORE_KINK * period)
        .collect();
    let mut times = merge_times(
        &merge_times(
            &uniform_times(start, period, periods, SAMPLES_PER_PERIOD),
            &knots,
        ),
        &before,
    );
    // The run's end is a kink too, where the simulator reports the value just after it (the
    // next period's): a jump drawn at the right edge of the plot, into a period not shown.
    times.pop();
    times
}

fn simulate(
    model: &LuGre,
    pl: &PiecewiseLinear,
    periods: u32,
    gamma: Gamma,
    times: &[f64],
) -> Result<Trajectory> {
    let mut out = Trajectory::with_capacity(times.len());
    Simulator::new(model, gamma, 0.0)?.at_times(pl, periods, times, &mut out)?;
    Ok(out)
}

/// `(rho, y°(rho))` over one period: a uniform grid and the turning points.
fn loop_in_time(hl: &HysteresisLoop) -> Vec<(f64, f64)> {
    let p = hl.period();
    let mut rhos = uniform_times(0.0, p, 1, SAMPLES_PER_PERIOD);
    rhos = merge_times(&rhos, hl.turning_rho());
    rhos.iter().map(|&r| (r, hl.y_at(r))).collect()
}

/// The four figures of Examples 2 and 3 (Figs. 6-9 and 10-13): the input, y_gamma for
/// gamma = 1, 10, 100 with y*_u, the periods y*_{u,k} converging to y°, and the convergence
/// in the (u, y) plane. The input is at unit speed, so t = rho.
pub(super) fn convergence_figures(
    ex: &LoopExample,
    first: u32,
    periods: u32,
    k_count: u32,
) -> Result<Vec<PaperFigure>> {
    let model = paper_model(ex.sigma0)?;
    let tp = match &ex.input {
        PaperInput::TurningPoints(u) => TurningPoints::new(u)?,
        PaperInput::Bimodal(b) => b.turning_points(),
    };
    let pl = PiecewiseLinear::from_turning_points(&tp, 1.0)?;
    let times = plot_times(&pl, periods);
    let star = simulate(&model, &pl, periods, Gamma::INFINITE, &times)?;
    let c = Convergence {
        ex,
        first,
        example: if first == 6 { "Example 2" } else { "Example 3" },
        periods,
        period: pl.period(),
        model,
        pl,
        times,
        star,
    };
    let fig_input = c.input_figure(&tp);
    let fig_gamma = c.gamma_figure()?;
    let (fig_k, k_curves) = c.periods_figure(k_count);
    let fig_plane = if first == 6 {
        c.graph_figure()
    } else {
        c.graphs_figure(k_curves, k_count)?
    };
    Ok(vec![fig_input, fig_gamma, fig_k, fig_plane])
}

/// What the four figures of one example share: the input at unit speed (so t = rho) and y*_u
/// over the periods shown.
struct Convergence<'a> {
    ex: &'a LoopExample,
    /// The first figure's number: 6 (Example 2) or 10 (Example 3).
    first: u32,
    example: &'static str,
    periods: u32,
    period: f64,
    model: LuGre,
    pl: PiecewiseLinear,
    /// The output times of every response drawn.
    times: Vec<f64>,
    star: Trajectory,
}

/// The k-th period of y*_u in the (u, y) plane, and its colour (Fig. 13 draws them).
type PeriodGraph = (u32, Vec<(f64, f64)>, RGBColor);

impl Convergence<'_> {
    /// The span of t shown.
    fn span(&self) -> String {
        sig(self.periods as f64 * self.period, 6)
    }

    /// Figs. 6 and 10: the input.
    fn input_figure(&self, tp: &TurningPoints) -> PaperFigure {
        let (example, periods) = (self.example, self.periods);
        let turning: Vec<String> = tp.values().iter().map(|&u| sig(u, 6)).collect();
        let turning = turning.join(", ");
        // The input: its knots, whose values repeat every period (the last knot of a period is
        // the next one's first, listed once).
        let values = self.pl.values();
        let input: Vec<(f64, f64)> = self
            .pl
            .knot_times(periods)
            .iter()
            .enumerate()
            .map(|(i, &t)| (t, values[i % (values.len() - 1)]))
            .collect();
        PaperFigure {
            number: self.first,
            title: format!("{example}: the input u(t)"),
            caption: format!(
                "u(t) versus t: {example}'s input, turning points {turning} at unit speed (so \
                 ψᵤ = u and ρ = t), period T = {}; {periods} periods shown.",
                sig(self.period, 6)
            ),
            figure: Figure::new("t", "u(t)")
                .curve(Curve::new(input, LineStyle::Solid, BLACK).key("u").width(3)),
            columns: ["t", "u"],
        }
    }

    /// Figs. 7 and 11: y_gamma for gamma = 1, 10, 100, and y*_u.
    fn gamma_figure(&self) -> Result<PaperFigure> {
        let (example, star) = (self.example, &self.star);
        // y*_u, then y_gamma for gamma = 1, 10, 100 on top of it (gamma = 100 is within a
        // line's width of y*_u: drawn first, y*_u would hide it).
        let mut fig = Figure::new("t", "yᵧ(t), y⋆ᵤ(t)").curve(
            Curve::new(pairs(&star.t, &star.y), LineStyle::Solid, BLACK)
                .label("y⋆ᵤ(t) (γ → ∞, eqs. 6-7)")
                .key("y-star"),
        );
        for (gamma, style, color) in [
            (1.0, LineStyle::Dashed, BLUE),
            (10.0, LineStyle::DashDot, RED),
            (100.0, LineStyle::Dotted, GREEN),
        ] {
            let y = simulate(
                &self.model,
                &self.pl,
                self.periods,
                Gamma::new(gamma)?,
                &self.times,
            )?;
            fig = fig.curve(
                Curve::new(pairs(&y.t, &y.y), style, color)
                    .label(format!("yᵧ(t), γ = {}", sig(gamma, 6)))
                    .key(format!("y-gamma{}", sig(gamma, 6)))
                    .width(if style == LineStyle::Dotted { 3 } else { 2 }),
            );
        }
        let span = self.span();
        Ok(PaperFigure {
            number: self.first + 1,
            title: format!("{example}: yᵧ(t) for γ = 1, 10, 100 and y⋆ᵤ(t)"),
            caption: format!(
                "yᵧ(t) versus t ({example}: σ0 = σ1 = 1, Fc = 1, Fs = 2, vs = 1, β = 1, x0 = 0). \
                 Dashed γ = 1, dash-dotted γ = 10, dotted γ = 100; solid y⋆ᵤ(t) versus t. As γ \
                 grows yᵧ converges to y⋆ᵤ. Computed exactly (eq. 5 is linear on each segment \
                 of the input), not by a numerical ODE solver; t ∈ [0, {span}]. The vertical \
                 steps are the jumps of σ1 x′/γ where u′ changes sign."
            ),
            figure: fig,
            columns: ["t", "y"],
        })
    }

    /// Figs. 8 and 12: the periods y*_{u,k} converging to y°; also returns each period in the
    /// (u, y) plane.
    fn periods_figure(&self, k_count: u32) -> (PaperFigure, Vec<PeriodGraph>) {
        let (ex, example, star, period) = (self.ex, self.example, &self.star, self.period);
        // y° first, under the y*_{u,k} that converge onto it.
        let mut fig = Figure::new("t ∈ [0, T]", "y⋆ᵤ,ₖ(t), y°ᵤ(t)").curve(
            Curve::new(loop_in_time(&ex.hl), LineStyle::Solid, BLACK)
                .label("y°ᵤ(t), the periodic steady state")
                .key("y-circ")
                .width(3),
        );
        let k_colors = [BLUE, RED, GREEN, ORANGE];
        let mut k_curves = Vec::new();
        for k in 0..k_count {
            let shift = f64::from(k) * period;
            let range = star.range_between(shift, shift + period);
            let pts: Vec<(f64, f64)> = range.map(|i| (star.t[i] - shift, star.y[i])).collect();
            let pts_u: Vec<(f64, f64)> = star
                .range_between(shift, shift + period)
                .map(|i| (star.u[i], star.y[i]))
                .collect();
            let color = k_colors[k as usize % k_colors.len()];
            fig = fig.curve(
                Curve::new(pts, LineStyle::Dashed, color)
                    .label(format!("y⋆ᵤ,ₖ(t), k = {k}"))
                    .key(format!("y-star-k{k}")),
            );
            k_curves.push((k, pts_u, color));
        }
        let figure = PaperFigure {
            number: self.first + 2,
            title: format!(
                "{example}: y⋆ᵤ,ₖ(t), k = 0..{}, converging to y°ᵤ(t)",
                k_count - 1
            ),
            caption: format!(
                "Convergence of the functions y⋆ᵤ,ₖ(t) = y⋆ᵤ(t + kT) to y°ᵤ. Dashed y⋆ᵤ,ₖ(t) \
                 versus t for k = {}; solid y°ᵤ(t) versus t (eqs. 8 and 10). The distance \
                 shrinks by exp(−aT) = {} per period (a = σ0/g(0) = {}).",
                (0..k_count)
                    .map(|k| k.to_string())
                    .collect::<Vec<_>>()
                    .join(", "),
                sig((-ex.hl.model().a() * period).exp(), 4),
                sig(ex.hl.model().a(), 6)
            ),
            figure: fig,
            columns: ["t", "y"],
        };
        (figure, k_curves)
    }

    /// The hysteresis loop, solid, under what converges to it in the (u, y) plane.
    fn loop_curve(&self) -> Curve {
        let hl = &self.ex.hl;
        Curve::new(arc_points(hl, 0.0, hl.period()), LineStyle::Solid, BLACK)
            .label("hysteresis loop G°ᵤ")
            .key("loop")
            .width(3)
    }

    /// Fig. 9: G*_u (the whole simulated response) dotted, the loop solid.
    fn graph_figure(&self) -> PaperFigure {
        let (example, star, span) = (self.example, &self.star, self.span());
        let fig = Figure::new("u", "y⋆ᵤ, y°ᵤ").curve(self.loop_curve()).curve(
            Curve::new(pairs(&star.u, &star.y), LineStyle::Dotted, BLUE)
                .label("G⋆ᵤ = {(u(t), y⋆ᵤ(t)), t ≥ 0}")
                .key("G-star")
                .width(3),
        );
        PaperFigure {
            number: self.first + 3,
            title: format!("{example}: G⋆ᵤ converging to the hysteresis loop G°ᵤ"),
            caption: format!(
                "Convergence of the output-versus-input graph G⋆ᵤ to the hysteresis loop G°ᵤ. \
                 Dotted G⋆ᵤ (from x0 = 0, t ∈ [0, {span}]); solid G°ᵤ."
            ),
            figure: fig,
            columns: ["u", "y"],
        }
    }

    /// Fig. 13: the graphs (u, y*_{u,k}) for each k, and the loop.
    fn graphs_figure(&self, k_curves: Vec<PeriodGraph>, k_count: u32) -> Result<PaperFigure> {
        let styles = [LineStyle::Dashed, LineStyle::DashDot, LineStyle::Dotted];
        let mut fig = Figure::new("u", "y⋆ᵤ,ₖ, y°ᵤ").curve(self.loop_curve());
        for (k, pts, color) in k_curves {
            let style = styles[k as usize % styles.len()];
            fig = fig.curve(
                Curve::new(pts, style, color)
                    .label(format!("(u(t), y⋆ᵤ,ₖ(t)), k = {k}"))
                    .key(format!("graph-k{k}"))
                    .width(if style == LineStyle::Dotted { 3 } else { 2 }),
            );
        }
        let b = self.ex.bimodal()?;
        Ok(PaperFigure {
            number: self.first + 3,
            title: format!(
                "{}: (u, y⋆ᵤ,ₖ), k = 0..{}, converging to the loop",
                self.example,
                k_count - 1
            ),
            caption: format!(
                "Convergence of the graphs {{(u(t), y⋆ᵤ,ₖ(t)), t ∈ [0, ρ₄]}} to the hysteresis \
                 loop {{(u(t), y°ᵤ(t)), t ∈ [0, ρ₄]}} (solid). k = 0 dashed, k = 1 dash-dotted, \
                 k = 2 dotted; the minor loop is the small lobe between u = {} and u = {}.",
                sig(b.umin2, 6),
                sig(b.umax1, 6)
            ),
            figure: fig,
            columns: ["u", "y"],
        })
    }
}

fn pairs(x: &[f64], y: &[f64]) -> Vec<(f64, f64)> {
    x.iter().copied().zip(y.iter().copied()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plot_times_bracket_every_kink_and_stop_before_the_end() {
        let tp = TurningPoints::new(&[0.0, 1.0, 0.2, 1.5]).unwrap();
        let pl = PiecewiseLinear::from_turning_points(&tp, 1.0).unwrap();
        let times = plot_times(&pl, 3);
        assert!(times.windows(2).all(|w| w[0] < w[1]));
        let (start, end) = pl.span(3);
        assert_eq!(times[0], start);
        assert!(*times.last().unwrap() < end);
        for &k in &pl.knot_times(3)[1..] {
            let before = k - BEFORE_KINK * pl.period();
            assert!(times.contains(&before), "{k}");
        }
    }
}
