//! What a column holds ([`Role`]): the time, the displacement, the velocity, the force or the
//! normal force, each under its usual names; and a header field split into its name and unit
//! ([`Field`]).

use std::fmt;

/// What a column holds. A header names it by any of its [`Role::names`] (case-insensitive, a
/// unit in brackets or parentheses ignored); any other header name is a [`Role::Named`] column,
/// read only when asked for by that name (`lugre cycles --column NAME`).
#[derive(Debug, Clone, Eq)]
pub enum Role {
    /// `t`: the samples' times (strictly increasing).
    T,
    /// `u`: the displacement.
    U,
    /// `v`: the velocity (a velocity record).
    V,
    /// `F`: the (friction) force.
    F,
    /// `N`: the normal force.
    N,
    /// A column of any other name, as written (without its unit), compared case-insensitively.
    Named(String),
}

/// The usual names of each role, lower case (the first is the role's own letter).
const NAMES: [(&str, &[&str]); 5] = [
    ("t", &["t", "time"]),
    ("u", &["u", "x", "position", "displacement"]),
    ("v", &["v", "velocity"]),
    // `y` is the model's output, the friction force, in the paper's notation and in the files
    // `lugre loop --csv` and `lugre simulate --csv` write.
    ("F", &["f", "force", "friction", "y"]),
    ("N", &["n", "normal", "normal force", "load"]),
];

impl Role {
    /// The five roles with usual names, in the order a file without a header holds them
    /// (`t` first).
    pub const KNOWN: [Role; 5] = [Role::T, Role::U, Role::V, Role::F, Role::N];

    /// The role of a header field or of a name given on the command line: `Time [s]` is
    /// [`Role::T`], `Friction (uN)` is [`Role::F`], `strain` is `Named("strain")`.
    pub fn of(text: &str) -> Role {
        let (name, _) = split_unit(text);
        let lower = name.to_lowercase();
        match NAMES
            .iter()
            .position(|(_, names)| names.contains(&lower.as_str()))
        {
            Some(k) => Role::KNOWN[k].clone(),
            None => Role::Named(name.to_string()),
        }
    }

    /// How messages and Python's dictionaries name the role: `t`, `u`, `v`, `F`, `N`, or the
    /// column's own name.
    pub fn name(&self) -> &str {
        match self.known() {
            Some(k) => NAMES[k].0,
            None => match self {
                Role::Named(name) => name,
                _ => unreachable!("every other role is known"),
            },
        }
    }

    /// The header names that mean this role (lower case; none for [`Role::Named`], whose name
    /// is its own).
    pub fn names(&self) -> &'static [&'static str] {
        self.known().map_or(&[], |k| NAMES[k].1)
    }

    /// The position of a known role in [`Role::KNOWN`].
    fn known(&self) -> Option<usize> {
        match self {
            Role::T => Some(0),
            Role::U => Some(1),
            Role::V => Some(2),
            Role::F => Some(3),
            Role::N => Some(4),
            Role::Named(_) => None,
        }
    }

    /// Its usual names in words, for a message: "u, x, position or displacement".
    pub(crate) fn names_in_words(&self) -> String {
        let names: Vec<&str> = self
            .names()
            .iter()
            .map(|n| {
                if *n == "f" || *n == "n" {
                    self.name()
                } else {
                    n
                }
            })
            .collect();
        match names.split_last() {
            Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
            _ => names.join(""),
        }
    }
}

impl PartialEq for Role {
    fn eq(&self, other: &Role) -> bool {
        match (self, other) {
            (Role::Named(a), Role::Named(b)) => a.to_lowercase() == b.to_lowercase(),
            _ => self.known().is_some() && self.known() == other.known(),
        }
    }
}

impl fmt::Display for Role {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Role::Named(name) => write!(f, "'{name}'"),
            known => f.write_str(known.name()),
        }
    }
}

/// One field of a header line: as written, its name and unit, and its role.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// The field as written (`Position [mm]`).
    pub text: String,
    /// Without the unit (`Position`).
    pub name: String,
    /// The unit in brackets or parentheses at its end (`mm`), if any.
    pub unit: Option<String>,
    pub role: Role,
}

impl Field {
    pub(crate) fn parse(text: &str) -> Field {
        let (name, unit) = split_unit(text);
        Field {
            text: text.to_string(),
            name: name.to_string(),
            unit: unit.map(str::to_string),
            role: Role::of(text),
        }
    }

    /// The name compared with names given on the command line (lower case, no unit).
    pub(crate) fn bare(&self) -> String {
        self.name.to_lowercase()
    }
}

/// `Time [s]` as (`Time`, `s`), `time(s)` as (`time`, `s`), `u` as (`u`, none); an empty unit
/// (`u []`) is none.
pub(crate) fn split_unit(text: &str) -> (&str, Option<&str>) {
    let text = text.trim();
    let open = match text.chars().last() {
        Some(']') => '[',
        Some(')') => '(',
        _ => return (text, None),
    };
    let inner = &text[..text.len() - 1];
    match inner.rfind(open) {
        Some(k) => {
            let unit = inner[k + 1..].trim();
            (inner[..k].trim_end(), (!unit.is_empty()).then_some(unit))
        }
        None => (text, None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn usual_names_and_units() {
        for (text, role, unit) in [
            ("Time [s]", Role::T, Some("s")),
            ("time(s)", Role::T, Some("s")),
            ("t", Role::T, None),
            ("Displacement [um]", Role::U, Some("um")),
            ("X", Role::U, None),
            ("position (mm)", Role::U, Some("mm")),
            ("Velocity [m/s]", Role::V, Some("m/s")),
            ("f", Role::F, None),
            ("Friction [uN]", Role::F, Some("uN")),
            ("y", Role::F, None),
            ("Normal force [N]", Role::N, Some("N")),
            ("load", Role::N, None),
            ("rho", Role::Named("rho".into()), None),
            ("Strain [%]", Role::Named("strain".into()), Some("%")),
            ("u []", Role::U, None),
        ] {
            let field = Field::parse(text);
            assert_eq!(field.role, role, "{text}");
            assert_eq!(field.unit.as_deref(), unit, "{text}");
        }
        assert_eq!(Field::parse(" Time [s] ").name, "Time");
        assert_eq!(split_unit("a(b)c"), ("a(b)c", None));
        assert_eq!(split_unit("u]"), ("u]", None));
    }

    #[test]
    fn names_for_messages() {
        assert_eq!(Role::F.name(), "F");
        assert_eq!(Role::of("Strain").name(), "Strain");
        assert_eq!(Role::of("Strain").to_string(), "'Strain'");
        assert_eq!(Role::U.to_string(), "u");
        assert_eq!(Role::U.names_in_words(), "u, x, position or displacement");
        assert_eq!(Role::F.names_in_words(), "F, force, friction or y");
        assert_eq!(Role::T.names_in_words(), "t or time");
        assert_ne!(Role::T, Role::Named("t".into()));
    }
}
