//! A crate's files and the imports between them, read from the source text (no compiler): see
//! `tests/architecture.rs` for what counts as an import.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// One import: the file that imports, the file that defines what it imports, and the path as
/// written (for messages).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Edge {
    pub from: String,
    pub to: String,
    pub via: String,
}

/// What one file says: the module path it is, the items it defines, the names it re-exports, its
/// child modules, and every path it names (absolute, from the crate root).
#[derive(Clone, Debug, Default)]
struct File {
    module: Vec<String>,
    defines: BTreeSet<String>,
    /// `pub use a::b as c`: c → [a, b] (absolute).
    reexports: BTreeMap<String, Vec<String>>,
    /// `pub use a::*`: [a] (absolute).
    globs: Vec<Vec<String>>,
    /// Every path named (absolute), with the text it was written as.
    paths: Vec<(Vec<String>, String)>,
}

pub struct Crate {
    files: BTreeMap<String, File>,
    /// Module path → file.
    modules: BTreeMap<Vec<String>, String>,
}

impl Crate {
    /// Every `.rs` file under `root` but those under the folders `skip`; `root/lib.rs` or
    /// `root/main.rs` is the crate root.
    pub fn read(root: &Path, skip: &[&str]) -> Crate {
        let mut sources = Vec::new();
        walk(root, root, skip, &mut sources);
        Crate::from_sources(sources)
    }

    /// A crate from (path relative to its root, text) pairs.
    pub fn from_sources(sources: Vec<(String, String)>) -> Crate {
        let mut modules = BTreeMap::new();
        for (path, _) in &sources {
            modules.insert(module_of(path), path.clone());
        }
        let mut files = BTreeMap::new();
        for (path, text) in &sources {
            files.insert(path.clone(), parse(&module_of(path), path, text));
        }
        Crate { files, modules }
    }

    pub fn files(&self) -> Vec<String> {
        self.files.keys().cloned().collect()
    }

    /// The top-level module a file belongs to ("view" for view/layout.rs; "" for the root).
    pub fn top_module(&self, file: &str) -> String {
        self.files.get(file).and_then(|f| f.module.first().cloned()).unwrap_or_default()
    }

    /// Every import between two different files, once per (from, to).
    pub fn edges(&self) -> Vec<Edge> {
        let mut seen = BTreeMap::new();
        for (name, file) in &self.files {
            for (path, text) in &file.paths {
                let mut visited = BTreeSet::new();
                if let Some(to) = self.resolve(path, &mut visited) {
                    if &to != name {
                        seen.entry((name.clone(), to.clone())).or_insert_with(|| text.clone());
                    }
                }
            }
        }
        seen.into_iter().map(|((from, to), via)| Edge { from, to, via }).collect()
    }

    /// The file that defines what `path` names: the longest prefix that is a file, then its
    /// re-exports followed; None for paths outside the crate.
    fn resolve(&self, path: &[String], visited: &mut BTreeSet<Vec<String>>) -> Option<String> {
        if !visited.insert(path.to_vec()) {
            return None;
        }
        let n = (0..=path.len()).rev().find(|&n| self.modules.contains_key(&path[..n]))?;
        let file_name = self.modules[&path[..n]].clone();
        let Some(name) = path.get(n) else { return Some(file_name) };
        let file = &self.files[&file_name];
        if file.defines.contains(name) {
            return Some(file_name);
        }
        if let Some(target) = file.reexports.get(name) {
            let mut full = target.clone();
            full.extend_from_slice(&path[n + 1..]);
            if let Some(found) = self.resolve(&full, visited) {
                return Some(found);
            }
        }
        for glob in &file.globs {
            let mut full = glob.clone();
            full.extend_from_slice(&path[n..]);
            if let Some(found) = self.resolve(&full, visited) {
                if self.files[&found].defines.contains(name) || found != file_name {
                    return Some(found);
                }
            }
        }
        Some(file_name)
    }

    /// The cycles: each strongly connected set of two or more files, sorted.
    pub fn cycles(&self) -> Vec<Vec<String>> {
        let names = self.files();
        let index: BTreeMap<&String, usize> = names.iter().enumerate().map(|(i, n)| (n, i)).collect();
        let mut next = vec![Vec::new(); names.len()];
        for e in self.edges() {
            next[index[&e.from]].push(index[&e.to]);
        }
        let mut out: Vec<Vec<String>> = strongly_connected(&next)
            .into_iter()
            .filter(|c| c.len() > 1)
            .map(|c| {
                let mut c: Vec<String> = c.into_iter().map(|i| names[i].clone()).collect();
                c.sort();
                c
            })
            .collect();
        out.sort();
        out
    }
}

fn walk(root: &Path, dir: &Path, skip: &[&str], out: &mut Vec<(String, String)>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        let rel = p.strip_prefix(root).unwrap().to_string_lossy().replace('\\', "/");
        if p.is_dir() {
            if !skip.contains(&rel.as_str()) {
                walk(root, &p, skip, out);
            }
        } else if rel.ends_with(".rs") {
            out.push((rel, std::fs::read_to_string(&p).unwrap()));
        }
    }
}

/// "view/layout.rs" → [view, layout]; "view/mod.rs" → [view]; "lib.rs" → [].
fn module_of(path: &str) -> Vec<String> {
    let mut parts: Vec<String> = path.trim_end_matches(".rs").split('/').map(str::to_string).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib" | "main")) {
        parts.pop();
    }
    parts
}

/// Tarjan's strongly connected components.
fn strongly_connected(next: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct State<'a> {
        next: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        stack: Vec<usize>,
        on: Vec<bool>,
        counter: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(s: &mut State, v: usize) {
        s.index[v] = Some(s.counter);
        s.low[v] = s.counter;
        s.counter += 1;
        s.stack.push(v);
        s.on[v] = true;
        for i in 0..s.next[v].len() {
            let w = s.next[v][i];
            match s.index[w] {
                None => {
                    visit(s, w);
                    s.low[v] = s.low[v].min(s.low[w]);
                }
                Some(iw) if s.on[w] => s.low[v] = s.low[v].min(iw),
                _ => {}
            }
        }
        if Some(s.low[v]) == s.index[v] {
            let mut c = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on[w] = false;
                c.push(w);
                if w == v {
                    break;
                }
            }
            s.out.push(c);
        }
    }
    let n = next.len();
    let mut s = State {
        next,
        index: vec![None; n],
        low: vec![0; n],
        stack: Vec::new(),
        on: vec![false; n],
        counter: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if s.index[v].is_none() {
            visit(&mut s, v);
        }
    }
    s.out
}

// --------------------------------------------------------------------------------- the reader

/// Tokens of Rust source with comments, strings and character literals removed.
fn tokens(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let peek = |k: usize| chars.get(i + k).copied().unwrap_or('\0');
        if c == '/' && peek(1) == '/' {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && peek(1) == '*' {
            let mut depth = 0;
            while i < chars.len() {
                if chars[i] == '/' && peek_at(&chars, i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if chars[i] == '*' && peek_at(&chars, i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if c == 'r' && (peek(1) == '"' || (peek(1) == '#' && (peek(2) == '"' || peek(2) == '#'))) {
            // A raw string r"…", r#"…"#.
            let mut j = i + 1;
            let mut hashes = 0;
            while peek_at(&chars, j) == '#' {
                hashes += 1;
                j += 1;
            }
            j += 1;
            loop {
                if j >= chars.len() {
                    break;
                }
                if chars[j] == '"' && (0..hashes).all(|h| peek_at(&chars, j + 1 + h) == '#') {
                    j += 1 + hashes;
                    break;
                }
                j += 1;
            }
            i = j;
        } else if c == '"' || (c == 'b' && peek(1) == '"') {
            let mut j = if c == 'b' { i + 2 } else { i + 1 };
            while j < chars.len() && chars[j] != '"' {
                if chars[j] == '\\' {
                    j += 1;
                }
                j += 1;
            }
            i = j + 1;
        } else if c == '\'' {
            // A character literal ('a', '\n', '\u{2212}') or a lifetime ('a).
            if peek(1) == '\\' {
                let mut j = i + 2;
                while j < chars.len() && chars[j] != '\'' {
                    j += 1;
                }
                i = j + 1;
            } else if peek(2) == '\'' {
                i += 3;
            } else {
                i += 1;
                while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
            }
        } else if c.is_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push(chars[start..i].iter().collect());
        } else if c == ':' && peek(1) == ':' {
            out.push("::".into());
            i += 2;
        } else if c.is_whitespace() {
            i += 1;
        } else {
            out.push(c.to_string());
            i += 1;
        }
    }
    out
}

fn peek_at(chars: &[char], i: usize) -> char {
    chars.get(i).copied().unwrap_or('\0')
}

const ITEM_KEYWORDS: &[&str] =
    &["fn", "struct", "enum", "trait", "const", "static", "type", "union", "mod", "macro_rules"];

/// Reads one file: its definitions, re-exports, child modules and the paths it names.
fn parse(module: &[String], path: &str, text: &str) -> File {
    let t = tokens(text);
    let mut file = File { module: module.to_vec(), ..Default::default() };
    // Child modules declared in the file (`mod x;` and inline `mod x { … }`).
    let mut children: BTreeSet<String> = BTreeSet::new();
    for w in t.windows(2) {
        if w[0] == "mod" {
            children.insert(w[1].clone());
        }
    }
    // The module the code at each token is in: the file's, or an inline module's inside it.
    let mut scope: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < t.len() {
        let tok = t[i].as_str();
        match tok {
            "{" => depth += 1,
            "}" => {
                depth = depth.saturating_sub(1);
                if scope.last().is_some_and(|(_, d)| *d == depth) {
                    scope.pop();
                }
            }
            _ => {}
        }
        let here: Vec<String> = module.iter().cloned().chain(scope.iter().map(|(n, _)| n.clone())).collect();
        let top_level = scope.is_empty() && depth == 0;
        if tok == "mod" && t.get(i + 2).map(String::as_str) == Some("{") {
            scope.push((t[i + 1].clone(), depth));
            depth += 1;
            i += 3;
            continue;
        }
        if ITEM_KEYWORDS.contains(&tok) && top_level {
            if let Some(name) = t.get(if tok == "macro_rules" { i + 2 } else { i + 1 }) {
                file.defines.insert(name.clone());
            }
        }
        if tok == "use" {
            let public = i > 0 && (t[i - 1] == "pub" || t[i - 1] == ")");
            let end = (i..t.len()).find(|&k| t[k] == ";").unwrap_or(t.len());
            let mut leaves = Vec::new();
            use_tree(&t[i + 1..end], &mut Vec::new(), &mut leaves);
            for (segs, alias) in leaves {
                let Some(abs) = absolute(&here, &segs, &children, path) else { continue };
                let text = segs.join("::");
                // A facade's re-export of its own descendants: followed by `resolve`, no edge.
                let descendant = abs.starts_with(module) && abs.len() > module.len() + 1;
                if public && top_level && descendant {
                    if segs.last().map(String::as_str) == Some("*") {
                        file.globs.push(abs[..abs.len() - 1].to_vec());
                    } else if let Some(name) = alias.clone().or_else(|| abs.last().cloned()) {
                        file.reexports.insert(name, abs.clone());
                    }
                    continue;
                }
                if segs.last().map(String::as_str) == Some("*") {
                    let target = abs[..abs.len() - 1].to_vec();
                    if public && top_level {
                        file.globs.push(target.clone());
                    }
                    file.paths.push((target, text));
                } else {
                    if public && top_level {
                        let name = alias.clone().unwrap_or_else(|| abs.last().cloned().unwrap_or_default());
                        if name != "self" {
                            file.reexports.insert(name, abs.clone());
                        }
                    }
                    let abs = if abs.last().map(String::as_str) == Some("self") {
                        abs[..abs.len() - 1].to_vec()
                    } else {
                        abs
                    };
                    file.paths.push((abs, text));
                }
            }
            i = end + 1;
            continue;
        }
        // An inline path: crate::a::b, super::x, self::x, child::x.
        let starts = matches!(tok, "crate" | "super" | "self") || children.contains(tok);
        let after_sep = i > 0 && t[i - 1] == "::";
        if starts && !after_sep && t.get(i + 1).map(String::as_str) == Some("::") {
            let mut segs = vec![t[i].clone()];
            let mut k = i + 1;
            while t.get(k).map(String::as_str) == Some("::")
                && t.get(k + 1).is_some_and(|s| s.chars().next().is_some_and(|c| c.is_alphabetic() || c == '_'))
            {
                segs.push(t[k + 1].clone());
                k += 2;
            }
            if let Some(abs) = absolute(&here, &segs, &children, path) {
                file.paths.push((abs, segs.join("::")));
            }
            i = k;
            continue;
        }
        i += 1;
    }
    file
}

/// A use tree's leaves: (segments, alias).
fn use_tree(t: &[String], prefix: &mut Vec<String>, out: &mut Vec<(Vec<String>, Option<String>)>) {
    let mut i = 0;
    let mut segs = prefix.clone();
    while i < t.len() {
        match t[i].as_str() {
            "::" => i += 1,
            "{" => {
                // Split the group's items at top-level commas.
                let mut depth = 0;
                let mut start = i + 1;
                let mut k = i + 1;
                while k < t.len() {
                    match t[k].as_str() {
                        "{" => depth += 1,
                        "}" if depth == 0 => break,
                        "}" => depth -= 1,
                        "," if depth == 0 => {
                            use_tree(&t[start..k], &mut segs.clone(), out);
                            start = k + 1;
                        }
                        _ => {}
                    }
                    k += 1;
                }
                if start < k {
                    use_tree(&t[start..k], &mut segs.clone(), out);
                }
                return;
            }
            "as" => {
                out.push((segs.clone(), t.get(i + 1).cloned()));
                return;
            }
            s => {
                segs.push(s.to_string());
                i += 1;
            }
        }
    }
    if segs.len() > prefix.len() || !segs.is_empty() {
        out.push((segs, None));
    }
}

/// A path as written in module `here`, from the crate root; None for other crates.
fn absolute(here: &[String], segs: &[String], children: &BTreeSet<String>, _file: &str) -> Option<Vec<String>> {
    let first = segs.first()?;
    let mut base: Vec<String>;
    let mut rest = segs;
    match first.as_str() {
        "crate" => {
            base = Vec::new();
            rest = &segs[1..];
        }
        "self" => {
            base = here.to_vec();
            rest = &segs[1..];
        }
        "super" => {
            base = here.to_vec();
            while rest.first().map(String::as_str) == Some("super") {
                base.pop();
                rest = &rest[1..];
            }
        }
        s if children.contains(s) => base = here.to_vec(),
        _ => return None,
    }
    base.extend(rest.iter().cloned());
    Some(base)
}
