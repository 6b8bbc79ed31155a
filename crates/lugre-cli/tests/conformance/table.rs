//! The conformance table as the Rust runner reads it: the cases, their files and command
//! lines, the paths that select numbers from an answer, the checks and the messages spelled
//! per front end (`tests/conformance/README.md` is the format).

use std::path::Path;

use serde::de::{Deserializer, MapAccess, Visitor};
use serde::Deserialize;
use serde_json::Value;

/// A refusal: its kind (`value` or `type`) and message.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    pub kind: String,
    pub message: String,
}

impl Failure {
    pub fn new(kind: &str, message: impl Into<String>) -> Self {
        Self {
            kind: kind.into(),
            message: message.into(),
        }
    }
}

/// What a front end answered: its result in the shape of the CLI's `--json`, or a refusal.
pub type Outcome = Result<Value, Failure>;

/// An object's entries in the order written (a request's fields are applied in that order,
/// as a MATLAB struct's or a Python call's are).
#[derive(Debug, Default, Clone)]
pub struct Fields(pub Vec<(String, Value)>);

impl<'de> Deserialize<'de> for Fields {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Fields;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Fields, A::Error> {
                let mut entries = Vec::new();
                while let Some(entry) = map.next_entry()? {
                    entries.push(entry);
                }
                Ok(Fields(entries))
            }
        }
        d.deserialize_map(V)
    }
}

impl Fields {
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.0.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }

    pub fn num(&self, name: &str) -> Option<f64> {
        self.get(name).map(number)
    }

    pub fn numbers(&self, name: &str) -> Option<Vec<f64>> {
        self.get(name).map(numbers)
    }
}

/// The numbers of a JSON array (or one number).
pub fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().map(number).collect(),
        other => vec![number(other)],
    }
}

/// A number, or one JSON cannot hold: `"nan"`, `"inf"`, `"-inf"`.
pub fn number(v: &Value) -> f64 {
    match v.as_str() {
        Some("nan") => f64::NAN,
        Some("inf") => f64::INFINITY,
        Some("-inf") => f64::NEG_INFINITY,
        _ => v.as_f64().unwrap_or_else(|| panic!("a number: {v}")),
    }
}

#[derive(Debug, Deserialize)]
pub struct FileSpec {
    pub name: String,
    pub header: String,
    pub columns: Vec<String>,
}

#[derive(Debug, Deserialize)]
pub struct Expected {
    #[serde(default)]
    pub same: Vec<Value>,
    #[serde(default)]
    pub checks: Vec<(String, String, Value)>,
}

#[derive(Debug, Deserialize)]
pub struct ExpectedError {
    #[serde(default = "value_kind")]
    pub kind: String,
    pub message: String,
}

fn value_kind() -> String {
    "value".into()
}

#[derive(Debug, Deserialize)]
pub struct Case {
    pub id: String,
    pub what: String,
    pub command: String,
    #[serde(default)]
    pub cli: Vec<String>,
    #[serde(default)]
    pub fields: Fields,
    pub front_ends: Vec<String>,
    #[serde(default)]
    pub file: Option<FileSpec>,
    #[serde(default)]
    pub spell: serde_json::Map<String, Value>,
    #[serde(default)]
    pub ok: Option<Expected>,
    #[serde(default)]
    pub error: Option<ExpectedError>,
    #[serde(skip)]
    spelling: serde_json::Map<String, Value>,
}

#[derive(Deserialize)]
struct Table {
    spelling: serde_json::Map<String, Value>,
    sets: serde_json::Map<String, Value>,
    cases: Vec<Case>,
}

pub const FRONT_ENDS: [&str; 5] = ["cli", "python", "c", "mex", "fmu"];

/// The table, each case checked for its form.
pub fn load() -> Vec<Case> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/conformance/cases.json");
    let text = std::fs::read_to_string(&path).expect("tests/conformance/cases.json");
    let table: Table = serde_json::from_str(&text).expect("cases.json is the table's format");
    let mut seen = std::collections::BTreeSet::new();
    let mut cases = table.cases;
    for c in &mut cases {
        assert!(seen.insert(c.id.clone()), "two cases are called {}", c.id);
        assert!(!c.what.is_empty(), "{}: say what it checks", c.id);
        assert!(
            c.ok.is_some() != c.error.is_some(),
            "{}: one of ok and error",
            c.id
        );
        assert!(
            !c.front_ends.is_empty() && c.front_ends.iter().all(|f| FRONT_ENDS.contains(&&f[..])),
            "{}: front ends {:?}",
            c.id,
            c.front_ends
        );
        assert_eq!(
            c.applies("cli"),
            !c.cli.is_empty(),
            "{}: a case for the CLI has its command line, and only then",
            c.id
        );
        c.spelling = table.spelling.clone();
        // `@name` in `same`: the table's set of paths of that name.
        if let Some(ok) = &mut c.ok {
            ok.same = ok
                .same
                .iter()
                .flat_map(|s| match s.as_str().and_then(|s| s.strip_prefix('@')) {
                    Some(set) => table.sets[set].as_array().expect("a set of paths").clone(),
                    None => vec![s.clone()],
                })
                .collect();
        }
    }
    cases
}

impl Case {
    pub fn applies(&self, front_end: &str) -> bool {
        self.front_ends.iter().any(|f| f == front_end)
    }

    /// The command line, with `@file` the case's file (written into `dir`) and `@dir/` the
    /// directory.
    pub fn cli_args(&self, dir: &Path) -> Vec<String> {
        let file = self.file.as_ref().map(|f| {
            let path = dir.join(&f.name);
            let columns: Vec<Vec<f64>> = f
                .columns
                .iter()
                .map(|c| self.fields.numbers(c).expect("a file's column is a field"))
                .collect();
            let mut text = format!("{}\n", f.header);
            for i in 0..columns[0].len() {
                // `{:?}`: the shortest decimal that reads back as the same double.
                let row: Vec<String> = columns.iter().map(|c| format!("{:?}", c[i])).collect();
                text += &format!("{}\n", row.join(","));
            }
            std::fs::write(&path, text).expect("write the case's file");
            path
        });
        self.cli
            .iter()
            .map(|a| self.fill(a, dir, file.as_deref()))
            .collect()
    }

    fn fill(&self, text: &str, dir: &Path, file: Option<&Path>) -> String {
        let mut s = text.replace("@dir/", &format!("{}/", dir.display()));
        if let Some(file) = file {
            s = s.replace("@file", &file.display().to_string());
        }
        s
    }

    /// `name` as `front_end` spells it: the case's own spelling, else the table's (the CLI:
    /// `--name` with `-` for `_`), else the name.
    fn spelled(&self, name: &str, front_end: &str) -> String {
        let own = self.spell.get(name).and_then(|s| s.get(front_end));
        let table = self.spelling.get(front_end).and_then(|s| s.get(name));
        match own.or(table).and_then(Value::as_str) {
            Some(s) => s.to_string(),
            None if front_end == "cli" => format!("--{}", name.replace('_', "-")),
            None => name.to_string(),
        }
    }

    /// The expected message for `front_end`: `{name}` spelled, `{@file}` and `{@dir}` filled.
    pub fn message(&self, front_end: &str, dir: &Path) -> String {
        let template = &self.error.as_ref().expect("an error case").message;
        let mut out = String::new();
        let mut rest = template.as_str();
        while let Some(open) = rest.find('{') {
            out += &rest[..open];
            let end = rest[open..].find('}').expect("a closed {") + open;
            let name = &rest[open + 1..end];
            out += &match name {
                "@file" => {
                    let f = self.file.as_ref().expect("the case has a file");
                    dir.join(&f.name).display().to_string()
                }
                "@dir" => dir.display().to_string(),
                // The core's table: a parameter added to it needs no edit here.
                "@lugre_parameters" => lugre::fit::Family::LuGre.parameters().join(", "),
                _ => match name.split_once(':') {
                    Some((kind, k)) => at(kind, k.parse().expect("{at:INDEX}"), front_end),
                    None => self.spelled(name, front_end),
                },
            };
            rest = &rest[end + 1..];
        }
        out + rest
    }

    /// What is wrong with `got` (the answer of `front_end`), given the CLI's answer as the
    /// reference (None: no reference, only the checks): one line per problem.
    pub fn judge(
        &self,
        front_end: &str,
        got: &Outcome,
        reference: Option<&Outcome>,
        dir: &Path,
    ) -> Vec<String> {
        let tag = format!("{} [{front_end}]", self.id);
        match (&self.error, &self.ok, got) {
            (Some(e), _, Err(f)) => {
                let want = self.message(front_end, dir);
                let mut bad = Vec::new();
                if f.kind != e.kind {
                    bad.push(format!("{tag}: a {} error, wanted {}", f.kind, e.kind));
                }
                if f.message != want {
                    bad.push(format!(
                        "{tag}: message\n    got  {}\n    want {want}",
                        f.message
                    ));
                }
                bad
            }
            (Some(e), _, Ok(_)) => vec![format!("{tag}: accepted, wanted \"{}\"", e.message)],
            (_, Some(_), Err(f)) => vec![format!("{tag}: refused: {}", f.message)],
            (_, Some(ok), Ok(v)) => {
                let mut bad: Vec<String> = ok
                    .checks
                    .iter()
                    .filter_map(|c| check(v, c).err().map(|e| format!("{tag}: {e}")))
                    .collect();
                if let Some(Ok(r)) = reference {
                    for s in &ok.same {
                        let (cli, own) = pair(s);
                        let (a, b) = (select(r, cli), select(v, own));
                        if !same(&a, &b) {
                            bad.push(format!(
                                "{tag}: {own} is not the CLI's {cli}\n    got  {b:?}\n    CLI  {a:?}"
                            ));
                        }
                    }
                }
                bad
            }
            (None, None, _) => unreachable!("checked on load"),
        }
    }
}

/// Element `k` (0-based) of an array, as `front_end` counts: `{at:k}` is `[k]` (the core's
/// messages, C, Python) or `(k+1)` (MATLAB); `{item:k}`, a value of a list given on the
/// command line, is `: item k+1` there.
fn at(kind: &str, k: usize, front_end: &str) -> String {
    match (kind, front_end) {
        (_, "mex") => format!("({})", k + 1),
        ("item", "cli") => format!(": item {}", k + 1),
        ("at" | "item", _) => format!("[{k}]"),
        (other, _) => panic!("unknown placeholder {{{other}:{k}}}"),
    }
}

/// A `same` entry: one path for both, or `[cli_path, own_path]`.
fn pair(s: &Value) -> (&str, &str) {
    match s {
        Value::String(p) => (p, p),
        Value::Array(a) => (a[0].as_str().unwrap(), a[1].as_str().unwrap()),
        other => panic!("a same entry: {other}"),
    }
}

/// Equal to the last bit (numbers), or equal (strings, null, booleans); lists of the same
/// length, and not empty (a path that selects nothing is a mistake in the table).
fn same(a: &[Value], b: &[Value]) -> bool {
    !a.is_empty()
        && a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| match (x.as_f64(), y.as_f64()) {
                (Some(x), Some(y)) => x.to_bits() == y.to_bits(),
                _ => x == y,
            })
}

/// The values a path selects: `a.b` keys, `[]` every element, `[k]` one (negative from the
/// end), `[k:]` from k on; a leading `#` counts them.
pub fn select(v: &Value, path: &str) -> Vec<Value> {
    if let Some(p) = path.strip_prefix('#') {
        let inner = select(v, p);
        let n = match &inner[..] {
            [Value::Array(a)] => a.len(),
            other => other.len(),
        };
        return vec![Value::from(n as u64)];
    }
    let mut current = vec![v.clone()];
    for segment in path.split('.') {
        let (key, mut rest) = match segment.find('[') {
            Some(i) => (&segment[..i], &segment[i..]),
            None => (segment, ""),
        };
        current = current
            .iter()
            .map(|x| x.get(key).cloned().unwrap_or(Value::Null))
            .collect();
        while let Some(close) = rest.find(']') {
            let inside = &rest[1..close];
            rest = &rest[close + 1..];
            current = current.into_iter().flat_map(|x| index(x, inside)).collect();
        }
    }
    // A path ending at an array selects its elements.
    match &current[..] {
        [Value::Array(a)] => a.clone(),
        _ => current,
    }
}

fn index(x: Value, inside: &str) -> Vec<Value> {
    let Value::Array(a) = x else {
        return vec![Value::Null];
    };
    let at = |k: &str| -> usize {
        let k: i64 = k.parse().expect("an index");
        if k < 0 {
            (a.len() as i64 + k).max(0) as usize
        } else {
            k as usize
        }
    };
    if inside.is_empty() {
        a
    } else if let Some(from) = inside.strip_suffix(':') {
        let from = at(from);
        a.into_iter().skip(from).collect()
    } else {
        let k = at(inside);
        vec![a.get(k).cloned().unwrap_or(Value::Null)]
    }
}

/// One check `[path, op, value]`: every value the path selects compares so with `value`.
fn check(v: &Value, (path, op, want): &(String, String, Value)) -> Result<(), String> {
    let got = select(v, path);
    if got.is_empty() {
        return Err(format!("{path} selects nothing"));
    }
    for g in &got {
        let ok = match (g.as_f64(), want.as_f64()) {
            (Some(g), Some(w)) => match op.as_str() {
                "==" => g == w,
                "!=" => g != w,
                "<" => g < w,
                "<=" => g <= w,
                ">" => g > w,
                ">=" => g >= w,
                other => panic!("unknown check '{other}'"),
            },
            _ => match op.as_str() {
                "==" => g == want,
                "!=" => g != want,
                other => return Err(format!("{path} = {g} cannot be compared by '{other}'")),
            },
        };
        if !ok {
            return Err(format!("check {path} {op} {want} fails: {g}"));
        }
    }
    Ok(())
}
