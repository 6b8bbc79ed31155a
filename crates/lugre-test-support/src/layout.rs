//! The module graph of a crate, read from its source: which top-level modules each top-level
//! module imports (`crate::m::...`, `use crate::{m, ...}`, and names the crate root re-exports
//! from `m`), with comments and test modules (from the first `#[cfg(test)]` of a file, and
//! files named `tests.rs`) left out. The layout tests state the crate's dependency rules over this graph.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Top-level module -> the top-level modules it imports (itself excluded).
pub type Graph = BTreeMap<String, BTreeSet<String>>;

/// The graph of the crate whose `src` directory is `src` (`lib.rs`/`main.rs` are the root:
/// their own imports are not edges).
pub fn module_graph(src: &Path) -> Graph {
    let mut files = Vec::new();
    collect(src, &mut files);
    let root = ["lib.rs", "main.rs"]
        .iter()
        .map(|f| src.join(f))
        .filter(|p| p.exists())
        .map(|p| code(&std::fs::read_to_string(p).unwrap_or_default()))
        .collect::<Vec<_>>()
        .join("\n");
    let exports = root_exports(&root);
    let mut graph = Graph::new();
    for path in files {
        let rel = path.strip_prefix(src).expect("under src");
        let first = rel.components().next().expect("a file");
        let top = first
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if top == "lib" || top == "main" {
            continue;
        }
        let text = code(&std::fs::read_to_string(&path).unwrap_or_default());
        let entry = graph.entry(top.clone()).or_default();
        for name in crate_paths(&text) {
            let module = exports.get(&name).cloned().unwrap_or(name);
            if module != top {
                entry.insert(module);
            }
        }
    }
    let modules: BTreeSet<String> = graph.keys().cloned().collect();
    for deps in graph.values_mut() {
        deps.retain(|d| modules.contains(d));
    }
    graph
}

/// The graph of the submodules of `src/<dir>` (each file or folder directly under it is a node):
/// which of its siblings each imports, through `crate::<dir>::name` or, from inside, `super::`
/// paths that lead to `<dir>` (`super::name` in `src/<dir>/a.rs`, `super::super::name` in
/// `src/<dir>/a/b.rs`). The `mod.rs` of `<dir>` is left out (it declares them all).
pub fn submodule_graph(src: &Path, dir: &str) -> Graph {
    let base = src.join(dir);
    let mut files = Vec::new();
    collect(&base, &mut files);
    let mut graph = Graph::new();
    for path in files {
        let rel = path.strip_prefix(&base).expect("under the folder");
        let depth = rel.components().count();
        let node = rel
            .components()
            .next()
            .expect("a file")
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if node == "mod" {
            continue;
        }
        let text = code(&std::fs::read_to_string(&path).unwrap_or_default());
        let up = "super::".repeat(depth - usize::from(rel.ends_with("mod.rs")));
        let mut names = BTreeSet::new();
        for prefix in [format!("crate::{dir}::"), up] {
            let mut rest = text.as_str();
            while let Some(i) = rest.find(&prefix) {
                let before = rest[..i].chars().last();
                rest = &rest[i + prefix.len()..];
                // `super::super::x` also contains `super::x`: only whole prefixes count.
                if before.is_some_and(|c| c == ':' || c.is_alphanumeric() || c == '_') {
                    continue;
                }
                if let Some(group) = rest.strip_prefix('{') {
                    let end = matching_brace(group);
                    names.extend(
                        split_top_level(&group[..end])
                            .iter()
                            .filter_map(|item| ident(item.trim())),
                    );
                } else if let Some(name) = ident(rest) {
                    names.insert(name);
                }
            }
        }
        names.remove(&node);
        graph.entry(node).or_default().extend(names);
    }
    let nodes: BTreeSet<String> = graph.keys().cloned().collect();
    for deps in graph.values_mut() {
        deps.retain(|d| nodes.contains(d));
    }
    graph
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

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .map(|d| d.filter_map(Result::ok).map(|e| e.path()).collect())
        .unwrap_or_default();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            collect(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs")
            && p.file_name().is_some_and(|f| f != "tests.rs")
        {
            out.push(p);
        }
    }
}

/// The code of a file: comments removed, cut at its first `#[cfg(test)]`.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines()
        .map(|l| match l.find("//") {
            Some(i) => &l[..i],
            None => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The first segment of every `crate::` path, including each item of `use crate::{...}`.
fn crate_paths(code: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        rest = &rest[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = matching_brace(group);
            for item in split_top_level(&group[..end]) {
                if let Some(name) = ident(item.trim()) {
                    out.insert(name);
                }
            }
        } else if let Some(name) = ident(rest) {
            out.insert(name);
        }
    }
    out
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
    let id: String = s
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    (!id.is_empty()).then_some(id)
}

fn matching_brace(s: &str) -> usize {
    let mut depth = 1;
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return i;
                }
            }
            _ => {}
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
