//! The reader's rules, each with the files that break them: the header names and units, the
//! files other lugre commands write, `--columns` and `--scale` mistakes, line numbers (CRLF, CR,
//! comments before the header), delimiters, streaming, and the message of each error.

use lugre_io::{
    read, Delimiter, Error, Labels, ReadOptions, Reader, Role, Selector, Spec, Table, MAX_LINE,
};

fn opts() -> ReadOptions {
    ReadOptions::default()
}

fn table(text: &str, spec: &Spec, options: ReadOptions) -> Result<Table, Error> {
    read(text.as_bytes(), spec, options)
}

/// The values of `role` in `text`, read with `spec`.
fn values(text: &str, spec: &Spec, role: Role) -> Vec<f64> {
    let mut t = table(text, spec, opts()).unwrap_or_else(|e| panic!("{text:?}: {e}"));
    t.take(&role)
        .unwrap_or_else(|| panic!("{text:?}: no {role}"))
}

fn message(text: &str, spec: &Spec, options: ReadOptions) -> String {
    match table(text, spec, options) {
        Ok(t) => panic!("{text:?}: accepted as {t:?}"),
        Err(e) => e.to_string(),
    }
}

fn series() -> Spec {
    Spec::new([Role::U])
}

fn record() -> Spec {
    Spec::new([Role::U, Role::F])
}

#[test]
fn usual_names_with_units_are_read_and_the_units_kept() {
    // `lugre cycles --input` on this file said "no column 'u'".
    let text = "Time [s],Displacement [um]\n0,1\n1,-1\n2,3\n";
    let t = table(text, &series(), opts()).unwrap();
    let time = t.t.as_ref().unwrap();
    assert_eq!(time.values, [0.0, 1.0, 2.0]);
    assert_eq!(time.info.unit.as_deref(), Some("s"));
    assert_eq!(time.info.name.as_deref(), Some("Time [s]"));
    let u = t.get(&Role::U).unwrap();
    assert_eq!(u.values, [1.0, -1.0, 3.0]);
    assert_eq!(u.info.unit.as_deref(), Some("um"));
    // `lugre dynamics --input` on this one said "no column 'F'".
    let text = "time [s]\tforce [N]\n0\t0\n10\t1.425\n";
    let t = table(text, &Spec::new([Role::F]).require_time(), opts()).unwrap();
    assert_eq!(t.get(&Role::F).unwrap().values, [0.0, 1.425]);
    assert_eq!(t.get(&Role::F).unwrap().info.unit.as_deref(), Some("N"));
    // Every usual name, any case, parentheses too.
    for (header, role) in [
        ("T", Role::T),
        ("TIME (s)", Role::T),
        ("x", Role::U),
        ("Position(mm)", Role::U),
        ("displacement", Role::U),
        ("V [m/s]", Role::V),
        ("velocity", Role::V),
        ("f", Role::F),
        ("Force [N]", Role::F),
        ("friction", Role::F),
        ("y", Role::F),
        ("n", Role::N),
        ("Normal [uN]", Role::N),
        ("normal force", Role::N),
        ("Load", Role::N),
    ] {
        let text = format!("other,{header}\n9,1\n9,2\n");
        let spec = if role == Role::T {
            Spec::new([]).require_time()
        } else {
            Spec::new([role.clone()])
        };
        assert_eq!(values(&text, &spec, role.clone()), [1.0, 2.0], "{header}");
    }
}

#[test]
fn columns_a_command_does_not_read_are_ignored() {
    // `simulate`/`loop --input` refused the t,u,F file `fit` reads.
    assert_eq!(
        values("t,u,F\n0,1,5\n1,2,6\n", &series(), Role::U),
        [1.0, 2.0]
    );
    // Text in a column nobody reads.
    let text = "Time [s];Position [mm];Note\n0;1;start\n1;2;\n";
    assert_eq!(values(text, &series(), Role::U), [1.0, 2.0]);
    // A column named by a name of its own (`lugre cycles --column strain`).
    let text = "t,strain [%],u\n0,0.5,9\n1,0.25,9\n";
    let strain = Spec::new([Role::of("Strain")]);
    let t = table(text, &strain, opts()).unwrap();
    assert_eq!(t.columns[0].values, [0.5, 0.25]);
    assert_eq!(t.columns[0].info.unit.as_deref(), Some("%"));
    // Optional columns: read where present.
    let spec = record().optional(Role::N);
    let t = table("u,F\n0,1\n", &spec, opts()).unwrap();
    assert_eq!(t.columns.len(), 2);
    let t = table("N,u,F\n5,0,1\n", &spec, opts()).unwrap();
    assert_eq!(t.get(&Role::N).unwrap().values, [5.0]);
}

/// What `lugre loop --csv`, `simulate --csv`, `dynamics --csv` and `fit --csv` write reads
/// back where it makes sense.
#[test]
fn files_written_by_the_commands_read_back() {
    let fit = record();
    // loop --csv: rho is the loop's parameter, not a time: u and y (= F) are read, no times.
    let t = table("rho,u,y\n0,0,0\n0.5,0.5,0.39\n1,1,0.63\n", &fit, opts()).unwrap();
    assert!(t.t.is_none());
    assert_eq!(t.get(&Role::F).unwrap().values, [0.0, 0.39, 0.63]);
    // simulate --csv.
    let t = table("t,u,z,dz,y\n0,0,0,1,0\n1,1,0.5,0.5,0.6\n", &fit, opts()).unwrap();
    assert_eq!(t.t.unwrap().values, [0.0, 1.0]);
    assert_eq!(t.columns[1].values, [0.0, 0.6]);
    // dynamics --csv: x is the displacement, friction the force (v and drive ignored).
    let text = "t,x,v,z,friction,drive\n0,0,0,0,0,0\n1,2,3,4,5,6\n";
    let t = table(text, &fit, opts()).unwrap();
    assert_eq!(t.columns[0].values, [0.0, 2.0]);
    assert_eq!(t.columns[1].values, [0.0, 5.0]);
    // fit --csv: fit and residual ignored.
    let text = "t,u,F,fit,residual\n0,0,1,1.1,-0.1\n1,1,2,2.1,-0.1\n";
    assert_eq!(values(text, &fit, Role::F), [1.0, 2.0]);
    // cycles reads u from any of them.
    assert_eq!(
        values("rho,u,y\n0,3,0\n1,4,1\n", &series(), Role::U),
        [3.0, 4.0]
    );
}

#[test]
fn a_role_twice_or_a_column_in_two_roles_is_refused() {
    let text = "t,u,F\n0,1,2\n1,2,3\n";
    let cases: [(&str, Result<ReadOptions, Error>, &str); 5] = [
        (
            // The two roles the options put on column 1 are named, not t found there too.
            text,
            opts().parse_columns("u=1,F=1"),
            "line 1: column 1 ('t') would be read as both u and F: give each its own column with --columns",
        ),
        (
            text,
            opts().parse_columns("u=1,u=2"),
            "--columns: u is given twice (u=1 and u=2)",
        ),
        (
            text,
            opts().parse_scale("u=2,u=3"),
            "--scale: u is given twice (u=2 and u=3)",
        ),
        (
            // F chosen as the column the header names u, which u is read from too.
            text,
            opts().parse_columns("F=u"),
            "line 1: column 2 ('u') would be read as both u and F: give each its own column with --columns",
        ),
        (
            "0,1,2\n",
            opts().parse_columns("u=2,F=2"),
            "line 1: column 2 would be read as both u and F: give each its own column with --columns",
        ),
    ];
    for (text, options, want) in cases {
        let got = match options {
            Err(e) => e.to_string(),
            Ok(o) => message(text, &record(), o),
        };
        assert_eq!(got, want);
    }
    // Columns u=1,F=1 of a header without t: both roles on column 1.
    let e = message(
        "u,F\n1,2\n",
        &record(),
        opts().parse_columns("u=1,F=1").unwrap(),
    );
    assert!(
        e.contains("column 1 ('u') would be read as both u and F"),
        "{e}"
    );
}

#[test]
fn a_header_with_two_columns_of_a_role_read_is_refused() {
    let e = message("u,u,F\n0,1,2\n", &record(), opts());
    assert_eq!(
        e,
        "line 1: the header has two columns for u: 'u' (column 1) and 'u' (column 2); say which with --columns u=NUMBER"
    );
    // Two names of one role are two columns of it.
    let e = message("x,Position [mm]\n0,1\n", &series(), opts());
    assert!(
        e.contains("two columns for u: 'x' (column 1) and 'Position [mm]' (column 2)"),
        "{e}"
    );
    let e = message("t,time,u\n0,0,1\n", &series(), opts());
    assert!(e.contains("two columns for t"), "{e}");
    // Said which: read.
    let o = opts().parse_columns("u=2").unwrap();
    assert_eq!(
        table("u,u,F\n0,1,2\n", &record(), o).unwrap().columns[0].values,
        [1.0]
    );
    // Two columns of a role not read do not matter.
    assert_eq!(values("u,F,F\n0,1,2\n", &series(), Role::U), [0.0]);
    // A name that names two columns cannot choose one.
    let e = message(
        "u,u,F\n0,1,2\n",
        &record(),
        opts().parse_columns("u=u").unwrap(),
    );
    assert!(
        e.contains("--columns u=u: the header 'u,u,F' has more than one column of that name"),
        "{e}"
    );
}

#[test]
fn line_numbers_are_the_editors() {
    for (text, want) in [
        ("t,u\n0,1\n1\n", "line 3: expected 2 values (t,u), found 1"),
        (
            "t,u\r\n0,1\r\n1\r\n",
            "line 3: expected 2 values (t,u), found 1",
        ),
        ("t,u\r0,1\r1\r", "line 3: expected 2 values (t,u), found 1"),
        (
            "t,u\r\n\r\n# c\r\n0,1\r\n1\r\n",
            "line 5: expected 2 values",
        ),
        (
            "\u{feff}t,u\r\n0,1\r\n0,2\r\n",
            "line 3: times must be strictly increasing",
        ),
        // Header errors name the header's line, after comments and blank lines.
        (
            "# rig 3\n# 2024-05-01\n\ntime,value\n0,1\n",
            "line 4: no column u",
        ),
        (
            "# c\r\n# d\r\nu,u\r\n0,1\r\n",
            "line 3: the header has two columns for u",
        ),
        (
            "# c\n1,2,3\n",
            "line 2: expected 1 column (u) or 2 columns (t,u), found 3",
        ),
    ] {
        let e = message(text, &series(), opts());
        assert!(e.starts_with(want), "{text:?}: {e} (wanted {want})");
    }
    // The error carries the line, the column and the value.
    match table(
        "# c\r\nt,Position [mm]\r\n0,1\r\n1,abc\r\n",
        &series(),
        opts(),
    ) {
        Err(Error::NotANumber {
            line,
            column,
            value,
        }) => assert_eq!(
            (line, column.as_str(), value.as_str()),
            (4, "Position [mm]", "'abc'")
        ),
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_delimiter_is_found_or_given() {
    let tab = "Time [s]\tPosition [mm]\tFriction [uN]\n0\t1.5\t-2\n0.5\t2.5\t-3\n";
    assert_eq!(values(tab, &record(), Role::F), [-2.0, -3.0]);
    let semi = "# a comment; with a semicolon\ntime(s);x;force\n0;1;2\n1;3;4\n";
    assert_eq!(values(semi, &record(), Role::F), [2.0, 4.0]);
    let spaces = "  t   u    F\n 0  1   2  \n\n1 3 4\n";
    assert_eq!(values(spaces, &record(), Role::U), [1.0, 3.0]);
    // Units in brackets stay with their names when spaces separate the fields.
    let spaced = "Time [s]  Position [mm]\n0 1\n1 2\n";
    let t = table(spaced, &series(), opts()).unwrap();
    assert_eq!(t.get(&Role::U).unwrap().info.unit.as_deref(), Some("mm"));
    // A one-column file with a unit: its name has a space, but no separator.
    assert_eq!(
        values("Displacement [um]\n1\n2\n", &series(), Role::U),
        [1.0, 2.0]
    );
    // Quoted fields.
    let quoted = "\"Time [s]\",\"Position, mm\"\n0,\"1\"\n";
    let o = opts().parse_columns("u=Position, mm");
    assert!(o.is_err(), "a comma splits --columns");
    let o = opts().parse_columns("u=2").unwrap();
    assert_eq!(
        table(quoted, &series(), o).unwrap().columns[0].values,
        [1.0]
    );
    // Given: overrides what the first line suggests; messages say how fields were split.
    let spaces = opts().with_delimiter(Delimiter::Spaces);
    let t = table("t u F\n0 1 2\n", &record(), spaces).unwrap();
    assert_eq!(t.columns[1].values, [2.0]);
    let e = message(
        "t\tu\tF\n0\t1\t2\n",
        &record(),
        opts().with_delimiter(Delimiter::Comma),
    );
    assert!(
        e.ends_with("(fields separated by commas); name it with --columns u=NAME"),
        "{e}"
    );
    let e = message("t\tu\tF\n0\t1\n", &record(), opts());
    assert_eq!(
        e,
        "line 2: expected 3 values (t,u,F), found 2 (fields separated by tabs)"
    );
}

#[test]
fn the_usual_shapes_of_a_file() {
    let s = values(
        "\u{feff}t,u\r\n# comment\r\n0, 0\r\n1,1\r\n\r\n2,0.5\r\n\n",
        &series(),
        Role::U,
    );
    assert_eq!(s, [0.0, 1.0, 0.5]);
    // No header: u, or t,u; u,F or t,u,F.
    let t = table("u\n1\n-2\n", &series(), opts()).unwrap();
    assert!(t.t.is_none());
    let t = table("0,1\n1,2\n", &series(), opts()).unwrap();
    assert_eq!(t.t.unwrap().values, [0.0, 1.0]);
    let t = table("0,1,2\n1,2,3\n", &record(), opts()).unwrap();
    assert_eq!(t.columns[1].values, [2.0, 3.0]);
    assert_eq!(values("7", &series(), Role::U), [7.0]);
    // Lines of separators only are blank; a first data row with an empty cell is data.
    assert_eq!(values(",,\nt,u\n,\n0,1\n", &series(), Role::U), [1.0]);
    let missing = record().allow_missing(Role::F);
    let t = table("0,1,\n1,2,3\n", &missing, opts()).unwrap();
    assert!(t.columns[1].values[0].is_nan());
    assert_eq!(t.columns[1].values[1], 3.0);
    // Columns in any order, any case.
    let t = table("F,t,U\n5,0,1\n6,1,2\n", &record(), opts()).unwrap();
    assert_eq!(t.columns[0].values, [1.0, 2.0]);
    assert_eq!(t.columns[1].values, [5.0, 6.0]);
    // Times required.
    let e = message("u\n1\n", &series().require_time(), opts());
    assert!(
        e.starts_with("line 1: no column t (t or time) in the header 'u'"),
        "{e}"
    );
    let e = message("1\n2\n", &series().require_time(), opts());
    assert!(
        e.starts_with("line 1: expected 2 columns (t,u), found 1"),
        "{e}"
    );
}

#[test]
fn columns_and_scale() {
    let lab = "Time [s]\tNormal [uN]\tPosition [mm]\tFriction [uN]\n0\t5e6\t1\t-2\n1\t5e6\t3\t-4\n";
    let o = opts()
        .parse_columns("t=Time,u=Position,F=4")
        .unwrap()
        .parse_scale("u=1e-3,F=-1e-6,t=2")
        .unwrap();
    let mut t = table(lab, &record(), o).unwrap();
    assert_eq!(t.take(&Role::T).unwrap(), [0.0, 2.0]);
    assert_eq!(t.take(&Role::U).unwrap(), [1e-3, 3e-3]);
    assert_eq!(t.take(&Role::F).unwrap(), [2e-6, 4e-6]);
    // Without --columns the header's names are enough (N is not read unless asked for).
    assert_eq!(values(lab, &record(), Role::U), [1.0, 3.0]);
    let normal = record().optional(Role::N).positive(Role::N);
    assert_eq!(values(lab, &normal, Role::N), [5e6, 5e6]);
    for (columns, want) in [
        ("u=9", "line 1: --columns u=9: the file has 4 columns (numbered from 1)"),
        (
            "u=Positon",
            "line 1: --columns u=Positon: no such column in the header 'Time [s],Normal [uN],Position [m...' (48 characters) (did you mean 'Position [mm]'?) (fields separated by tabs)",
        ),
        ("v=1", "--columns: unknown column role 'v' (this command reads t, u, F)"),
    ] {
        let o = opts().parse_columns(columns).unwrap();
        assert_eq!(message(lab, &record(), o), want);
    }
    let e = message(
        "0,1\n",
        &series(),
        opts().parse_columns("u=Position").unwrap(),
    );
    assert!(
        e.contains("--columns u=Position: the file has no header line"),
        "{e}"
    );
    let e = message("0,1,2\n", &record(), opts().parse_columns("u=2").unwrap());
    assert_eq!(
        e,
        "line 1: the file has no header line: give every column's number with --columns"
    );
    let o = opts().parse_columns("u=3,F=1").unwrap();
    let t = table("9,0,1\n9,1,2\n", &record(), o).unwrap();
    assert!(t.t.is_none());
    assert_eq!(t.columns[1].values, [9.0, 9.0]);
    // A value times its factor must stay finite.
    let o = opts().parse_scale("u=1e10").unwrap();
    let e = message("u\n1e300\n", &series(), o);
    assert_eq!(
        e,
        "line 2: u = 1e300 times the --scale factor 10000000000 is not a finite number"
    );
    // A positive role.
    let e = message(
        "u,F,N\n0,1,5\n0,1,-1\n",
        &record().optional(Role::N).positive(Role::N),
        opts(),
    );
    assert_eq!(e, "line 3: N must be > 0, got -1");
    // In Python, the options are keywords.
    let o = ReadOptions::new(Labels::PYTHON)
        .select(Role::U, Selector::Index(7))
        .unwrap();
    assert_eq!(
        message("0,1\n", &series(), o),
        "line 1: columns u=7: the file has 2 columns (numbered from 1)"
    );
}

#[test]
fn errors_name_the_line_the_column_and_the_value() {
    let cases: [(&str, Spec, &str); 16] = [
        (
            "t,u\n0,1\n1,2,3\n",
            series(),
            "line 3: expected 2 values (t,u), found 3",
        ),
        (
            "a,b\n0,1\n",
            series(),
            "line 1: no column u (u, x, position or displacement) in the header 'a,b'",
        ),
        (
            "t,u\n0,1\n0,2\n",
            series(),
            "line 3: times must be strictly increasing, t = 0 follows t = 0",
        ),
        (
            "t,u,F\n1e300,1,2\n1e299,1,2\n",
            record(),
            "line 3: times must be strictly increasing, t = 1e299 follows t = 1e300",
        ),
        (
            "t,u\n0,nan\n",
            series(),
            "line 2: u must be a finite number, got NaN",
        ),
        (
            "u,F\n0,-inf\n",
            record(),
            "line 2: F must be a finite number, got -inf",
        ),
        (
            "t,u\n0,abc\n",
            series(),
            "line 2: u = 'abc' is not a number",
        ),
        (
            "u\n0\n1 # peak\n",
            series(),
            "line 3: u = '1 # peak' is not a number",
        ),
        ("t,u\n0,\n", series(), "line 2: empty value for u"),
        ("t,u\n,0\n", series(), "line 2: empty value for t"),
        (
            "t,u\n0,\u{ff}\n",
            series(),
            "line 2: u = 'ÿ' is not a number",
        ),
        ("t,u\n", series(), "no data rows"),
        ("# only\n\n", series(), "no data rows"),
        ("\u{feff}", series(), "no data rows"),
        (
            "1,2,3,4\n",
            record(),
            "line 1: expected 2 columns (u,F) or 3 columns (t,u,F), found 4",
        ),
        (
            "t,u\n0,1\n",
            record(),
            "line 1: no column F (F, force, friction or y) in the header 't,u'",
        ),
    ];
    for (text, spec, want) in cases {
        let e = message(text, &spec, opts());
        assert!(e.starts_with(want), "{text:?}: {e} (wanted {want})");
    }
    let bytes = |b: &'static [u8], spec: &Spec| read(b, spec, opts()).unwrap_err().to_string();
    assert_eq!(
        bytes(b"t,u\n0,\xff\n", &series()),
        "line 2: not valid UTF-8 text"
    );
    assert_eq!(
        bytes(b"t,\xb5\n0,0\n", &series()),
        "line 1: not valid UTF-8 text"
    );
    // A cell or a header a megabyte long is shown in a few dozen characters.
    let garbage = "x".repeat(100_000);
    let e = message(&format!("u,F\n{garbage},0\n"), &record(), opts());
    assert!(
        e.starts_with("line 2: u = 'xxxxxxxx") && e.len() < 100,
        "{e}"
    );
    let e = message(&format!("u,{garbage}\n0,0\n"), &record(), opts());
    assert!(e.starts_with("line 1: no column F") && e.len() < 200, "{e}");
    // A column asked for by a name of its own, with the closest name.
    let e = message(
        "Time [s]\tPosition [mm]\n0\t1\n",
        &Spec::new([Role::of("Positon")]),
        opts(),
    );
    assert_eq!(e, "line 1: no column 'Positon' in the header 'Time [s],Position [mm]' (fields separated by tabs); did you mean 'Position [mm]'?");
    let e = message("1,2\n", &Spec::new([Role::of("strain")]), opts());
    assert_eq!(e, "line 1: no header line, so no column 'strain' (a file without a header has the columns u or t,u)");
}

#[test]
fn line_length_is_bounded() {
    // As /dev/zero would be, without reading it all into one line.
    let zeros = std::io::Read::take(std::io::repeat(0), 64 * MAX_LINE as u64);
    let e = read(zeros, &series(), opts()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 1: a line is longer than 1048576 bytes (not a CSV file of numbers?)"
    );
    let mut text = vec![b' '; MAX_LINE - 10];
    text.extend_from_slice(b"1\n2\n");
    assert_eq!(
        read(&text[..], &series(), opts()).unwrap().columns[0].values,
        [1.0, 2.0]
    );
    // Lines ended by CR alone are lines: a long file of them is read.
    let text = "0.5\r".repeat(MAX_LINE);
    assert_eq!(
        read(text.as_bytes(), &series(), opts()).unwrap().columns[0]
            .values
            .len(),
        MAX_LINE
    );
}

/// Rows are streamed: a history is read in constant memory, row by row.
#[test]
fn rows_are_streamed() {
    /// A file of `rows` rows `t,u` made as it is read, never held whole.
    struct Generated {
        row: u64,
        rows: u64,
        pending: Vec<u8>,
    }
    impl std::io::Read for Generated {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            if self.pending.is_empty() {
                if self.row == self.rows {
                    return Ok(0);
                }
                self.pending = if self.row == 0 {
                    b"Time [s],Position [mm]\r\n".to_vec()
                } else {
                    format!("{},{}\r\n", self.row, self.row % 7).into_bytes()
                };
                self.row += 1;
            }
            let n = buf.len().min(self.pending.len());
            buf[..n].copy_from_slice(&self.pending[..n]);
            self.pending.drain(..n);
            Ok(n)
        }
    }
    let rows = 200_000;
    let source = Generated {
        row: 0,
        rows,
        pending: Vec::new(),
    };
    let mut r = Reader::new(source, opts())
        .unwrap()
        .rows(&series())
        .unwrap();
    assert_eq!(r.time().unwrap().unit.as_deref(), Some("s"));
    assert_eq!(r.columns()[0].unit.as_deref(), Some("mm"));
    let (mut n, mut sum) = (0u64, 0.0);
    while let Some(row) = r.next_row().unwrap() {
        n += 1;
        sum += row.values[0];
        assert_eq!(row.t, Some(n as f64));
    }
    assert_eq!(n, rows - 1);
    assert_eq!(sum, (1..rows).map(|k| (k % 7) as f64).sum::<f64>());
    assert_eq!(r.line(), rows);
}

#[test]
fn the_header_is_known_before_the_columns_are_chosen() {
    // `fit` and `simulate` read a velocity record when the header has v and no u.
    let r = Reader::new("t,velocity [m/s],F\n0,1,2\n".as_bytes(), opts()).unwrap();
    assert!(r.header_has(&Role::V) && !r.header_has(&Role::U));
    assert_eq!(r.motion(), Role::V);
    assert_eq!(r.delimiter(), Delimiter::Comma);
    let mut t = r
        .rows(&Spec::new([Role::V, Role::F]))
        .unwrap()
        .collect_table()
        .unwrap();
    assert_eq!(t.take(&Role::V), Some(vec![1.0]));
    let r = Reader::new("0,1\n".as_bytes(), opts()).unwrap();
    assert!(r.header().is_none());
    assert_eq!(r.motion(), Role::U);
    // A displacement beside the velocity is the motion (`lugre dynamics --csv` writes both).
    let r = Reader::new("t,x,v\n0,1,2\n".as_bytes(), opts()).unwrap();
    assert_eq!(r.motion(), Role::U);
    // Chosen: `v` by --columns, or `u` by --columns over a header's `v`.
    for (columns, header, motion) in [("v=x", "t,x,v", Role::V), ("u=3", "t,v,pos", Role::U)] {
        let o = opts().parse_columns(columns).unwrap();
        let text = format!("{header}\n0,1,2\n");
        assert_eq!(Reader::new(text.as_bytes(), o).unwrap().motion(), motion);
    }
}
