//! The units on a figure's axes: those of the input file's header (`Position [mm]`), unless
//! `--scale` changed the values, replaced by `--units t=s,u=mm,F=N`; none where neither gives
//! one. Velocities, energies and stiffnesses take units made of these.

use anyhow::{bail, Result};
use lugre_io::{ReadOptions, Role, Table};

/// The units of the time, the displacement and the force, for axis labels.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Units {
    pub(crate) t: Option<String>,
    pub(crate) u: Option<String>,
    pub(crate) force: Option<String>,
}

impl Units {
    /// SI (s, m, N): a preset's parameters are SI.
    pub(crate) fn si() -> Self {
        Units {
            t: Some("s".into()),
            u: Some("m".into()),
            force: Some("N".into()),
        }
    }

    /// The header's units of the columns read into `table` (a velocity record's `v` gives
    /// the displacement's as its unit times the time's), except those `options` scaled.
    pub(crate) fn of_file(table: &Table, options: &ReadOptions) -> Self {
        let unit = |role: Role| -> Option<String> {
            if options.scales(&role) {
                return None;
            }
            table.get(&role).and_then(|c| c.info.unit.clone())
        };
        let t = unit(Role::T);
        let u = unit(Role::U).or_else(|| {
            // A velocity record: `mm/s` over `s` is `mm`.
            let v = unit(Role::V)?;
            let per = format!("/{}", t.as_deref().unwrap_or("s"));
            v.strip_suffix(&per).map(str::to_string)
        });
        Units {
            t,
            u,
            force: unit(Role::F),
        }
    }

    /// The units of the header of the file at `path` (the first column of each role), except
    /// for roles `options` scales; none if the file has no header or cannot be read (its
    /// reading reports that).
    pub(crate) fn of_header(path: &std::path::Path, options: &ReadOptions) -> Self {
        let Ok(reader) = lugre_io::Reader::open(path, options.clone()) else {
            return Units::default();
        };
        let unit = |role: Role| -> Option<String> {
            if options.scales(&role) {
                return None;
            }
            let fields = reader.header()?;
            fields.iter().find(|f| f.role == role)?.unit.clone()
        };
        Units {
            t: unit(Role::T),
            u: unit(Role::U),
            force: unit(Role::F),
        }
    }

    /// The units of a figure of a command that reads `file` (its header's, for roles
    /// `options` does not scale) or, without one, runs a model that is SI when `preset`; then
    /// `--units` (`flag`) over them.
    pub(crate) fn for_figure(
        file: Option<&std::path::Path>,
        options: &ReadOptions,
        preset: bool,
        flag: Option<&str>,
    ) -> Result<Self> {
        let units = match file {
            Some(file) => Units::of_header(file, options),
            None if preset => Units::si(),
            None => Units::default(),
        };
        units.with_flag(flag)
    }

    /// These units with those of `--units ROLE=UNIT,...` (roles `t`, `u`, `F` by any of their
    /// header names) in their place.
    pub(crate) fn with_flag(mut self, text: Option<&str>) -> Result<Self> {
        let Some(text) = text else {
            return Ok(self);
        };
        for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let Some((role, unit)) = item.split_once('=') else {
                bail!("--units: '{item}' is not ROLE=UNIT (e.g. u=mm,F=N)");
            };
            let unit = unit.trim();
            if unit.is_empty() {
                bail!("--units: the unit of '{}' is empty", role.trim());
            }
            let unit = Some(unit.to_string());
            match Role::of(role.trim()) {
                Role::T => self.t = unit,
                Role::U => self.u = unit,
                Role::F => self.force = unit,
                _ => bail!(
                    "--units: unknown quantity '{}' (give t=UNIT, u=UNIT or F=UNIT)",
                    role.trim()
                ),
            }
        }
        Ok(self)
    }

    fn label(name: &str, unit: Option<String>) -> String {
        match unit {
            Some(unit) => format!("{name} [{unit}]"),
            None => name.to_string(),
        }
    }

    pub(crate) fn t(&self, name: &str) -> String {
        Self::label(name, self.t.clone())
    }

    pub(crate) fn u(&self, name: &str) -> String {
        Self::label(name, self.u.clone())
    }

    pub(crate) fn force(&self, name: &str) -> String {
        Self::label(name, self.force.clone())
    }

    /// The displacement's unit per the time's (seconds if the time has none).
    pub(crate) fn velocity(&self, name: &str) -> String {
        let t = self.t.as_deref().unwrap_or("s");
        Self::label(name, self.u.as_ref().map(|u| format!("{u}/{t}")))
    }

    /// The force's unit times the displacement's (J for N and m).
    pub(crate) fn energy(&self, name: &str) -> String {
        let unit = match (&self.force, &self.u) {
            (Some(f), Some(u)) if f == "N" && u == "m" => Some("J".to_string()),
            (Some(f), Some(u)) => Some(format!("{f} {u}")),
            _ => None,
        };
        Self::label(name, unit)
    }

    /// The force's unit per the displacement's.
    pub(crate) fn stiffness(&self, name: &str) -> String {
        let unit = match (&self.force, &self.u) {
            (Some(f), Some(u)) => Some(format!("{f}/{u}")),
            _ => None,
        };
        Self::label(name, unit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_flag_replaces_what_the_file_or_preset_gave() {
        let si = Units::si();
        assert_eq!(si.energy("E"), "E [J]");
        assert_eq!(si.velocity("v"), "v [m/s]");
        let mm = Units::si().with_flag(Some("u=mm")).unwrap();
        assert_eq!(mm.u("A"), "A [mm]");
        assert_eq!(mm.energy("E"), "E [N mm]");
        assert_eq!(mm.stiffness("k"), "k [N/mm]");
        let named = Units::default()
            .with_flag(Some("Position=um, friction=mN, time=ms"))
            .unwrap();
        assert_eq!(named.velocity("v"), "v [um/ms]");
        assert_eq!(named.force("F"), "F [mN]");
        assert_eq!(Units::default().u("A"), "A");
        assert_eq!(
            Units::default()
                .with_flag(Some("w=s"))
                .unwrap_err()
                .to_string(),
            "--units: unknown quantity 'w' (give t=UNIT, u=UNIT or F=UNIT)"
        );
        assert!(Units::default().with_flag(Some("u")).is_err());
        assert!(Units::default().with_flag(Some("F=")).is_err());
    }

    #[test]
    fn a_files_units_unless_scaled() {
        let text = "Time [s]\tPosition [mm]\tFriction [N]\n0\t0\t0\n1\t1\t1\n";
        let spec = lugre_io::Spec::new([Role::U, Role::F]);
        let table = lugre_io::read(text.as_bytes(), &spec, ReadOptions::default()).unwrap();
        let units = Units::of_file(&table, &ReadOptions::default());
        assert_eq!(units.u("u"), "u [mm]");
        assert_eq!(units.t("t"), "t [s]");
        let scaled = ReadOptions::default().scale(Role::U, 1e-3).unwrap();
        let table = lugre_io::read(text.as_bytes(), &spec, scaled.clone()).unwrap();
        assert_eq!(Units::of_file(&table, &scaled).u("u"), "u");
    }
}
