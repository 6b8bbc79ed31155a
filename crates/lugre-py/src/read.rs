//! `lugre.read`: a data file's columns by role, read by the reader every lugre front end uses
//! (the `lugre-io` crate: the same names, units, delimiters, comments, options and messages as
//! the `lugre` command's `--input`). The Python wrapper (`lugre.read`) puts the arrays in a
//! `lugre.Columns` dict with the units beside them.

use std::path::PathBuf;

use lugre_io::{Delimiter, Labels, ReadOptions, Reader, Role, Selector, Spec};
use numpy::IntoPyArray;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyInt, PyString};

use crate::convert::{real, type_name, value_error};

/// The columns of the data file `path` as numpy float64 arrays keyed by role ("t", "u", "v",
/// "F", "N", or a column's own name), with each column's unit and header name. Called by
/// `lugre.read` (see its docstring).
#[pyfunction]
#[pyo3(signature = (path, columns=None, scale=None, delimiter=None, roles=None))]
#[allow(clippy::type_complexity)]
pub fn read<'py>(
    py: Python<'py>,
    path: &Bound<'py, PyAny>,
    columns: Option<&Bound<'py, PyAny>>,
    scale: Option<&Bound<'py, PyAny>>,
    delimiter: Option<&Bound<'py, PyAny>>,
    roles: Option<&Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let path = path_of(path)?;
    let options = options(columns, scale, delimiter)?;
    let roles = roles_of(roles)?;
    let mut table = py
        .detach(|| -> Result<_, lugre_io::FileError> {
            let reader = Reader::open(&path, options.clone())?;
            let spec = spec(&reader, &options, roles).map_err(|e| e.in_file(&path))?;
            reader
                .rows(&spec)
                .and_then(lugre_io::Rows::collect_table)
                .map_err(|e| e.in_file(&path))
        })
        .map_err(value_error)?;
    let (values, units, names) = (PyDict::new(py), PyDict::new(py), PyDict::new(py));
    let all = table.t.take().into_iter().chain(table.columns);
    for column in all {
        let key = column.info.role.name().to_string();
        units.set_item(&key, column.info.unit)?;
        names.set_item(&key, column.info.name)?;
        values.set_item(&key, column.values.into_pyarray(py))?;
    }
    Ok((values, units, names))
}

/// What to read: the roles asked for; else every known role the header has; else, without a
/// header, `u`, `t,u` or `t,u,F` by the number of columns.
fn spec<R: std::io::Read>(
    reader: &Reader<R>,
    options: &ReadOptions,
    roles: Option<Vec<Role>>,
) -> Result<Spec, lugre_io::Error> {
    if let Some(roles) = roles {
        return Ok(Spec::new(roles));
    }
    let known = || Role::KNOWN.into_iter().filter(|r| *r != Role::T);
    if reader.header().is_some() || options.selects_any() {
        // Every role the header has or the options choose (none found: u is asked for, and
        // the reader says it is missing).
        let present: Vec<Role> = known()
            .filter(|r| reader.header_has(r) || options.selects(r))
            .collect();
        return Ok(match present.is_empty() {
            true => Spec::new([Role::U]),
            false => Spec::new(present),
        });
    }
    Ok(match reader.width() {
        3 => Spec::new([Role::U, Role::F]),
        _ => Spec::new([Role::U]),
    })
}

fn path_of(obj: &Bound<'_, PyAny>) -> PyResult<PathBuf> {
    if obj.is_instance_of::<PyString>() || obj.hasattr("__fspath__")? {
        return obj.extract::<PathBuf>();
    }
    Err(PyTypeError::new_err(format!(
        "path must be a str or an os.PathLike, got {}",
        type_name(obj)
    )))
}

/// `columns`, `scale` and `delimiter` as the reader's options (messages name the keywords).
fn options(
    columns: Option<&Bound<'_, PyAny>>,
    scale: Option<&Bound<'_, PyAny>>,
    delimiter: Option<&Bound<'_, PyAny>>,
) -> PyResult<ReadOptions> {
    let mut options = ReadOptions::new(Labels::PYTHON);
    if let Some(obj) = columns.filter(|c| !c.is_none()) {
        options = if let Ok(text) = obj.cast::<PyString>() {
            options
                .parse_columns(&text.to_cow()?)
                .map_err(value_error)?
        } else if let Ok(dict) = obj.cast::<PyDict>() {
            let mut o = options;
            for (key, value) in dict.iter() {
                let role = role_key(&key, "columns")?;
                o = o.select(role, selector(&value)?).map_err(value_error)?;
            }
            o
        } else {
            return Err(PyTypeError::new_err(format!(
                "columns must be a dict (role -> header name or 1-based column number) or a str 'ROLE=COLUMN,...', got {}",
                type_name(obj)
            )));
        };
    }
    if let Some(obj) = scale.filter(|s| !s.is_none()) {
        options = if let Ok(text) = obj.cast::<PyString>() {
            options.parse_scale(&text.to_cow()?).map_err(value_error)?
        } else if let Ok(dict) = obj.cast::<PyDict>() {
            let mut o = options;
            for (key, value) in dict.iter() {
                let role = role_key(&key, "scale")?;
                let what = format!("scale[{:?}]", role.name());
                o = o.scale(role, real(&value, &what)?).map_err(value_error)?;
            }
            o
        } else {
            return Err(PyTypeError::new_err(format!(
                "scale must be a dict (role -> factor) or a str 'ROLE=FACTOR,...', got {}",
                type_name(obj)
            )));
        };
    }
    if let Some(obj) = delimiter.filter(|d| !d.is_none()) {
        let Ok(text) = obj.cast::<PyString>() else {
            return Err(PyTypeError::new_err(format!(
                "delimiter must be a str, got {}",
                type_name(obj)
            )));
        };
        let d = match &*text.to_cow()? {
            "comma" | "," => Delimiter::Comma,
            "semicolon" | ";" => Delimiter::Semicolon,
            "tab" | "\t" => Delimiter::Tab,
            "space" | " " => Delimiter::Spaces,
            other => {
                return Err(PyValueError::new_err(format!(
                    "delimiter must be 'comma', 'semicolon', 'tab' or 'space', got {}",
                    lugre_io::text::quoted(other)
                )))
            }
        };
        options = options.with_delimiter(d);
    }
    Ok(options)
}

/// A role given as a dict key: a str (`"u"`, `"position"`, a column's own name).
fn role_key(key: &Bound<'_, PyAny>, what: &str) -> PyResult<Role> {
    match key.cast::<PyString>() {
        Ok(s) => Ok(Role::of(&s.to_cow()?)),
        Err(_) => Err(PyTypeError::new_err(format!(
            "{what}: a role must be a str ('t', 'u', 'v', 'F', 'N' or a column's name), got {}",
            type_name(key)
        ))),
    }
}

/// A column given as a dict value: a header name (str) or a 1-based number (int).
fn selector(value: &Bound<'_, PyAny>) -> PyResult<Selector> {
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(Selector::Name(s.to_cow()?.into_owned()));
    }
    if value.is_instance_of::<PyInt>() && !value.is_instance_of::<PyBool>() {
        let i: i64 = value.extract()?;
        return match usize::try_from(i) {
            Ok(i) => Ok(Selector::Index(i)),
            Err(_) => Err(PyValueError::new_err(format!(
                "columns: a column number must be >= 1, got {i}"
            ))),
        };
    }
    Err(PyTypeError::new_err(format!(
        "columns: a column must be a header name (str) or a 1-based number (int), got {}",
        type_name(value)
    )))
}

/// `roles`: the columns the file must hold, as a sequence of str.
fn roles_of(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<Role>>> {
    let Some(obj) = obj.filter(|r| !r.is_none()) else {
        return Ok(None);
    };
    let wrong = || {
        PyTypeError::new_err(format!(
            "roles must be a sequence of str ('u', 'F', a column's name), got {}",
            type_name(obj)
        ))
    };
    if obj.is_instance_of::<PyString>() {
        return Err(wrong());
    }
    let mut roles = Vec::new();
    for item in obj.try_iter().map_err(|_| wrong())? {
        let item = item?;
        let Ok(s) = item.cast::<PyString>() else {
            return Err(wrong());
        };
        let role = Role::of(&s.to_cow()?);
        if role == Role::T {
            return Err(PyValueError::new_err(
                "roles: t is read whenever the file has it; name the value columns",
            ));
        }
        if roles.contains(&role) {
            return Err(PyValueError::new_err(format!(
                "roles: {role} is given twice"
            )));
        }
        roles.push(role);
    }
    if roles.is_empty() {
        return Err(PyValueError::new_err("roles: name at least one column"));
    }
    Ok(Some(roles))
}
