//! The streaming rainflow engine on arbitrary f64 sequences: no panic; the block path, the
//! per-sample walk, the energy-tracking walk and the count into columns (branch-free, as the
//! Python binding does it) find the same reversals and cycles; the counts add up
//! (reversals = 2 full + half + 1).
#![no_main]

use libfuzzer_sys::fuzz_target;
use lugre::cycles::Collect;
use lugre::{CycleColumns, CycleCounter, HistoryError, RateIndependent};

/// Counts `u` pushed in slices of `chunk` (0: all at once).
fn count(u: &[f64], gate: f64, chunk: usize) -> Result<(Collect, u64, u64, u64), HistoryError> {
    let mut sink = Collect::default();
    let mut c = CycleCounter::new(gate)?;
    if chunk == 0 {
        c.push_all(u, &mut sink)?;
    } else {
        for part in u.chunks(chunk) {
            c.push_all(part, &mut sink)?;
        }
    }
    let s = c.finish(&mut sink)?;
    Ok((sink, s.reversals, s.full_cycles, s.half_cycles))
}

/// Counts `u` into columns in slices of `chunk`.
fn count_columns(u: &[f64], gate: f64, chunk: usize) -> Result<CycleColumns, HistoryError> {
    let mut columns = CycleColumns::new();
    let mut c = CycleCounter::new(gate)?;
    for part in u.chunks(chunk.max(1)) {
        c.push_all(part, &mut columns)?;
    }
    c.finish(&mut columns)?;
    Ok(columns)
}

/// The columns of `sink`'s reversals and cycles (closure -1 / NaN for half cycles), NaN
/// compared by its bits.
fn as_columns(sink: &Collect) -> (Vec<(i64, u64)>, Vec<(u64, u64, u64, i64, i64, i64, u64)>) {
    let reversals = sink
        .reversals
        .iter()
        .map(|r| (r.index as i64, r.u.to_bits()))
        .collect();
    let cycles = sink
        .cycles
        .iter()
        .map(|c| {
            let (k, pos) = c
                .closure
                .map_or((-1, f64::NAN), |k| (k.index as i64, k.position));
            let (range, mean, count) = (c.range.to_bits(), c.mean.to_bits(), c.count.to_bits());
            (
                range,
                mean,
                count,
                c.start as i64,
                c.end as i64,
                k,
                pos.to_bits(),
            )
        })
        .collect();
    (reversals, cycles)
}

fuzz_target!(|data: &[u8]| {
    let Some((&head, rest)) = data.split_first() else {
        return;
    };
    let mut u = lugre_fuzz::values(rest);
    // Long runs reach the block path (64 samples or more at a time) and cross its blocks of
    // 2048.
    if head & 1 == 1 && !u.is_empty() {
        let base = u.clone();
        while u.len() < 2100 {
            u.extend_from_slice(&base);
        }
    }
    let gate = match head >> 5 {
        0..=3 => 0.0,
        4 => 0.5,
        5 => 1e-300,
        6 => 3.0,
        _ => f64::from(head & 0x1f),
    };
    let whole = count(&u, gate, 0);
    let each = count(&u, gate, 1);
    let odd = count(&u, gate, 67);
    match (&whole, &each, &odd) {
        (Ok(a), Ok(b), Ok(c)) => {
            assert_eq!(a, b, "block path and per-sample walk agree");
            assert_eq!(a, c, "chunking does not matter");
            let (sink, reversals, full, half) = a;
            assert_eq!(*reversals, sink.reversals.len() as u64);
            assert_eq!(reversals, &(2 * full + half + 1), "counts add up");
            for c in &sink.cycles {
                assert!(c.range.is_finite() && c.mean.is_finite() && c.range >= 0.0);
                if let Some(cl) = c.closure {
                    assert!(cl.index > c.end && cl.position <= cl.index as f64);
                    assert!(cl.position >= (cl.index - 1) as f64, "{c:?}");
                }
            }
        }
        // Compared as printed: an error may carry a NaN sample.
        (Err(a), Err(b), Err(c)) => {
            assert_eq!(format!("{a:?}"), format!("{b:?}"));
            assert_eq!(format!("{a:?}"), format!("{c:?}"));
        }
        _ => panic!("the paths disagree: {whole:?} {each:?} {odd:?}"),
    }

    // Into columns: the same reversals and cycles, closures included.
    for chunk in [u.len(), 67] {
        match (count_columns(&u, gate, chunk), &whole) {
            (Ok(c), Ok((plain, ..))) => {
                let reversals: Vec<(i64, u64)> = c
                    .reversal_index
                    .iter()
                    .zip(&c.reversal_u)
                    .map(|(&i, u)| (i, u.to_bits()))
                    .collect();
                let cycles: Vec<_> = (0..c.len())
                    .map(|k| {
                        let bits = |v: &Vec<f64>| v[k].to_bits();
                        let (start, end) = (c.start[k], c.end[k]);
                        (
                            bits(&c.range),
                            bits(&c.mean),
                            bits(&c.count),
                            start,
                            end,
                            c.closure[k],
                            bits(&c.closure_position),
                        )
                    })
                    .collect();
                assert_eq!((reversals, cycles), as_columns(plain), "columns agree");
            }
            (Err(a), Err(b)) => assert_eq!(format!("{a:?}"), format!("{b:?}")),
            (c, p) => panic!("columns and plain counts disagree: {c:?} {p:?}"),
        }
    }

    // The energy walk counts the same cycles.
    let sigma0 = 2.0f64.powi(i32::from(head & 0x1f) - 12);
    let model = RateIndependent::new(sigma0, 1.5).unwrap();
    let mut sink = Collect::default();
    // y*(0) = sigma0 x0 = 0.5.
    let counter = CycleCounter::new(gate).and_then(|c| c.with_energy(model, 0.5 / sigma0));
    let energy = counter.and_then(|mut c| {
        c.push_all(&u, &mut sink)?;
        c.finish(&mut sink)
    });
    match (energy, &whole) {
        (Ok(_), Ok((plain, ..))) => {
            assert_eq!(sink.reversals, plain.reversals);
            assert_eq!(sink.cycles.len(), plain.cycles.len());
            for (e, p) in sink.cycles.iter().zip(&plain.cycles) {
                assert_eq!(
                    (e.range, e.mean, e.count, e.start, e.end),
                    (p.range, p.mean, p.count, p.start, p.end)
                );
                assert_eq!(e.closure, p.closure);
                if let Some(en) = e.energy {
                    assert!(en.arc.dissipation >= 0.0, "{en:?}");
                    assert!(
                        en.y_start.abs() <= 1.5 && en.y_closure.abs() <= 1.5,
                        "{en:?}"
                    );
                }
            }
        }
        (Err(HistoryError::EnergyOverflow { .. }), _) => {}
        (Err(e), Err(p)) => assert_eq!(format!("{e:?}"), format!("{p:?}")),
        (e, p) => panic!("energy and plain counts disagree: {e:?} {p:?}"),
    }
});
