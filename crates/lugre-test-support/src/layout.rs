//! The module graph of a crate, read from its source: which top-level modules each top-level
//! module imports, for the layout tests to state the crate's dependency rules over.
//!
//! Every file is read whole, with comments and string and character literals left out, and
//! without its test code: a `#[cfg(test)] mod NAME { ... }` block (braces matched), and the
//! file (with the folder below it) of a `#[cfg(test)] mod NAME;` declaration. Anything else
//! under `#[cfg(test)]` (a helper function, say) is code like the rest, and so are the lines
//! after it.
//!
//! An import is any path that starts at `crate::`, `super::` or `self::` (a `use` with its
//! `{...}` groups, or a path in an expression), resolved to the module it names from the module
//! it stands in: `super::super::loops::X` in `src/dynamics/request.rs` names `loops`, and so
//! does `super::loops::X` inside a `mod inner { ... }` of `src/dynamics.rs`. A name the crate
//! root re-exports (`pub use m::{A, B}` in `lib.rs` or `main.rs`) counts as its module `m`.
//! Paths that start elsewhere are other crates or the module's own children.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Top-level module -> the top-level modules it imports (itself excluded).
pub type Graph = BTreeMap<String, BTreeSet<String>>;

/// The graph of the crate whose `src` directory is `src` (`lib.rs`/`main.rs` are the root:
/// their own imports are not edges).
pub fn module_graph(src: &Path) -> Graph {
    graph_of(&read_crate(src))
}

/// The graph of the submodules of `src/<dir>` (each file or folder directly under it is a node):
/// which of its siblings each imports, through any path that resolves to `<dir>::name`
/// (`crate::<dir>::name`, `super::name` in `src/<dir>/a.rs`, `super::super::name` in
/// `src/<dir>/a/b.rs`). The `mod.rs` of `<dir>` is left out (it declares them all).
pub fn submodule_graph(src: &Path, dir: &str) -> Graph {
    submodule_graph_of(&read_crate(src), dir)
}

/// The modules that import each other in a circle (strongly connected components of more
/// than one module, or a module importing itself), each sorted.
pub fn cycles(graph: &Graph) -> Vec<Vec<String>> {
    // Reachability closure: fine for a few dozen modules.
    let reach = |from: &String| {
        let mut seen = BTreeSet::new();
        let mut stack: Vec<&String> = graph[from].iter().collect();
        while let Some(m) = stack.pop() {
            if seen.insert(m.clone()) {
                stack.extend(graph.get(m).into_iter().flatten());
            }
        }
        seen
    };
    let reaches: BTreeMap<&String, BTreeSet<String>> =
        graph.keys().map(|m| (m, reach(m))).collect();
    let mut out: Vec<Vec<String>> = Vec::new();
    for (m, r) in &reaches {
        let comp: Vec<String> = reaches
            .iter()
            .filter(|(n, rn)| r.contains(**n) && rn.contains(*m))
            .map(|(n, _)| (*n).clone())
            .collect();
        if comp.len() > 1 && !out.contains(&comp) {
            out.push(comp);
        }
    }
    out
}

/// A module path, from the crate root: `["dynamics", "request"]`; `[]` is the root.
type ModPath = Vec<String>;

/// A file of the crate without its test code: the module it is, its code, and the paths it
/// imports, resolved from the crate root.
struct File {
    module: ModPath,
    code: String,
    imports: BTreeSet<ModPath>,
}

/// Every `.rs` file under `src` with its module path, the test files left out.
fn read_crate(src: &Path) -> Vec<File> {
    let mut paths = Vec::new();
    collect(src, &mut paths);
    let sources = paths
        .iter()
        .map(|p| {
            let rel = p.strip_prefix(src).expect("under src");
            let text = std::fs::read_to_string(p).unwrap_or_default();
            (module_path(rel), text)
        })
        .collect();
    without_tests(sources)
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .map(|d| d.filter_map(Result::ok).map(|e| e.path()).collect())
        .unwrap_or_default();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            collect(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// `dynamics/request.rs` -> `[dynamics, request]`; `dynamics/mod.rs`, `dynamics.rs` ->
/// `[dynamics]`; `lib.rs`, `main.rs` -> `[]`.
fn module_path(rel: &Path) -> ModPath {
    let mut parts: ModPath = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().to_string())
        .collect();
    let last = parts.pop().unwrap_or_default();
    let stem = last.trim_end_matches(".rs");
    let is_root = parts.is_empty() && (stem == "lib" || stem == "main");
    if stem != "mod" && !is_root {
        parts.push(stem.to_string());
    }
    parts
}

/// The files of `sources` (module path, text) outside every test module, each with its test
/// blocks blanked and its imports resolved.
fn without_tests(sources: Vec<(ModPath, String)>) -> Vec<File> {
    let mut test_modules = BTreeSet::new();
    let mut files = Vec::new();
    for (module, text) in sources {
        let (code, declared) = strip_tests(&code_only(&text));
        let scopes = inline_modules(&code);
        for (at, name) in declared {
            let mut path = scope_at(&module, &scopes, at);
            path.push(name);
            test_modules.insert(path);
        }
        files.push((module, code, scopes));
    }
    files
        .into_iter()
        .filter(|(m, _, _)| !test_modules.iter().any(|t| m.starts_with(t)))
        .map(|(module, code, scopes)| {
            let imports = imports(&code, &module, &scopes);
            File {
                module,
                code,
                imports,
            }
        })
        .collect()
}

fn graph_of(files: &[File]) -> Graph {
    let root: String = files
        .iter()
        .filter(|f| f.module.is_empty())
        .map(|f| f.code.as_str())
        .collect::<Vec<_>>()
        .join("\n");
    let exports = root_exports(&root);
    let mut graph = Graph::new();
    for f in files.iter().filter(|f| !f.module.is_empty()) {
        let top = &f.module[0];
        let entry = graph.entry(top.clone()).or_default();
        for path in f.imports.iter().filter(|p| !p.is_empty()) {
            let module = exports.get(&path[0]).unwrap_or(&path[0]);
            if module != top {
                entry.insert(module.clone());
            }
        }
    }
    retain_nodes(graph)
}

fn submodule_graph_of(files: &[File], dir: &str) -> Graph {
    let mut graph = Graph::new();
    for f in files
        .iter()
        .filter(|f| f.module.len() > 1 && f.module[0] == dir)
    {
        let node = &f.module[1];
        let names = f
            .imports
            .iter()
            .filter(|p| p.len() > 1 && p[0] == dir && &p[1] != node)
            .map(|p| p[1].clone());
        graph.entry(node.clone()).or_default().extend(names);
    }
    retain_nodes(graph)
}

/// Drops the edges to names that are not nodes (items, other crates' modules).
fn retain_nodes(mut graph: Graph) -> Graph {
    let nodes: BTreeSet<String> = graph.keys().cloned().collect();
    for deps in graph.values_mut() {
        deps.retain(|d| nodes.contains(d));
    }
    graph
}

/// The code of a file with comments, string literals (kept as `""`) and character literals
/// (kept as `' '`) taken out, so that neither a `"crate::x"` nor a `'{'` is read as code.
fn code_only(text: &str) -> String {
    let s: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < s.len() {
        let (next, literal_end) = (s.get(i + 1).copied(), literal_end(&s, i));
        i = match (s[i], next, literal_end) {
            ('/', Some('/'), _) => (i..s.len()).find(|&j| s[j] == '\n').unwrap_or(s.len()),
            ('/', Some('*'), _) => {
                out.push(' ');
                block_comment_end(&s, i)
            }
            ('\'', _, Some(end)) => {
                out.push_str("' '");
                end
            }
            (_, _, Some(end)) => {
                out.push_str("\"\"");
                end
            }
            (c, _, None) => {
                out.push(c);
                i + 1
            }
        };
    }
    out
}

/// The index just past the string or character literal that starts at `i`, if one does
/// (`"..."`, `r#"..."#`, `'x'`; not a lifetime `'a` nor a raw identifier `r#type`).
fn literal_end(s: &[char], i: usize) -> Option<usize> {
    match (s[i], s.get(i + 1)) {
        ('"', _) => Some(string_end(s, i + 1)),
        ('r', Some('"' | '#')) if starts_literal(s, i) => raw_string_end(s, i),
        ('\'', _) => char_literal_end(s, i),
        _ => None,
    }
}

/// An `r` at `i` starts a raw string (`r"`, `r#"`, `br"`) only if it does not end an
/// identifier.
fn starts_literal(s: &[char], i: usize) -> bool {
    let before = |k: usize| k.checked_sub(1).map(|k| s[k]);
    match before(i) {
        Some('b') => !before(i - 1).is_some_and(is_ident_char),
        Some(c) => !is_ident_char(c),
        None => true,
    }
}

/// The index just past the `*/` that closes the (nestable) block comment opened at `i`.
fn block_comment_end(s: &[char], i: usize) -> usize {
    let (mut depth, mut j) = (0, i);
    while j + 1 < s.len() {
        match (s[j], s[j + 1]) {
            ('/', '*') => (depth, j) = (depth + 1, j + 2),
            ('*', '/') => {
                (depth, j) = (depth - 1, j + 2);
                if depth == 0 {
                    return j;
                }
            }
            _ => j += 1,
        }
    }
    s.len()
}

/// The index just past the `"` that closes a string whose contents start at `i`.
fn string_end(s: &[char], mut i: usize) -> usize {
    while i < s.len() {
        match s[i] {
            '\\' => i += 2,
            '"' => return i + 1,
            _ => i += 1,
        }
    }
    s.len()
}

/// The index just past the raw string `r#..#"...."#..#` at `i`, or `None` for a raw
/// identifier (`r#type`).
fn raw_string_end(s: &[char], i: usize) -> Option<usize> {
    let hashes = s[i + 1..].iter().take_while(|&&c| c == '#').count();
    let open = i + 1 + hashes;
    if s.get(open) != Some(&'"') {
        return None;
    }
    let close = (open + 1..s.len())
        .find(|&j| s[j] == '"' && (1..=hashes).all(|k| s.get(j + k) == Some(&'#')));
    Some(close.map_or(s.len(), |j| j + 1 + hashes))
}

/// The index just past the character literal at `i` (`'x'`, `'\n'`, `'\u{7f}'`), or `None`
/// for a lifetime or label (`'a`).
fn char_literal_end(s: &[char], i: usize) -> Option<usize> {
    match (s.get(i + 1), s.get(i + 2)) {
        (Some('\\'), _) => (i + 3..s.len()).find(|&j| s[j] == '\'').map(|j| j + 1),
        (Some(_), Some('\'')) => Some(i + 3),
        _ => None,
    }
}

fn is_ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// `code` with every `#[cfg(test)] mod NAME { ... }` blanked (same length, so positions
/// hold), and the positions and names of the `#[cfg(test)] mod NAME;` declarations.
fn strip_tests(code: &str) -> (String, Vec<(usize, String)>) {
    const ATTR: &str = "#[cfg(test)]";
    let mut out = code.to_string();
    let mut declared = Vec::new();
    let mut from = 0;
    while let Some(k) = out[from..].find(ATTR) {
        let at = from + k;
        from = at + ATTR.len();
        let Some((name, after)) = test_module(&out[from..]) else {
            continue;
        };
        let rest = &out[from + after..];
        if rest.starts_with(';') {
            declared.push((at, name));
        } else if let Some(body) = rest.strip_prefix('{') {
            // An unclosed block runs to the end of the file.
            let end = (from + after + 1 + matching_brace(body) + 1).min(out.len());
            out.replace_range(at..end, &" ".repeat(end - at));
            from = end;
        }
    }
    (out, declared)
}

/// After a `#[cfg(test)]`: the name of the module it marks and the offset of what follows the
/// name (`;` or `{`), skipping other attributes and a visibility; `None` if it marks no module.
fn test_module(s: &str) -> Option<(String, usize)> {
    let mut i = skip_ws(s, 0);
    while s[i..].starts_with("#[") {
        i = skip_ws(s, i + 2 + matching(&s[i + 2..], '[', ']') + 1);
    }
    if s[i..].starts_with("pub") && !s[i + 3..].starts_with(is_ident_char) {
        i = skip_ws(s, i + 3);
        if s[i..].starts_with('(') {
            i = skip_ws(s, i + s[i..].find(')')? + 1);
        }
    }
    let start = skip_ws(s, i + 3);
    if !s[i..].starts_with("mod") || start == i + 3 {
        return None;
    }
    let name = ident(&s[start..])?;
    let after = skip_ws(s, start + name.len());
    Some((name, after))
}

fn skip_ws(s: &str, i: usize) -> usize {
    let i = i.min(s.len());
    i + (s[i..].len() - s[i..].trim_start().len())
}

/// An inline module of a file: the byte range of its body and its name.
type Scope = (std::ops::Range<usize>, String);

/// The inline `mod NAME { ... }` blocks of `code` (test blocks already blanked).
fn inline_modules(code: &str) -> Vec<Scope> {
    let mut out = Vec::new();
    for (at, _) in code.match_indices("mod") {
        let before = code[..at].chars().last();
        if before.is_some_and(|c| is_ident_char(c) || c == ':') {
            continue;
        }
        let start = skip_ws(code, at + 3);
        let Some(name) = ident(&code[start..]).filter(|_| start > at + 3) else {
            continue;
        };
        let open = skip_ws(code, start + name.len());
        if let Some(body) = code[open..].strip_prefix('{') {
            let end = open + 1 + matching_brace(body);
            out.push((open + 1..end, name));
        }
    }
    out
}

/// The module that position `at` of a file of module `file` stands in.
fn scope_at(file: &[String], scopes: &[Scope], at: usize) -> ModPath {
    let mut path = file.to_vec();
    // Outer blocks start first: `inline_modules` lists them in order of their `mod`.
    path.extend(
        scopes
            .iter()
            .filter(|(r, _)| r.contains(&at))
            .map(|(_, n)| n.clone()),
    );
    path
}

/// Every path in `code` that starts at `crate`, `super` or `self` (`$crate` in a macro too),
/// each item of a `{...}` group a path of its own, resolved from the module it stands in.
fn imports(code: &str, file: &[String], scopes: &[Scope]) -> BTreeSet<ModPath> {
    let mut out = BTreeSet::new();
    let mut i = 0;
    while i < code.len() {
        let Some(start) = next_path_start(code, i) else {
            break;
        };
        let (paths, end) = use_tree(code, start);
        let here = scope_at(file, scopes, start);
        out.extend(paths.iter().filter_map(|p| resolve(&here, p)));
        i = end.max(start + 1);
    }
    out
}

/// The position of the next `crate::`, `super::` or `self::` at or after `from` that starts a
/// path (not the tail of `a::super::`, nor of an identifier such as `myself::`).
fn next_path_start(code: &str, from: usize) -> Option<usize> {
    let mut best: Option<usize> = None;
    for key in ["crate::", "super::", "self::"] {
        let mut k = from;
        while let Some(j) = code[k..].find(key) {
            let at = k + j;
            let before = code[..at].chars().last();
            if !before.is_some_and(|c| is_ident_char(c) || c == ':') {
                best = Some(best.map_or(at, |b| b.min(at)));
                break;
            }
            k = at + key.len();
        }
    }
    best
}

/// The paths of the use tree (or expression path) at `i`, segment by segment, and the position
/// just past it: `a::{b, c::{d, e}}` gives `a::b`, `a::c::d`, `a::c::e`; a glob ends the
/// path.
fn use_tree(code: &str, i: usize) -> (Vec<ModPath>, usize) {
    let mut prefix = ModPath::new();
    let mut i = skip_ws(code, i);
    loop {
        let Some(seg) = ident(&code[i..]) else {
            let end = if code[i..].starts_with('*') { i + 1 } else { i };
            return (vec![prefix], end);
        };
        i += seg.len();
        prefix.push(seg);
        let Some(rest) = code[i..].strip_prefix("::") else {
            return (vec![prefix], i);
        };
        i = code.len() - rest.len();
        if let Some(group) = rest.strip_prefix('{') {
            let end = matching_brace(group);
            let mut paths = Vec::new();
            let mut offset = i + 1;
            for item in split_top_level(&group[..end]) {
                let (sub, _) = use_tree(code, offset);
                offset += item.len() + 1;
                paths.extend(sub.into_iter().map(|s| [prefix.clone(), s].concat()));
            }
            return (paths, i + 1 + end + 1);
        }
    }
}

/// The absolute path that `path`, written in module `here`, names: `crate` is the root,
/// `super` the parent, `self` the module itself; `None` past the root.
fn resolve(here: &[String], path: &[String]) -> Option<ModPath> {
    let mut out = match path.first().map(String::as_str) {
        Some("crate") => ModPath::new(),
        _ => here.to_vec(),
    };
    for seg in path {
        match seg.as_str() {
            "crate" | "self" => {}
            "super" => {
                out.pop()?;
            }
            _ => out.push(seg.clone()),
        }
    }
    Some(out)
}

/// Names the root re-exports (`pub use m::{A, B}` / `pub use m::A`) -> `m`.
fn root_exports(root: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    for stmt in root.split(';') {
        let Some(i) = stmt.find("pub use ") else {
            continue;
        };
        let path = stmt[i + "pub use ".len()..].trim();
        let path = path.strip_prefix("crate::").unwrap_or(path);
        let Some(module) = ident(path) else { continue };
        let tail = &path[module.len()..];
        let names: Vec<String> = match tail.find('{') {
            Some(b) => split_top_level(&tail[b + 1..tail.rfind('}').unwrap_or(tail.len())])
                .iter()
                .filter_map(|s| s.trim().rsplit("::").next().and_then(ident))
                .collect(),
            None => tail
                .rsplit("::")
                .next()
                .and_then(ident)
                .into_iter()
                .collect(),
        };
        for n in names {
            out.insert(n, module.clone());
        }
    }
    out
}

fn ident(s: &str) -> Option<String> {
    let id: String = s.chars().take_while(|&c| is_ident_char(c)).collect();
    (!id.is_empty() && !id.starts_with(|c: char| c.is_ascii_digit())).then_some(id)
}

/// The index in `s` of the `}` that closes a `{` just before `s` (`s.len()` if none does).
fn matching_brace(s: &str) -> usize {
    matching(s, '{', '}')
}

/// The index of the `close` that closes an `open` just before `s` (`s.len()` if none does).
fn matching(s: &str, open: char, close: char) -> usize {
    let mut depth = 1;
    for (i, c) in s.char_indices() {
        if c == open {
            depth += 1;
        } else if c == close {
            depth -= 1;
            if depth == 0 {
                return i;
            }
        }
    }
    s.len()
}

fn split_top_level(s: &str) -> Vec<&str> {
    let (mut out, mut depth, mut start) = (Vec::new(), 0, 0);
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&s[start..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A crate of in-memory files (path under `src`, text).
    fn crate_of(files: &[(&str, &str)]) -> Vec<File> {
        let sources = files
            .iter()
            .map(|(p, t)| (module_path(Path::new(p)), t.to_string()))
            .collect();
        without_tests(sources)
    }

    fn deps(g: &Graph, m: &str) -> Vec<String> {
        g[m].iter().cloned().collect()
    }

    /// Three leaf modules to import.
    const LEAVES: [(&str, &str); 3] = [("b.rs", ""), ("c.rs", ""), ("d.rs", "")];

    fn graph_with(a: &str) -> Graph {
        let mut files = vec![("lib.rs", "mod a; mod b; mod c; mod d;"), ("a.rs", a)];
        files.extend(LEAVES);
        graph_of(&crate_of(&files))
    }

    #[test]
    fn a_use_after_a_test_function_counts() {
        let g = graph_with("#[cfg(test)]\nfn helper() {}\nuse crate::b::X;\n");
        assert_eq!(deps(&g, "a"), ["b"]);
    }

    #[test]
    fn only_the_test_module_block_is_skipped() {
        let a = r#"use crate::b::X;
#[cfg(test)]
mod tests {
    use crate::c::Y;
    fn f(x: bool) {
        if x { let _ = ("{", '{', '\''); } else { crate::c::g(); }
    }
    mod deeper { use crate::c::Z; }
}
fn after() { crate::d::h() }
"#;
        assert_eq!(deps(&graph_with(a), "a"), ["b", "d"]);
    }

    #[test]
    fn a_declared_test_module_file_is_test_code() {
        let files = [
            ("lib.rs", "mod a; mod b; mod c; mod d;"),
            (
                "a/mod.rs",
                "#[cfg(test)]\n#[allow(dead_code)]\npub(crate) mod checks;\nmod inner;",
            ),
            ("a/checks.rs", "use crate::b::X;"),
            ("a/checks/more.rs", "use crate::c::X;"),
            ("a/inner.rs", "use crate::d::X;"),
            ("b.rs", ""),
            ("c.rs", ""),
            ("d.rs", ""),
        ];
        assert_eq!(deps(&graph_of(&crate_of(&files)), "a"), ["d"]);
    }

    #[test]
    fn super_from_a_nested_file_names_the_module_it_reaches() {
        let files = [
            ("lib.rs", "mod dynamics; mod loops;"),
            ("dynamics/mod.rs", "mod request;"),
            ("dynamics/request.rs", "use super::super::loops::X;"),
            ("loops/mod.rs", ""),
        ];
        let g = graph_of(&crate_of(&files));
        assert_eq!(deps(&g, "dynamics"), ["loops"]);
        assert!(g["loops"].is_empty());
    }

    #[test]
    fn paths_resolve_from_the_module_they_stand_in() {
        let code = code_only(
            "use self::x::Y;\nuse super::{z, super::c::{self, W}};\n\
             mod inner { fn f() { super::super::d::e(); } }\nfn g() { crate::k::<u8>(); }",
        );
        let here = ["a".to_string(), "b".to_string()];
        let got = imports(&code, &here, &inline_modules(&code));
        let want: BTreeSet<ModPath> = ["a/b/x/Y", "a/z", "c", "c/W", "a/d/e", "k"]
            .iter()
            .map(|p| p.split('/').map(String::from).collect())
            .collect();
        assert_eq!(got, want);
    }

    #[test]
    fn comments_and_literals_are_not_code() {
        let a = "// use crate::b::X;\n/* crate::c /* nested */ crate::c */\n\
                 const S: &str = \"crate::c::Y\"; const R: &str = r#\"crate::\"c\"#;\n\
                 fn f<'a>(x: &'a str) -> char { let _ = x; crate::d::g() }";
        assert_eq!(deps(&graph_with(a), "a"), ["d"]);
    }

    #[test]
    fn a_root_re_export_counts_as_its_module() {
        let files = [
            ("lib.rs", "mod a; mod error; pub use error::{Error, Kind};"),
            ("a.rs", "fn f() -> crate::Error { todo!() }"),
            ("error.rs", ""),
        ];
        assert_eq!(deps(&graph_of(&crate_of(&files)), "a"), ["error"]);
    }

    #[test]
    fn siblings_are_found_through_super_and_crate_paths() {
        let files = [
            ("lib.rs", "mod commands;"),
            ("commands/mod.rs", "mod fit; mod loops; mod paper;"),
            ("commands/fit.rs", "use super::loops::X;"),
            ("commands/paper/mod.rs", "mod page;"),
            (
                "commands/paper/page.rs",
                "use super::super::fit::Y; use crate::commands::loops;",
            ),
            (
                "commands/loops.rs",
                "#[cfg(test)]\nmod tests { use super::super::fit; }",
            ),
        ];
        let g = submodule_graph_of(&crate_of(&files), "commands");
        assert_eq!(deps(&g, "fit"), ["loops"]);
        assert_eq!(deps(&g, "paper"), ["fit", "loops"]);
        assert!(g["loops"].is_empty());
    }
}
