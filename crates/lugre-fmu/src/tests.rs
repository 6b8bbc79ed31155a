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
        let want_vr = vr::PARAMETERS + u32::try_from(i).expect("a few parameters");
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

fn path(file: &str) -> String {
    format!("{}/fmu/{file}", env!("CARGO_MANIFEST_DIR"))
}

fn read(file: &str) -> String {
    std::fs::read_to_string(path(file)).expect("the model description")
}

/// The marker lines the table's variables stand between in each model description.
const BEGIN: &str = "<!-- The friction parameters, written from the core's table";
const END: &str = "<!-- end of the parameters from the core's table -->";

/// The variable of parameter `i` of the table, as the XML writes it.
fn variable(i: usize, p: Parameter) -> String {
    let start = LuGreParams::canudas_de_wit_1995()
        .get(p)
        .expect("a LuGre parameter");
    let r = vr::PARAMETERS + u32::try_from(i).expect("a few parameters");
    format!(
        r#"<Float64 name="{p}" valueReference="{r}" causality="parameter" variability="fixed" start="{start}" unit="{}" description="{}"/>"#,
        fmi_unit(p),
        description(p)
    )
}

/// `xml` with the lines between the markers written from the core's table.
fn with_the_table(xml: &str) -> String {
    let lines: Vec<&str> = xml.split('\n').collect();
    let begin = lines.iter().position(|l| l.trim_start().starts_with(BEGIN));
    let end = lines.iter().position(|l| l.trim() == END);
    let (Some(begin), Some(end)) = (begin, end) else {
        panic!("the model description has no markers for the table's parameters");
    };
    let indent = &lines[begin][..lines[begin].len() - lines[begin].trim_start().len()];
    let mut out: Vec<String> = lines[..=begin].iter().map(|l| l.to_string()).collect();
    for (i, p) in Parameter::LUGRE.into_iter().enumerate() {
        out.push(format!("{indent}{}", variable(i, p)));
    }
    out.extend(lines[end..].iter().map(|l| l.to_string()));
    out.join("\n")
}

/// The units the model description defines (`<Unit name="..."`).
fn defined_units(xml: &str) -> Vec<&str> {
    xml.split("<Unit name=\"")
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .collect()
}

/// The parameters' variables are written from the core's table (`LUGRE_BLESS=1` rewrites the
/// files), each with a unit the description defines.
#[test]
fn the_parameters_are_written_from_the_table() {
    for file in ["lugre-friction.xml", "lugre-mass.xml"] {
        let xml = read(file);
        let want = with_the_table(&xml);
        if std::env::var_os("LUGRE_BLESS").is_some() && want != xml {
            std::fs::write(path(file), &want).expect("write the model description");
        }
        assert!(
            read(file) == want,
            "fmu/{file} is not the core's table: run LUGRE_BLESS=1 cargo test -p lugre-fmu"
        );
        let units = defined_units(&xml);
        for p in Parameter::LUGRE {
            assert!(
                units.contains(&fmi_unit(p).as_str()),
                "fmu/{file}: {p}'s unit {} has no <Unit> in <UnitDefinitions>",
                fmi_unit(p)
            );
        }
    }
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
    assert!(found[2].starts_with("reference 100"), "{found:?}");
    assert_eq!(fmi_unit(Parameter::Sigma1), "N.s/m");
}

/// Held by each test that reads [`last_logged`], so that another's messages do not come between.
pub(crate) static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// The messages the FMU logged, collected by the host's callback below.
static LOGGED: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

pub(crate) unsafe extern "C" fn collect(
    _env: *mut std::ffi::c_void,
    _status: crate::Status,
    _category: *const std::ffi::c_char,
    message: *const std::ffi::c_char,
) {
    // SAFETY: the FMU passes a NUL-terminated message.
    let text = unsafe { std::ffi::CStr::from_ptr(message) };
    LOGGED
        .lock()
        .unwrap()
        .push(text.to_string_lossy().into_owned());
}

pub(crate) fn last_logged() -> String {
    LOGGED.lock().unwrap().last().cloned().unwrap_or_default()
}

/// A co-simulation instance of the FMU of `token`, logging to [`collect`].
pub(crate) fn co_simulation(token: &std::ffi::CStr) -> crate::Instance {
    use std::ptr::{null, null_mut};
    crate::fmi3InstantiateCoSimulation(
        c"m".as_ptr(),
        token.as_ptr(),
        null(),
        false,
        false,
        false,
        false,
        null(),
        0,
        null_mut(),
        Some(collect),
        null(),
    )
}

/// FMI 3.0's order, called as a host calls it: out of order is `fmi3Error` with a message,
/// and the instance keeps its time.
#[test]
fn calls_out_of_order_are_errors() {
    use crate::*;
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    use std::ptr::{null, null_mut};
    let token = std::ffi::CString::new(MASS_TOKEN).unwrap();
    let me = fmi3InstantiateModelExchange(
        c"m".as_ptr(),
        token.as_ptr(),
        null(),
        false,
        false,
        null_mut(),
        Some(collect),
    );
    assert_eq!(fmi3SetTime(me, 1.0), Status::Error);
    assert_eq!(
        last_logged(),
        "fmi3SetTime is not allowed in the instantiated state (after instantiation or fmi3Reset): only in continuous-time mode"
    );
    let (mut a, mut b, mut c, mut t) = (false, false, false, 0.0);
    let step = |i, t0, h, t: &mut f64, a: &mut bool, b: &mut bool, c: &mut bool| {
        fmi3DoStep(i, t0, h, false, a, b, c, t)
    };
    assert_eq!(
        step(me, 0.0, 1e-3, &mut t, &mut a, &mut b, &mut c),
        Status::Error
    );
    assert!(last_logged().starts_with("fmi3DoStep is not allowed in the instantiated state"));
    fmi3FreeInstance(me);

    let cs = co_simulation(&token);
    assert_eq!(
        fmi3EnterInitializationMode(cs, false, 0.0, 0.0, false, 0.0),
        Status::Ok
    );
    assert_eq!(fmi3ExitInitializationMode(cs), Status::Ok);
    assert_eq!(
        step(cs, 0.0, 1e-3, &mut t, &mut a, &mut b, &mut c),
        Status::Ok
    );
    assert_eq!(t, 1e-3);
    assert_eq!(
        fmi3EnterInitializationMode(cs, false, 0.0, 0.0, false, 0.0),
        Status::Error
    );
    assert_eq!(
        last_logged(),
        "fmi3EnterInitializationMode is not allowed in step mode: only in the instantiated state (after instantiation or fmi3Reset) (fmi3Reset starts the instance again)"
    );
    assert_eq!(fmi3SetTime(cs, 0.0), Status::Error);
    assert_eq!(
        last_logged(),
        "fmi3SetTime is a model-exchange function: this instance is a co-simulation"
    );
    assert_eq!(
        step(cs, 1e-3, f64::NAN, &mut t, &mut a, &mut b, &mut c),
        Status::Error
    );
    assert_eq!(
        last_logged(),
        "fmi3DoStep: the communication step size must be a finite number >= 0, got NaN"
    );
    let mut now = [0.0];
    assert_eq!(
        fmi3GetFloat64(cs, [vr::TIME].as_ptr(), 1, now.as_mut_ptr(), 1),
        Status::Ok
    );
    assert_eq!(now, [1e-3], "the time is kept");
    assert_eq!(fmi3Terminate(cs), Status::Ok);
    assert_eq!(
        step(cs, 1e-3, 1e-3, &mut t, &mut a, &mut b, &mut c),
        Status::Error
    );
    assert!(last_logged().starts_with("fmi3DoStep is not allowed in the terminated state"));
    assert_eq!(fmi3Reset(cs), Status::Ok);
    assert_eq!(
        fmi3EnterInitializationMode(cs, false, 0.0, 0.0, false, 0.0),
        Status::Ok
    );
    fmi3FreeInstance(cs);
}
