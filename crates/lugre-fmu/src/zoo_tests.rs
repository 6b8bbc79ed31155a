//! The zoo FMUs' model descriptions (`fmu/zoo/NAME.xml`) are the core's table
//! ([`zoo::model_description`]; `LUGRE_BLESS=1` rewrites them), one for each model and no
//! other, and every variable's reference names the variable the code serves there.

use lugre::zoo::MODELS;

use crate::zoo::{self, Zoo};
use crate::Unit;

fn dir() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fmu/zoo")
}

#[test]
fn the_zoo_model_descriptions_are_written_from_the_table() {
    let bless = std::env::var_os("LUGRE_BLESS").is_some();
    for spec in &MODELS {
        let want = zoo::model_description(spec).unwrap();
        let path = dir().join(format!("{}.xml", spec.name));
        let have = std::fs::read_to_string(&path).unwrap_or_default();
        if bless && have != want {
            std::fs::create_dir_all(dir()).unwrap();
            std::fs::write(&path, &want).unwrap();
        }
        assert!(
            std::fs::read_to_string(&path).unwrap_or_default() == want,
            "fmu/zoo/{}.xml is not the core's table: run bash scripts/write-tables.sh",
            spec.name
        );
    }
    // No description of a model the table no longer has.
    for entry in std::fs::read_dir(dir()).unwrap() {
        let path = entry.unwrap().path();
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        if MODELS.iter().all(|m| m.name != stem) {
            if bless {
                std::fs::remove_file(&path).unwrap();
            } else {
                panic!("fmu/zoo/{stem}.xml: no model of the table has this name (bash scripts/write-tables.sh removes it)");
            }
        }
    }
}

/// Every `name="..." valueReference="..."` of a description is what the code calls the
/// variable at that reference; the token is the code's and names the model.
#[test]
fn the_descriptions_name_what_the_code_serves() {
    for spec in &MODELS {
        let xml = zoo::model_description(spec).unwrap();
        let unit = Zoo::new(spec);
        let mut seen = 0;
        let tags = |kind: &'static str| xml.split(kind).skip(1);
        for tag in tags("<Float64 ").chain(tags("<UInt64 ")) {
            let Some(name) = tag
                .split("name=\"")
                .nth(1)
                .and_then(|t| t.split('"').next())
            else {
                continue;
            };
            let Some(r) = tag
                .split("valueReference=\"")
                .nth(1)
                .and_then(|t| t.split('"').next())
                .and_then(|t| t.parse::<u32>().ok())
            else {
                continue;
            };
            assert_eq!(unit.name_of(r), name, "{}: reference {r}", spec.name);
            seen += 1;
        }
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
