//! `lugre paper` run as a user would: the real binary writing into a temporary directory. Every
//! file is produced, PNGs decode at the right size, SVGs are well-formed XML, the CSVs hold
//! numbers, index.html links only to files that exist, and every number in its tables equals
//! the one `lugre loop --json` prints for the same example.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

mod common;
use common::lugre;

/// A fresh directory under cargo's scratch space for integration tests (target/tmp): the
/// shared run's files stay there for inspection after the tests and are replaced next time.
fn temp_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("lugre-paper-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// One run of `lugre paper` shared by the tests: its directory and stdout.
fn paper() -> &'static (PathBuf, String) {
    static RUN: OnceLock<(PathBuf, String)> = OnceLock::new();
    RUN.get_or_init(|| {
        // A directory that does not exist yet, two levels deep: --out creates it.
        let dir = temp_dir("run").join("figures");
        let out = lugre(&["paper", "--out", dir.to_str().unwrap()]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            out.stderr.is_empty(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        (dir, String::from_utf8(out.stdout).unwrap())
    })
}

/// The file that marks the folder as written by `lugre paper` (its own files may be replaced).
const MARK: &str = ".lugre-paper";

fn files(dir: &Path) -> BTreeSet<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

#[test]
fn every_figure_is_written_as_svg_png_and_csv() {
    let (dir, _) = paper();
    let names = files(dir);
    for n in 3..=17 {
        let stem = format!("fig{n:02}");
        for ext in ["svg", "png"] {
            assert!(names.contains(&format!("{stem}.{ext}")), "{stem}.{ext}");
        }
        let csv: Vec<&String> = names
            .iter()
            .filter(|f| f.starts_with(&format!("{stem}-")) && f.ends_with(".csv"))
            .collect();
        assert!(!csv.is_empty(), "{stem} has no CSV");
    }
    assert!(names.contains("index.html"));
    assert!(names.contains(MARK), "the folder is marked as lugre's");
    // Nothing else: no temporary files left behind, no figure outside 03..17.
    for name in &names {
        let ok = name == "index.html"
            || name == "canudas1995"
            || name == "models"
            || name == MARK
            || (name.starts_with("fig")
                && (name.ends_with(".svg") || name.ends_with(".png") || name.ends_with(".csv")));
        assert!(ok, "unexpected file {name}");
    }
}

#[test]
fn pngs_decode_at_their_size() {
    let (dir, _) = paper();
    for n in 3..=17 {
        let path = dir.join(format!("fig{n:02}.png"));
        let decoder = png::Decoder::new(std::fs::File::open(&path).unwrap());
        let mut reader = decoder.read_info().expect("a PNG header");
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).expect("the image decodes");
        assert_eq!((info.width, info.height), (1000, 700), "{}", path.display());
        // Not blank: a figure has dark pixels (axes, text, curves) on white.
        let dark = buf.chunks(3).filter(|p| p.iter().all(|&c| c < 100)).count();
        assert!(dark > 1000, "{}: {dark} dark pixels", path.display());
    }
}

#[test]
fn svgs_are_well_formed_with_their_text() {
    let (dir, _) = paper();
    for n in 3..=17 {
        let path = dir.join(format!("fig{n:02}.svg"));
        let text = std::fs::read_to_string(&path).unwrap();
        let doc =
            roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let root = doc.root_element();
        assert_eq!(root.tag_name().name(), "svg");
        assert_eq!(root.attribute("width"), Some("1000"));
        assert_eq!(root.attribute("height"), Some("700"));
        let texts = root
            .descendants()
            .filter(|d| d.has_tag_name("text"))
            .count();
        assert!(texts > 10, "{}: {texts} text elements", path.display());
    }
    // Symbols are text, not pictures: the captions' notation is searchable in the SVG.
    let fig15 = std::fs::read_to_string(dir.join("fig15.svg")).unwrap();
    for want in [
        "minor loop, ρ ∈ [ρ₁, ρ₅]",
        "(u(t₁), y°(t₁))",
        "(u(t₅), y°(t₅))",
    ] {
        assert!(fig15.contains(want), "fig15.svg lacks {want}");
    }
}

#[test]
fn csvs_hold_the_curves_points() {
    let (dir, _) = paper();
    for name in files(dir).iter().filter(|f| f.ends_with(".csv")) {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        let mut lines = text.lines();
        let header = lines.next().unwrap();
        assert_eq!(header.split(',').count(), 2, "{name}: {header}");
        let mut rows = 0;
        for line in lines {
            let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            assert!(
                v.len() == 2 && v.iter().all(|x| x.is_finite()),
                "{name}: {line}"
            );
            rows += 1;
        }
        assert!(rows >= 2, "{name}: {rows} rows");
    }
}

/// The values of `attr="..."` in `html`.
fn attribute_values<'a>(html: &'a str, attr: &str) -> Vec<&'a str> {
    let key = format!(" {attr}=\"");
    html.match_indices(&key)
        .map(|(i, _)| {
            let rest = &html[i + key.len()..];
            &rest[..rest.find('"').unwrap()]
        })
        .collect()
}

#[test]
fn the_page_links_only_files_that_exist() {
    let (dir, _) = paper();
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    let names = files(dir);
    let mut linked = BTreeSet::new();
    for target in attribute_values(&html, "src")
        .into_iter()
        .chain(attribute_values(&html, "href"))
    {
        if let Some(anchor) = target.strip_prefix('#') {
            assert!(html.contains(&format!("id=\"{anchor}\"")), "#{anchor}");
            continue;
        }
        if target == "canudas1995/index.html" || target == "models/index.html" {
            // The second and third reports, each in its own folder.
            assert!(dir.join(target).is_file(), "{target} does not exist");
            continue;
        }
        assert!(
            !target.contains(':') && !target.contains('/'),
            "not a local file next to the page: {target}"
        );
        assert!(names.contains(target), "{target} does not exist");
        linked.insert(target.to_string());
    }
    // Every figure, image and data file is reachable from the page.
    for name in names
        .iter()
        .filter(|n| *n != "index.html" && *n != "canudas1995" && *n != "models" && *n != MARK)
    {
        assert!(
            linked.contains(name),
            "{name} is not linked from index.html"
        );
    }
    // Self-contained: no script, no stylesheet or font fetched from anywhere.
    for banned in ["<script", "<link", "@import", "url("] {
        assert!(!html.contains(banned), "{banned}");
    }
    for n in 3..=17 {
        assert!(
            html.contains(&format!("<b>Fig. {n}.</b>")),
            "caption of Fig. {n}"
        );
    }
    // The errata of Theorem A and the stable form.
    for want in [
        "errata",
        "overflows",
        "expm1",
        "i = 0, 2",
        "i = 2 and i = 4",
    ] {
        assert!(html.contains(want), "{want}");
    }
}

/// The JSON value at a dotted path (`loops.1.work`).
fn at<'a>(json: &'a serde_json::Value, path: &str) -> &'a serde_json::Value {
    path.split('.')
        .fold(json, |v, key| match key.parse::<usize>() {
            Ok(i) => &v[i],
            Err(_) => &v[key],
        })
}

#[test]
fn table_numbers_equal_lugre_loop_json() {
    let (dir, _) = paper();
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let mut tables = 0;
    for block in html.split(" data-args=\"").skip(1) {
        let args_end = block.find('"').unwrap();
        let args: Vec<&str> = block[..args_end].split_whitespace().collect();
        let body = &block[..block.find("<!-- /numbers -->").expect("end of the block")];
        let mut cmd = args.clone();
        cmd.push("--json");
        let out = lugre(&cmd);
        assert!(out.status.success(), "{cmd:?}");
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();

        let mut checked = 0;
        for cell in body.split(" data-json=\"").skip(1) {
            let path = &cell[..cell.find('"').unwrap()];
            let value_start = cell.find('>').unwrap() + 1;
            let text = &cell[value_start..value_start + cell[value_start..].find('<').unwrap()];
            let shown: f64 = text.parse().unwrap_or_else(|_| panic!("{path}: '{text}'"));
            let want = at(&json, path)
                .as_f64()
                .unwrap_or_else(|| panic!("{cmd:?}: no number at {path}"));
            assert_eq!(
                shown.to_bits(),
                want.to_bits(),
                "{cmd:?} {path}: page {text}, JSON {want}"
            );
            checked += 1;
        }
        // Turning points, every loop's energies, and Theorem A for the bimodal inputs.
        let loops = json["loops"].as_array().unwrap().len();
        let turning = json["turning_points"].as_array().unwrap().len();
        let theorem_a = if json.get("theorem_a").is_some() {
            14
        } else {
            0
        };
        assert_eq!(
            checked,
            4 + 3 * turning + theorem_a + 11 * loops,
            "{cmd:?}: every number of the table is tagged"
        );
        if args.contains(&"--bimodal") {
            assert!(body.contains("theorem_a.minor_loop.1"), "{cmd:?}");
            assert_eq!(loops, 2, "{cmd:?}: the major and Theorem A's minor loop");
        }
        tables += 1;
    }
    // Examples 2, 3, 4 and the variants of Figs. 16 and 17.
    assert_eq!(tables, 5);
}

#[test]
fn the_summary_says_what_was_written_and_the_headline_numbers() {
    let (dir, stdout) = paper();
    assert!(stdout.starts_with("Wrote "), "{stdout}");
    assert!(stdout.contains(&dir.display().to_string()));
    for want in [
        "fig03..fig17.svg and .png",
        "index.html",
        "lugre loop --bimodal 0,0.5,1,1.5 --sigma0 6",
        "y°(0) = ",
        "rho_5 = 2",
        "work W = ",
        "dissipated D = ",
    ] {
        assert!(stdout.contains(want), "{want} in {stdout}");
    }
}

/// Bad input: exit status 2, one line on stderr containing `want`, nothing on stdout.
fn rejects(args: &[&str], want: &str) {
    let out = lugre(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: one line, got {err}");
    assert!(err.contains(want), "{args:?}: wanted '{want}' in {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
}

#[test]
fn an_unwritable_out_is_one_clear_error() {
    let dir = temp_dir("bad");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("a-file");
    std::fs::write(&file, "not a directory").unwrap();
    let under_file = file.join("figures");
    rejects(
        &["paper", "--out", under_file.to_str().unwrap()],
        "cannot create the output directory",
    );
    rejects(
        &["paper", "--out", file.to_str().unwrap()],
        "cannot create the output directory",
    );
    // Nothing was written next to the file.
    assert_eq!(files(&dir).len(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The second report (Canudas de Wit et al. 1995): Figs. 2, 3, 4, 6, 8 as SVG, PNG and CSV, and
/// a page that links only its own files and the first report.
#[test]
fn the_second_report() {
    let (dir, _) = paper();
    let second = dir.join("canudas1995");
    let names = files(&second);
    for n in [2, 3, 4, 6, 8] {
        for ext in ["svg", "png"] {
            assert!(
                names.contains(&format!("fig{n:02}.{ext}")),
                "fig{n:02}.{ext}"
            );
        }
    }
    let html = std::fs::read_to_string(second.join("index.html")).unwrap();
    links_only_its_own_files(&html, &names);
    // The numbers shown: the stick-slip period and a break-away force.
    assert!(html.contains("period"), "{html}");
    assert!(html.contains("r = 10 N/s"), "{html}");
}

/// The third report: LuGre and every model of the core's zoo table on Fig. 15's input (one
/// figure each) and on a nested input (one figure), with a page that links only its own files;
/// LuGre's minor loop drifts, every Masing model's closes.
#[test]
fn the_third_report_compares_every_model_of_the_zoo() {
    let (dir, _) = paper();
    let third = dir.join("models");
    let names = files(&third);
    let models = 1 + lugre::zoo::MODELS.len();
    for n in 1..=models + 1 {
        for ext in ["svg", "png"] {
            assert!(
                names.contains(&format!("fig{n:02}.{ext}")),
                "fig{n:02}.{ext}"
            );
        }
    }
    let html = std::fs::read_to_string(third.join("index.html")).unwrap();
    links_only_its_own_files(&html, &names);
    let lugre = html
        .find("LuGre on its default values")
        .expect("LuGre's figure");
    assert!(
        html[lugre..].contains("The minor loop does not close"),
        "LuGre's minor loop drifts"
    );
    for spec in lugre::zoo::MODELS.iter().filter(|m| m.closes_minor_loops) {
        let line = format!("{} on its default values", spec.label);
        let at = html.find(&line).unwrap_or_else(|| panic!("{line}"));
        assert!(
            html[at..].contains("The minor loop closes: F_C − F_A = 0."),
            "{}",
            spec.label
        );
    }
}

/// Every image and link of a report's page is one of its folder's files, or the first report.
fn links_only_its_own_files(html: &str, names: &BTreeSet<String>) {
    for target in attribute_values(html, "src")
        .into_iter()
        .chain(attribute_values(html, "href"))
    {
        if target == "../index.html" {
            continue;
        }
        assert!(names.contains(target), "{target} does not exist");
    }
}
