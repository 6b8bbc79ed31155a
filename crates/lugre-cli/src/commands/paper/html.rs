//! `index.html` of `lugre paper`: one self-contained page (inline style, no script, nothing
//! fetched from the network) showing every redrawn figure with its caption, a table of each
//! example's hysteresis loop, and the errata of Theorem A.
//!
//! The page links only to the files `lugre paper` writes next to it. Numbers in the tables are
//! printed as the shortest decimal that reads back to the same f64 (the form `lugre loop
//! --json` prints), and each carries `data-json="PATH"`, the place of the same number in
//! `lugre loop ARGS --json` for the table's `data-args`, so that they can be checked
//! mechanically (the integration tests do).

use lugre::{Loop, TheoremA};
use std::fmt::Write;

use super::{LoopExample, Paper, PaperFigure};
use crate::fmt::{exact, sig};
use crate::hysteresis::kind_name;

/// A section of the page: an anchor, a heading, an introduction, its figures and the loop
/// examples it tabulates.
struct Section<'a> {
    id: &'static str,
    heading: &'static str,
    intro: &'static str,
    figures: &'static [u32],
    examples: Vec<&'a LoopExample>,
}

/// The page's sections, in order.
fn sections(paper: &Paper) -> [Section<'_>; 5] {
    let example = |id: &'static str| paper.examples.iter().filter(move |e| e.id == id);
    [
        Section {
            id: "normalized-input",
            heading: "§3.2.2 The normalized input",
            intro: "The hysteresis loop depends on the input only through its normalized \
                    input ψᵤ = u ∘ ρᵤ⁻¹, piecewise linear with slopes ±1 between the turning \
                    points (eq. 12).",
            figures: &[3],
            examples: vec![],
        },
        Section {
            id: "example1",
            heading: "§4.1 Example 1: an approach to the concept of hysteresis loop",
            intro: "The Dahl model (ρ = 1) followed by a first-order lag (eq. 18), driven by \
                    uᵧ(t) = sin(2πt/γ). The Dahl part is solved exactly, the lag by an \
                    adaptive L-stable integrator (relative tolerance 1e-10).",
            figures: &[4],
            examples: vec![],
        },
        Section {
            id: "example2",
            heading: "§4.2 Example 2: the hysteresis loop of the LuGre model",
            intro: "LuGre with the Stribeck curve of Fig. 5 and σ0 = σ1 = 1, f = 0, driven by \
                    the triangle input of period 2 from x0 = 0.",
            figures: &[5, 6, 7, 8, 9],
            examples: example("example2").collect(),
        },
        Section {
            id: "example3",
            heading: "§4.3 Example 3: a hysteresis loop with a minor loop",
            intro: "The model of Example 2 driven by the bimodal input with turning points \
                    0, 1, 0.2, 1.5 (Definition 1: uₘᵢₙ,₁ = 0, uₘₐₓ,₁ = 1, uₘᵢₙ,₂ = 0.2, \
                    uₘₐₓ,₂ = 1.5).",
            figures: &[10, 11, 12, 13],
            examples: example("example3").collect(),
        },
        Section {
            id: "example4",
            heading: "§4.4 Example 4: the shape of the minor loop",
            intro: "σ0 = 6 and the bimodal input 0, 1, 0.5, 1.5; then σ0 = 1 (Fig. 16), then \
                    also uₘᵢₙ,₂ = 0.2 (Fig. 17). The minor loop is the arc ρ ∈ [ρ₁, ρ₅] of \
                    Theorem A (b).",
            figures: &[14, 15, 16, 17],
            examples: paper
                .examples
                .iter()
                .filter(|e| matches!(e.id, "example4" | "fig16" | "fig17"))
                .collect(),
        },
    ]
}

pub(crate) fn page(paper: &Paper) -> String {
    let sections = sections(paper);
    let mut h = String::with_capacity(64 * 1024);
    h.push_str(HEAD);
    let _ = write!(
        h,
        "<h1>Minor loops of the Dahl and LuGre models: the paper's figures, redrawn</h1>\n\
         <p class=\"lead\">Figures 3-17 of F. Ikhouane, V. Mañosa, G. Pujol, <i>Minor loops of \
         the Dahl and LuGre models</i>, recomputed and redrawn by <code>lugre paper</code> \
         (lugre {}). Each figure is below as PNG, with links to its SVG and to the CSV of every \
         curve drawn. The tables give each example's hysteresis loop y° as \
         <code>lugre loop … --json</code> prints it.</p>\n",
        env!("CARGO_PKG_VERSION")
    );
    h.push_str("<nav><ul>");
    for s in &sections {
        let _ = write!(h, "<li><a href=\"#{}\">{}</a></li>", s.id, esc(s.heading));
    }
    h.push_str("<li><a href=\"#theorem-a\">Theorem A: errata and the stable form</a></li>");
    h.push_str("<li><a href=\"#numbers\">About the numbers</a></li>");
    h.push_str(
        "<li><a href=\"canudas1995/index.html\">Second report: friction in closed loop \
         (Canudas de Wit et al. 1995, Figs. 2, 3, 4, 6, 8)</a></li>\
         <li><a href=\"models/index.html\">Third report: LuGre next to every model of \
         the zoo (closing and drifting minor \
         loops)</a></li></ul></nav>\n",
    );

    for s in &sections {
        section(&mut h, paper, s);
    }
    errata(&mut h);
    h.push_str(NUMBERS);
    h.push_str("</body>\n</html>\n");
    h
}

fn section(h: &mut String, paper: &Paper, s: &Section) {
    let _ = write!(
        h,
        "<section id=\"{}\">\n<h2>{}</h2>\n<p>{}</p>\n",
        s.id,
        esc(s.heading),
        esc(s.intro)
    );
    for &n in s.figures {
        if let Some(f) = paper.figures.iter().find(|f| f.number == n) {
            figure(h, f);
        }
        for ex in s.examples.iter().filter(|e| e.figures.last() == Some(&n)) {
            table(h, ex);
        }
    }
    h.push_str("</section>\n");
}

pub(super) fn figure(h: &mut String, f: &PaperFigure) {
    let stem = f.stem();
    let (w, hgt) = f.figure.size;
    let _ = write!(
        h,
        "<figure id=\"{stem}\">\n<img src=\"{stem}.png\" width=\"{w}\" height=\"{hgt}\" \
         alt=\"Figure {n}\">\n<figcaption><b>Fig. {n}.</b> {cap}<br>\n<span class=\"files\">\
         <a href=\"{stem}.svg\">{stem}.svg</a> · <a href=\"{stem}.png\">{stem}.png</a> · \
         data:",
        n = f.number,
        cap = esc(&f.caption)
    );
    for (name, _) in f.csv_files() {
        let _ = write!(h, " <a href=\"{name}\">{name}</a>");
    }
    h.push_str("</span></figcaption>\n</figure>\n");
}

/// A number cell: the shortest round-trip form, tagged with its place in the JSON report.
fn num(h: &mut String, path: &str, x: f64) {
    let _ = write!(h, "<td data-json=\"{path}\">{}</td>", exact(x));
}

fn table(h: &mut String, ex: &LoopExample) {
    let args = ex.loop_args();
    let hl = &ex.hl;
    let m = hl.model();
    let _ = write!(
        h,
        "<div class=\"numbers\" id=\"{id}-numbers\" data-args=\"{args}\">\n\
         <h3>{title}: the hysteresis loop</h3>\n\
         <p>Same numbers: <code>lugre {args} --json</code>. LuGre σ0 = {sigma0}, \
         g(0) = Fs = <span data-json=\"g0\">{g0}</span>, a = σ0/g(0) = \
         <span data-json=\"a\">{a}</span>, period P = ρ₄ = <span data-json=\"period\">{p}</span> \
         (the total variation of u per period).</p>\n",
        id = ex.id,
        title = esc(&ex.title),
        args = esc(&args.join(" ")),
        sigma0 = exact(ex.sigma0),
        g0 = exact(m.g0()),
        a = exact(m.a()),
        p = exact(hl.period()),
    );
    if let Some(note) = &ex.note {
        let _ = writeln!(h, "<p class=\"note\">{}</p>", esc(note));
    }

    h.push_str(
        "<table>\n<caption>y° at the turning points</caption>\n\
         <tr><th>k</th><th>ρₖ</th><th>u = ψᵤ(ρₖ)</th><th>y°(ρₖ)</th></tr>\n",
    );
    for (k, p) in hl.turning_loop_points().iter().enumerate() {
        let _ = write!(h, "<tr><td>{k}</td>");
        num(h, &format!("turning_points.{k}.rho"), p.rho);
        num(h, &format!("turning_points.{k}.u"), p.u);
        num(h, &format!("turning_points.{k}.y"), p.y);
        h.push_str("</tr>\n");
    }
    h.push_str("</table>\n");

    if let Some(ta) = &ex.theorem_a {
        theorem_a_table(h, ta);
    }

    loops_table(h, &ex.loops);
    let _ = write!(
        h,
        "<p>Energy dissipated per period (the work over the whole loop): \
         <span data-json=\"work_per_period\">{}</span> (≈ {}).</p>\n</div><!-- /numbers -->\n",
        exact(hl.work_per_period()),
        sig(hl.work_per_period(), 6)
    );
}

/// Theorem A's rho_0 .. rho_5 and y° there, and the minor loop.
fn theorem_a_table(h: &mut String, ta: &TheoremA) {
    h.push_str(
        "<table>\n<caption>Theorem A: ρ₀ … ρ₅ and y° there</caption>\n\
         <tr><th>i</th><th>ρᵢ</th><th>y°(ρᵢ)</th></tr>\n",
    );
    for i in 0..6 {
        let _ = write!(h, "<tr><td>{i}</td>");
        num(h, &format!("theorem_a.rho.{i}"), ta.rho[i]);
        num(h, &format!("theorem_a.y.{i}"), ta.y[i]);
        h.push_str("</tr>\n");
    }
    h.push_str("<tr><td>minor loop [ρ₁, ρ₅]</td>");
    num(h, "theorem_a.minor_loop.0", ta.minor_loop[0]);
    num(h, "theorem_a.minor_loop.1", ta.minor_loop[1]);
    h.push_str("</tr>\n</table>\n");
}

/// Every loop: its arc, its turning points and its energies.
fn loops_table(h: &mut String, loops: &[Loop]) {
    h.push_str(
        "<table class=\"wide\">\n<caption>Every loop: the arc from ρ_A through the reversal \
         ρ_B to ρ_C, the first return to u_A, and the energy over it</caption>\n\
         <tr><th>#</th><th>kind</th><th>ρ_A</th><th>ρ_B</th><th>ρ_C</th><th>u_A</th>\
         <th>u_B</th><th>y°(ρ_A)</th><th>y°(ρ_C)</th><th>work W = ∫ y° dψ</th>\
         <th>stored ΔV</th><th>dissipated D = W − ΔV</th><th>gap y_C − y_A</th></tr>\n",
    );
    for (i, l) in loops.iter().enumerate() {
        let kind = kind_name(l.kind);
        let _ = write!(h, "<tr><td>{i}</td><td>{kind}</td>");
        num(h, &format!("loops.{i}.start.rho"), l.start.rho);
        num(h, &format!("loops.{i}.reversal.rho"), l.reversal.rho);
        num(h, &format!("loops.{i}.end.rho"), l.end.rho);
        num(h, &format!("loops.{i}.start.u"), l.start.u);
        num(h, &format!("loops.{i}.reversal.u"), l.reversal.u);
        num(h, &format!("loops.{i}.start.y"), l.start.y);
        num(h, &format!("loops.{i}.end.y"), l.end.y);
        num(h, &format!("loops.{i}.work"), l.energy.work);
        num(
            h,
            &format!("loops.{i}.stored_energy_change"),
            l.energy.stored_energy_change,
        );
        num(h, &format!("loops.{i}.dissipation"), l.energy.dissipation);
        num(h, &format!("loops.{i}.closure_gap"), l.energy.closure_gap);
        h.push_str("</tr>\n");
    }
    h.push_str("</table>\n");
}

fn errata(h: &mut String) {
    h.push_str(
        "<section id=\"theorem-a\">\n<h2>Theorem A: errata and the stable form used here</h2>\n\
         <p>The proof's eqs. 13-16 are right; the theorem's <em>statement</em> has two sign \
         errors, and its formula for y°(0) cannot be evaluated in floating point for stiff \
         models.</p>\n<ol>\n\
         <li><b>Sign of g(0)[…] on the loop's segments.</b> The statement gives \
         y°(t) = e<sup>−a(t−ρᵢ)</sup> (y°(ρᵢ) <b>−</b> g(0)[e<sup>a(t−ρᵢ)</sup> − 1]) for \
         every segment i = 0 … 3. The sign is <b>+</b> on the increasing segments \
         (i = 0, 2: ρ ∈ [0, ρ₁] and [ρ₂, ρ₃]) and − only on the decreasing ones (i = 1, 3), \
         as in eqs. 13 and 15.</li>\n\
         <li><b>Sign of g(0)[…] in the recursion for y°(ρᵢ).</b> The statement gives \
         y°(ρᵢ) = e<sup>−a(ρᵢ−ρᵢ₋₁)</sup> (y°(ρᵢ₋₁) <b>+</b> g(0)[…]) for every \
         i = 1 … 4. The sign is <b>−</b> for i = 2 and i = 4, at the ends of the decreasing \
         segments, as in eqs. 14 and 16.</li>\n</ol>\n\
         <p>Also, ψᵤ and y° in the statement are functions of the normalized variable ρ, not \
         of the time t (they coincide only for a normalized input such as Example 4's).</p>\n\
         <p><b>Overflow of the printed formula.</b> The formula for y°(0) (eq. 13) multiplies \
         e<sup>aρ₁</sup>, e<sup>aρ₂</sup>, e<sup>aρ₃</sup>, e<sup>aρ₄</sup> with \
         a = σ0/g(0). In double precision e<sup>aρ₄</sup> overflows once aρ₄ &gt; ~709: with \
         the realistic σ0 = 10⁵ N/m, Fs = 1.5 N and an input travelling 1 cm up and down, \
         aρ₄ ≈ 1333 and the printed formula gives ∞/∞.</p>\n\
         <p><b>The stable form used instead.</b> On segment k, from turning point u<sub>k</sub> \
         to u<sub>k+1</sub>, of length L<sub>k</sub> and direction s<sub>k</sub> = ±1:</p>\n\
         <pre>y(ρ)    = s_k g0 + (y_k − s_k g0) exp(−a (ρ − ρ_k))\n\
         y_{k+1} = s_k g0 + (y_k − s_k g0) exp(−a L_k)</pre>\n\
         <p>One period is the affine map y<sub>N</sub> = E y<sub>0</sub> + c with \
         E = exp(−aP) and c = Σ<sub>k</sub> s<sub>k</sub> g0 (1 − exp(−aL<sub>k</sub>)) \
         exp(−a(P − ρ<sub>k+1</sub>)), so y°(0) = c / (1 − E). Every exponent is ≤ 0, so \
         nothing overflows; 1 − exp(−x) is computed with expm1 (and a series where aP is \
         tiny). It equals eq. 13 wherever eq. 13 is finite. All loops, tables and Figs. 8-17 \
         use it.</p>\n</section>\n",
    );
}

/// Escapes text for HTML element content and attribute values.
pub(super) fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

pub(super) const HEAD: &str =
    "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
<title>Minor loops of the Dahl and LuGre models: figures redrawn by lugre</title>\n<style>\n\
body { font-family: 'DejaVu Sans', Verdana, sans-serif; max-width: 1080px; margin: 2em auto; \
padding: 0 1em; color: #111; line-height: 1.45; }\n\
h1 { font-size: 1.6em; } h2 { margin-top: 2.2em; border-bottom: 1px solid #bbb; }\n\
figure { margin: 1.5em 0; } figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }\n\
figcaption { font-size: 0.95em; } .files { font-size: 0.85em; color: #444; }\n\
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.9em; }\n\
caption { text-align: left; font-weight: bold; padding: 0.3em 0; }\n\
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: right; }\n\
th { background: #f0f0f0; } td[data-json] { font-family: 'DejaVu Sans Mono', monospace; }\n\
.wide { display: block; overflow-x: auto; } .numbers { background: #fafafa; padding: 0.2em 1em; \
border-left: 3px solid #0a5ab5; margin: 1.5em 0; }\n\
.note { font-style: italic; } pre { background: #f4f4f4; padding: 0.6em; overflow-x: auto; }\n\
nav ul { columns: 2; }\n</style>\n</head>\n<body>\n";

const NUMBERS: &str = "<section id=\"numbers\">\n<h2>About the numbers</h2>\n\
<p>Every number in the tables is the shortest decimal that reads back to exactly the same \
double-precision value, as <code>lugre loop --json</code> prints it: run the command shown \
above a table and compare. They are the rate-independent limit (γ → ∞): the loop depends \
only on σ0 and g(0) = Fs, not on σ1, f or the shape of g away from 0. The work over an arc is \
W = ∫ y° dψ; ΔV = (y_C² − y_A²)/(2σ0) is the change of the energy stored in the bristles; \
D = W − ΔV = (1/g(0)) ∫ y°² dρ ≥ 0 is the energy dissipated. A minor loop's work can be \
negative (its arc does not close); its dissipation cannot. The CSV files hold the points of \
each curve as drawn; <code>lugre loop --csv</code> and <code>lugre simulate --csv</code> give \
the curves at any resolution.</p>\n</section>\n";
