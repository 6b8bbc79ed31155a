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
}
