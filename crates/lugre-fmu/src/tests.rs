//! The model descriptions (`fmu/*.xml`) against the code: every friction parameter's name,
//! value reference, start value, unit and description is the core's ([`Parameter`], the Table I
//! values the FMUs start from), and every variable's value reference names the variable the
//! code serves there. A parameter added to the core's table, or an edit of the XML, fails here
//! until the two agree.

use std::collections::BTreeMap;

use lugre::model::Parameter;
use lugre::LuGreParams;

use crate::{friction, mass, vr, Kind, Unit};

/// The attributes of every `<Float64 .../>` variable of a model description, in order.
fn float64_variables(xml: &str) -> Vec<BTreeMap<String, String>> {
    xml.split("<Float64 ")
        .skip(1)
        .map(|rest| attributes(&rest[..rest.find("/>").expect("a self-closed <Float64>")]))
        .collect()
}

/// `key="value"` pairs (the XML files use double quotes and no entities in these tags).
fn attributes(tag: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    let mut rest = tag;
    while let Some(eq) = rest.find("=\"") {
        let key = rest[..eq].trim().to_string();
        let after = &rest[eq + 2..];
        let end = after.find('"').expect("a closing quote");
        out.insert(key, after[..end].to_string());
        rest = &after[end + 1..];
    }
    out
}

/// The core's unit in FMI's spelling (a product is written with `.`: `N s/m` is `N.s/m`).
fn fmi_unit(p: Parameter) -> String {
    p.unit().replace(' ', ".")
}

fn description(p: Parameter) -> String {
    format!("{} ({})", p.description(), p.domain().condition())
}

/// `what` when the XML has `have` where the code has `want`.
fn differ(what: String, have: Option<&String>, want: String) -> Option<String> {
    (have != Some(&want)).then(|| format!("{what}: {have:?} in the XML, {want:?} in the code"))
}

/// Every difference between a model description and the core's table or the code.
fn drifts(xml: &str, unit: &dyn Unit) -> Vec<String> {
    let variables = float64_variables(xml);
    let table1 = LuGreParams::canudas_de_wit_1995();
    let mut out = Vec::new();
    for (i, p) in Parameter::LUGRE.into_iter().enumerate() {
        let Some(v) = variables.iter().find(|v| v["name"] == p.name()) else {
            out.extend(differ(format!("{p}"), None, "a variable".into()));
            continue;
        };
        let want_vr = vr::PARAMETERS + u32::try_from(i).expect("7 parameters");
        out.extend(differ(
            format!("{p}'s reference"),
            v.get("valueReference"),
            want_vr.to_string(),
        ));
        out.extend(differ(
            format!("{p}'s causality"),
            v.get("causality"),
            "parameter".into(),
        ));
        // The start as the number it is (`1e5` and `100000` are the same start).
        let start = v.get("start").and_then(|s| s.parse::<f64>().ok());
        let want = table1.get(p).expect("a LuGre parameter");
        if start != Some(want) {
            out.push(format!(
                "{p}'s start: {start:?} in the XML, {want} in the core"
            ));
        }
        out.extend(differ(format!("{p}'s unit"), v.get("unit"), fmi_unit(p)));
        out.extend(differ(
            format!("{p}'s description"),
            v.get("description"),
            description(p),
        ));
    }
    for v in &variables {
        let r: u32 = v["valueReference"].parse().expect("a value reference");
        out.extend(differ(
            format!("reference {r}"),
            v.get("name"),
            unit.name_of(r).into(),
        ));
    }
    out
}

fn read(file: &str) -> String {
    let path = format!("{}/fmu/{file}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).expect("the model description")
}

#[test]
fn the_model_descriptions_are_the_cores_table_and_the_codes_references() {
    let friction = friction::Friction::new(Kind::CoSimulation);
    let mass = mass::Mass::new(Kind::CoSimulation);
    assert_eq!(drifts(&read("lugre-friction.xml"), &friction), [""; 0]);
    assert_eq!(drifts(&read("lugre-mass.xml"), &mass), [""; 0]);
}

#[test]
fn a_drift_is_seen() {
    // sigma0 starting at 1e4, fs described otherwise, z0 under another name: three drifts.
    let xml = read("lugre-friction.xml")
        .replace(r#"start="100000""#, r#"start="10000""#)
        .replace("stiction force (> 0)", "stiction")
        .replace(r#"name="z0""#, r#"name="x0""#);
    let found = drifts(&xml, &friction::Friction::new(Kind::CoSimulation));
    assert_eq!(found.len(), 3, "{found:#?}");
    assert!(
        found[0].starts_with("sigma0's start: Some(10000.0)"),
        "{found:?}"
    );
    assert!(found[1].starts_with("fs's description"), "{found:?}");
    assert!(found[2].starts_with("reference 17"), "{found:?}");
    assert_eq!(fmi_unit(Parameter::Sigma1), "N.s/m");
}
