//! Minor loops: Theorem A's edge cases, random Definition-1 inputs, nesting on a hand-designed
//! 7-modal input, invariance under rotating the period's start, an independent brute-force
//! characterization of the loops, and linear scaling.
//!
//! References: Theorem A (b) (the minor loop is the arc `[rho_1, rho_5]`), pairings, parents,
//! depths and first-return points worked out by hand (below), `y°` and energies of the 7-modal
//! and repeated-extrema inputs by mpmath quadrature (`tests/reference/make_reference.py`,
//! modules `seven` and `repeated` of `tests/common/reference_values.rs`).

mod common;

use std::collections::HashMap;

use common::reference_values::{repeated, seven};
use common::{
    assert_close, assert_rel, check_loop_invariants, loop_of, random_turning_points, Lcg,
};
use lugre::{Bimodal, HysteresisLoop, Loop, LoopKind, LuGre, RateIndependent, TheoremA};
use lugre_test_support::prec::{CLOSED_FORM, FEW_ULPS, IDENTITY, LOOP};

fn describe(loops: &[Loop]) -> String {
    loops
        .iter()
        .enumerate()
        .map(|(i, l)| {
            format!(
                "  {i}: {:?} rho [{}, {}, {}] u [{}, {}, {}] parent {:?} depth {}",
                l.kind,
                l.start.rho,
                l.reversal.rho,
                l.end.rho,
                l.start.u,
                l.reversal.u,
                l.end.u,
                l.parent,
                l.depth
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn bimodal_loop(model: RateIndependent, b: &Bimodal) -> HysteresisLoop {
    HysteresisLoop::new(model, &b.turning_points()).unwrap()
}

/// Theorem A (b): the major loop and exactly one minor loop, the arc `[rho_1, rho_5]` turning
/// at `rho_2`; `rho` compared exactly (the crate and `Bimodal::rho` add the same f64 terms in
/// the same order).
#[track_caller]
fn assert_theorem_a_minor_loop(b: &Bimodal, hl: &HysteresisLoop, what: &str) {
    let loops = hl.loops();
    let rho = b.rho();
    assert_eq!(
        loops.len(),
        2,
        "{what} {b:?}: Theorem A has exactly one minor loop [rho_1, rho_5] = [{}, {}]; got\n{}",
        rho[1],
        rho[5],
        describe(&loops)
    );
    let (major, minor) = (&loops[0], &loops[1]);
    assert_eq!(major.kind, LoopKind::Major);
    assert_eq!(major.start.u, b.umax2, "{what} {b:?}");
    assert_eq!(major.reversal.u, b.umin1, "{what} {b:?}");
    assert_eq!(
        [minor.start.rho, minor.reversal.rho, minor.end.rho],
        [rho[1], rho[2], rho[5]],
        "{what} {b:?}: minor loop\n{}",
        describe(&loops)
    );
    assert_eq!(
        TheoremA::new(b, hl).minor_loop,
        [minor.start.rho, minor.end.rho]
    );
    assert_eq!(
        [minor.start.u, minor.reversal.u],
        [b.umax1, b.umin2],
        "{what} {b:?}"
    );
    assert_close(
        &format!("{what} {b:?} u_C"),
        minor.end.u,
        b.umax1,
        b.umax1.abs(),
        FEW_ULPS,
    );
    assert_eq!((minor.parent, minor.depth), (Some(0), 1));
    let g0 = hl.model().g0();
    assert_eq!(minor.start.y, hl.turning_y()[1]);
    assert_eq!(minor.reversal.y, hl.turning_y()[2]);
    // y_C: eqs. 13-16 from y°(rho_2) over umax1 - umin2 (not y_at(rho_5): at high stiffness an
    // ulp of rho_5 moves y° by ~2 a ulp(rho_5) g0)
    let y_c = common::advance(hl.model(), hl.turning_y()[2], 1.0, b.umax1 - b.umin2);
    assert_close(&format!("{what} {b:?} y_C"), minor.end.y, y_c, g0, LOOP);
    check_loop_invariants(hl, &loops, IDENTITY);
}

// ---------------------------------------------------------------------------------------------
// 4. Theorem A's edge cases

#[test]
fn theorem_a_with_umin1_equal_to_umin2() {
    for sigma0 in [1.0, 6.0, 1e5] {
        let model = LuGre::paper()
            .with_sigma0(sigma0)
            .unwrap()
            .rate_independent();
        let b = Bimodal::new(0.0, 0.0, 1.0, 1.5).unwrap();
        let hl = bimodal_loop(model, &b);
        assert_theorem_a_minor_loop(&b, &hl, &format!("sigma0 = {sigma0}"));
        // by hand: rho_1 = 1, rho_2 = 2, rho_5 = 3 (the input touches umin1 again at rho_2)
        assert_eq!(b.rho()[1..3], [1.0, 2.0]);
        assert_eq!(b.rho()[5], 3.0);
    }
}

/// Regression: with `umax1 == umax2` the first version reported a second minor loop, the arc
/// `[rho_3, rho_4] = [2.6, 4.6]` (1 -> 0 -> 1, turning at the global minimum), which is the rest
/// of the major loop, not a minor loop of Theorem A.
#[test]
fn theorem_a_with_umax1_equal_to_umax2() {
    for sigma0 in [1.0, 6.0, 1e5] {
        let model = LuGre::paper()
            .with_sigma0(sigma0)
            .unwrap()
            .rate_independent();
        let b = Bimodal::new(0.0, 0.2, 1.0, 1.0).unwrap();
        let hl = bimodal_loop(model, &b);
        assert_theorem_a_minor_loop(&b, &hl, &format!("sigma0 = {sigma0}"));
    }
}

/// A random Definition-1 tuple: `umin1 <= umin2 < umax1 <= umax2`, with gaps log-uniform over
/// four decades; `umin1 == umin2` with probability `p_min_tie`, `umax1 == umax2` with
/// probability `p_max_tie` (never both).
fn random_bimodal(rng: &mut Lcg, p_min_tie: f64, p_max_tie: f64) -> Bimodal {
    let umin1 = rng.range(-5.0, 5.0);
    let min_tie = rng.chance(p_min_tie);
    let max_tie = !min_tie && rng.chance(p_max_tie);
    let umin2 = if min_tie {
        umin1
    } else {
        umin1 + rng.log_uniform(-3.0, 1.0)
    };
    let umax1 = umin2 + rng.log_uniform(-3.0, 1.0);
    let umax2 = if max_tie {
        umax1
    } else {
        umax1 + rng.log_uniform(-3.0, 1.0)
    };
    Bimodal::new(umin1, umin2, umax1, umax2).unwrap()
}

fn random_model(rng: &mut Lcg) -> RateIndependent {
    RateIndependent::new(rng.log_uniform(-3.0, 3.0), rng.log_uniform(-1.0, 1.0)).unwrap()
}

#[test]
fn random_definition_1_inputs_have_theorem_a_minor_loop() {
    // strict inequalities and umin1 == umin2
    let mut rng = Lcg(0x5eed_0001);
    for i in 0..2000 {
        let b = random_bimodal(&mut rng, 0.25, 0.0);
        let model = random_model(&mut rng);
        assert_theorem_a_minor_loop(&b, &bimodal_loop(model, &b), &format!("case {i}"));
    }
}

/// Regression, as `theorem_a_with_umax1_equal_to_umax2`, over random tuples.
#[test]
fn random_definition_1_inputs_with_umax1_equal_to_umax2_have_theorem_a_minor_loop() {
    let mut rng = Lcg(0x5eed_0002);
    for i in 0..500 {
        let b = random_bimodal(&mut rng, 0.0, 1.0);
        assert_eq!(b.umax1, b.umax2);
        let model = random_model(&mut rng);
        assert_theorem_a_minor_loop(&b, &bimodal_loop(model, &b), &format!("case {i}"));
    }
}

// ---------------------------------------------------------------------------------------------
// 5. Nesting on a 7-modal input, worked out by hand
//
// Turning points (7 maxima, 7 minima), rho_k and segment lengths:
//
//   u     10   0   8   1   5   3   9   2   7   4   6  4.5 8.5 3.5 (10)
//   rho    0  10  18  25  29  31  37  44  49  52  54 55.5 59.5 64.5 (71)
//
// ASTM three-point rule from the global maximum 10 (stack, then what closes):
//   10 0 8 1 5 3 9   : X = |9 - 3| = 6 > Y = |3 - 5| = 2  -> (5, 3);  X = |9 - 1| = 8 > 7 -> (8, 1)
//   10 0 9 2 7 4 6 4.5 8.5 : 4 > 1.5 -> (6, 4.5);  4.5 > 3 -> (7, 4);  6.5 < 7 stop
//   10 0 9 2 8.5 3.5 10    : 6.5 > 5 -> (8.5, 3.5);  8 > 7 -> (9, 2);  10 = 10 rising -> (10, 0)
//
// First returns (rho_C): the return to u_A after B, walking forward over nested cycles:
//   (8, 1):   up 1 -> 5 (4), down 5 -> 3 (2), up 3 -> 8 (5): rho_C = 25 + 11 = 36, not 25 + 7
//   (5, 3):   31 + 2 = 33
//   (9, 2):   44 + 5 + 3 + 2 + 1.5 + 4 + 5 + 5.5 = 70, not 44 + 7
//   (7, 4):   up 4 -> 6 (2), down to 4.5 (1.5), up to 7 (2.5): rho_C = 52 + 6 = 58, not 55
//   (6, 4.5): 55.5 + 1.5 = 57
//   (8.5, 3.5): 64.5 + 5 = 69.5
// Parents (smallest arc containing): (8, 1), (9, 2) -> major; (5, 3) -> (8, 1);
// (7, 4), (8.5, 3.5) -> (9, 2); (6, 4.5) -> (7, 4). Depths 1, 2, 1, 2, 3, 2.

const SEVEN_PARENTS: [Option<usize>; 7] =
    [None, Some(0), Some(1), Some(0), Some(3), Some(4), Some(3)];
const SEVEN_DEPTHS: [usize; 7] = [0, 1, 2, 1, 2, 3, 2];

#[test]
fn seven_modal_pairing_parents_depths_and_first_returns() {
    let hl = loop_of(seven::SIGMA0, seven::G0, &seven::U);
    for k in 0..14 {
        assert_rel(
            &format!("seven y(rho_{k})"),
            hl.turning_y()[k],
            seven::Y[k],
            LOOP,
        );
    }
    let loops = hl.loops();
    assert_eq!(loops.len(), 7, "\n{}", describe(&loops));
    for (i, (l, r)) in loops.iter().zip(seven::LOOPS).enumerate() {
        let what = |w: &str| format!("seven loop {i} {w}");
        // rho and u are small integers and halves: exact
        assert_eq!(
            [l.start.rho, l.reversal.rho, l.end.rho],
            [r[0], r[1], r[2]],
            "{}\n{}",
            what("rho"),
            describe(&loops)
        );
        assert_eq!(
            [l.start.u, l.reversal.u, l.end.u],
            [r[3], r[4], r[5]],
            "{}",
            what("u")
        );
        assert_rel(&what("y_A"), l.start.y, r[6], LOOP);
        assert_rel(&what("y_B"), l.reversal.y, r[7], LOOP);
        assert_rel(&what("y_C"), l.end.y, r[8], LOOP);
        assert_rel(&what("W"), l.energy.work, r[9], LOOP);
        assert_rel(&what("D"), l.energy.dissipation, r[10], LOOP);
        if i == 0 {
            assert_eq!(l.energy.stored_energy_change, 0.0);
        } else {
            assert_rel(&what("dV"), l.energy.stored_energy_change, r[11], LOOP);
        }
        assert_eq!(l.parent, SEVEN_PARENTS[i], "{}", what("parent"));
        assert_eq!(l.depth, SEVEN_DEPTHS[i], "{}", what("depth"));
    }
    // the cycles nested on a return branch push the parent's end past rho_B + |u_A - u_B|
    for i in [1, 3, 4] {
        let l = &loops[i];
        let naive = l.reversal.rho + (l.start.u - l.reversal.u).abs();
        assert!(
            l.end.rho > naive,
            "loop {i}: end {} <= rho_B + |u_A - u_B| = {naive}",
            l.end.rho
        );
    }
    assert_eq!(loops[1].end.rho, 36.0);
    assert_eq!(loops[3].end.rho, 70.0);
    assert_eq!(loops[4].end.rho, 58.0);
    check_loop_invariants(&hl, &loops, IDENTITY);
}

#[test]
fn seven_modal_started_elsewhere_wraps_arcs_past_the_period() {
    // The same cyclic input given from the minimum 1 (rho 25 above): every rho moves by -25
    // (mod 71), and the arc of (8, 1), [18, 36] above, becomes [64, 82], past P = 71.
    let u: Vec<f64> = seven::U[3..]
        .iter()
        .chain(&seven::U[..3])
        .copied()
        .collect();
    let hl = loop_of(seven::SIGMA0, seven::G0, &u);
    let loops = hl.loops();
    let find = |ua: f64, ub: f64| {
        loops
            .iter()
            .find(|l| l.start.u == ua && l.reversal.u == ub)
            .unwrap_or_else(|| panic!("no loop ({ua}, {ub}) in\n{}", describe(&loops)))
    };
    let l = find(8.0, 1.0);
    assert_eq!([l.start.rho, l.reversal.rho, l.end.rho], [64.0, 71.0, 82.0]);
    let major = &loops[0];
    assert_eq!(
        [major.start.rho, major.reversal.rho, major.end.rho],
        [46.0, 56.0, 117.0]
    );
    for (ua, ub, rho) in [
        (5.0, 3.0, [4.0, 6.0, 8.0]),
        (9.0, 2.0, [12.0, 19.0, 45.0]),
        (6.0, 4.5, [29.0, 30.5, 32.0]),
    ] {
        let l = find(ua, ub);
        assert_eq!(
            [l.start.rho, l.reversal.rho, l.end.rho],
            rho,
            "({ua}, {ub})"
        );
    }
    check_loop_invariants(&hl, &loops, IDENTITY);
}

// ---------------------------------------------------------------------------------------------
// 6. Invariance under rotating the period's start

/// A loop without its position: `(u_A, u_B, u_C, y_A, y_B, y_C, W, D, rho_B - rho_A,
/// rho_C - rho_A, depth)`.
fn signature(l: &Loop) -> [f64; 11] {
    [
        l.start.u,
        l.reversal.u,
        l.end.u,
        l.start.y,
        l.reversal.y,
        l.end.y,
        l.energy.work,
        l.energy.dissipation,
        l.reversal.rho - l.start.rho,
        l.end.rho - l.start.rho,
        l.depth as f64,
    ]
}

/// Compares two signatures: `u` and arc lengths relative to the input's scale, `y` relative to
/// `g0`, `W` and `D` relative to `g0 (rho_C - rho_A)` (the most `|W|` can be), depth exactly.
fn same_signature(a: &[f64; 11], b: &[f64; 11], g0: f64, uscale: f64, tol: f64) -> bool {
    let close = |x: f64, y: f64, s: f64| (x - y).abs() <= tol * s;
    let energy = g0 * b[9];
    (0..3).all(|i| close(a[i], b[i], uscale))
        && (3..6).all(|i| close(a[i], b[i], g0))
        && (6..8).all(|i| close(a[i], b[i], energy))
        && (8..10).all(|i| close(a[i], b[i], uscale))
        && a[10] == b[10]
}

/// The loops of every rotation of `u` are those of `u`: the major loop, and the minor loops as
/// a multiset.
fn assert_rotation_invariant(sigma0: f64, g0: f64, u: &[f64], what: &str) {
    let base = loop_of(sigma0, g0, u).loops();
    let uscale = u.iter().fold(0.0f64, |m, v| m.max(v.abs())) * (u.len() as f64);
    let sig = |l: &Loop| signature(l);
    let mut base_minor: Vec<[f64; 11]> = base[1..].iter().map(sig).collect();
    base_minor.sort_by(|a, b| {
        a.iter()
            .zip(b)
            .map(|(x, y)| x.total_cmp(y))
            .find(|o| o.is_ne())
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    for r in 1..u.len() {
        let rotated: Vec<f64> = u[r..].iter().chain(&u[..r]).copied().collect();
        let hl = loop_of(sigma0, g0, &rotated);
        let loops = hl.loops();
        check_loop_invariants(&hl, &loops, IDENTITY);
        assert_eq!(
            loops.len(),
            base.len(),
            "{what}, rotation {r}:\n{}",
            describe(&loops)
        );
        assert!(
            same_signature(&sig(&loops[0]), &sig(&base[0]), g0, uscale, IDENTITY),
            "{what}, rotation {r}: major loop {:?} != {:?}",
            sig(&loops[0]),
            sig(&base[0])
        );
        // match each minor loop to a distinct one of the base
        let mut unused = base_minor.clone();
        for l in &loops[1..] {
            let s = sig(l);
            match unused
                .iter()
                .position(|b| same_signature(&s, b, g0, uscale, IDENTITY))
            {
                Some(j) => {
                    unused.swap_remove(j);
                }
                None => panic!("{what}, rotation {r}: loop {s:?} not among\n{unused:?}"),
            }
        }
    }
}

#[test]
fn loops_do_not_depend_on_where_the_period_starts() {
    assert_rotation_invariant(1.0, 2.0, &seven::U, "7-modal");
    assert_rotation_invariant(1.0, 2.0, &[0.0, 1.0, 0.2, 1.5], "Example 3");
    assert_rotation_invariant(6.0, 2.0, &[0.0, 1.0, 0.5, 1.5], "Example 4");
    assert_rotation_invariant(1.0, 2.0, &[0.0, 1.0, 0.0, 1.5], "umin1 == umin2");
    assert_rotation_invariant(1.0, 2.0, &[0.0, 1.0, 0.2, 1.0], "umax1 == umax2");
    let mut rng = Lcg(0x5eed_0003);
    for i in 0..5 {
        let u = random_turning_points(&mut rng, 40);
        assert_rotation_invariant(rng.log_uniform(-2.0, 2.0), 1.5, &u, &format!("random {i}"));
    }
}

#[test]
fn repeated_maxima_and_minima() {
    // 10 three times, 0 three times, 3 twice.
    assert_rotation_invariant(1.0, 2.0, &repeated::U, "repeated extrema");
    let n = repeated::U.len();
    for r in 0..n {
        let rotated: Vec<f64> = repeated::U[r..]
            .iter()
            .chain(&repeated::U[..r])
            .copied()
            .collect();
        let hl = loop_of(1.0, 2.0, &rotated);
        for k in 0..n {
            assert_rel(
                &format!("repeated, rotation {r}: y(rho_{k})"),
                hl.turning_y()[k],
                repeated::Y[(k + r) % n],
                LOOP,
            );
        }
        let loops = hl.loops();
        assert_rel(
            "repeated W per period",
            hl.work_per_period(),
            repeated::WORK_PER_PERIOD,
            LOOP,
        );
        assert_rel(
            "repeated major W",
            loops[0].energy.work,
            repeated::WORK_PER_PERIOD,
            LOOP,
        );
        // the major loop turns at a global minimum, from a global maximum
        assert_eq!((loops[0].start.u, loops[0].reversal.u), (10.0, 0.0));
    }
}

// ---------------------------------------------------------------------------------------------
// An independent characterization of the loops, checked by brute force on random inputs.
//
// For a cyclic sequence of distinct turning points, (A, B) is a loop with u_A > u_B (a "hanging"
// cycle; mirror everything for u_A < u_B) iff
//   (i)   every turning point strictly between A and B (going forward) lies in (u_B, u_A);
//   (ii)  going forward from B, the input reaches u_A before it goes below u_B;
//   (iii) going backward from A, the input reaches u_B before it goes above u_A;
// and its arc ends at the first return to u_A after B (found by walking). The pair (global
// maximum, global minimum) passes in both orientations; the major loop is the one starting at
// the maximum. Parent: the loop with the shortest arc containing this one; depth: how many arcs
// contain it. (This is the ASTM rainflow pairing: (i) the cycles between A and B closed
// before, (ii) B -> u_A closes (A, B), (iii) A was not closed by an earlier, smaller range.)

#[derive(Debug, Clone, Copy)]
struct BruteLoop {
    a: usize,
    b: usize,
    /// rho_A (in [0, P)) and the arc length rho_C - rho_A
    start: f64,
    len: f64,
}

fn brute_force_loops(u: &[f64]) -> Vec<BruteLoop> {
    let n = u.len();
    let mut rho = vec![0.0; n + 1];
    for k in 0..n {
        rho[k + 1] = rho[k] + (u[(k + 1) % n] - u[k]).abs();
    }
    let imax = (0..n).fold(0, |m, k| if u[k] > u[m] { k } else { m });
    let imin = (0..n).fold(0, |m, k| if u[k] < u[m] { k } else { m });
    let mut out = Vec::new();
    for a in 0..n {
        let ua = u[a];
        // d = +1: A is the upper end of the pair (B below it); d = -1: the mirror image
        for d in [1.0, -1.0] {
            let mut extreme = ua; // the most extreme value (away from A) seen after A
            for j in 1..n {
                let b = (a + j) % n;
                let ub = u[b];
                if d * (ub - ua) >= 0.0 {
                    break; // (i) fails for every later B
                }
                if d * (ub - extreme) >= 0.0 {
                    continue; // not beyond everything between A and it: (i) fails
                }
                extreme = ub;
                if d < 0.0 && a == imin && b == imax {
                    continue; // the major pair, counted once, from the maximum
                }
                if returns(u, b, ua, ub, d, 1) && returns(u, a, ub, ua, -d, n - 1) {
                    let len = walk_to(u, &rho, a, j, ua);
                    out.push(BruteLoop {
                        a,
                        b,
                        start: rho[a],
                        len,
                    });
                }
            }
        }
    }
    out
}

/// (ii)/(iii): walking from `from` (forward if `steps == 1`, else backward), does the input
/// reach `target` (on the `d` side) before going past `limit` (on the other side)?
fn returns(u: &[f64], from: usize, target: f64, limit: f64, d: f64, steps: usize) -> bool {
    let n = u.len();
    for j in 1..n {
        let k = (from + j * steps) % n;
        if d * (u[k] - target) >= 0.0 {
            return true;
        }
        if d * (u[k] - limit) < 0.0 {
            return false;
        }
    }
    false
}

/// The arc length from A (index `a`) through B (`j` turning points later) to the first return
/// to `ua` after B.
fn walk_to(u: &[f64], rho: &[f64], a: usize, j: usize, ua: f64) -> f64 {
    let n = u.len();
    let p = rho[n];
    let abs_rho = |k: usize| rho[k % n] + p * ((k / n) as f64);
    let mut k = a + j;
    loop {
        let next = u[(k + 1) % n];
        let cur = u[k % n];
        if (next - ua) * (cur - ua) <= 0.0 {
            return abs_rho(k) + (ua - cur).abs() - rho[a];
        }
        k += 1;
    }
}

#[test]
fn brute_force_characterization_reproduces_the_hand_worked_7_modal_loops() {
    // a check of the brute force itself, against the pairing worked out by hand above
    let bl = brute_force_loops(&seven::U);
    let mut got: Vec<(f64, f64, f64)> = bl
        .iter()
        .map(|l| (l.start, l.start + l.len, seven::U[l.a]))
        .collect();
    got.sort_by(|x, y| x.0.total_cmp(&y.0));
    let want: Vec<(f64, f64, f64)> = seven::LOOPS.iter().map(|r| (r[0], r[2], r[3])).collect();
    assert_eq!(got, want);
}

#[test]
fn random_inputs_match_the_brute_force_characterization() {
    let mut rng = Lcg(0x5eed_0004);
    for case in 0..200 {
        let n = 2 * (2 + (rng.next_u64() % 31) as usize);
        let u = random_turning_points(&mut rng, n);
        let hl = loop_of(rng.log_uniform(-2.0, 2.0), 1.0, &u);
        let p = hl.period();
        let loops = hl.loops();
        check_loop_invariants(&hl, &loops, IDENTITY);
        let brute = brute_force_loops(&u);
        let what = format!("case {case}, u = {u:?}\n{}", describe(&loops));
        assert_eq!(
            loops.len(),
            n / 2,
            "every turning point in exactly one pair: {what}"
        );
        assert_eq!(brute.len(), n / 2, "brute force: {brute:?}");
        let index: HashMap<u64, usize> = u
            .iter()
            .enumerate()
            .map(|(k, v)| (v.to_bits(), k))
            .collect();
        let key = |l: &Loop| (index[&l.start.u.to_bits()], index[&l.reversal.u.to_bits()]);
        let by_pair: HashMap<(usize, usize), &BruteLoop> =
            brute.iter().map(|l| ((l.a, l.b), l)).collect();
        for l in &loops {
            let b = by_pair
                .get(&key(l))
                .unwrap_or_else(|| panic!("loop {:?} not a brute-force loop: {what}", key(l)));
            assert_close("rho_A", l.start.rho, b.start, p, CLOSED_FORM);
            assert_close(
                "rho_C - rho_A",
                l.end.rho - l.start.rho,
                b.len,
                p,
                CLOSED_FORM,
            );
        }
        // parents and depths
        let contains = |outer: &Loop, inner: &Loop| {
            let off = (inner.start.rho - outer.start.rho).rem_euclid(p);
            let off = if off > p * (1.0 - 1e-12) { 0.0 } else { off };
            off + (inner.end.rho - inner.start.rho)
                <= (outer.end.rho - outer.start.rho) * (1.0 + 1e-12)
        };
        for (i, l) in loops.iter().enumerate().skip(1) {
            let containing: Vec<usize> = (0..loops.len())
                .filter(|&j| j != i && contains(&loops[j], l))
                .collect();
            let smallest = containing.iter().copied().min_by(|&x, &y| {
                (loops[x].end.rho - loops[x].start.rho)
                    .total_cmp(&(loops[y].end.rho - loops[y].start.rho))
            });
            assert_eq!(l.parent, smallest, "loop {i} parent: {what}");
            assert_eq!(l.depth, containing.len(), "loop {i} depth: {what}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 8. Linear scaling

#[test]
fn a_hundred_thousand_turning_points() {
    let mut rng = Lcg(0x5eed_0005);
    let u = random_turning_points(&mut rng, 100_000);
    let started = std::time::Instant::now();
    let hl = loop_of(3.0, 1.5, &u);
    let loops = hl.loops();
    let elapsed = started.elapsed();
    assert_eq!(loops.len(), 50_000);
    check_loop_invariants(&hl, &loops, IDENTITY);
    assert!(loops.iter().map(|l| l.depth).max().unwrap() >= 3);
    // generous: well under a second even in debug builds; quadratic behaviour would take minutes
    assert!(
        elapsed.as_secs_f64() < 20.0,
        "loops() of 1e5 turning points took {elapsed:?}"
    );
}

/// The table holds the same loops as the records, in the order rainflow closes them: every
/// parent after its children, the major loop last; start and reversal given as turning points.
#[test]
fn loop_table_is_the_loops_in_closing_order() {
    let model = LuGre::paper().rate_independent();
    let mut rng = Lcg(17);
    let mut inputs: Vec<Vec<f64>> = [2, 4, 8, 50, 1000]
        .iter()
        .map(|&n| random_turning_points(&mut rng, n))
        .collect();
    // Ties: repeated maxima and minima, touches that do not close.
    inputs.push(vec![0.0, 2.0, 1.0, 2.0, 0.0, 2.0, 1.0, 2.0, 1.0, 3.0]);
    inputs.push(vec![0.0, 8.0, 3.0, 6.0, 3.0, 4.0]);
    for u in inputs {
        let hl = loop_of_model(model, &u);
        let (t, loops) = (hl.loop_table(), hl.loops());
        assert_eq!(t.len(), loops.len());
        assert_eq!(t.major(), t.len() - 1);
        assert_eq!(t.parent(t.major()), None);
        let (tu, ty, trho) = (hl.turning_points(), hl.turning_y(), hl.turning_rho());
        // Rows by where they start in the period of the major loop, as `loops()` orders them.
        let mut matched = vec![false; loops.len()];
        for row in 0..t.len() {
            if let Some(p) = t.parent(row) {
                assert!(p > row, "parent {p} of row {row} closes before it");
                assert_eq!(t.depth()[row], t.depth()[p] + 1);
            }
            let (k_a, k_b) = (t.start()[row], t.reversal()[row]);
            let l = loops
                .iter()
                .position(|l| l.start.rho == trho[k_a] && l.reversal.rho == t.reversal_rho()[row])
                .unwrap_or_else(|| panic!("row {row} is not among the loops"));
            assert!(!matched[l], "two rows for loop {l}");
            matched[l] = true;
            let r = &loops[l];
            assert_eq!((r.start.u, r.start.y), (tu[k_a], ty[k_a]));
            assert_eq!((r.reversal.u, r.reversal.y), (tu[k_b], ty[k_b]));
            assert_eq!(
                [r.end.rho, r.end.u, r.end.y],
                [t.end_rho()[row], t.end_u()[row], t.end_y()[row]]
            );
            assert_eq!(
                [
                    r.energy.work,
                    r.energy.stored_energy_change,
                    r.energy.dissipation,
                    r.energy.closure_gap
                ],
                [
                    t.work()[row],
                    t.stored_energy_change()[row],
                    t.dissipation()[row],
                    t.closure_gap()[row]
                ]
            );
            assert_eq!(r.depth, t.depth()[row]);
            assert_eq!(r.kind == LoopKind::Major, row == t.major());
        }
    }
}

fn loop_of_model(model: RateIndependent, u: &[f64]) -> HysteresisLoop {
    HysteresisLoop::new(model, &lugre::TurningPoints::new(u).unwrap()).unwrap()
}
