//! What the user says about a file ([`ReadOptions`]): which column holds which role
//! (`--columns t=Time,u=3`), the factor of each role (`--scale u=1e-3,F=-1`) and the delimiter.
//! A role given twice, a column numbered 0 and a factor that is 0 or not finite are refused
//! here; a column given two roles is refused once the header is known ([`crate::Reader::rows`]).

use crate::{Delimiter, Error, Role};

/// Where a role's column is: by its header name (units ignored, any case) or its 1-based
/// position.
#[derive(Debug, Clone, PartialEq)]
pub enum Selector {
    Name(String),
    Index(usize),
}

impl std::fmt::Display for Selector {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Selector::Name(name) => f.write_str(name),
            Selector::Index(i) => write!(f, "{i}"),
        }
    }
}

/// How messages name the two options: `--columns` and `--scale` on the command line,
/// `columns` and `scale` in Python.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Labels {
    pub columns: &'static str,
    pub scale: &'static str,
}

impl Labels {
    pub const CLI: Labels = Labels {
        columns: "--columns",
        scale: "--scale",
    };
    pub const PYTHON: Labels = Labels {
        columns: "columns",
        scale: "scale",
    };
}

/// The columns chosen, the factors and the delimiter.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadOptions {
    select: Vec<(Role, Selector)>,
    scale: Vec<(Role, f64, String)>,
    delimiter: Option<Delimiter>,
    labels: Labels,
}

impl Default for ReadOptions {
    fn default() -> Self {
        Self::new(Labels::CLI)
    }
}

impl ReadOptions {
    /// No column chosen, no factor, the delimiter found from the file; messages name the
    /// options by `labels`.
    pub fn new(labels: Labels) -> Self {
        Self {
            select: Vec::new(),
            scale: Vec::new(),
            delimiter: None,
            labels,
        }
    }

    /// `ROLE=COLUMN,...` (`--columns`): each column by its header name or 1-based number.
    pub fn parse_columns(mut self, text: &str) -> Result<Self, Error> {
        for (role, value) in pairs(self.labels.columns, "ROLE=COLUMN", text)? {
            let selector = match value.parse::<usize>() {
                Ok(i) => Selector::Index(i),
                Err(_) => Selector::Name(value.to_string()),
            };
            self = self.select(role, selector)?;
        }
        Ok(self)
    }

    /// `ROLE=FACTOR,...` (`--scale`).
    pub fn parse_scale(mut self, text: &str) -> Result<Self, Error> {
        for (role, value) in pairs(self.labels.scale, "ROLE=FACTOR", text)? {
            let factor = value.parse::<f64>().map_err(|_| Error::FactorNotANumber {
                option: self.labels.scale,
                role: role.to_string(),
                value: value.to_string(),
            })?;
            self = self.scale_text(role, factor, value.to_string())?;
        }
        Ok(self)
    }

    /// The column of `role` (a role given twice, by any of its names, is refused).
    pub fn select(mut self, role: Role, selector: Selector) -> Result<Self, Error> {
        let option = self.labels.columns;
        if selector == Selector::Index(0) {
            return Err(Error::ColumnZero {
                option,
                role: role.name().into(),
            });
        }
        if let Some((first, s)) = self.select.iter().find(|(r, _)| *r == role) {
            return Err(Error::RoleTwice {
                option,
                role: role.to_string(),
                first: format!("{}={s}", first.name()),
                second: format!("{}={selector}", role.name()),
            });
        }
        self.select.push((role, selector));
        Ok(self)
    }

    /// The factor of `role`'s values (finite, not 0; a role given twice is refused).
    pub fn scale(self, role: Role, factor: f64) -> Result<Self, Error> {
        let text = lugre::error::num(factor);
        self.scale_text(role, factor, text)
    }

    fn scale_text(mut self, role: Role, factor: f64, text: String) -> Result<Self, Error> {
        let option = self.labels.scale;
        if !factor.is_finite() || factor == 0.0 {
            return Err(Error::BadFactor {
                option,
                role: role.name().into(),
                value: text,
            });
        }
        if let Some((first, _, t)) = self.scale.iter().find(|(r, _, _)| *r == role) {
            return Err(Error::RoleTwice {
                option,
                role: role.to_string(),
                first: format!("{}={t}", first.name()),
                second: format!("{}={text}", role.name()),
            });
        }
        self.scale.push((role, factor, text));
        Ok(self)
    }

    /// Splits fields with `delimiter` instead of the one found from the file.
    pub fn with_delimiter(mut self, delimiter: Delimiter) -> Self {
        self.delimiter = Some(delimiter);
        self
    }

    /// Whether the column of `role` is chosen.
    pub fn selects(&self, role: &Role) -> bool {
        self.selector(role).is_some()
    }

    /// Refuses a role chosen or scaled that is not one of `reads` (nor `t`).
    pub fn check_roles(&self, reads: &[Role]) -> Result<(), Error> {
        let known = |r: &Role| *r == Role::T || reads.contains(r);
        let unknown = |option: &'static str, role: &Role| Error::UnknownRole {
            option,
            role: role.name().into(),
            reads: std::iter::once("t")
                .chain(reads.iter().map(Role::name).filter(|r| *r != "t"))
                .fold(Vec::new(), |mut seen, name| {
                    // A role a command reads twice (a named column that is also `u`) once.
                    if !seen.contains(&name) {
                        seen.push(name);
                    }
                    seen
                })
                .join(", "),
        };
        if let Some((r, _)) = self.select.iter().find(|(r, _)| !known(r)) {
            return Err(unknown(self.labels.columns, r));
        }
        if let Some((r, _, _)) = self.scale.iter().find(|(r, _, _)| !known(r)) {
            return Err(unknown(self.labels.scale, r));
        }
        Ok(())
    }

    pub(crate) fn selector(&self, role: &Role) -> Option<&Selector> {
        self.select.iter().find(|(r, _)| r == role).map(|(_, s)| s)
    }

    /// Whether the values of `role` are multiplied by a factor (`--scale`): the unit in the
    /// file's header then no longer applies.
    pub fn scales(&self, role: &Role) -> bool {
        self.scale.iter().any(|(r, _, _)| r == role)
    }

    /// Whether any column is chosen.
    pub fn selects_any(&self) -> bool {
        !self.select.is_empty()
    }

    pub(crate) fn factor(&self, role: &Role) -> f64 {
        self.scale
            .iter()
            .find(|(r, _, _)| r == role)
            .map_or(1.0, |(_, f, _)| *f)
    }

    pub(crate) fn delimiter(&self) -> Option<Delimiter> {
        self.delimiter
    }

    pub(crate) fn labels(&self) -> Labels {
        self.labels
    }
}

/// `ROLE=VALUE` items separated by commas, each role as [`Role::of`] reads it.
fn pairs<'a>(
    option: &'static str,
    form: &'static str,
    text: &'a str,
) -> Result<Vec<(Role, &'a str)>, Error> {
    text.split(',')
        .map(|item| match item.split_once('=') {
            Some((role, value)) if !role.trim().is_empty() && !value.trim().is_empty() => {
                Ok((Role::of(role), value.trim()))
            }
            _ => Err(Error::NotAPair {
                option,
                item: crate::text::excerpt(item.trim()),
                form,
            }),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn columns(text: &str) -> Result<ReadOptions, Error> {
        ReadOptions::default().parse_columns(text)
    }

    fn scale(text: &str) -> Result<ReadOptions, Error> {
        ReadOptions::default().parse_scale(text)
    }

    #[test]
    fn columns_by_name_or_number() {
        let o = columns("t=Time, u=3,Friction=Force [uN]").unwrap();
        assert_eq!(o.selector(&Role::T), Some(&Selector::Name("Time".into())));
        assert_eq!(o.selector(&Role::U), Some(&Selector::Index(3)));
        // A role by any of its names.
        assert_eq!(
            o.selector(&Role::F),
            Some(&Selector::Name("Force [uN]".into()))
        );
        assert!(o.selects(&Role::F) && !o.selects(&Role::N));
        let o = scale("u=1e-3,F=-1e6").unwrap();
        assert_eq!((o.factor(&Role::U), o.factor(&Role::F)), (1e-3, -1e6));
        assert_eq!(o.factor(&Role::T), 1.0);
    }

    #[test]
    fn mistakes_are_refused() {
        for (result, want) in [
            (
                columns("u=1,u=2"),
                "--columns: u is given twice (u=1 and u=2)",
            ),
            (
                columns("u=1,x=Position"),
                "--columns: u is given twice (u=1 and u=Position)",
            ),
            (scale("u=2,u=3"), "--scale: u is given twice (u=2 and u=3)"),
            (columns("u=0"), "--columns u=0: columns are numbered from 1"),
            (columns("u"), "--columns: 'u' is not ROLE=COLUMN"),
            (columns("u="), "--columns: 'u=' is not ROLE=COLUMN"),
            (columns(""), "--columns: '' is not ROLE=COLUMN"),
            (scale("=2"), "--scale: '=2' is not ROLE=FACTOR"),
            (scale("u=abc"), "--scale u=abc: not a number"),
            (
                scale("u=0"),
                "--scale u=0: a factor must be a finite number other than 0",
            ),
            (
                scale("F=inf"),
                "--scale F=inf: a factor must be a finite number other than 0",
            ),
        ] {
            match result {
                Ok(o) => panic!("{want}: accepted as {o:?}"),
                Err(e) => assert_eq!(e.to_string(), want),
            }
        }
        let python = ReadOptions::new(Labels::PYTHON)
            .select(Role::U, Selector::Index(1))
            .unwrap()
            .select(Role::of("position"), Selector::Index(2))
            .unwrap_err();
        assert_eq!(
            python.to_string(),
            "columns: u is given twice (u=1 and u=2)"
        );
        let e = ReadOptions::new(Labels::PYTHON)
            .scale(Role::U, f64::NAN)
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "scale u=NaN: a factor must be a finite number other than 0"
        );
    }

    #[test]
    fn roles_the_command_does_not_read() {
        let reads = [Role::U, Role::F, Role::N];
        assert!(columns("t=1,u=2,F=3").unwrap().check_roles(&reads).is_ok());
        let e = scale("w=2").unwrap().check_roles(&reads).unwrap_err();
        assert_eq!(
            e.to_string(),
            "--scale: unknown column role 'w' (this command reads t, u, F, N)"
        );
        let e = columns("v=2").unwrap().check_roles(&reads).unwrap_err();
        assert!(e
            .to_string()
            .starts_with("--columns: unknown column role 'v'"));
    }
}
