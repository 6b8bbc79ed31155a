//! A case through the C ABI (`lugre_c`'s functions, called as C calls them): the request
//! built from the case's fields, the answer put in the shape of the CLI's `--json` (C's
//! `-1`/`0` for "none" as `null`), a refusal as its status and `lugre_last_error()`.

use std::ffi::{CStr, CString};
use std::ptr;

use lugre_c::*;
use serde_json::{json, Value};

use super::table::{number, numbers, Case, Failure, Fields, Outcome};

/// A failed call: its message (every status but OK is a `value` refusal in C).
fn status(s: LugreStatus) -> Result<(), Failure> {
    if s == LugreStatus::Ok {
        return Ok(());
    }
    let message = unsafe { CStr::from_ptr(lugre_last_error()) }
        .to_string_lossy()
        .into_owned();
    assert_eq!(
        s,
        LugreStatus::InvalidArgument,
        "a refusal of the input: {message}"
    );
    Err(Failure::new("value", message))
}

pub fn run(case: &Case) -> Outcome {
    let f = &case.fields;
    match case.command.as_str() {
        "loop" => run_loop(f),
        "cycles" => cycles(f),
        "simulate" => simulate(f),
        "element" => element(f),
        "fit" => fit(f),
        "dynamics" => dynamics(f),
        "sweep" => sweep(f),
        other => panic!("{}: the C ABI has no command '{other}'", case.id),
    }
}

/// A model handle freed on drop.
struct Model(*mut LugreModel);

impl Drop for Model {
    fn drop(&mut self) {
        lugre_model_free(self.0);
    }
}

/// The model a `model` object names: `{"family": "dahl", "rho": .., "fc": ..}`, or LuGre's
/// defaults (or `"preset": "canudas1995"`) with the parameters given set by name.
fn model(m: Option<&Value>) -> Result<Model, Failure> {
    let empty = serde_json::Map::new();
    let m = m.map_or(&empty, |v| v.as_object().expect("model is an object"));
    let mut out = ptr::null_mut();
    if m.get("family").and_then(Value::as_str) == Some("dahl") {
        // By name, the others at the core's defaults (as the MEX gateway makes Dahl models).
        let given: Vec<(std::ffi::CString, f64)> = m
            .iter()
            .filter(|(k, _)| *k != "family")
            .map(|(k, v)| (std::ffi::CString::new(k.as_str()).unwrap(), number(v)))
            .collect();
        let names: Vec<*const std::ffi::c_char> = given.iter().map(|(k, _)| k.as_ptr()).collect();
        let values: Vec<f64> = given.iter().map(|&(_, v)| v).collect();
        status(lugre_model_new_named(
            LUGRE_FAMILY_DAHL,
            names.len(),
            names.as_ptr(),
            values.as_ptr(),
            &mut out,
        ))?;
        return Ok(Model(out));
    }
    let mut p = LugreParams::default();
    match m.get("preset").and_then(Value::as_str) {
        Some("canudas1995") => status(lugre_params_canudas1995(&mut p))?,
        Some(other) => panic!("unknown preset {other}"),
        None => {}
    }
    for (name, value) in m {
        if name == "preset" || name == "family" {
            continue;
        }
        let c = CString::new(name.as_str()).unwrap();
        status(lugre_params_set(&mut p, c.as_ptr(), number(value)))?;
    }
    status(lugre_model_new(&p, &mut out))?;
    Ok(Model(out))
}

fn point(rho: f64, u: f64, y: f64) -> Value {
    json!({"rho": rho, "u": u, "y": y})
}

fn run_loop(f: &Fields) -> Outcome {
    let u = f.numbers("turning_points").expect("turning_points");
    let mut hl = ptr::null_mut();
    let zoo = f.get("model").filter(|m| m.get("model").is_some());
    match zoo {
        Some(m) => zoo_loop(m, &u, &mut hl)?,
        None => {
            let m = model(f.get("model"))?;
            status(lugre_loop_new(m.0, u.as_ptr(), u.len(), &mut hl))?;
        }
    }
    let result = loop_json(hl, f.get("samples"));
    lugre_loop_free(hl);
    result
}

/// The loop of the zoo's model `m["model"]` (see [`zoo_model`]).
fn zoo_loop(m: &Value, u: &[f64], hl: &mut *mut LugreLoop) -> Result<(), Failure> {
    let zoo = zoo_model(m)?;
    let result = status(lugre_zoo_loop_new(zoo, u.as_ptr(), u.len(), hl));
    lugre_zoo_free(zoo);
    result
}

/// The zoo's model `m["model"]` whose parameters are the other keys of `m` (a number or an
/// array each), given by name as a C caller gives them; freed by the caller.
fn zoo_model(m: &Value) -> Result<*mut LugreZoo, Failure> {
    let name = m["model"].as_str().expect("model names the model");
    let m = m.as_object().expect("model is an object");
    let given: Vec<(CString, Vec<f64>)> = m
        .iter()
        .filter(|(k, _)| *k != "model")
        .map(|(k, v)| {
            let values = match v {
                Value::Array(items) => items.iter().map(number).collect(),
                v => vec![number(v)],
            };
            (CString::new(k.as_str()).unwrap(), values)
        })
        .collect();
    let names: Vec<*const std::ffi::c_char> = given.iter().map(|(k, _)| k.as_ptr()).collect();
    let values: Vec<*const f64> = given.iter().map(|(_, v)| v.as_ptr()).collect();
    let lens: Vec<usize> = given.iter().map(|(_, v)| v.len()).collect();
    let model = CString::new(name).unwrap();
    let mut zoo = ptr::null_mut();
    status(lugre_zoo_new(
        model.as_ptr(),
        names.len(),
        names.as_ptr(),
        values.as_ptr(),
        lens.as_ptr(),
        &mut zoo,
    ))?;
    Ok(zoo)
}

fn loop_json(hl: *mut LugreLoop, samples: Option<&Value>) -> Outcome {
    let mut n = 0;
    status(lugre_loop_turning_len(hl, &mut n))?;
    let (mut u, mut rho, mut y) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    status(lugre_loop_turning(
        hl,
        u.as_mut_ptr(),
        rho.as_mut_ptr(),
        y.as_mut_ptr(),
        n,
    ))?;
    let (mut work, mut period) = (0.0, 0.0);
    status(lugre_loop_summary(hl, &mut work, &mut period))?;
    let mut k = 0;
    status(lugre_loop_table_len(hl, &mut k))?;
    let mut kind = vec![0i32; k];
    let mut c: Vec<Vec<f64>> = (0..13).map(|_| vec![0.0; k]).collect();
    let (mut parent, mut depth) = (vec![0i64; k], vec![0i64; k]);
    let columns = LugreLoopColumns {
        kind: kind.as_mut_ptr(),
        start_rho: c[0].as_mut_ptr(),
        start_u: c[1].as_mut_ptr(),
        start_y: c[2].as_mut_ptr(),
        reversal_rho: c[3].as_mut_ptr(),
        reversal_u: c[4].as_mut_ptr(),
        reversal_y: c[5].as_mut_ptr(),
        end_rho: c[6].as_mut_ptr(),
        end_u: c[7].as_mut_ptr(),
        end_y: c[8].as_mut_ptr(),
        work: c[9].as_mut_ptr(),
        stored_energy_change: c[10].as_mut_ptr(),
        dissipation: c[11].as_mut_ptr(),
        closure_gap: c[12].as_mut_ptr(),
        parent: parent.as_mut_ptr(),
        depth: depth.as_mut_ptr(),
    };
    status(lugre_loop_table(hl, &columns, k))?;
    let loops: Vec<Value> = (0..k)
        .map(|i| {
            json!({
                "kind": if kind[i] == 0 { "major" } else { "minor" },
                "start": point(c[0][i], c[1][i], c[2][i]),
                "reversal": point(c[3][i], c[4][i], c[5][i]),
                "end": point(c[6][i], c[7][i], c[8][i]),
                "work": c[9][i],
                "stored_energy_change": c[10][i],
                "dissipation": c[11][i],
                "closure_gap": c[12][i],
                "parent": (parent[i] >= 0).then_some(parent[i]),
                "depth": depth[i],
            })
        })
        .collect();
    let mut out = json!({
        "period": period,
        "work_per_period": work,
        "turning_points": (0..n).map(|i| point(rho[i], u[i], y[i])).collect::<Vec<_>>(),
        "loops": loops,
    });
    if let Some(s) = samples {
        let n = s.as_f64().expect("samples") as usize;
        // Buffers of n: the call must write no more.
        let (mut r, mut u, mut y) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        status(lugre_loop_sample(
            hl,
            n,
            r.as_mut_ptr(),
            u.as_mut_ptr(),
            y.as_mut_ptr(),
        ))?;
        out["points"] = (0..n).map(|i| point(r[i], u[i], y[i])).collect();
    }
    Ok(out)
}

fn cycles(f: &Fields) -> Outcome {
    let h = f.numbers("history").expect("history");
    let with_model = f.get("model").is_some();
    let gate = f.num("gate").unwrap_or(0.0);
    let mut c = ptr::null_mut();
    if let Some(m) = f.get("model").filter(|m| m.get("model").is_some()) {
        // A model of the zoo: x0 passed only when the case gives it (to be refused).
        let zoo = zoo_model(m)?;
        let x0 = f.num("x0");
        let x0 = x0.as_ref().map_or(ptr::null(), |x| x as *const f64);
        let s = lugre_zoo_cycles_new(zoo, h.as_ptr(), h.len(), gate, x0, &mut c);
        lugre_zoo_free(zoo);
        status(s)?;
    } else {
        let m = with_model.then(|| model(f.get("model"))).transpose()?;
        status(lugre_cycles_new(
            h.as_ptr(),
            h.len(),
            gate,
            m.as_ref().map_or(ptr::null(), |m| m.0),
            f.num("x0").unwrap_or(0.0),
            &mut c,
        ))?;
    }
    let mut n = 0;
    status(lugre_cycles_len(c, &mut n))?;
    let mut d: Vec<Vec<f64>> = (0..8).map(|_| vec![0.0; n]).collect();
    let mut i: Vec<Vec<i64>> = (0..3).map(|_| vec![0; n]).collect();
    let columns = LugreCycleColumns {
        range: d[0].as_mut_ptr(),
        mean: d[1].as_mut_ptr(),
        count: d[2].as_mut_ptr(),
        start: i[0].as_mut_ptr(),
        end: i[1].as_mut_ptr(),
        closure: i[2].as_mut_ptr(),
        closure_position: d[3].as_mut_ptr(),
        work: d[4].as_mut_ptr(),
        stored_energy_change: d[5].as_mut_ptr(),
        dissipation: d[6].as_mut_ptr(),
        closure_gap: d[7].as_mut_ptr(),
    };
    let s = lugre_cycles_columns(c, &columns, n);
    lugre_cycles_free(c);
    status(s)?;
    let rows: Vec<Value> = (0..n)
        .map(|k| {
            let full = d[2][k] == 1.0;
            let energy = |col: usize| (full && with_model).then_some(d[col][k]);
            json!({
                "range": d[0][k], "mean": d[1][k], "count": d[2][k],
                "start": i[0][k], "end": i[1][k],
                "closure": full.then_some(i[2][k]),
                "closure_position": full.then_some(d[3][k]),
                "work": energy(4), "stored_energy_change": energy(5),
                "dissipation": energy(6), "closure_gap": energy(7),
            })
        })
        .collect();
    Ok(json!({ "cycles": rows }))
}

fn simulate(f: &Fields) -> Outcome {
    let (t, x) = (f.numbers("t").unwrap(), f.numbers("x").unwrap());
    let n = t.len().min(x.len());
    if let Some(m) = f.get("model").filter(|m| m.get("model").is_some()) {
        return zoo_simulate(m, &t[..n], &x[..n], f.num("x0"));
    }
    let m = model(f.get("model"))?;
    let (mut z, mut y) = (vec![0.0; n], vec![0.0; n]);
    status(lugre_simulate(
        m.0,
        t.as_ptr(),
        x.as_ptr(),
        t.len(),
        f.num("x0").unwrap_or(0.0),
        z.as_mut_ptr(),
        y.as_mut_ptr(),
    ))?;
    Ok(json!({"t": t, "u": x, "z": z, "y": y}))
}

/// A model of the zoo from rest (see [`zoo_model`]): the force at each knot; an initial state
/// given is passed, for the C ABI to refuse.
fn zoo_simulate(m: &Value, t: &[f64], x: &[f64], z0: Option<f64>) -> Outcome {
    let zoo = zoo_model(m)?;
    let mut y = vec![0.0; t.len()];
    let z0 = z0.as_ref().map_or(ptr::null(), |z| z as *const f64);
    let s = lugre_zoo_simulate(zoo, t.as_ptr(), x.as_ptr(), t.len(), z0, y.as_mut_ptr());
    lugre_zoo_free(zoo);
    status(s)?;
    Ok(json!({"t": t, "u": x, "y": y}))
}

/// The steady-state sweep: `lugre_sweep`'s table as `{"points": [{column: value}, ...]}`.
fn sweep(f: &Fields) -> Outcome {
    let m = model(f.get("model"))?;
    let (a, fr) = (
        f.numbers("amplitudes").unwrap(),
        f.numbers("frequencies").unwrap(),
    );
    let rows = a.len() * fr.len();
    let mut table = vec![0.0; rows * LUGRE_SWEEP_COLUMNS];
    status(lugre_sweep(
        m.0,
        a.as_ptr(),
        a.len(),
        fr.as_ptr(),
        fr.len(),
        f.num("offset").unwrap_or(0.0),
        f.num("tol").unwrap_or(0.0),
        table.as_mut_ptr(),
        rows,
    ))?;
    let points: Vec<Value> = table
        .chunks(LUGRE_SWEEP_COLUMNS)
        .map(|row| {
            let point: serde_json::Map<String, Value> = (0..LUGRE_SWEEP_COLUMNS)
                .map(|c| {
                    let name = unsafe { std::ffi::CStr::from_ptr(lugre_sweep_column(c)) };
                    (name.to_string_lossy().into_owned(), json!(row[c]))
                })
                .collect();
            Value::Object(point)
        })
        .collect();
    Ok(json!({ "points": points }))
}

/// The friction element from rest at `x[0]` (time 0) through `x[1..]`, each over its step
/// `dt` (else the knots `t`'s differences).
fn element(f: &Fields) -> Outcome {
    let m = model(f.get("model"))?;
    let x = f.numbers("x").unwrap();
    let dt = f.numbers("dt").unwrap_or_else(|| {
        let t = f.numbers("t").expect("t or dt");
        t.windows(2).map(|w| w[1] - w[0]).collect()
    });
    let z0 = f.num("z0").unwrap_or(0.0);
    let mut e = ptr::null_mut();
    status(lugre_element_new(m.0, z0, &mut e))?;
    let result = (|| {
        status(lugre_element_reset(e, 0.0, x[0], z0))?;
        let (mut zs, mut fs) = (Vec::new(), Vec::new());
        for (k, h) in dt.iter().enumerate() {
            let mut force = 0.0;
            status(lugre_element_step(e, x[k + 1], *h, &mut force))?;
            let mut z = 0.0;
            let null = ptr::null_mut();
            status(lugre_element_state(e, null, null, &mut z, null))?;
            zs.push(z);
            fs.push(force);
        }
        Ok(json!({"z": zs, "F": fs}))
    })();
    lugre_element_free(e);
    result
}

const NAMES: [&str; 7] = ["sigma0", "sigma1", "sigma2", "fc", "fs", "vs", "beta"];

fn fit(f: &Fields) -> Outcome {
    let dahl = f.get("family").and_then(Value::as_str) == Some("dahl");
    // The values held parameters keep: a model of the family with `fix`'s values.
    let fixed = f
        .get("fix")
        .and_then(Value::as_object)
        .cloned()
        .unwrap_or_default();
    let mut values = serde_json::Map::new();
    if dahl {
        values.insert("family".into(), "dahl".into());
    }
    values.extend(fixed.clone());
    let m = (!fixed.is_empty())
        .then(|| model(Some(&Value::Object(values))))
        .transpose()?;
    let fix = CString::new(fixed.keys().cloned().collect::<Vec<_>>().join(",")).unwrap();
    let mut o = LugreFitOptions {
        family: 0,
        model: ptr::null(),
        fix: ptr::null(),
        free: ptr::null(),
        x0: 0.0,
        starts: 0,
    };
    status(lugre_fit_options_default(&mut o))?;
    o.family = if dahl {
        LUGRE_FAMILY_DAHL
    } else {
        LUGRE_FAMILY_LUGRE
    };
    o.model = m.as_ref().map_or(ptr::null(), |m| m.0);
    o.fix = fix.as_ptr();
    o.x0 = f.num("x0").unwrap_or(0.0);
    o.starts = f.num("starts").unwrap_or(0.0) as usize;
    let (u, force) = (f.numbers("u").unwrap(), f.numbers("f").unwrap());
    let n = u.len();
    let mut r = LugreFitResult::default();
    let mut fitted = vec![0.0; n];
    let full = f.get("kind").and_then(Value::as_str) == Some("full");
    status(if full {
        let t = f.numbers("t").expect("a full fit's t");
        lugre_fit(
            t.as_ptr(),
            u.as_ptr(),
            force.as_ptr(),
            n,
            &o,
            &mut r,
            fitted.as_mut_ptr(),
        )
    } else {
        lugre_fit_slow(
            u.as_ptr(),
            force.as_ptr(),
            n,
            &o,
            &mut r,
            fitted.as_mut_ptr(),
        )
    })?;
    let names: &[&str] = if dahl { &["rho", "fc"] } else { &NAMES };
    let mut parameters = serde_json::Map::new();
    for (k, name) in names.iter().enumerate().take(r.parameters) {
        if r.fitted[k] == 1 {
            parameters.insert(
                name.to_string(),
                json!({"value": r.value[k], "stderr": r.std_error[k],
                       "ci95": [r.ci95_lo[k], r.ci95_hi[k]], "at_bound": r.at_bound[k] == 1}),
            );
        }
    }
    let mut out = json!({
        "parameters": parameters, "rms": r.rms, "samples": r.samples, "dof": r.dof,
        "t_quantile": r.t_quantile, "condition_number": r.condition_number,
        "iterations": r.iterations, "evaluations": r.evaluations, "starts": r.starts,
        "converged": r.converged == 1,
    });
    if !full {
        out["turning_points"] = r.turning_points.into();
    }
    Ok(out)
}

/// A request handle freed on drop.
struct Request(*mut LugreDynamics);

impl Drop for Request {
    fn drop(&mut self) {
        lugre_dynamics_free(self.0);
    }
}

fn dynamics(f: &Fields) -> Outcome {
    let mut d = ptr::null_mut();
    status(lugre_dynamics_new(&mut d))?;
    let d = Request(d);
    // The fields in the order given, as a C caller sets them.
    for (name, value) in &f.0 {
        let c = CString::new(name.as_str()).unwrap();
        match (name.as_str(), value) {
            ("scenario", Value::String(s)) => {
                let s = CString::new(s.as_str()).unwrap();
                status(lugre_dynamics_set_scenario(d.0, s.as_ptr()))?;
            }
            // A model of the zoo by its name (the elasto-plastic one), else LuGre's.
            ("model", m) if m.get("model").is_some() => {
                let zoo = zoo_model(m)?;
                let result = status(lugre_dynamics_set_zoo(d.0, zoo));
                lugre_zoo_free(zoo);
                result?
            }
            ("model", m) => status(lugre_dynamics_set_model(d.0, model(Some(m))?.0))?,
            // Points: [[t, value], ...].
            (_, Value::Array(a)) if a.first().is_some_and(Value::is_array) => {
                let (t, v): (Vec<f64>, Vec<f64>) =
                    a.iter().map(|p| (number(&p[0]), number(&p[1]))).unzip();
                status(lugre_dynamics_set_points(
                    d.0,
                    c.as_ptr(),
                    t.as_ptr(),
                    v.as_ptr(),
                    t.len(),
                ))?;
            }
            (_, Value::Bool(b)) => {
                let x = [f64::from(u8::from(*b))];
                status(lugre_dynamics_set(d.0, c.as_ptr(), x.as_ptr(), 1))?;
            }
            (_, v) => {
                let x = numbers(v);
                status(lugre_dynamics_set(d.0, c.as_ptr(), x.as_ptr(), x.len()))?;
            }
        }
    }
    let mut m = ptr::null_mut();
    status(lugre_dynamics_run(d.0, &mut m))?;
    let result = motion_json(m);
    lugre_motion_free(m);
    result
}

fn motion_json(m: *mut LugreMotion) -> Outcome {
    let mut n = 0;
    status(lugre_motion_len(m, &mut n))?;
    let mut c: Vec<Vec<f64>> = (0..6).map(|_| vec![0.0; n]).collect();
    let [t, x, v, z, fr, dr] = &mut c[..] else {
        unreachable!()
    };
    status(lugre_motion_columns(
        m,
        n,
        t.as_mut_ptr(),
        x.as_mut_ptr(),
        v.as_mut_ptr(),
        z.as_mut_ptr(),
        fr.as_mut_ptr(),
        dr.as_mut_ptr(),
    ))?;
    let mut s = LugreMotionSummary::default();
    status(lugre_motion_summary(m, &mut s))?;
    let loops = (0..s.loops)
        .map(|i| friction_loop(m, i))
        .collect::<Result<Vec<Value>, Failure>>()?;
    Ok(json!({
        "t": c[0], "x": c[1], "v": c[2], "z": c[3], "friction": c[4], "drive": c[5],
        "events": vec![json!({}); s.events],
        "stats": {"steps": s.steps, "rejected": s.rejected},
        "energy": {"input": s.energy_input, "stored_start": s.stored_start,
                   "stored_end": s.stored_end, "dissipated": s.dissipated},
        "breakaway": (s.has_breakaway == 1).then(|| json!({
            "t": s.breakaway_t, "force": s.breakaway_force, "x": s.breakaway_x})),
        "t_end": s.t_end,
        "loops": loops,
    }))
}

/// Loop `i` of the run as a loop of the CLI's `loops`.
fn friction_loop(m: *mut LugreMotion, i: usize) -> Outcome {
    let mut l = LugreFrictionLoop {
        t_start: 0.0,
        t_turn: 0.0,
        t_close: 0.0,
        turning_points: ptr::null(),
        turning_points_len: 0,
        work: 0.0,
        bristle_energy_change: 0.0,
        dissipation: 0.0,
        rate_independent_work: 0.0,
    };
    status(lugre_motion_loop(m, i, &mut l))?;
    // SAFETY: the motion owns `turning_points_len` values there while it lives.
    let turning = unsafe { std::slice::from_raw_parts(l.turning_points, l.turning_points_len) };
    Ok(json!({
        "t_start": l.t_start, "t_turn": l.t_turn, "t_close": l.t_close,
        "turning_points": turning, "work": l.work,
        "bristle_energy_change": l.bristle_energy_change, "dissipation": l.dissipation,
        "rate_independent_work": l.rate_independent_work,
    }))
}
