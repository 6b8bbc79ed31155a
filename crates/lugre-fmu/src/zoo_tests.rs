//! The zoo FMUs' model descriptions (`fmu/zoo/NAME.xml`) are the core's table
//! ([`zoo::model_description`]; `LUGRE_BLESS=1` rewrites them), one for each model and no
//! other, and every variable's reference names the variable the code serves there.

use lugre::zoo::{ZooModelSpec, MODELS};

use crate::zoo::{self, Zoo};
use crate::Unit;

/// Each of `specs`' descriptions by `write` is `fmu/DIR/NAME.xml` (`LUGRE_BLESS=1` rewrites
/// them), and `fmu/DIR` has no other.
pub(crate) fn check_written(
    dir_name: &str,
    specs: &[&ZooModelSpec],
    write: fn(&ZooModelSpec) -> Result<String, String>,
) {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fmu")
        .join(dir_name);
    let bless = std::env::var_os("LUGRE_BLESS").is_some();
    for spec in specs {
        let want = write(spec).unwrap();
        let path = dir.join(format!("{}.xml", spec.name));
        let have = std::fs::read_to_string(&path).unwrap_or_default();
        if bless && have != want {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(&path, &want).unwrap();
        }
        assert!(
            std::fs::read_to_string(&path).unwrap_or_default() == want,
            "fmu/{dir_name}/{}.xml is not the core's table: run bash scripts/write-tables.sh",
            spec.name
        );
    }
    // No description of a model the table no longer has.
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        if specs.iter().all(|m| m.name != stem) {
            if bless {
                std::fs::remove_file(&path).unwrap();
            } else {
                panic!("fmu/{dir_name}/{stem}.xml: no model of the table has this name (bash scripts/write-tables.sh removes it)");
            }
        }
    }
}

#[test]
fn the_zoo_model_descriptions_are_written_from_the_table() {
    let specs: Vec<&ZooModelSpec> = MODELS.iter().collect();
    check_written("zoo", &specs, zoo::model_description);
}

/// How many of `xml`'s `name="..." valueReference="..."` there are; each is what `unit` calls
/// the variable at that reference.
pub(crate) fn check_names(xml: &str, unit: &dyn Unit, model: &str) -> usize {
    let mut seen = 0;
    let tags = |kind: &'static str| xml.split(kind).skip(1);
    for tag in tags("<Float64 ").chain(tags("<UInt64 ")) {
        let attribute = |key: &str| {
            tag.split(&format!("{key}=\""))
                .nth(1)
                .and_then(|t| t.split('"').next())
                .map(str::to_string)
        };
        let (Some(name), Some(r)) = (attribute("name"), attribute("valueReference")) else {
            continue;
        };
        let r: u32 = r.parse().unwrap();
        assert_eq!(unit.name_of(r), name, "{model}: reference {r}");
        seen += 1;
    }
    seen
}

/// Every `name="..." valueReference="..."` of a description is what the code calls the
/// variable at that reference; the token is the code's and names the model.
#[test]
fn the_descriptions_name_what_the_code_serves() {
    for spec in &MODELS {
        let xml = zoo::model_description(spec).unwrap();
        let seen = check_names(&xml, &Zoo::new(spec), spec.name);
        assert!(seen >= 6 + spec.parameters.len(), "{}: {seen}", spec.name);
        assert_eq!(
            zoo::model_of(zoo::token(spec).as_bytes()).map(|m| m.name),
            Some(spec.name)
        );
    }
}

#[test]
fn an_unknown_unit_is_named() {
    let mut spec = MODELS[0];
    let mut p = spec.parameters.to_vec();
    p[0].unit = "furlong";
    spec.parameters = Box::leak(p.into_boxed_slice());
    assert_eq!(
        zoo::model_description(&spec).unwrap_err(),
        "the unit \"furlong\" has no SI base units in lugre-fmu's zoo::UNITS: add it there"
    );
}

/// The FMI calls of a zoo FMU as a host makes them: model exchange refused at instantiation,
/// configuration mode only for a model with element arrays, the values counted per variable.
#[test]
fn a_zoo_instance_through_the_fmi_functions() {
    use crate::tests::last_logged;
    use crate::*;
    use std::ptr::{null, null_mut};
    let _serial = crate::tests::SERIAL
        .lock()
        .unwrap_or_else(|e| e.into_inner());
    let instantiate = |spec, me: bool| {
        let token = std::ffi::CString::new(zoo::token(spec)).unwrap();
        if me {
            let log = Some(crate::tests::collect as _);
            fmi3InstantiateModelExchange(
                c"z".as_ptr(),
                token.as_ptr(),
                null(),
                false,
                false,
                null_mut(),
                log,
            )
        } else {
            crate::tests::co_simulation(&token)
        }
    };
    let bouc_wen = MODELS
        .iter()
        .find(|m| zoo::default_elements(m).is_none())
        .unwrap();
    assert!(instantiate(bouc_wen, true).is_null());
    assert_eq!(
        last_logged(),
        format!(
            "lugre-{}.fmu is co-simulation only (a rate-independent element has no continuous state)",
            bouc_wen.name
        )
    );
    let cs = instantiate(bouc_wen, false);
    assert_eq!(fmi3EnterConfigurationMode(cs), Status::Error);
    assert_eq!(
        last_logged(),
        "fmi3EnterConfigurationMode: this FMU has no structural parameters"
    );
    fmi3FreeInstance(cs);

    let arrays = MODELS
        .iter()
        .find(|m| zoo::default_elements(m).is_some())
        .unwrap();
    let n = zoo::default_elements(arrays).unwrap();
    let cs = instantiate(arrays, false);
    let first = vr::PARAMETERS;
    let values = vec![1.0; n + 1];
    assert_eq!(
        fmi3SetFloat64(cs, [first].as_ptr(), 1, values.as_ptr(), n + 1),
        Status::Error
    );
    assert_eq!(
        last_logged(),
        format!(
            "1 value references for {} values: their variables hold {n}",
            n + 1
        )
    );
    assert_eq!(
        fmi3SetFloat64(cs, [first, zoo::vr::U].as_ptr(), 2, values.as_ptr(), n + 1),
        Status::Ok
    );
    assert_eq!(fmi3EnterConfigurationMode(cs), Status::Ok);
    assert_eq!(
        fmi3SetUInt64(cs, [zoo::vr::ELEMENTS].as_ptr(), 1, [1].as_ptr(), 1),
        Status::Ok
    );
    assert_eq!(fmi3ExitConfigurationMode(cs), Status::Ok);
    let mut count = [0_u64];
    assert_eq!(
        fmi3GetUInt64(cs, [zoo::vr::ELEMENTS].as_ptr(), 1, count.as_mut_ptr(), 1),
        Status::Ok
    );
    assert_eq!(count, [1]);
    assert_eq!(
        fmi3EnterInitializationMode(cs, false, 0.0, 0.0, false, 0.0),
        Status::Ok
    );
    assert_eq!(fmi3ExitInitializationMode(cs), Status::Error);
    assert!(
        last_logged().ends_with(
            "has no values for elements = 1: set its 1 values before the end of initialization"
        ),
        "{}",
        last_logged()
    );
    fmi3FreeInstance(cs);
}
