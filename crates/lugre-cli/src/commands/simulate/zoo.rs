//! `lugre simulate --model NAME` for a model of the zoo: the force at each sample of a
//! piecewise-linear input (an `--input` record, linear between samples, or turning points at
//! `--speed`) from rest, by [`ZooModel::simulate`] (exact for the rate-independent models, at
//! finite rate for the elasto-plastic one). Nothing here names a model: the table does.

use anyhow::{anyhow, bail, Result};
use lugre::zoo::ZooModel;
use lugre::Trajectory;
use std::io::Write;

use super::drive::build_drive;
use super::output::{print_rows, print_written, response_figure};
use super::SimulateArgs;
use crate::args::Interpolate;
use crate::io::atomic::write_atomic;
use crate::io::csv::NumberRows;
use crate::io::json::JsonOut;
use crate::plot::Units;
use crate::zoo_args::{zoo_json, zoo_line};
use lugre_io::Role;

/// The columns of the zoo's response (LuGre's without its state `z, dz`: the zoo's states
/// differ from model to model).
const COLUMNS: [&str; 3] = ["t", "u", "y"];

pub(super) fn run(args: &SimulateArgs, model: &ZooModel) -> Result<()> {
    refuse_lugre_flags(args, model)?;
    let (drive, text, normal) = build_drive(args)?;
    if normal.is_some() {
        bail!(
            "--columns N=...: the normal force scales LuGre's friction coefficient; --model {} takes forces as they are",
            model.spec().name
        );
    }
    let Some((t, u)) = drive.zoo_samples(args.samples_per_period)? else {
        bail!(
            "--model {}: the models of the zoo take a piecewise-linear input (--input FILE read linearly, --turning-points or --bimodal)",
            model.spec().name
        );
    };
    if let Some(path) = &args.plot.path {
        crate::plot::check_path(path)?;
    }
    let y = model
        .simulate(&t, &u)
        .map_err(|e| match &args.input.input {
            Some(path) => anyhow!("{}: {e}", path.display()),
            None => anyhow!(e),
        })?;
    let out = Trajectory {
        t,
        u,
        y,
        ..Trajectory::default()
    };
    report(args, model, &text, &out)
}

/// LuGre's own flags are refused with a model of the zoo, each by name.
fn refuse_lugre_flags(args: &SimulateArgs, model: &ZooModel) -> Result<()> {
    let given = [
        ("--x0", args.x0.is_some()),
        ("--gamma", args.gamma.is_some()),
        ("--periods", args.periods.is_some()),
        ("--tol", args.tol.is_some()),
        ("--times", args.times.is_some()),
        ("--sine", args.sine.is_some()),
        (
            "--interpolate cubic",
            args.interpolate == Interpolate::Cubic,
        ),
    ];
    if let Some((flag, _)) = given.iter().find(|(_, on)| *on) {
        return Err(model.simulate_option(flag).into());
    }
    Ok(())
}

/// Writes the CSV and the figure asked for, then prints the JSON document or the table.
fn report(args: &SimulateArgs, model: &ZooModel, input: &str, out: &Trajectory) -> Result<()> {
    if let Some(path) = &args.output.csv {
        write_atomic(path, |w| write_csv(w, out))?;
    }
    if let Some(path) = &args.plot.path {
        let units = Units::for_figure(
            args.input.input.as_deref(),
            &args.data.options(&[Role::U, Role::V])?,
            false,
            args.plot.units.as_deref(),
        )?;
        response_figure(out, model.spec().label, &units).save(path)?;
    }
    let stdout = std::io::stdout();
    if args.output.json {
        let mut j = JsonOut::new(stdout.lock());
        j.raw("{\"model\":")?;
        j.raw(&zoo_json(model).to_string())?;
        for (name, column) in COLUMNS.iter().zip([&out.t, &out.u, &out.y]) {
            j.raw(&format!(",\"{name}\":"))?;
            j.array(column)?;
        }
        j.raw("}\n")?;
        j.finish()?;
        return Ok(());
    }
    let mut w = std::io::BufWriter::new(stdout.lock());
    writeln!(w, "{}; from rest", zoo_line(model))?;
    writeln!(w, "Input: {input}")?;
    print_rows(&mut w, &COLUMNS, &[&out.t, &out.u, &out.y])?;
    print_written(&mut w, args, &COLUMNS.join(","), out.t.len())?;
    w.flush()?;
    Ok(())
}

fn write_csv(w: &mut dyn Write, out: &Trajectory) -> Result<()> {
    let mut rows = NumberRows::new();
    writeln!(w, "{}", COLUMNS.join(","))?;
    for i in 0..out.t.len() {
        rows.write(w, &[out.t[i], out.u[i], out.y[i]])?;
    }
    Ok(())
}
