//! The names of a cycle's columns, one list for every front end: `lugre cycles --csv` and
//! `--json`, the Python dicts of `lugre.cycles`, the C ABI's `LugreCycleColumns` and the MEX
//! gateway's struct fields (each front end writes or is checked against these names).

use super::{Cycle, CycleColumns};

/// A cell of a cycle's row ([`Cycle::row`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// A real number.
    Number(f64),
    /// A sample index.
    Index(u64),
    /// No value: the closure of a half cycle, the energies without a model.
    Missing,
}

impl Cycle {
    /// The columns of a cycle's row, in order: the table rainflow counters yield (`range`,
    /// `mean`, `count`, `start`, `end`), the closure (`closure`, `closure_position`), the
    /// energies over the arc ([`crate::ArcEnergy`]'s `work`, `stored_energy_change`,
    /// `dissipation`, `closure_gap`) and `y*` at the start and the closure (`y_start`,
    /// `y_closure`).
    pub const COLUMNS: [&'static str; 13] = [
        "range",
        "mean",
        "count",
        "start",
        "end",
        "closure",
        "closure_position",
        "work",
        "stored_energy_change",
        "dissipation",
        "closure_gap",
        "y_start",
        "y_closure",
    ];

    /// The cycle's values in the order of [`Self::COLUMNS`].
    pub fn row(&self) -> [Cell; 13] {
        use Cell::{Index, Missing, Number};
        let closure = self
            .closure
            .map_or([Missing; 2], |c| [Index(c.index), Number(c.position)]);
        let energy = self.energy.map_or([Missing; 6], |e| {
            [
                e.arc.work,
                e.arc.stored_energy_change,
                e.arc.dissipation,
                e.arc.closure_gap,
                e.y_start,
                e.y_closure,
            ]
            .map(Number)
        });
        let [c0, c1] = closure;
        let [e0, e1, e2, e3, e4, e5] = energy;
        [
            Number(self.range),
            Number(self.mean),
            Number(self.count),
            Index(self.start),
            Index(self.end),
            c0,
            c1,
            e0,
            e1,
            e2,
            e3,
            e4,
            e5,
        ]
    }
}

impl CycleColumns {
    /// The names of the cycle columns, the first of [`Cycle::COLUMNS`] (the columns keep no
    /// `y_start`, `y_closure`): `range`, ..., `closure_gap`, the fields of the same names.
    pub const NAMES: [&'static str; 11] = {
        let mut names = [""; 11];
        let mut i = 0;
        while i < names.len() {
            names[i] = Cycle::COLUMNS[i];
            i += 1;
        }
        names
    };
}

/// A cycle column by name ([`CycleColumns::column_mut`]): numbers or sample indices.
#[derive(Debug)]
pub enum ColumnMut<'a> {
    Real(&'a mut Vec<f64>),
    Index(&'a mut Vec<i64>),
}

impl CycleColumns {
    /// The column called `name` (one of [`Self::NAMES`], the field of that name), for a front
    /// end that reads or writes the columns by the core's names.
    pub fn column_mut(&mut self, name: &str) -> Option<ColumnMut<'_>> {
        use ColumnMut::{Index, Real};
        // By place in NAMES: the names are written once, there.
        Some(match Self::NAMES.iter().position(|&n| n == name)? {
            0 => Real(&mut self.range),
            1 => Real(&mut self.mean),
            2 => Real(&mut self.count),
            3 => Index(&mut self.start),
            4 => Index(&mut self.end),
            5 => Index(&mut self.closure),
            6 => Real(&mut self.closure_position),
            7 => Real(&mut self.work),
            8 => Real(&mut self.stored_energy_change),
            9 => Real(&mut self.dissipation),
            _ => Real(&mut self.closure_gap),
        })
    }

    /// The names of the columns these columns fill, in the order of [`Self::NAMES`]: `range`
    /// to `end`, then `closure`, `closure_position` if closures are kept, then the four
    /// energies if they are.
    pub fn kept_names(&self) -> Vec<&'static str> {
        let mut out = Self::NAMES[..5].to_vec();
        if self.keeps_closures() {
            out.extend_from_slice(&Self::NAMES[5..7]);
        }
        if self.keeps_energy() {
            out.extend_from_slice(&Self::NAMES[7..]);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cycles::{Closure, CycleEnergy};
    use crate::ArcEnergy;

    #[test]
    fn a_row_follows_the_columns() {
        let mut c = Cycle {
            range: 3.0,
            mean: 0.5,
            count: 1.0,
            start: 4,
            end: 5,
            closure: Some(Closure {
                index: 6,
                position: 5.5,
            }),
            energy: None,
        };
        let row = c.row();
        assert_eq!(
            row[Cycle::COLUMNS.iter().position(|&n| n == "end").unwrap()],
            Cell::Index(5)
        );
        assert_eq!(row[6], Cell::Number(5.5));
        assert_eq!(row[7..], [Cell::Missing; 6]);
        c.energy = Some(CycleEnergy {
            arc: ArcEnergy {
                work: 1.0,
                stored_energy_change: 2.0,
                dissipation: 3.0,
                closure_gap: 4.0,
            },
            y_start: 5.0,
            y_closure: 6.0,
        });
        c.closure = None;
        let row = c.row();
        assert_eq!(row[5..7], [Cell::Missing; 2]);
        assert_eq!(row[12], Cell::Number(6.0));
        assert_eq!(CycleColumns::NAMES[..], Cycle::COLUMNS[..11]);
    }

    /// Each column by name holds, row by row, the cell of that name of each cycle's row.
    #[test]
    fn the_columns_by_name_are_the_rows_cells() {
        use crate::{CycleCounter, CycleSink, LuGre};
        let u = [-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0];
        let model = LuGre::paper().rate_independent();
        fn count<S: CycleSink>(u: &[f64], model: crate::RateIndependent, sink: &mut S) {
            let mut counter = CycleCounter::new(0.0)
                .unwrap()
                .with_energy(Some(model), 0.0)
                .unwrap();
            counter.push_all(u, sink).unwrap();
            counter.finish(sink).unwrap();
        }
        let mut cycles: Vec<Cycle> = Vec::new();
        count(&u, model, &mut cycles);
        let mut c = CycleColumns::new().with_energy(true);
        count(&u, model, &mut c);
        assert_eq!(c.kept_names(), CycleColumns::NAMES);
        for (j, name) in CycleColumns::NAMES.into_iter().enumerate() {
            let cells: Vec<Cell> = match c.column_mut(name).unwrap() {
                ColumnMut::Real(v) => v.iter().map(|&x| Cell::Number(x)).collect(),
                ColumnMut::Index(v) => v.iter().map(|&i| Cell::Index(i as u64)).collect(),
            };
            for (k, cycle) in cycles.iter().enumerate() {
                let want = cycle.row()[j];
                let have = cells[k];
                let same = match (want, have) {
                    (Cell::Missing, Cell::Number(x)) => x.is_nan(),
                    (Cell::Missing, Cell::Index(_)) => c.closure[k] == -1,
                    _ => want == have,
                };
                assert!(same, "{name} of cycle {k}: {have:?}, the row has {want:?}");
            }
        }
        assert!(c.column_mut("y_start").is_none());
        let c = CycleColumns::new().with_closures(false);
        assert_eq!(c.kept_names(), CycleColumns::NAMES[..5]);
    }
}
