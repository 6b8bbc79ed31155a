//! `--plot` of `lugre simulate` run as a user would: y against t and y against u, side by side
//! in one SVG or PNG file.

mod common;
use common::lugre;

#[test]
fn simulate_draws_y_against_t_and_against_u() {
    let dir = std::env::temp_dir().join(format!("lugre-simulate-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (png, svg) = (dir.join("y.png"), dir.join("y.svg"));
    for path in [&png, &svg] {
        let out = lugre(&[
            "simulate",
            "--bimodal",
            "0,0.2,1,1.5",
            "--gamma",
            "10",
            "--periods",
            "3",
            "--plot",
            path.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            stdout.contains("Drew y against t and y against u to"),
            "{stdout}"
        );
    }
    let decoder = png::Decoder::new(std::fs::File::open(&png).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (1600, 650));

    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("well-formed SVG");
    let labels: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(str::trim)
        .collect();
    for want in [
        "time t",
        "input u",
        "y against t, γ = 10",
        "y against u, γ = 10",
    ] {
        assert!(labels.contains(&want), "{want} in {labels:?}");
    }

    // A bad file name is refused before the simulation runs, and nothing is written.
    let bad = dir.join("y.pdf");
    let out = lugre(&[
        "simulate",
        "--sine",
        "1,2",
        "--periods",
        "1000000",
        "--plot",
        bad.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("must end in .svg or .png"), "{err}");
    assert!(!bad.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
