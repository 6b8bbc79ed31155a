//! Tests of [`crate::cycles`] against the `rainflow` package, hand-worked histories, mpmath and
//! the periodic loop.

use super::*;
use crate::{HysteresisLoop, LoopKind, TurningPoints};
use lugre_test_support::prec::{
    rel_diff, CLOSED_FORM, CYCLE_ENERGY, IDENTITY, LOOP, TINY_LOOP_WORK,
};

fn reversals(u: &[f64], gate: f64) -> Vec<(u64, f64)> {
    count_cycles(u, gate)
        .unwrap()
        .reversals
        .iter()
        .map(|r| (r.index, r.u))
        .collect()
}

/// `(range, mean, count, start, end)` as `rainflow.extract_cycles` yields them.
fn rows(h: &History) -> Vec<(f64, f64, f64, u64, u64)> {
    h.cycles
        .iter()
        .map(|c| (c.range, c.mean, c.count, c.start, c.end))
        .collect()
}

#[test]
fn astm_e1049_worked_example() {
    // ASTM E1049-85 §5.4.4, Fig. 6 / Table 4: range 3: 0.5, 4: 1.5, 6: 0.5, 8: 1.0, 9: 0.5.
    // Row by row, from rainflow 3.2.0:
    //   list(rainflow.extract_cycles([-2, 1, -3, 5, -1, 3, -4, 4, -2]))
    let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];
    let h = count_cycles(&u, 0.0).unwrap();
    assert_eq!(
        rows(&h),
        vec![
            (3.0, -0.5, 0.5, 0, 1),
            (4.0, -1.0, 0.5, 1, 2),
            (4.0, 1.0, 1.0, 4, 5),
            (8.0, 1.0, 0.5, 2, 3),
            (9.0, 0.5, 0.5, 3, 6),
            (8.0, 0.0, 0.5, 6, 7),
            (6.0, 1.0, 0.5, 7, 8),
        ]
    );
    let mut table = std::collections::BTreeMap::new();
    for c in &h.cycles {
        *table.entry(c.range as i64).or_insert(0.0) += c.count;
    }
    let table: Vec<(i64, f64)> = table.into_iter().collect();
    assert_eq!(
        table,
        vec![(3, 0.5), (4, 1.5), (6, 0.5), (8, 1.0), (9, 0.5)]
    );
    assert_eq!(h.reversals.len(), 9);
    let s = h.summary;
    assert_eq!(
        (s.samples, s.reversals, s.full_cycles, s.half_cycles),
        (9, 9, 1, 6)
    );
}

/// The LCG of `testdata/make_reference.py`.
struct Lcg(u64);

impl Lcg {
    fn next_u64(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0
    }
    fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `series()` of `testdata/make_reference.py`.
fn reference_series(rng: &mut Lcg, case: usize) -> Vec<f64> {
    let n = 3 + rng.next_u64() % 38;
    let mut out: Vec<f64> = Vec::new();
    let mut x = 0.0;
    for _ in 0..n {
        match case % 4 {
            0 => x = ((rng.next_u64() >> 33) % 7) as f64 - 3.0,
            1 => {
                if rng.next_f64() >= 0.2 {
                    x += rng.next_f64() - 0.5;
                }
            }
            2 => {
                if rng.next_f64() >= 0.2 || out.is_empty() {
                    x = rng.next_f64() * 10.0 - 5.0;
                }
            }
            _ => x += ((rng.next_u64() >> 33) % 5) as f64 - 2.0,
        }
        out.push(x);
    }
    out
}

#[test]
fn agrees_with_the_rainflow_package_row_by_row() {
    // testdata/rainflow_reference.txt: rainflow 3.2.0's reversals() and extract_cycles() on 300
    // random series with plateaus and ties (see testdata/make_reference.py).
    let text = include_str!("testdata/rainflow_reference.txt");
    let mut rng = Lcg(0x853C_49E6_748F_EA9B);
    let mut cases = 0;
    for (case, line) in text.lines().enumerate() {
        let u = reference_series(&mut rng, case);
        let mut parts = line.split('|');
        assert_eq!(parts.next(), Some(case.to_string().as_str()));
        let want_rev: Vec<(u64, f64)> = parts
            .next()
            .unwrap()
            .split(',')
            .map(|p| {
                let (i, v) = p.split_once(':').unwrap();
                (i.parse().unwrap(), v.parse().unwrap())
            })
            .collect();
        let want_cyc: Vec<(f64, f64, f64, u64, u64)> = parts
            .next()
            .unwrap()
            .split(',')
            .filter(|p| !p.is_empty())
            .map(|p| {
                let f: Vec<&str> = p.split(':').collect();
                (
                    f[0].parse().unwrap(),
                    f[1].parse().unwrap(),
                    f[2].parse().unwrap(),
                    f[3].parse().unwrap(),
                    f[4].parse().unwrap(),
                )
            })
            .collect();
        let h = count_cycles(&u, 0.0).unwrap();
        let got_rev: Vec<(u64, f64)> = h.reversals.iter().map(|r| (r.index, r.u)).collect();
        assert_eq!(got_rev, want_rev, "case {case}: {u:?}");
        assert_eq!(rows(&h), want_cyc, "case {case}: {u:?}");
        cases += 1;
    }
    assert_eq!(cases, 300);
}

#[test]
fn reversal_conventions() {
    // Plateaus: an extremum is reported at its last sample, the first sample as itself.
    assert_eq!(
        reversals(&[1.0, 1.0, 0.0, 0.0, 2.0, 2.0], 0.0),
        vec![(0, 1.0), (3, 0.0), (5, 2.0)]
    );
    // Points that keep the direction are not reversals; the last sample always is.
    assert_eq!(
        reversals(&[0.0, 1.0, 2.0, 1.5, 1.0], 0.0),
        vec![(0, 0.0), (2, 2.0), (4, 1.0)]
    );
    // Two samples: two reversals and a half cycle (rainflow 3.2 yields nothing here).
    let h = count_cycles(&[0.0, 1.0], 0.0).unwrap();
    assert_eq!(rows(&h), vec![(1.0, 0.5, 0.5, 0, 1)]);
    // A constant history: first and last sample, one half cycle of range 0, as
    // rainflow.extract_cycles([3, 3, 3]) == [(0, 3.0, 0.5, 0, 2)].
    let h = count_cycles(&[3.0, 3.0, 3.0], 0.0).unwrap();
    assert_eq!(rows(&h), vec![(0.0, 3.0, 0.5, 0, 2)]);
}

#[test]
fn gate_drops_small_reversals() {
    let u = [0.0, 1.0, 0.9, 1.0, 0.95, 2.0, 1.2, 1.25, 0.0, 0.05];
    assert_eq!(reversals(&u, 0.0).len(), 10);
    // H = 0.5: the wiggles near 1 and 1.2 and the final 0.05 are noise; the plateau-like
    // return to 1 does not matter, 2 at index 5 is the peak.
    assert_eq!(reversals(&u, 0.5), vec![(0, 0.0), (5, 2.0), (8, 0.0)]);
    // Exactly H counts as a reversal (ranges >= H are kept).
    assert_eq!(
        reversals(&[0.0, 1.0, 0.5, 2.0], 0.5),
        vec![(0, 0.0), (1, 1.0), (2, 0.5), (3, 2.0)]
    );
    // Ties move a candidate extreme to its last sample even across noise.
    assert_eq!(
        reversals(&[0.0, 1.0, 0.9, 1.0, 0.0], 0.5),
        vec![(0, 0.0), (3, 1.0), (4, 0.0)]
    );
    // A history that never leaves the band: first and last sample.
    assert_eq!(
        reversals(&[0.0, 0.3, -0.2, 0.1], 0.5),
        vec![(0, 0.0), (3, 0.1)]
    );
    // The noise before the first excursion is ignored.
    assert_eq!(
        reversals(&[0.0, 0.3, -0.2, 3.0, 2.9, -1.0], 0.5),
        vec![(0, 0.0), (3, 3.0), (5, -1.0)]
    );
}

#[test]
fn gated_reversal_ranges_are_at_least_the_gate() {
    let mut rng = Lcg(7);
    for case in 0..400 {
        let u = reference_series(&mut rng, case);
        let gate = 0.25 * (case % 8) as f64;
        let h = count_cycles(&u, gate).unwrap();
        let r = &h.reversals;
        if r.len() > 2 || gate == 0.0 {
            for w in r.windows(2) {
                assert!(w[0].index < w[1].index);
                assert!((w[1].u - w[0].u).abs() >= gate, "{case}: {r:?}");
            }
        }
        // Every reversal is a sample, and the stack pairs up: counts add up to reversals - 1
        // half-cycle steps (each full cycle removes two, each half cycle one).
        for rev in r {
            assert_eq!(u[rev.index as usize], rev.u);
        }
        let s = h.summary;
        assert_eq!(2 * s.full_cycles + s.half_cycles, s.reversals - 1, "{case}");
    }
}

/// First sample after `end` at which the history is back at `u[start]` (at or past it), by
/// scanning.
fn brute_closure(u: &[f64], start: usize, end: usize) -> (usize, f64) {
    let (ua, ub) = (u[start], u[end]);
    let i = (end + 1..u.len())
        .find(|&i| if ua < ub { u[i] <= ua } else { u[i] >= ua })
        .expect("a full cycle closes");
    (i, (i - 1) as f64 + (ua - u[i - 1]) / (u[i] - u[i - 1]))
}

#[test]
fn closure_is_the_first_return_to_the_start_value() {
    // Nested: the cycle (1, 0.2) [indices 1, 2] contains (0.8, 0.5) [3, 4]; both close on the
    // run from 0.5 up to 1.5: 0.8 is reached at 4 + 0.3, 1 at 4 + 0.5.
    let u = [0.0, 1.0, 0.2, 0.8, 0.5, 1.5, -0.3];
    let h = count_cycles(&u, 0.0).unwrap();
    let full: Vec<(u64, u64, u64, f64)> = h
        .cycles
        .iter()
        .filter(|c| c.is_full())
        .map(|c| {
            let cl = c.closure.unwrap();
            (c.start, c.end, cl.index, cl.position)
        })
        .collect();
    assert_eq!(full.len(), 2);
    assert_eq!(full[0].0..full[0].2 + 1, 3..6);
    assert!((full[0].3 - 4.3).abs() < CLOSED_FORM * 5.0);
    assert_eq!((full[1].0, full[1].1, full[1].2, full[1].3), (1, 2, 5, 4.5));
    assert!(h.cycles.iter().all(|c| c.is_full() == c.closure.is_some()));

    // Every full cycle of the random series, against a scan; with a gate too (the samples
    // between two reversals stay between them, so the first return is still on the closing
    // run).
    let mut rng = Lcg(11);
    for case in 0..600 {
        let u = reference_series(&mut rng, case);
        let gate = [0.0, 0.3, 1.0][case % 3];
        let h = count_cycles(&u, gate).unwrap();
        for c in h.cycles.iter().filter(|c| c.is_full()) {
            let cl = c.closure.unwrap();
            let (i, pos) = brute_closure(&u, c.start as usize, c.end as usize);
            assert_eq!(cl.index as usize, i, "{case}: {c:?} in {u:?}");
            assert!(
                (cl.position - pos).abs() <= 4.0 * f64::EPSILON * pos,
                "{case}"
            );
            assert!(cl.position > (i - 1) as f64 && cl.position <= i as f64);
        }
    }
}

#[test]
fn streaming_in_pieces_gives_the_same_cycles() {
    let mut rng = Lcg(3);
    let u: Vec<f64> = (0..5000)
        .scan(0.0, |x, _| {
            *x += rng.next_f64() - 0.5;
            Some(*x)
        })
        .collect();
    let whole =
        count_cycles_with_energy(&u, 0.1, crate::LuGre::paper().rate_independent(), 0.0).unwrap();
    let model = crate::LuGre::paper().rate_independent();
    let mut counter = CycleCounter::new(0.1)
        .unwrap()
        .with_energy(model, 0.0)
        .unwrap();
    let mut cycles: Vec<Cycle> = Vec::new();
    for chunk in u.chunks(37) {
        for &x in chunk {
            counter.push(x, &mut cycles).unwrap();
        }
    }
    let summary = counter.finish(&mut cycles).unwrap();
    assert_eq!(cycles, whole.cycles);
    assert_eq!(summary, whole.summary);
}

/// A full cycle of the energy references: (start, end, closure, position, W, dV, D, gap,
/// y_A, y_C).
type Row = (u64, u64, u64, f64, f64, f64, f64, f64, f64, f64);

// testdata/make_energy_reference.py: rainflow 3.2.0 cycles, closure by scanning, y* by eq. 6
// solved exactly per piece and W, D by mp.quad at mp.dps = 50. PAPER: sigma0 = 6, g0 = 2;
// STIFF: Canudas de Wit 1995 stiffness, micrometre motions; TINY: loops 1e-5 wide near
// y* = 0.56 g0, where W is 1e-6 of dV and D.
#[rustfmt::skip]
const PAPER: [Row; 5] = [
    (3, 4, 5, 4.3000000000000000444, 0.0099367735885433115192, -0.089851523970464905355, 0.099788297559008216874, -0.4621903223468267607, 1.3975175585213243789, 0.9353272361744976182),
    (1, 2, 5, 4.5, 0.84898335572480392099, -0.13870155280051035759, 0.98768490852531427858, -0.49966678519445433818, 1.9153619837746312978, 1.4156951985801769596),
    (7, 8, 9, 8.4545454545454545409, 0.2133153515609922846, -0.11070121524406544049, 0.32401656680505772509, -0.43905028130895170332, 1.7323525313673906755, 1.2933022500584389722),
    (6, 9, 10, 9.6818181818181818067, 3.4983814072421302592, -0.0084239805391747962789, 3.5068053877813050555, 0.025660803793379273442, -1.9825225300945433087, -1.9568617263011640353),
    (11, 12, 13, 12.333333333333333416, -0.05562491446379962139, -0.22154253243645047336, 0.16591761797265085197, -0.88868565509997302355, 1.9400969077361551321, 1.0514112526361821085),
];
#[rustfmt::skip]
const PAPER_Y: [f64; 14] = [0.30000000000000001665, 1.9153619837746312978, -1.6448063744447915102, 1.3975175585213243789, -0.61867244226927430062, 1.8696239760836983961, -1.9825225300945433087, 1.7323525313673906755, -1.1671995819455965827, 1.8831836476259631813, -1.9947174410818409973, 1.9400969077361551321, 0.51231670849046905499, 1.61433259575053135];
#[rustfmt::skip]
const STIFF: [Row; 4] = [
    (3, 4, 5, 4.2499999999999999788, -1.0850291825692644523e-7, -3.9907277200079607983e-7, 2.905698537438696346e-7, -0.099255234050431399298, 0.45169484886311348617, 0.35243961481268208687),
    (1, 2, 5, 4.5000000000000000424, 4.1295953153450582886e-7, -3.8041156519861060924e-6, 4.2170751835206119212e-6, -0.42686723958724113207, 1.104604292826409888, 0.67773705323916875594),
    (7, 8, 9, 8.4347826086956521667, -2.3942814518711841124e-7, -1.9298392557332626214e-6, 1.6904111105461442102e-6, -0.27023953023774985052, 0.84924151260542481464, 0.57900198236767496412),
    (6, 9, 10, 9.5384615384615384555, 0.00002880859920621281751, -9.5327816112648970665e-7, 0.000029761877367339307217, 0.07425704375884886187, -1.3208830492240334624, -1.2466260054651846005),
];
#[rustfmt::skip]
const STIFF_Y: [f64; 12] = [0.0, 1.104604292826409888, -0.54181962828228069195, 0.45169484886311348617, -0.10154953210399971785, 1.0778361267868043999, -1.3208830492240334624, 0.84924151260542481464, -0.29385919068635409711, 1.1128581291565183808, -1.4657095586848388073, 1.3072221940857690715];
#[rustfmt::skip]
const TINY: [Row; 3] = [
    (1, 2, 3, 2.4999999999972244424, -3.7290398423823058863e-11, -4.1717835947842458757e-6, 4.1717463043858220526e-6, -7.4581019070483982098e-6, 0.55936637209041577985, 0.55935891398850873146),
    (4, 5, 6, 5.0024987506246818222, 2.3305472604003167082e-10, -0.000010427996602574786371, 0.000010428229657300826402, -0.000018644239194788681111, 0.5593239980163512563, 0.55930535377715646762),
    (3, 6, 7, 6.0476666666666670038, -0.000036672780412029683099, -0.0040943153511174334518, 0.0040576425707054037687, -0.0073681021395049243001, 0.55936518490817909369, 0.55199708276867416939),
];
#[rustfmt::skip]
const TINY_Y: [f64; 8] = [0.0, 0.55936637209041577985, 0.55935264302703216836, 0.55936518490817909369, 0.5593239980163512563, 0.55933967581906889502, 0.54564958738100691089, 0.67032760933342998379];

/// (sigma0, g0, x0, history, cycles, y* at every sample).
type EnergyCase = (f64, f64, f64, Vec<f64>, &'static [Row], &'static [f64]);

#[test]
fn energies_match_mpmath() {
    let cases: [EnergyCase; 3] = [
        (
            6.0,
            2.0,
            0.05,
            vec![
                0.0, 1.0, 0.2, 0.8, 0.5, 1.5, -0.3, 0.6, 0.1, 1.2, -1.0, 0.4, 0.25, 0.7,
            ],
            &PAPER,
            &PAPER_Y,
        ),
        (
            1e5,
            1.5,
            0.0,
            vec![
                0.0, 2e-5, 5e-6, 1.5e-5, 1e-5, 3e-5, -1e-5, 1.2e-5, 2e-6, 2.5e-5, -4e-5, 1e-6,
            ],
            &STIFF,
            &STIFF_Y,
        ),
        (
            1.0,
            1.5,
            0.0,
            vec![0.0, 0.7, 0.69999, 0.70001, 0.69998, 0.700005, 0.69, 0.9],
            &TINY,
            &TINY_Y,
        ),
    ];
    for (sigma0, g0, x0, u, want, want_y) in cases {
        let model = crate::RateIndependent::new(sigma0, g0).unwrap();
        let h = count_cycles_with_energy(&u, 0.0, model, x0).unwrap();
        let full: Vec<&Cycle> = h.cycles.iter().filter(|c| c.is_full()).collect();
        assert_eq!(full.len(), want.len());
        for (c, w) in full.iter().zip(want) {
            let cl = c.closure.unwrap();
            let e = c.energy.unwrap();
            assert_eq!((c.start, c.end, cl.index), (w.0, w.1, w.2));
            assert!(rel_diff(cl.position, w.3) < CLOSED_FORM, "{c:?}");
            // W and D against the cycle's own scale, the work a full swing would do over its
            // arc (g0 * range; W itself can be much smaller). dV comes from y* at both ends,
            // each good to a few ulps of g0, so its scale is g0 (range + |y| / sigma0).
            let scale = g0 * c.range;
            let scale_dv = g0 * (c.range + g0 / sigma0);
            for (got, want, what, scale) in [
                (e.arc.work, w.4, "W", scale),
                (e.arc.stored_energy_change, w.5, "dV", scale_dv),
                (e.arc.dissipation, w.6, "D", scale),
            ] {
                assert!(
                    (got - want).abs() < CYCLE_ENERGY * scale,
                    "{what}: {got} vs {want} ({c:?})"
                );
            }
            for (got, want) in [
                (e.arc.closure_gap, w.7),
                (e.y_start, w.8),
                (e.y_closure, w.9),
            ] {
                assert!((got - want).abs() < LOOP * g0, "{got} vs {want}");
            }
            // The work keeps its own digits even on tiny loops (relative error about
            // 1e-16 / (a range); W = dV + D would keep only 1e-16 / W of them).
            assert!(
                rel_diff(e.arc.work, w.4) < TINY_LOOP_WORK,
                "{} vs {}",
                e.arc.work,
                w.4
            );
        }
        // y* at every sample, through the histories that end there.
        for k in 1..u.len() {
            let hk = count_cycles_with_energy(&u[..=k], 0.0, model, x0).unwrap();
            let y = hk.summary.energy.unwrap().y_end;
            assert!(
                (y - want_y[k]).abs() < LOOP * g0,
                "y*[{k}] = {y} vs {}",
                want_y[k]
            );
        }
        let total = h.summary.energy.unwrap();
        assert!((total.y_end - want_y[want_y.len() - 1]).abs() < LOOP * g0);
        assert_eq!(total.y_start, sigma0 * x0);
        assert!(
            (total.work - total.stored_energy_change - total.dissipation).abs()
                < IDENTITY * total.dissipation.max(g0 * 1e-6)
        );
    }
}

#[test]
fn work_is_stored_energy_plus_dissipation_on_random_histories() {
    let mut rng = Lcg(5);
    for case in 0..200 {
        let u: Vec<f64> = reference_series(&mut rng, case)
            .iter()
            .map(|x| x * 0.3)
            .collect();
        let sigma0 = [0.1, 1.0, 30.0, 1e4][case % 4];
        let gate = [0.0, 0.1][case % 2];
        let model = crate::RateIndependent::new(sigma0, 1.5).unwrap();
        let h = count_cycles_with_energy(&u, gate, model, 0.0).unwrap();
        for c in h.cycles.iter().filter(|c| c.is_full()) {
            let e = c.energy.unwrap();
            assert!(e.arc.dissipation >= 0.0);
            // dV comes from y* at both ends, each good to a few ulps of g0: its error is about
            // 1e-16 g0 |y| / sigma0, not relative to the cycle.
            let scale = 1.5 * (c.range + 1.5 / sigma0);
            assert!(
                (e.arc.work - e.arc.stored_energy_change - e.arc.dissipation).abs()
                    < CYCLE_ENERGY * scale,
                "{case}: {e:?}"
            );
            assert!(e.y_start.abs() <= 1.5 && e.y_closure.abs() <= 1.5);
        }
    }
}

#[test]
fn periodic_history_agrees_with_the_loop() {
    // Paper Example 4 (sigma0 = 6, g0 = 2, turning points 0, 1, 0.5, 1.5), repeated for 8
    // periods and sampled 7 times per unit of travel: after k periods y* is within
    // |y°(0) - y*(0)| exp(-a P k) = 2 exp(-12 k) of y°, below rounding from the third period
    // on. The minor cycle (1, 0.5) of every later period is lugre loop's minor loop.
    let tp = [0.0, 1.0, 0.5, 1.5];
    let periods = 8;
    let mut u = vec![0.0];
    for _ in 0..periods {
        for k in 0..4 {
            let (from, to) = (tp[k], tp[(k + 1) % 4]);
            let n = ((to - from) * 7.0f64).abs().round() as usize;
            for j in 1..=n {
                u.push(from + (to - from) * (j as f64 / n as f64));
            }
        }
    }
    let model = crate::LuGre::paper()
        .with_sigma0(6.0)
        .unwrap()
        .rate_independent();
    let h = count_cycles_with_energy(&u, 0.0, model, 0.0).unwrap();
    let hl = HysteresisLoop::new(model, &TurningPoints::new(&tp).unwrap()).unwrap();
    let loops = hl.loops();
    let minor = loops.iter().find(|l| l.kind == LoopKind::Minor).unwrap();
    let minors: Vec<&Cycle> = h
        .cycles
        .iter()
        .filter(|c| c.is_full() && c.range == 0.5)
        .collect();
    assert_eq!(minors.len(), periods);
    let scale = hl.model().g0() * hl.period();
    for c in &minors[3..] {
        let e = c.energy.unwrap();
        assert_eq!(u[c.start as usize], 1.0);
        assert_eq!(u[c.end as usize], 0.5);
        assert!(
            (e.y_start - minor.start.y).abs() < LOOP * 2.0,
            "{e:?} {minor:?}"
        );
        assert!((e.y_closure - minor.end.y).abs() < LOOP * 2.0);
        assert!(
            (e.arc.work - minor.energy.work).abs() < CYCLE_ENERGY * scale,
            "{e:?} {minor:?}"
        );
        assert!((e.arc.dissipation - minor.energy.dissipation).abs() < CYCLE_ENERGY * scale);
        assert!(
            (e.arc.stored_energy_change - minor.energy.stored_energy_change).abs() < LOOP * scale
        );
        assert!((e.arc.closure_gap - minor.energy.closure_gap).abs() < LOOP * 2.0);
    }
    // The same history given by its turning points only gives the same y* and energies
    // (rate independence: only the path matters).
    let turning: Vec<f64> = std::iter::once(0.0)
        .chain((0..periods).flat_map(|_| [1.0, 0.5, 1.5, 0.0]))
        .collect();
    let ht = count_cycles_with_energy(&turning, 0.0, model, 0.0).unwrap();
    let minors_t: Vec<&Cycle> = ht.cycles.iter().filter(|c| c.range == 0.5).collect();
    for (a, b) in minors.iter().zip(minors_t) {
        let (ea, eb) = (a.energy.unwrap(), b.energy.unwrap());
        assert!((ea.arc.work - eb.arc.work).abs() < CYCLE_ENERGY * scale);
        assert!((ea.y_closure - eb.y_closure).abs() < LOOP * 2.0);
    }
}

/// One counter: `with_energy(None, _)` leaves it counting only (the same rows, no energies),
/// a model given after the first sample is refused (the energies start at the first one).
#[test]
fn one_counter_with_or_without_a_model() {
    let u = [0.0, 2.0, 1.0, 3.0, -1.0];
    let plain = count_cycles(&u, 0.0).unwrap();
    let mut sink = Collect::default();
    let mut counter = CycleCounter::new(0.0)
        .unwrap()
        .with_energy(None, f64::NAN)
        .unwrap();
    counter.push_all(&u, &mut sink).unwrap();
    assert_eq!(counter.finish(&mut sink).unwrap(), plain.summary);
    assert_eq!(sink.cycles, plain.cycles);
    let model = crate::RateIndependent::new(2.0, 1.0).unwrap();
    let mut counter = CycleCounter::new(0.0).unwrap();
    counter.push(0.0, &mut sink).unwrap();
    assert_eq!(
        counter.with_energy(model, 0.0).unwrap_err(),
        HistoryError::EnergyAfterStart { samples: 1 }
    );
    let e = CycleCounter::new(0.0).unwrap().with_energy(model, 0.6);
    assert!(matches!(e, Err(HistoryError::BadInitialState { .. })));
}

#[test]
fn errors_name_the_offending_value() {
    assert_eq!(count_cycles(&[], 0.0).unwrap_err(), HistoryError::Empty);
    assert_eq!(
        count_cycles(&[1.0], 0.0).unwrap_err(),
        HistoryError::TooShort { samples: 1 }
    );
    assert!(matches!(
        count_cycles(&[0.0, 1.0, f64::NAN], 0.0).unwrap_err(),
        HistoryError::Data(crate::DataError::NotFinite { index: 2, .. })
    ));
    let e = count_cycles(&[0.0, f64::NEG_INFINITY], 0.0).unwrap_err();
    assert_eq!(
        e,
        HistoryError::Data(crate::DataError::NotFinite {
            what: "u",
            index: 1,
            value: f64::NEG_INFINITY
        })
    );
    // The wording every front end shares.
    assert_eq!(e.to_string(), "u[1] must be a finite number, got -inf");
    assert_eq!(
        count_cycles(&[0.0, 1e308], 0.0).unwrap_err(),
        HistoryError::TooLarge {
            index: 1,
            value: 1e308
        }
    );
    for gate in [-1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            count_cycles(&[0.0, 1.0], gate).unwrap_err(),
            HistoryError::BadGate { .. }
        ));
    }
    let model = crate::RateIndependent::new(2.0, 1.0).unwrap();
    let e = count_cycles_with_energy(&[0.0, 1.0], 0.0, model, 0.6).unwrap_err();
    assert!(e.to_string().starts_with("x0 must satisfy"), "{e}");
    // Ranges and means of values up to f64::MAX / 2 stay finite.
    let big = f64::MAX / 2.0;
    let h = count_cycles(&[-big, big, -big, big], 0.0).unwrap();
    assert!(h
        .cycles
        .iter()
        .all(|c| c.range.is_finite() && c.mean.is_finite()));
}

#[test]
fn histogram_bins_every_cycle() {
    let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];
    let h = count_cycles(&u, 0.0).unwrap();
    let mut hist = Histogram::new(3, -4.0, 5.0).unwrap();
    for c in &h.cycles {
        hist.add(c);
    }
    // Range bins [0, 3), [3, 6), [6, 9]: 3, 4, 4(full) | 8, 9, 8, 6.
    assert_eq!(hist.range_edges(), vec![0.0, 3.0, 6.0, 9.0]);
    assert_eq!(hist.range_counts(), &[0.0, 2.0, 2.0]);
    assert_eq!(hist.total(), 4.0);
    // Mean bins [-4, -1), [-1, 2), [2, 5]: range 3..6 means -0.5, -1, 1 -> all in the middle.
    assert_eq!(hist.range_row(1), &[0.0, 2.0, 0.0]);
    assert!(Histogram::new(0, 0.0, 1.0).is_err());
    assert!(Histogram::new(4, 1.0, 0.0).is_err());
}

/// Long histories whose runs, cycles and closures straddle block boundaries: random walks
/// (deep stacks), integer steps (ties, plateaus), a slow sine (long runs, nested wiggles), the
/// reference series one after another, a growing then decaying oscillation (shallow stacks and
/// half cycles, then a deep draining one), a ramp longer than two blocks and back with wiggles.
fn long_histories() -> Vec<Vec<f64>> {
    let mut rng = Lcg(17);
    let mut histories: Vec<Vec<f64>> = Vec::new();
    // Random walks: uniform steps, and nearly Gaussian ones (sums of four uniforms).
    histories.push(
        (0..40_000)
            .scan(0.0, |x, _| {
                *x += rng.next_f64() - 0.5;
                Some(*x)
            })
            .collect(),
    );
    histories.push(
        (0..40_000)
            .scan(0.0, |x, _| {
                *x += (0..4).map(|_| rng.next_f64()).sum::<f64>() - 2.0;
                Some(*x)
            })
            .collect(),
    );
    // Integer random walk (ties, plateaus, equal ranges).
    histories.push(
        (0..30_000)
            .scan(0.0, |x, _| {
                *x += ((rng.next_u64() >> 33) % 5) as f64 - 2.0;
                Some(*x)
            })
            .collect(),
    );
    // Slow sine with noise: runs of hundreds to thousands of samples, nested wiggles.
    histories.push(
        (0..30_000)
            .map(|k| {
                let t = k as f64 / 7000.0;
                (2.0 * std::f64::consts::PI * t).sin() * (1.0 + t) + 0.01 * (rng.next_f64() - 0.5)
            })
            .collect(),
    );
    // The reference series one after another.
    let mut joined = Vec::new();
    for case in 0..400 {
        joined.extend(reference_series(&mut rng, case));
    }
    histories.push(joined);
    // Growing, then decaying oscillation, then a random walk with a sine.
    let sign = |k: usize| [1.0, -1.0][k % 2];
    let mut osc: Vec<f64> = (0..6000).map(|k| k as f64 * sign(k)).collect();
    osc.extend((0..20_000).map(|k| (20_000 - k) as f64 * sign(k)));
    let mut x = 0.0;
    osc.extend((0..10_000).map(|k| {
        x += rng.next_f64() - 0.5;
        x + 50.0 * (k as f64 / 30.0).sin()
    }));
    histories.push(osc);
    // A ramp longer than two blocks, then a ramp back with wiggles (cycles nested along one
    // long run of the large scale), then a decaying oscillation (a converging residue).
    let mut ramp: Vec<f64> = (0..5000).map(|k| k as f64).collect();
    ramp.extend((0..5000).map(|k| 5000.0 - k as f64 + 30.0 * (k as f64 / 20.0).sin()));
    ramp.extend((0..3000).map(|k| 1000.0 * (k as f64 / 50.0).cos() * (-(k as f64) / 800.0).exp()));
    histories.push(ramp);
    histories
}

/// Counts `u` without a gate into `sink`, fed in pieces of `chunk` samples; 0 alternates
/// pieces below 64 samples (which take the per-sample walk) and longer ones (blocks).
fn count_in_pieces(u: &[f64], chunk: usize, sink: &mut impl CycleSink) -> CycleSummary {
    let mixed = [1, 3000, 7, 100, 2049, 63, 64];
    let mut counter = CycleCounter::new(0.0).unwrap();
    let mut rest = u;
    let mut k = 0;
    while !rest.is_empty() {
        let n = if chunk == 0 {
            mixed[k % mixed.len()]
        } else {
            chunk
        };
        let (c, r) = rest.split_at(n.min(rest.len()));
        counter.push_all(c, sink).unwrap();
        rest = r;
        k += 1;
    }
    counter.finish(sink).unwrap()
}

/// The per-sample walk's reversals and cycles of `u` without a gate (energies make every
/// sample go through it), the energies dropped.
fn walked(u: &[f64]) -> History {
    let model = crate::RateIndependent::new(1.0, 1.0).unwrap();
    let h = count_cycles_with_energy(u, 0.0, model, 0.0).unwrap();
    History {
        cycles: h
            .cycles
            .iter()
            .map(|c| Cycle { energy: None, ..*c })
            .collect(),
        summary: CycleSummary {
            energy: None,
            ..h.summary
        },
        ..h
    }
}

#[test]
fn block_path_agrees_with_the_per_sample_walk() {
    // Counting alone goes through blocks of samples (branch-free reversals, closures by binary
    // search); with energies every sample goes through the walk. Fed in chunks of several
    // sizes.
    for (n, u) in long_histories().iter().enumerate() {
        let walk = walked(u);
        assert!(walk.summary.full_cycles > 10, "history {n}");
        for chunk in [0, 1, 7, 64, 2048, 2049, 5000, u.len()] {
            let mut sink = Collect::default();
            let summary = count_in_pieces(u, chunk, &mut sink);
            assert_eq!(summary, walk.summary, "history {n}, chunk {chunk}");
            assert_eq!(sink.reversals, walk.reversals, "history {n}, chunk {chunk}");
            assert!(sink.cycles == walk.cycles, "history {n}, chunk {chunk}");
        }
    }
}

/// Every column of `c` row by row, NaN compared by its bits.
type ColumnRow = (f64, f64, f64, i64, i64, i64, u64, [u64; 4]);

fn column_rows(c: &CycleColumns) -> Vec<ColumnRow> {
    let energy = |v: &Vec<f64>, k: usize| v.get(k).map_or(0, |x| x.to_bits());
    (0..c.len())
        .map(|k| {
            (
                c.range[k],
                c.mean[k],
                c.count[k],
                c.start[k],
                c.end[k],
                c.closure.get(k).copied().unwrap_or(-2),
                c.closure_position.get(k).map_or(0, |x| x.to_bits()),
                [
                    energy(&c.work, k),
                    energy(&c.stored_energy_change, k),
                    energy(&c.dissipation, k),
                    energy(&c.closure_gap, k),
                ],
            )
        })
        .collect()
}

/// The columns of a history counted one cycle at a time.
fn expected_columns(h: &History, template: &CycleColumns) -> CycleColumns {
    let mut c = template.clone();
    for r in &h.reversals {
        c.reversal(*r);
    }
    for cy in &h.cycles {
        c.cycle(*cy);
    }
    c
}

#[test]
fn columns_agree_with_the_cycle_sink() {
    // Counting into columns takes the branch-free stretches of `count_fast` between the
    // reversals pushed one by one: compare every column with the per-sample walk, for every
    // choice of columns, fed in pieces of several sizes.
    let templates = [
        CycleColumns::new(),
        CycleColumns::new().with_reversals(false),
        CycleColumns::new().with_closures(false),
        CycleColumns::new()
            .with_reversals(false)
            .with_closures(false),
        CycleColumns::new().with_energy(true),
    ];
    for (n, u) in long_histories().iter().enumerate() {
        let walk = walked(u);
        for chunk in [0, 1, 64, 2048, 5000, u.len()] {
            for template in &templates {
                let want = expected_columns(&walk, template);
                let mut columns = template.clone();
                let summary = count_in_pieces(u, chunk, &mut columns);
                assert_eq!(summary, walk.summary, "history {n}, chunk {chunk}");
                assert!(columns.reversal_index == want.reversal_index, "history {n}");
                assert!(columns.reversal_u == want.reversal_u, "history {n}");
                let (got, want_rows) = (column_rows(&columns), column_rows(&want));
                assert_eq!(got.len(), want_rows.len(), "history {n}, chunk {chunk}");
                if let Some(k) = (0..got.len()).find(|&k| got[k] != want_rows[k]) {
                    panic!(
                        "history {n}, chunk {chunk}, cycle {k}: {:?} instead of {:?}",
                        got[k], want_rows[k]
                    );
                }
                let rows = columns.len();
                assert_eq!(rows, walk.cycles.len());
                let kept = |keep: bool| if keep { rows } else { 0 };
                assert_eq!(columns.closure.len(), kept(template.keeps_closures()));
                assert_eq!(columns.work.len(), kept(template.keeps_energy()));
                assert_eq!(
                    columns.reversal_u.len() as u64,
                    summary.reversals * u64::from(template.keeps_reversals())
                );
            }
        }
    }
}

#[test]
fn columns_with_energies() {
    // With a model the energies go to their columns (NaN for half cycles).
    let mut rng = Lcg(31);
    let u: Vec<f64> = (0..3000)
        .scan(0.0, |x, _| {
            *x += rng.next_f64() - 0.5;
            Some(*x)
        })
        .collect();
    let model = crate::LuGre::paper().rate_independent();
    let h = count_cycles_with_energy(&u, 0.05, model, 0.1).unwrap();
    let mut columns = CycleColumns::new().with_energy(true);
    let mut counter = CycleCounter::new(0.05)
        .unwrap()
        .with_energy(model, 0.1)
        .unwrap();
    counter.push_all(&u, &mut columns).unwrap();
    assert_eq!(counter.finish(&mut columns).unwrap(), h.summary);
    let want = expected_columns(&h, &CycleColumns::new().with_energy(true));
    assert_eq!(column_rows(&columns), column_rows(&want));
    assert_eq!(columns.reversal_index, want.reversal_index);
    // Emptied, the same columns count again from scratch.
    let filled = column_rows(&columns);
    columns.clear();
    assert!(columns.is_empty() && columns.reversal_u.is_empty() && columns.work.is_empty());
    let mut counter = CycleCounter::new(0.05)
        .unwrap()
        .with_energy(model, 0.1)
        .unwrap();
    counter.push_all(&u, &mut columns).unwrap();
    counter.finish(&mut columns).unwrap();
    assert_eq!(column_rows(&columns), filled);
    for (k, c) in h.cycles.iter().enumerate() {
        match c.energy {
            Some(e) => {
                assert_eq!(columns.work[k], e.arc.work);
                assert_eq!(columns.dissipation[k], e.arc.dissipation);
                assert_eq!(columns.stored_energy_change[k], e.arc.stored_energy_change);
                assert_eq!(columns.closure_gap[k], e.arc.closure_gap);
            }
            None => assert!(columns.work[k].is_nan() && c.count == 0.5),
        }
    }
    assert!(h.summary.full_cycles > 100);
}
