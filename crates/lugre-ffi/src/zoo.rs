//! The zoo's models through the C ABI: any model of the core's table
//! ([`lugre::zoo::MODELS`]: Maxwell-slip, Prandtl-Ishlinskii, ...) made by name from its
//! parameters given by name ([`lugre_zoo_new`]), its loop read through the same [`LugreLoop`]
//! accessors as LuGre's ([`lugre_zoo_loop_new`]), and the table itself
//! ([`lugre_zoo_model_name`], [`lugre_zoo_model_info`], [`lugre_zoo_parameter`]), so that a host
//! (the MEX gateway) needs no list of models or parameters of its own. The same defaults,
//! checks and messages as `lugre loop --model NAME` and `lugre.ZooModel`.
//!
//! ```c
//! const char *names[] = {"stiffness", "slip_force"};
//! double k[] = {1, 2}, f[] = {1, 0.5};
//! const double *values[] = {k, f};
//! size_t lens[] = {2, 2};
//! LugreZoo *m; LugreLoop *hl;
//! lugre_zoo_new("maxwell-slip", 2, names, values, lens, &m);
//! double u[] = {3, 1, 2, -3};
//! lugre_zoo_loop_new(m, u, 4, &hl);   /* then lugre_loop_turning, lugre_loop_table, ... */
//! double h[] = {0, 4, 1, 3, -4, -1, -3, 4, 0};
//! LugreCycles *cy;
//! lugre_zoo_cycles_new(m, h, 9, 0.0, NULL, &cy); /* then lugre_cycles_len, lugre_cycles_columns */
//! double t[] = {0, 1, 2, 3}, x[] = {0, 1, -1, 0.5}, force[4];
//! lugre_zoo_simulate(m, t, x, 4, NULL, force);   /* the force at each sample, from rest */
//! ```

use std::ffi::{c_char, CString};
use std::sync::OnceLock;

use lugre::zoo::{Shape, ZooModel, ZooModelSpec, MODELS};
use lugre::TurningPoints;

use super::{
    capacity, fail, free, guard, handle, handle_mut, input, output, set_out, text, values, Failure,
    LugreCycles, LugreLoop, LugreStatus, Periodic,
};

/// A validated model of the zoo.
pub struct LugreZoo {
    pub(crate) model: ZooModel,
}

/// [`LugreZooParameter::shape`]: one number.
pub const LUGRE_ZOO_SCALAR: i32 = 0;
/// [`LugreZooParameter::shape`]: one number per element.
pub const LUGRE_ZOO_ELEMENTS: i32 = 1;

/// A model of the zoo's entry in the core's table (static strings).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct LugreZooModelInfo {
    /// The name [`lugre_zoo_new`] takes, as `lugre loop --model`.
    pub name: *const c_char,
    /// The name in reports.
    pub label: *const c_char,
    /// The model's equations in one line.
    pub equations: *const c_char,
    /// The publication that defines it.
    pub reference: *const c_char,
    /// How many parameters it has ([`lugre_zoo_parameter`]'s indices).
    pub parameters: usize,
    /// 1 when every minor loop closes (Masing behaviour).
    pub closes_minor_loops: i32,
    /// 1 when the model has a finite-rate form ([`crate::lugre_dynamics_set_zoo`] takes it).
    pub finite_rate: i32,
}

/// A parameter of a model of the zoo (static strings and values).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct LugreZooParameter {
    /// The name [`lugre_zoo_new`] takes.
    pub name: *const c_char,
    /// The unit with displacements in m and forces in N.
    pub unit: *const c_char,
    pub description: *const c_char,
    /// The values it may take, as the messages write them.
    pub domain: *const c_char,
    /// [`LUGRE_ZOO_SCALAR`] or [`LUGRE_ZOO_ELEMENTS`].
    pub shape: i32,
    /// The default: `default_len` values (1 for a scalar), static.
    pub default_values: *const f64,
    pub default_len: usize,
    /// 1 when the slow (rate-independent) loop depends on it, 0 when only the finite rate
    /// does.
    pub slow_loop: i32,
}

/// The table's strings as C strings, made once: per model its four texts and per parameter
/// its four.
struct CTable {
    models: Vec<([CString; 4], Vec<[CString; 4]>)>,
}

fn c_table() -> &'static CTable {
    static TABLE: OnceLock<CTable> = OnceLock::new();
    TABLE.get_or_init(|| {
        let c = |s: &str| CString::new(s).unwrap_or_default();
        let models = MODELS
            .iter()
            .map(|m| {
                let texts = [c(m.name), c(m.label), c(m.equations), c(m.reference)];
                let parameters = m
                    .parameters
                    .iter()
                    .map(|p| [c(p.name), c(p.unit), c(p.description), c(&p.domain.text())])
                    .collect();
                (texts, parameters)
            })
            .collect();
        CTable { models }
    })
}

/// The name of model `index` of the zoo's table (static), or NULL past the last: the way to
/// list the models (`for (i = 0; lugre_zoo_model_name(i); i++)`).
#[no_mangle]
pub extern "C" fn lugre_zoo_model_name(index: usize) -> *const c_char {
    c_table()
        .models
        .get(index)
        .map_or(std::ptr::null(), |(texts, _)| texts[0].as_ptr())
}

/// The index in the table of the model called `model` (case-insensitive), or the core's
/// refusal naming the models.
fn model_index(model: *const c_char) -> Result<usize, Failure> {
    let name =
        text(model, "model")?.ok_or_else(|| fail(LugreStatus::NullPointer, "model is NULL"))?;
    let spec = ZooModelSpec::find(&name).ok_or_else(|| match ZooModel::new(&name, &[]) {
        Err(e) => Failure::from(e),
        Ok(_) => fail(
            LugreStatus::InvalidArgument,
            format!("unknown model '{name}'"),
        ),
    })?;
    Ok(MODELS.iter().position(|m| m.name == spec.name).unwrap_or(0))
}

/// The table's entry of the model called `model` to `out`.
#[no_mangle]
pub extern "C" fn lugre_zoo_model_info(
    model: *const c_char,
    out: *mut LugreZooModelInfo,
) -> LugreStatus {
    guard(|| {
        let out = handle_mut(out, "out")?;
        let i = model_index(model)?;
        let (m, (texts, _)) = (&MODELS[i], &c_table().models[i]);
        *out = LugreZooModelInfo {
            name: texts[0].as_ptr(),
            label: texts[1].as_ptr(),
            equations: texts[2].as_ptr(),
            reference: texts[3].as_ptr(),
            parameters: m.parameters.len(),
            closes_minor_loops: i32::from(m.closes_minor_loops),
            finite_rate: i32::from(m.finite_rate),
        };
        Ok(())
    })
}

/// Parameter `index` of the model called `model`, in the table's order, to `out`.
#[no_mangle]
pub extern "C" fn lugre_zoo_parameter(
    model: *const c_char,
    index: usize,
    out: *mut LugreZooParameter,
) -> LugreStatus {
    guard(|| {
        let out = handle_mut(out, "out")?;
        let i = model_index(model)?;
        let (m, (_, texts)) = (&MODELS[i], &c_table().models[i]);
        let (p, t) = m
            .parameters
            .get(index)
            .zip(texts.get(index))
            .ok_or_else(|| {
                fail(
                    LugreStatus::InvalidArgument,
                    format!("index must be below {}, got {index}", m.parameters.len()),
                )
            })?;
        *out = LugreZooParameter {
            name: t[0].as_ptr(),
            unit: t[1].as_ptr(),
            description: t[2].as_ptr(),
            domain: t[3].as_ptr(),
            shape: match p.shape {
                Shape::Scalar => LUGRE_ZOO_SCALAR,
                Shape::Elements => LUGRE_ZOO_ELEMENTS,
            },
            default_values: p.default.as_ptr(),
            default_len: p.default.len(),
            slow_loop: i32::from(p.slow_loop),
        };
        Ok(())
    })
}

/// The parameters given by name: `names[i]` has the `lens[i]` values at `values[i]`.
fn named_values(
    count: usize,
    names: *const *const c_char,
    values: *const *const f64,
    lens: *const usize,
) -> Result<Vec<(String, Vec<f64>)>, Failure> {
    if count == 0 {
        return Ok(Vec::new());
    }
    for (p, what) in [
        (names.is_null(), "names"),
        (values.is_null(), "values"),
        (lens.is_null(), "lens"),
    ] {
        if p {
            return Err(fail(LugreStatus::NullPointer, format!("{what} is NULL")));
        }
    }
    let mut out: Vec<(String, Vec<f64>)> = Vec::new();
    for i in 0..count {
        // SAFETY: the caller guarantees `count` readable entries in each array (not NULL).
        let (name, at, len) = unsafe { (*names.add(i), *values.add(i), *lens.add(i)) };
        let item = format!("names[{i}]");
        let name = text(name, &item)?
            .ok_or_else(|| fail(LugreStatus::NullPointer, format!("{item} is NULL")))?;
        if out.iter().any(|(n, _)| n.eq_ignore_ascii_case(name.trim())) {
            return Err(fail(
                LugreStatus::InvalidArgument,
                format!("{item} gives {} a second time", name.trim()),
            ));
        }
        // As given: the core checks every value, naming the parameter and the element.
        let v = self::values(at, len, &format!("values[{i}]"))?.to_vec();
        out.push((name.trim().to_string(), v));
    }
    Ok(out)
}

/// The model of the zoo called `model` (case-insensitive; [`lugre_zoo_model_name`] lists
/// them) from `count` parameters given by name: `names[i]` (case-insensitive, each once) has
/// the `lens[i]` values at `values[i]` (one for a scalar parameter, one per element for an
/// element array); every parameter not given takes the table's default. Refused with the
/// core's message (an unknown model or parameter, a value outside its domain, arrays of
/// different lengths), as `lugre loop --model` refuses it.
#[no_mangle]
pub extern "C" fn lugre_zoo_new(
    model: *const c_char,
    count: usize,
    names: *const *const c_char,
    values: *const *const f64,
    lens: *const usize,
    out: *mut *mut LugreZoo,
) -> LugreStatus {
    guard(|| {
        let name =
            text(model, "model")?.ok_or_else(|| fail(LugreStatus::NullPointer, "model is NULL"))?;
        let given = named_values(count, names, values, lens)?;
        let borrowed: Vec<(&str, &[f64])> = given
            .iter()
            .map(|(n, v)| (n.as_str(), v.as_slice()))
            .collect();
        let model = ZooModel::new(&name, &borrowed)?;
        set_out(out, LugreZoo { model })
    })
}

#[no_mangle]
pub extern "C" fn lugre_zoo_free(zoo: *mut LugreZoo) {
    free(zoo)
}

/// The values of parameter `index` of the model (the table's order; defaults included), to
/// `values` (`cap` of them; NULL skips) and their number to `len` (may be NULL): the model's
/// echo, as `lugre loop --json`'s `model`.
#[no_mangle]
pub extern "C" fn lugre_zoo_value(
    zoo: *const LugreZoo,
    index: usize,
    values: *mut f64,
    cap: usize,
    len: *mut usize,
) -> LugreStatus {
    guard(|| {
        let named = handle(zoo, "zoo")?.model.named();
        let (_, v) = named.get(index).ok_or_else(|| {
            fail(
                LugreStatus::InvalidArgument,
                format!("index must be below {}, got {index}", named.len()),
            )
        })?;
        if !len.is_null() {
            *handle_mut(len, "len")? = v.len();
        }
        if !values.is_null() {
            capacity(v.len(), cap)?;
            output(values, v);
        }
        Ok(())
    })
}

/// The loop and every minor loop of the model for the periodic input with one period's
/// turning points `u[0..n]` (as `lugre loop --model NAME --turning-points`), read with the
/// `lugre_loop_*` functions (the output `y` is the model's force) and freed by
/// `lugre_loop_free`.
#[no_mangle]
pub extern "C" fn lugre_zoo_loop_new(
    zoo: *const LugreZoo,
    u: *const f64,
    n: usize,
    out: *mut *mut LugreLoop,
) -> LugreStatus {
    guard(|| {
        let m = &handle(zoo, "zoo")?.model;
        let tp = TurningPoints::new(input(u, n, "u")?)?;
        let zl = m.loops(&tp)?;
        set_out(
            out,
            LugreLoop {
                inner: Periodic::Zoo(Box::new((m.clone(), zl))),
            },
        )
    })
}

/// The rainflow cycles of the history `u[0..n]` with the noise gate `gate` (0: none), each full
/// cycle with its energies along the model's path from rest at `u[0]` (as `lugre cycles --model
/// NAME`), read with `lugre_cycles_len` and `lugre_cycles_columns` and freed by
/// `lugre_cycles_free`. The history is held whole: more than the core's
/// `lugre::zoo::MAX_HISTORY_SAMPLES` (2^27) samples are refused, before anything is allocated.
/// `x0` is NULL: the model starts from rest; an initial state given (as to `lugre_cycles_new`)
/// is refused with the core's message, as `lugre cycles --model NAME --x0` refuses it.
#[no_mangle]
pub extern "C" fn lugre_zoo_cycles_new(
    zoo: *const LugreZoo,
    u: *const f64,
    n: usize,
    gate: f64,
    x0: *const f64,
    out: *mut *mut LugreCycles,
) -> LugreStatus {
    guard(|| {
        let m = &handle(zoo, "zoo")?.model;
        if !x0.is_null() {
            let label = m.spec().label;
            return Err(lugre::HistoryError::StartsFromRest { model: label }.into());
        }
        let u = input(u, n, "u")?;
        lugre::zoo::check_held(m, u.len())
            .map_err(|e| fail(LugreStatus::InvalidArgument, format!("u: {e}")))?;
        let mut columns = lugre::CycleColumns::new()
            .with_reversals(false)
            .with_closures(true)
            .with_energy(true);
        m.count_cycles(u, gate, &mut columns)?;
        set_out(out, LugreCycles { columns })
    })
}

/// The force at each of the `n` samples of the input `u` at the strictly increasing times `t`
/// (linear in between), from rest at `u[0]`, to `force_out` (`n` values; NULL skips), as
/// `lugre simulate --model NAME --input` gives it (the core's `ZooModel::simulate`: exact for
/// a rate-independent model, at finite rate where the model has rate dependence). `z0` is
/// NULL: an initial state given (as `lugre_simulate`'s `z0`) is refused with the core's
/// message, as `lugre simulate --model NAME --x0` refuses it. Nothing is written on a refusal.
#[no_mangle]
pub extern "C" fn lugre_zoo_simulate(
    zoo: *const LugreZoo,
    t: *const f64,
    u: *const f64,
    n: usize,
    z0: *const f64,
    force_out: *mut f64,
) -> LugreStatus {
    guard(|| {
        let m = &handle(zoo, "zoo")?.model;
        if !z0.is_null() {
            return Err(m.simulate_option("z0").into());
        }
        let force = m.simulate(input(t, n, "t")?, input(u, n, "u")?)?;
        output(force_out, &force);
        Ok(())
    })
}
