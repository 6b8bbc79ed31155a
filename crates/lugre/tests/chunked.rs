//! The chunked count equals the single pass: for any chunking and any merge tree, the same
//! rows (range, mean, count, start, end, closure index and position) in the same order, and
//! the same summary. Exact equality throughout (`==` on the f64 columns): the chunked count
//! computes every field with the single pass's expressions from the same samples.

use lugre::cycles::chunk::{assemble, close_in_chunk, count_chunk, merge, ChunkPlan};
use lugre::{count_cycles, CycleColumns, CycleCounter, CycleSummary, HistoryError};
use proptest::prelude::*;

/// The single pass into columns.
fn single(u: &[f64]) -> (CycleColumns, CycleSummary) {
    let mut c = CycleColumns::new().with_reversals(false);
    let mut counter = CycleCounter::new(0.0).unwrap();
    counter.push_all(u, &mut c).unwrap();
    let s = counter.finish(&mut c).unwrap();
    (c, s)
}

/// The chunked count with chunk boundaries `cuts` (sorted, inside `1..len`) and merges in the
/// order `order` picks (each entry chooses which adjacent pair of the current list to merge).
fn chunked(
    u: &[f64],
    cuts: &[usize],
    order: &[usize],
) -> Result<(CycleColumns, CycleSummary), HistoryError> {
    let mut bounds = vec![0];
    bounds.extend_from_slice(cuts);
    bounds.push(u.len());
    let mut leaves = Vec::new();
    let mut rows = Vec::new();
    for w in bounds.windows(2) {
        let (s, r) = count_chunk(&u[w[0]..w[1]], w[0] as u64)?;
        leaves.push(s);
        rows.push(r);
    }
    let mut plan = ChunkPlan::new(leaves.clone())?;
    let mut level = leaves;
    let mut pick = order.iter().cycle();
    while level.len() > 1 {
        let k = pick.next().map_or(0, |&p| p % (level.len() - 1));
        let (m, open) = merge(&level[k], &level[k + 1])?;
        plan.add_open(&open);
        level.splice(k..k + 2, [m]);
    }
    let summary = plan.finish(&level[0])?;
    let queries = plan.queries()?;
    for (k, w) in bounds.windows(2).enumerate() {
        let prev = (w[0] > 0).then(|| u[w[0] - 1]);
        let found = close_in_chunk(&u[w[0]..w[1]], w[0] as u64, prev, &queries[k])?;
        plan.resolve(&found);
    }
    let extras = plan.extras()?;
    let mut out = CycleColumns::new().with_reversals(false);
    for (own, extra) in rows.iter().zip(&extras) {
        let part = assemble(own, extra);
        append(&mut out, &part);
    }
    Ok((out, summary))
}

fn append(out: &mut CycleColumns, part: &CycleColumns) {
    out.range.extend_from_slice(&part.range);
    out.mean.extend_from_slice(&part.mean);
    out.count.extend_from_slice(&part.count);
    out.start.extend_from_slice(&part.start);
    out.end.extend_from_slice(&part.end);
    out.closure.extend_from_slice(&part.closure);
    out.closure_position
        .extend_from_slice(&part.closure_position);
}

/// Rows as comparable tuples (bit patterns, so that NaN positions of half cycles compare).
fn rows(c: &CycleColumns) -> Vec<(u64, u64, u64, i64, i64, i64, u64)> {
    (0..c.len())
        .map(|k| {
            (
                c.range[k].to_bits(),
                c.mean[k].to_bits(),
                c.count[k].to_bits(),
                c.start[k],
                c.end[k],
                c.closure[k],
                c.closure_position[k].to_bits(),
            )
        })
        .collect()
}

fn check(u: &[f64], cuts: &[usize], order: &[usize]) {
    let (want, want_summary) = single(u);
    let (got, got_summary) = chunked(u, cuts, order).unwrap();
    assert_eq!(
        rows(&got),
        rows(&want),
        "u = {u:?}, cuts = {cuts:?}, order = {order:?}"
    );
    assert_eq!(got_summary, want_summary, "u = {u:?}, cuts = {cuts:?}");
}

/// Sorted distinct cuts inside `1..n` from raw picks.
fn cuts_of(n: usize, raw: &[usize]) -> Vec<usize> {
    let mut c: Vec<usize> = raw.iter().map(|r| 1 + r % (n - 1)).collect();
    c.sort_unstable();
    c.dedup();
    c
}

/// Values from a few small integers: plateaus, ties and equal ranges everywhere.
fn small_ints() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec((-3i32..=3).prop_map(f64::from), 2..80)
}

/// A random walk.
fn walk() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-1.0f64..1.0, 2..300).prop_map(|steps| {
        let mut x = 0.0;
        steps
            .iter()
            .map(|s| {
                x += s;
                x
            })
            .collect()
    })
}

/// Values spread over many binades, with near-ties: differences round, so the tests compare
/// rounded differences (adversarial for any reasoning in exact arithmetic).
fn binades() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(
        (-1i32..=1, -60i32..60, 0u32..4).prop_map(|(sign, e, ulps)| {
            let base = 2f64.powi(e) * (1.0 + f64::EPSILON * f64::from(ulps));
            f64::from(sign) * base + if sign == 0 { 1.0 } else { 0.0 }
        }),
        2..120,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn small_integers_any_chunking(u in small_ints(), raw in prop::collection::vec(any::<usize>(), 0..12),
                                   order in prop::collection::vec(any::<usize>(), 1..12)) {
        let cuts = cuts_of(u.len(), &raw);
        check(&u, &cuts, &order);
    }

    #[test]
    fn random_walks_any_chunking(u in walk(), raw in prop::collection::vec(any::<usize>(), 0..20),
                                 order in prop::collection::vec(any::<usize>(), 1..20)) {
        let cuts = cuts_of(u.len(), &raw);
        check(&u, &cuts, &order);
    }

    #[test]
    fn many_binades_any_chunking(u in binades(), raw in prop::collection::vec(any::<usize>(), 0..16),
                                 order in prop::collection::vec(any::<usize>(), 1..16)) {
        let cuts = cuts_of(u.len(), &raw);
        check(&u, &cuts, &order);
    }

    #[test]
    fn chunks_of_one_sample(u in small_ints(), order in prop::collection::vec(any::<usize>(), 1..12)) {
        let cuts: Vec<usize> = (1..u.len()).collect();
        check(&u, &cuts, &order);
    }
}

#[test]
fn astm_example_every_cut() {
    let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];
    for a in 1..u.len() {
        for b in a..u.len() {
            let cuts: Vec<usize> = if a == b { vec![a] } else { vec![a, b] };
            for order in [[0], [1]] {
                check(&u, &cuts, &order);
            }
        }
    }
    // The rows are those of the worked example (count_cycles' own test).
    let h = count_cycles(&u, 0.0).unwrap();
    assert_eq!(h.summary.full_cycles, 1);
}

#[test]
fn constant_chunks_and_plateaus_across_cuts() {
    let cases: [&[f64]; 6] = [
        &[1.0, 1.0, 1.0, 1.0],
        &[0.0, 2.0, 2.0, 2.0, 2.0, 0.0, 1.0],
        &[0.0, 2.0, 2.0, 2.0, 3.0, 3.0, -1.0, -1.0, 0.0],
        &[5.0, 5.0, 4.0, 4.0, 6.0, 6.0, 6.0, 1.0, 1.0],
        &[0.0, -0.0, 0.0, 1.0, -0.0, 0.0],
        &[3.0, 3.0],
    ];
    for u in cases {
        let n = u.len();
        for mask in 0u32..(1 << (n - 1)) {
            let cuts: Vec<usize> = (1..n).filter(|k| mask & (1 << (k - 1)) != 0).collect();
            for order in [[0usize], [1], [7]] {
                check(u, &cuts, &order);
            }
        }
    }
}

#[test]
fn bad_chunks_are_errors() {
    assert_eq!(
        count_chunk(&[], 10).unwrap_err(),
        HistoryError::EmptyChunk { start: 10 }
    );
    let e = count_chunk(&[0.0, 1.0, f64::NAN], 100).unwrap_err();
    assert!(
        matches!(e, HistoryError::NotFinite { index: 102, .. }),
        "{e:?}"
    );
    let (a, _) = count_chunk(&[0.0, 1.0], 0).unwrap();
    let (b, _) = count_chunk(&[0.0, 1.0], 5).unwrap();
    assert_eq!(
        merge(&a, &b).unwrap_err(),
        HistoryError::NotAdjacent {
            left_end: 1,
            right_start: 5
        }
    );
    assert!(ChunkPlan::new(vec![b.clone()]).is_err());
    let bytes = a.to_bytes();
    assert_eq!(
        lugre::cycles::chunk::ChunkSummary::from_bytes(&bytes).unwrap(),
        a
    );
    assert!(lugre::cycles::chunk::ChunkSummary::from_bytes(&bytes[..bytes.len() - 1]).is_err());
}

#[test]
fn a_long_walk_in_uneven_chunks() {
    // 200 000 samples of a random walk (a fixed LCG), in 37 uneven chunks, merged left to
    // right and as a balanced tree.
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut x = 0.0;
    let u: Vec<f64> = (0..200_000)
        .map(|_| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            x += ((state >> 11) as f64 / (1u64 << 53) as f64) - 0.5;
            x
        })
        .collect();
    let cuts: Vec<usize> = (1..37).map(|k| k * k * 150 + k * 17).collect();
    check(&u, &cuts, &[0]);
    check(&u, &cuts, &[1, 3, 5, 0, 2, 4]);
}
