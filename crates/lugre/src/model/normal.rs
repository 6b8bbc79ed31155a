//! The normal-force scaling: a model of the friction coefficient `mu = F / N` instead of the
//! force `F`, for records that hold the normal force `N` at each sample (`lugre fit
//! --columns N=NAME`, `lugre simulate --columns N=NAME`, Python `lugre.fit(..., normal=N)`).
//!
//! The LuGre (and Dahl) force is linear in `sigma0`, `sigma1`, `sigma2`, `Fc` and `Fs` together,
//! so a model fitted to `F / N` has those parameters per newton of `N`: `Fc` and `Fs` become the
//! dimensionless coefficients `mu_c` and `mu_s`, `sigma0` is in `1/m`, `sigma1` and `sigma2` in
//! `s/m`; `vs`, `beta` and `rho` keep their units. A simulation of such a model gives `mu`, and
//! `N(t)` times it is the force ([`to_force`]). Every front end takes the names, units and
//! checks from here.

use super::Parameter;
use crate::error::NormalForceError;

/// The column role of the normal force in a data file (`--columns N=NAME`).
pub const COLUMN: &str = "N";

/// The quantity a model per newton describes: the friction coefficient `mu = F / N`.
pub const COEFFICIENT: &str = "mu";

/// Whether `p` scales with the force (its value per newton is `p / N`): the parameters whose
/// unit has the newton as a factor (`sigma0`, `sigma1`, `sigma2`, `Fc`, `Fs`), in which the
/// force is linear together; not `vs`, `beta` or the Dahl model's `rho`.
pub fn scales(p: Parameter) -> bool {
    p.unit() == "N" || p.unit().starts_with("N ") || p.unit().starts_with("N/")
}

/// The name of `p` in a model per newton: `mu_c` for `Fc`, `mu_s` for `Fs` (the friction
/// coefficients), else the parameter's own name.
pub const fn name(p: Parameter) -> &'static str {
    match p {
        Parameter::Fc => "mu_c",
        Parameter::Fs => "mu_s",
        _ => p.name(),
    }
}

/// [`name`] of the parameter called `name` (a fit's names); other names unchanged.
pub fn name_of(name: &'static str) -> &'static str {
    Parameter::from_name(name).map_or(name, self::name)
}

/// The unit of `p` in a model per newton: its unit with the newton taken out where it
/// [`scales`] (`N/m` -> `1/m`, `N s/m` -> `s/m`, `N` -> `1`).
pub fn unit(p: Parameter) -> String {
    let unit = p.unit();
    if !scales(p) {
        return unit.to_string();
    }
    match unit.strip_prefix('N').map(str::trim_start) {
        Some("") => "1".to_string(),
        Some(rest) if rest.starts_with('/') => format!("1{rest}"),
        Some(rest) => rest.to_string(),
        None => unit.to_string(),
    }
}

/// The units of `parameters` per newton, grouped by unit in their order, e.g. `mu_c, mu_s
/// dimensionless; sigma0 in 1/m; sigma1, sigma2 in s/m` (those that do not [`scale`](scales)
/// are left out: their units do not change).
pub fn units(parameters: &[Parameter]) -> String {
    let mut groups: Vec<(String, Vec<&str>)> = Vec::new();
    for &p in parameters.iter().filter(|&&p| scales(p)) {
        let u = unit(p);
        match groups.iter_mut().find(|(v, _)| *v == u) {
            Some((_, names)) => names.push(name(p)),
            None => groups.push((u, vec![name(p)])),
        }
    }
    groups.sort_by_key(|(u, _)| u != "1");
    groups
        .iter()
        .map(|(u, names)| match u.as_str() {
            "1" => format!("{} dimensionless", names.join(", ")),
            u => format!("{} in {u}", names.join(", ")),
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// Checks that every normal force is finite and `> 0`, naming the first that is not.
pub fn check(n: &[f64]) -> Result<(), NormalForceError> {
    match n.iter().position(|&v| !(v.is_finite() && v > 0.0)) {
        Some(index) => Err(NormalForceError::NotPositive {
            index,
            value: n[index],
        }),
        None => Ok(()),
    }
}

/// `F / N` in place: the friction coefficient a model per newton is fitted to, one normal force
/// per sample (checked first; nothing is changed on an error).
pub fn to_coefficient(f: &mut [f64], n: &[f64]) -> Result<(), NormalForceError> {
    if n.len() != f.len() {
        return Err(NormalForceError::Length {
            normal: n.len(),
            samples: f.len(),
        });
    }
    check(n)?;
    f.iter_mut().zip(n).for_each(|(f, n)| *f /= n);
    Ok(())
}

/// `mu` to the force in place: `y[i]` times the normal force at `at[i]`, with `N` given at the
/// increasing times `t` (at least one), linear between them and held beyond them.
pub fn to_force(t: &[f64], n: &[f64], at: &[f64], y: &mut [f64]) {
    let Some(last) = t.len().min(n.len()).checked_sub(1) else {
        return;
    };
    for (y, &ti) in y.iter_mut().zip(at) {
        let k = t[..=last].partition_point(|&x| x <= ti);
        let nk = match k {
            0 => n[0],
            k if k > last => n[last],
            k => {
                let w = (ti - t[k - 1]) / (t[k] - t[k - 1]);
                n[k - 1] + w * (n[k] - n[k - 1])
            }
        };
        *y *= nk;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_units_per_newton() {
        assert_eq!(name(Parameter::Fc), "mu_c");
        assert_eq!(name(Parameter::Fs), "mu_s");
        assert_eq!(name_of("sigma0"), "sigma0");
        assert_eq!(name_of("fs"), "mu_s");
        assert_eq!(unit(Parameter::Sigma0), "1/m");
        assert_eq!(unit(Parameter::Sigma1), "s/m");
        assert_eq!(unit(Parameter::Fc), "1");
        assert_eq!(unit(Parameter::Vs), "m/s");
        assert_eq!(unit(Parameter::Rho), "1/m");
        use Parameter::{Beta, Fc, Fs, Rho, Sigma0, Sigma1, Sigma2, Vs};
        assert_eq!(
            units(&[Sigma0, Sigma1, Sigma2, Fc, Fs, Vs, Beta]),
            "mu_c, mu_s dimensionless; sigma0 in 1/m; sigma1, sigma2 in s/m"
        );
        // The force is linear in these together; the others keep their units.
        for p in [Sigma0, Sigma1, Sigma2, Fc, Fs] {
            assert!(scales(p), "{p}");
        }
        for p in [Vs, Beta, Rho] {
            assert!(!scales(p), "{p}");
        }
        // Each that scales (any parameter of the table with the newton in its unit) loses it.
        for p in Parameter::ALL.into_iter().filter(|&p| scales(p)) {
            assert!(!unit(p).contains('N'), "{p}");
        }
    }

    #[test]
    fn coefficient_and_force() {
        let mut f = [2.0, 3.0, f64::NAN];
        to_coefficient(&mut f, &[4.0, 6.0, 1.0]).unwrap();
        assert_eq!(&f[..2], &[0.5, 0.5]);
        assert!(f[2].is_nan());
        let e = to_coefficient(&mut f, &[1.0, 0.0, 1.0]).unwrap_err();
        assert_eq!(
            e,
            NormalForceError::NotPositive {
                index: 1,
                value: 0.0
            }
        );
        assert_eq!(e.to_string(), "the normal force N must be > 0, got 0");
        assert_eq!(f[0], 0.5, "unchanged on an error");
        assert!(check(&[1.0, f64::INFINITY]).is_err());
        assert!(matches!(
            to_coefficient(&mut f, &[1.0]),
            Err(NormalForceError::Length {
                normal: 1,
                samples: 3
            })
        ));
        // Linear between the times, held beyond them.
        let mut y = [1.0; 4];
        to_force(&[0.0, 1.0], &[2.0, 4.0], &[-1.0, 0.25, 1.0, 3.0], &mut y);
        assert_eq!(y, [2.0, 2.5, 4.0, 4.0]);
    }
}
