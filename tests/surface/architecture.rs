//! The floors of docs/architecture.md (SPEC `X-floors`): numbers → mesh → gluing →
//! constructions (Ch. 4, then the surfaces built on them) → checks, certificates, pictures →
//! oracle → cli. A module may import only from its own floor or the floors below. The imports
//! that still go up are listed in `ALLOWED_UP` (each one a planned move, named in
//! docs/architecture.md); a new upward import fails, and so does a listed one that is gone
//! (the list only shrinks).

use super::spec_sync::rust_files;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Each top-level module of src/ and its floor.
const FLOORS: &[(&str, u32)] = &[
    ("numeric", 0),
    ("report", 0),
    ("exact", 0),
    ("mesh", 1),
    ("gluing", 2),
    ("construction", 3),
    ("surface", 4),
    ("msplines", 4),
    ("sdiff", 4),
    ("fitting", 4),
    ("conditions", 5),
    ("certify", 5),
    ("render", 5),
    ("oracle", 6),
    ("cli", 7),
];

/// Upward imports not yet moved (from, to), with the move that removes each.
const ALLOWED_UP: &[(&str, &str)] = &[];

fn floor(m: &str) -> Option<u32> {
    FLOORS.iter().find(|(n, _)| *n == m).map(|(_, f)| *f)
}

/// The top-level modules named as `crate::X` in code (comments dropped).
fn imports(src: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in src.lines() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(i) = rest.find("crate::") {
            let after = &rest[i + 7..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                out.insert(name);
            }
            rest = after;
        }
    }
    out
}

/// (from, to) of every import from a higher floor in src/.
fn upward_imports(root: &Path) -> BTreeSet<(String, String)> {
    let mut up = BTreeSet::new();
    for (m, f) in FLOORS {
        let mut files = Vec::new();
        rust_files(&root.join("src").join(m), &mut files);
        let single = root.join("src").join(format!("{m}.rs"));
        if single.is_file() {
            files.push(single);
        }
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap_or_default();
            for to in imports(&text) {
                if floor(&to).is_some_and(|g| g > *f) {
                    up.insert((m.to_string(), to));
                }
            }
        }
    }
    up
}

#[test]
fn x_floors_no_module_imports_from_a_floor_above_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    // Every top-level module has a floor.
    let mut dirs = Vec::new();
    for e in std::fs::read_dir(root.join("src")).expect("src").flatten() {
        let name = e
            .file_name()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if !["lib", "main"].contains(&name.as_str()) {
            dirs.push(name);
        }
    }
    for d in &dirs {
        assert!(floor(d).is_some(), "src/{d} has no floor in FLOORS");
    }
    let up = upward_imports(root);
    let allowed: BTreeSet<(String, String)> = ALLOWED_UP
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
    let new: Vec<_> = up.difference(&allowed).collect();
    let gone: Vec<_> = allowed.difference(&up).collect();
    assert!(new.is_empty(), "imports from a higher floor: {new:?}");
    assert!(
        gone.is_empty(),
        "moved: remove from ALLOWED_UP and docs/architecture.md: {gone:?}"
    );
    let scanned = dirs.len() as u64;
    crate::common::verdicts::record("X-floors", crate::common::verdicts::Seen::Holds, scanned);
}

#[test]
fn x_floors_import_scan_reads_code_not_comments() {
    let src = "use crate::surface::Pps; // crate::cli in a comment\n/// crate::oracle\nfn f() { crate::mesh::x(); }";
    let got: Vec<String> = imports(src).into_iter().collect();
    assert_eq!(got, vec!["mesh".to_string(), "surface".to_string()]);
}

#[test]
fn x_floors_planted_upward_import_is_found() {
    let root = std::env::temp_dir().join(format!("ppm-floors-{}", std::process::id()));
    std::fs::create_dir_all(root.join("src/mesh")).expect("dir");
    std::fs::write(
        root.join("src/mesh/x.rs"),
        "use crate::cli::run;\nuse crate::numeric::Q;\n",
    )
    .expect("write");
    let up = upward_imports(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(
        up.into_iter().collect::<Vec<_>>(),
        vec![("mesh".to_string(), "cli".to_string())]
    );
}

// SPEC `X-acyclic-files`: no cycle between the files of src/.
//
// Each file of src/ is a node, named by its module path (`src/a/b.rs` and `src/a/b/mod.rs` are
// `a::b`; `src/lib.rs` is the crate root). A file imports another when a path it names resolves
// there: the `use` trees (braces, `self`, `as`, globs) and the paths in code starting with
// `crate::`, `super::`, `self::` or a child module. A path resolves to the longest module
// prefix that is a file, then follows that file's `use` of the next name (a re-export: a
// mod.rs that re-exports `x::X` is not where `X` lives, so importing `X` through it is an edge
// to x.rs, not to mod.rs). Comments and string literals are not code. `#[cfg(test)]` modules
// (inline or in their own file) are left out: a test reaches into its parent and siblings to
// plant faults, which is not the library's structure and does not build into it. `src/main.rs`
// is the binary, another crate.

/// Source text with comments and string and character literals blanked to spaces, newlines
/// and byte offsets kept (so lines and the text of a `#[path]` stay where they were).
fn blank_comments_and_literals(src: &str) -> String {
    let b = src.as_bytes();
    let mut out = b.to_vec();
    let blank = |out: &mut Vec<u8>, from: usize, to: usize| {
        for c in &mut out[from..to.min(b.len())] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    };
    let mut i = 0;
    while i < b.len() {
        let rest = &b[i..];
        if rest.starts_with(b"//") {
            let end = rest
                .iter()
                .position(|&c| c == b'\n')
                .map_or(b.len(), |e| i + e);
            blank(&mut out, i, end);
            i = end;
        } else if rest.starts_with(b"/*") {
            let (mut depth, mut j) = (0usize, i);
            while j < b.len() {
                if b[j..].starts_with(b"/*") {
                    depth += 1;
                    j += 2;
                } else if b[j..].starts_with(b"*/") {
                    depth -= 1;
                    j += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    j += 1;
                }
            }
            blank(&mut out, i, j);
            i = j;
        } else if let Some(end) = raw_string_end(b, i) {
            blank(&mut out, i, end);
            i = end;
        } else if b[i] == b'"' && (i == 0 || !is_ident_byte(b[i - 1]) || b[i - 1] == b'b') {
            let mut j = i + 1;
            while j < b.len() && b[j] != b'"' {
                j += if b[j] == b'\\' { 2 } else { 1 };
            }
            blank(&mut out, i, j + 1);
            i = j + 1;
        } else if b[i] == b'\'' {
            // A character literal ('x', '\n', 'é'), not a lifetime ('a).
            let end = if rest.get(1) == Some(&b'\\') {
                rest.iter()
                    .skip(2)
                    .position(|&c| c == b'\'')
                    .map(|e| i + 2 + e + 1)
            } else {
                let ch = src[i + 1..].chars().next().map_or(1, char::len_utf8);
                (b.get(i + 1 + ch) == Some(&b'\'')).then_some(i + 2 + ch)
            };
            match end {
                Some(e) => {
                    blank(&mut out, i, e);
                    i = e;
                }
                None => i += 1,
            }
        } else {
            i += 1;
        }
    }
    // Only ASCII bytes were written, each over a whole character's bytes: valid UTF-8.
    String::from_utf8(out).unwrap_or_default()
}

fn is_ident_byte(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// End of a raw string literal (`r"…"`, `r#"…"#`, `br"…"`) starting at `i`.
fn raw_string_end(b: &[u8], i: usize) -> Option<usize> {
    if i > 0 && is_ident_byte(b[i - 1]) && b[i - 1] != b'b' {
        return None;
    }
    let mut j = i + usize::from(b[i] == b'b');
    if b.get(j) != Some(&b'r') {
        return None;
    }
    j += 1;
    let hashes = b[j..].iter().take_while(|&&c| c == b'#').count();
    j += hashes;
    if b.get(j) != Some(&b'"') {
        return None;
    }
    let close: Vec<u8> = std::iter::once(b'"')
        .chain(std::iter::repeat(b'#').take(hashes))
        .collect();
    let k = b[j + 1..].windows(close.len()).position(|w| w == close)?;
    Some(j + 1 + k + close.len())
}

/// A token of blanked code: a word or one punctuation character, with its line.
#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Word(String, usize),
    Punct(char, usize),
}

fn tokens(code: &str) -> Vec<Tok> {
    let mut out = Vec::new();
    let mut line = 1;
    let mut chars = code.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        if c == '\n' {
            line += 1;
        } else if c.is_alphanumeric() || c == '_' {
            let mut end = i + c.len_utf8();
            while let Some(&(j, d)) = chars.peek() {
                if !(d.is_alphanumeric() || d == '_') {
                    break;
                }
                end = j + d.len_utf8();
                chars.next();
            }
            out.push(Tok::Word(code[i..end].to_string(), line));
        } else if !c.is_whitespace() {
            out.push(Tok::Punct(c, line));
        }
    }
    out
}

fn word(t: Option<&Tok>) -> Option<&str> {
    match t {
        Some(Tok::Word(w, _)) => Some(w),
        _ => None,
    }
}

fn punct(t: Option<&Tok>, p: char) -> bool {
    matches!(t, Some(Tok::Punct(c, _)) if *c == p)
}

fn line_of(t: &Tok) -> usize {
    match t {
        Tok::Word(_, l) | Tok::Punct(_, l) => *l,
    }
}

/// Is `toks[i..]` a `::`?
fn path_sep(toks: &[Tok], i: usize) -> bool {
    punct(toks.get(i), ':') && punct(toks.get(i + 1), ':')
}

/// The flat paths of a use tree: (segments, name bound in scope). A glob ends in `*`.
fn use_tree(toks: &[Tok], prefix: &[String], out: &mut Vec<(Vec<String>, String)>) {
    let mut path = prefix.to_vec();
    let mut i = 0;
    if path_sep(toks, 0) {
        i = 2; // a leading `::` (an external crate)
    }
    loop {
        match toks.get(i) {
            Some(Tok::Punct('{', _)) => {
                // Split the group at its top-level commas.
                let mut depth = 0;
                let mut start = i + 1;
                for j in i..toks.len() {
                    match toks[j] {
                        Tok::Punct('{', _) => depth += 1,
                        Tok::Punct('}', _) => {
                            depth -= 1;
                            if depth == 0 {
                                use_tree(&toks[start..j], &path, out);
                                return;
                            }
                        }
                        Tok::Punct(',', _) if depth == 1 => {
                            use_tree(&toks[start..j], &path, out);
                            start = j + 1;
                        }
                        _ => {}
                    }
                }
                return;
            }
            Some(Tok::Punct('*', _)) => {
                path.push("*".into());
                out.push((path, "*".into()));
                return;
            }
            Some(Tok::Word(w, _)) => {
                path.push(w.clone());
                if path_sep(toks, i + 1) {
                    i += 3;
                    continue;
                }
                if w == "self" {
                    path.pop();
                }
                let alias = match (word(toks.get(i + 1)), word(toks.get(i + 2))) {
                    (Some("as"), Some(a)) => a.to_string(),
                    _ => path.last().cloned().unwrap_or_default(),
                };
                if !path.is_empty() {
                    out.push((path, alias));
                }
                return;
            }
            _ => return,
        }
    }
}

/// What one file says: its imports (path, line, module the path is relative to), the names
/// it binds at file level by `use`, the items it defines at file level, the other words of
/// its code (what a glob import may provide), and its `#[cfg(test)] mod name;` children
/// (name, `#[path]`).
#[derive(Default)]
struct FileScan {
    paths: Vec<(Vec<String>, usize, Vec<String>)>,
    /// The `pub use` paths among them (re-exports).
    reexports: BTreeSet<Vec<String>>,
    uses: Vec<(Vec<String>, String)>,
    defines: BTreeSet<String>,
    words: BTreeSet<String>,
    test_children: Vec<(String, Option<String>)>,
}

const ITEM_KEYWORDS: &[&str] = &[
    "fn", "struct", "enum", "trait", "type", "const", "static", "mod", "union",
];

/// The index after the item starting at `i`: its `;`, or its `{ … }` block.
fn skip_item(toks: &[Tok], i: usize) -> usize {
    let mut nest = 0i32;
    let mut j = i;
    while j < toks.len() {
        match toks[j] {
            Tok::Punct('(' | '[', _) => nest += 1,
            Tok::Punct(')' | ']', _) => nest -= 1,
            Tok::Punct(';', _) if nest == 0 => return j + 1,
            Tok::Punct('{', _) if nest == 0 => {
                let mut d = 0;
                while j < toks.len() {
                    match toks[j] {
                        Tok::Punct('{', _) => d += 1,
                        Tok::Punct('}', _) => {
                            d -= 1;
                            if d == 0 {
                                return j + 1;
                            }
                        }
                        _ => {}
                    }
                    j += 1;
                }
            }
            _ => {}
        }
        j += 1;
    }
    j
}

/// Scan one file of module `module`; `children` says whether a name is a child module of a
/// module path (a path may start with one).
fn scan_file(raw: &str, module: &[String], children: &dyn Fn(&[String], &str) -> bool) -> FileScan {
    let code = blank_comments_and_literals(raw);
    let toks = tokens(&code);
    let mut s = FileScan::default();
    let mut depth = 0usize;
    // Inline modules open at this point: (name, brace depth inside them).
    let mut inline: Vec<(String, usize)> = Vec::new();
    // The attributes read since the last item: `#[cfg(test)]`, `#[path = "…"]`.
    let mut test = false;
    let mut attr_path: Option<String> = None;
    let mut i = 0;
    while i < toks.len() {
        let here: Vec<String> = module
            .iter()
            .cloned()
            .chain(inline.iter().map(|(n, _)| n.clone()))
            .collect();
        if punct(toks.get(i), '#') && punct(toks.get(i + 1), '[') {
            let mut j = i + 2;
            let mut d = 1;
            let mut words = Vec::new();
            while j < toks.len() && d > 0 {
                match &toks[j] {
                    Tok::Punct('[', _) => d += 1,
                    Tok::Punct(']', _) => d -= 1,
                    Tok::Word(w, _) => words.push(w.as_str()),
                    _ => {}
                }
                j += 1;
            }
            test |= words == ["cfg", "test"];
            if words.first() == Some(&"path") {
                // The literal is blanked in `code`; read it from the same line of `raw`.
                let text = raw.lines().nth(line_of(&toks[i]) - 1).unwrap_or("");
                attr_path = text.split('"').nth(1).map(str::to_string);
            }
            i = j;
            continue;
        }
        let visibility = matches!(word(toks.get(i)), Some("pub" | "crate" | "in"))
            || punct(toks.get(i), '(')
                && word(i.checked_sub(1).and_then(|k| toks.get(k))) == Some("pub")
            || punct(toks.get(i), ')');
        if test && visibility {
            i += 1;
            continue;
        }
        if test {
            // A `#[cfg(test)]` item: skipped whole, but a `mod name;` names a test file.
            if word(toks.get(i)) == Some("mod") && punct(toks.get(i + 2), ';') {
                let name = word(toks.get(i + 1)).unwrap_or("").to_string();
                s.test_children.push((name, attr_path.take()));
            }
            i = skip_item(&toks, i);
            test = false;
            attr_path = None;
            continue;
        }
        attr_path = None;
        match &toks[i] {
            Tok::Word(w, _) if w == "mod" && punct(toks.get(i + 2), '{') => {
                let name = word(toks.get(i + 1)).unwrap_or("").to_string();
                if depth == 0 {
                    s.defines.insert(name.clone());
                }
                depth += 1;
                inline.push((name, depth));
                i += 3;
            }
            Tok::Word(w, line) if w == "use" => {
                let end = (i..toks.len())
                    .find(|&j| punct(toks.get(j), ';'))
                    .unwrap_or(toks.len());
                let mut flat = Vec::new();
                use_tree(&toks[i + 1..end], &[], &mut flat);
                let public = word(i.checked_sub(1).and_then(|k| toks.get(k))) == Some("pub")
                    || punct(i.checked_sub(1).and_then(|k| toks.get(k)), ')');
                for (p, name) in flat {
                    if public {
                        s.reexports.insert(p.clone());
                    }
                    s.paths.push((p.clone(), *line, here.clone()));
                    if depth == 0 {
                        s.uses.push((p, name));
                    }
                }
                i = end + 1;
            }
            Tok::Word(w, line)
                if (w == "crate" || w == "super" || w == "self" || children(&here, w))
                    && path_sep(&toks, i + 1)
                    && !(i >= 2 && path_sep(&toks, i - 2)) =>
            {
                let mut p = vec![w.clone()];
                let mut j = i + 1;
                while path_sep(&toks, j) {
                    match word(toks.get(j + 2)) {
                        Some(seg) => p.push(seg.to_string()),
                        None => break,
                    }
                    j += 3;
                }
                s.paths.push((p, *line, here));
                i = j;
            }
            // (`'static` is a lifetime, not an item.)
            Tok::Word(w, _)
                if depth == 0
                    && ITEM_KEYWORDS.contains(&w.as_str())
                    && !punct(i.checked_sub(1).and_then(|k| toks.get(k)), '\'') =>
            {
                if let Some(name) = word(toks.get(i + 1)) {
                    s.defines.insert(name.to_string());
                }
                i += 1;
            }
            Tok::Word(w, _) => {
                s.words.insert(w.clone());
                i += 1;
            }
            Tok::Punct('{', _) => {
                depth += 1;
                i += 1;
            }
            Tok::Punct('}', _) => {
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
                depth = depth.saturating_sub(1);
                i += 1;
            }
            _ => i += 1,
        }
    }
    s
}

/// The module path of a file under `src` (`None` for the binary's `main.rs`).
fn module_of(src: &Path, file: &Path) -> Option<Vec<String>> {
    let rel = file.strip_prefix(src).ok()?.with_extension("");
    let mut parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().to_string())
        .collect();
    match parts.last().map(String::as_str) {
        Some("main") if parts.len() == 1 => return None,
        Some("lib") if parts.len() == 1 => parts.clear(),
        Some("mod") => {
            parts.pop();
        }
        _ => {}
    }
    Some(parts)
}

/// The file graph of `root/src`: the files (module path → file) and the edges
/// (from, to) → first line of `from` that names `to`.
struct FileGraph {
    files: BTreeMap<Vec<String>, PathBuf>,
    edges: BTreeMap<(Vec<String>, Vec<String>), EdgeAt>,
}

/// Where an edge was seen: the line, and the name a glob import gave.
type EdgeAt = (usize, Option<String>);

/// A file-level `use`: the name it binds ("*" for a glob), its absolute target, a re-export.
type Binding = (String, Vec<String>, bool);

/// The names of the scanned files, to resolve paths with.
struct Names<'a> {
    files: &'a BTreeMap<Vec<String>, PathBuf>,
    scans: &'a BTreeMap<Vec<String>, FileScan>,
    bindings: BTreeMap<Vec<String>, Vec<Binding>>,
}

impl Names<'_> {
    /// The file that defines what the absolute path `a` names: its longest prefix that is a
    /// file, then that file's `use` of the next name (named, or a glob that gives it).
    fn resolve(&self, a: &[String], depth: u32) -> Option<Vec<String>> {
        let n = (0..=a.len())
            .rev()
            .find(|&n| self.files.contains_key(&a[..n]))?;
        let best = a[..n].to_vec();
        let (Some(name), true) = (a.get(n), depth < 16) else {
            return Some(best);
        };
        if name == "*" || self.scans[&best].defines.contains(name) {
            return Some(best);
        }
        let bound = &self.bindings[&best];
        let via = |target: &[String], from: usize| {
            let mut t = target.to_vec();
            t.extend(a[from..].iter().cloned());
            self.resolve(&t, depth + 1).or(Some(best.clone()))
        };
        if let Some((_, t, _)) = bound.iter().find(|(b, _, _)| b == name) {
            return via(t, n + 1);
        }
        for (_, g, _) in bound.iter().filter(|(b, _, _)| b == "*") {
            let gives = self
                .resolve(g, depth + 1)
                .is_some_and(|gf| self.provides(&gf, name, false, depth + 1));
            if gives {
                return via(g, n);
            }
        }
        Some(best)
    }

    /// Does file `f` give the name `w`: defined there, bound by its `use` or through one of
    /// its globs? Only re-exports count unless `all` (`f` is an ancestor of the importer).
    fn provides(&self, f: &Vec<String>, w: &str, all: bool, depth: u32) -> bool {
        let bound = &self.bindings[f];
        self.scans[f].defines.contains(w)
            || bound
                .iter()
                .any(|(b, _, public)| b == w && (all || *public))
            || depth < 4
                && bound
                    .iter()
                    .filter(|(b, _, public)| b == "*" && (all || *public))
                    .any(|(_, g, _)| {
                        self.resolve(g, depth + 1)
                            .is_some_and(|gf| self.provides(&gf, w, false, depth + 1))
                    })
    }
}

fn file_graph(root: &Path) -> FileGraph {
    let src = root.join("src");
    let mut paths = Vec::new();
    rust_files(&src, &mut paths);
    let mut texts: BTreeMap<Vec<String>, (PathBuf, String)> = BTreeMap::new();
    for p in paths {
        if let Some(m) = module_of(&src, &p) {
            let text = std::fs::read_to_string(&p).unwrap_or_default();
            texts.insert(m, (p, text));
        }
    }
    let modules: BTreeSet<Vec<String>> = texts.keys().cloned().collect();
    let children = |m: &[String], name: &str| {
        let mut c = m.to_vec();
        c.push(name.to_string());
        modules.contains(&c)
    };
    let scans: BTreeMap<Vec<String>, FileScan> = texts
        .iter()
        .map(|(m, (_, t))| (m.clone(), scan_file(t, m, &children)))
        .collect();
    // Files that are `#[cfg(test)] mod x;` of another file are left out.
    let mut tests: BTreeSet<PathBuf> = BTreeSet::new();
    for (m, s) in &scans {
        let file = &texts[m].0;
        let dir = file.parent().unwrap_or(&src).to_path_buf();
        let own = if file
            .file_name()
            .is_some_and(|n| n == "mod.rs" || n == "lib.rs")
        {
            dir.clone()
        } else {
            file.with_extension("")
        };
        for (name, at) in &s.test_children {
            match at {
                Some(p) => {
                    tests.insert(dir.join(p));
                }
                None => {
                    tests.insert(own.join(format!("{name}.rs")));
                    tests.insert(own.join(name).join("mod.rs"));
                }
            }
        }
    }
    let files: BTreeMap<Vec<String>, PathBuf> = texts
        .into_iter()
        .filter(|(_, (p, _))| !tests.contains(p))
        .map(|(m, (p, _))| (m, p))
        .collect();
    let absolute = |here: &[String], p: &[String]| -> Option<Vec<String>> {
        let first = p.first()?.as_str();
        match first {
            "crate" => Some(p[1..].to_vec()),
            "super" | "self" => {
                let mut base = here.to_vec();
                let mut rest = p;
                while rest.first().is_some_and(|s| s == "super") {
                    base.pop()?;
                    rest = &rest[1..];
                }
                if rest.first().is_some_and(|s| s == "self") {
                    rest = &rest[1..];
                }
                base.extend(rest.iter().cloned());
                Some(base)
            }
            _ if children(here, first) => Some(here.iter().chain(p).cloned().collect()),
            _ => None,
        }
    };
    // A file's `use` bindings as absolute paths: (name, target, a re-export); globs are
    // named "*".
    let bindings = scans
        .iter()
        .map(|(m, s)| {
            let b = s
                .uses
                .iter()
                .filter_map(|(p, name)| {
                    let mut a = absolute(m, p)?;
                    if name == "*" {
                        a.pop();
                    }
                    Some((name.clone(), a, s.reexports.contains(p)))
                })
                .collect();
            (m.clone(), b)
        })
        .collect();
    let names = Names {
        files: &files,
        scans: &scans,
        bindings,
    };
    let mut edges = BTreeMap::new();
    for m in files.keys() {
        let s = &scans[m];
        for (p, line, here) in &s.paths {
            let Some(mut a) = absolute(here, p) else {
                continue;
            };
            let mut targets = Vec::new();
            if a.last().is_some_and(|x| x == "*") && !s.reexports.contains(p) {
                // A glob import depends on where the names it gives that this file uses are
                // (its own definitions and named imports shadow the glob's); a glob
                // re-export, on the module it re-exports. From an ancestor, a glob also
                // gives its private names.
                a.pop();
                let Some(from) = names.resolve(&a, 0) else {
                    continue;
                };
                let all = m.starts_with(&from);
                for w in &s.words {
                    let shadowed = s.defines.contains(w) || s.uses.iter().any(|(_, n)| n == w);
                    if !shadowed && names.provides(&from, w, all, 0) {
                        let mut t = a.clone();
                        t.push(w.clone());
                        targets.extend(names.resolve(&t, 0).map(|f| (f, Some(w.clone()))));
                    }
                }
            } else {
                targets.extend(names.resolve(&a, 0).map(|f| (f, None)));
            }
            for (to, via) in targets {
                if &to != m {
                    edges.entry((m.clone(), to)).or_insert((*line, via));
                }
            }
        }
    }
    FileGraph { files, edges }
}

/// The strongly connected components with more than one file (Tarjan).
fn cycles(g: &FileGraph) -> Vec<Vec<Vec<String>>> {
    struct T<'a> {
        next: BTreeMap<&'a Vec<String>, Vec<&'a Vec<String>>>,
        index: BTreeMap<&'a Vec<String>, usize>,
        low: BTreeMap<&'a Vec<String>, usize>,
        stack: Vec<&'a Vec<String>>,
        on: BTreeSet<&'a Vec<String>>,
        out: Vec<Vec<Vec<String>>>,
    }
    fn visit<'a>(t: &mut T<'a>, v: &'a Vec<String>) {
        let i = t.index.len();
        t.index.insert(v, i);
        t.low.insert(v, i);
        t.stack.push(v);
        t.on.insert(v);
        for w in t.next.get(v).cloned().unwrap_or_default() {
            if !t.index.contains_key(w) {
                visit(t, w);
                let l = t.low[w].min(t.low[v]);
                t.low.insert(v, l);
            } else if t.on.contains(w) {
                let l = t.index[w].min(t.low[v]);
                t.low.insert(v, l);
            }
        }
        if t.low[v] == t.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = t.stack.pop() {
                t.on.remove(w);
                comp.push(w.clone());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                t.out.push(comp);
            }
        }
    }
    let mut t = T {
        next: BTreeMap::new(),
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    for (a, b) in g.edges.keys() {
        t.next.entry(a).or_default().push(b);
    }
    for v in g.files.keys() {
        if !t.index.contains_key(v) {
            visit(&mut t, v);
        }
    }
    t.out
}

/// Each cycle as its files and one line per edge inside it (`file:line → file`).
fn describe(g: &FileGraph, root: &Path, cycles: &[Vec<Vec<String>>]) -> String {
    let show = |m: &Vec<String>| {
        g.files[m]
            .strip_prefix(root)
            .unwrap_or(&g.files[m])
            .display()
            .to_string()
    };
    let mut s = String::new();
    for c in cycles {
        let names: Vec<String> = c.iter().map(show).collect();
        s.push_str(&format!(
            "\ncycle of {} files: {}\n",
            c.len(),
            names.join(", ")
        ));
        for ((a, b), (line, via)) in &g.edges {
            if c.contains(a) && c.contains(b) {
                let via = via
                    .as_ref()
                    .map_or(String::new(), |w| format!(" ({w}, by a glob)"));
                s.push_str(&format!("  {}:{line} → {}{via}\n", show(a), show(b)));
            }
        }
    }
    s
}

#[test]
fn x_acyclic_files_no_cycle_between_the_files_of_src() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let g = file_graph(root);
    assert!(
        g.files.len() > 100,
        "src/ scan found {} files",
        g.files.len()
    );
    assert!(g.edges.len() > g.files.len(), "{} edges", g.edges.len());
    let found = cycles(&g);
    assert!(
        found.is_empty(),
        "file cycles in src/ ({} files, {} edges):{}",
        g.files.len(),
        g.edges.len(),
        describe(&g, root, &found)
    );
    println!(
        "X-acyclic-files: {} files, {} edges, no cycle",
        g.files.len(),
        g.edges.len()
    );
    let scanned = g.files.len() as u64;
    crate::common::verdicts::record(
        "X-acyclic-files",
        crate::common::verdicts::Seen::Holds,
        scanned,
    );
}

/// A tree under the temp dir from (path, text) pairs; removed by the caller.
fn planted_tree(tag: &str, files: &[(&str, &str)]) -> PathBuf {
    let root = std::env::temp_dir().join(format!("ppm-acyclic-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    for (p, text) in files {
        let f = root.join(p);
        std::fs::create_dir_all(f.parent().expect("parent")).expect("dir");
        std::fs::write(f, text).expect("write");
    }
    root
}

fn m(s: &str) -> Vec<String> {
    s.split("::")
        .filter(|x| !x.is_empty())
        .map(String::from)
        .collect()
}

#[test]
fn x_acyclic_files_planted_two_file_cycle_is_found() {
    let root = planted_tree(
        "two",
        &[
            ("src/lib.rs", "pub mod a;\npub mod b;\n"),
            ("src/a.rs", "use crate::b::{g as h};\npub fn f() { h() }\n"),
            ("src/b.rs", "pub fn g() {\n    super::a::f();\n}\n"),
        ],
    );
    let g = file_graph(&root);
    let found = cycles(&g);
    let text = describe(&g, &root, &found);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(found, vec![vec![m("a"), m("b")]]);
    assert!(text.contains("src/a.rs:1 → src/b.rs"), "{text}");
    assert!(text.contains("src/b.rs:2 → src/a.rs"), "{text}");
}

#[test]
fn x_acyclic_files_reexport_through_mod_rs_is_not_a_cycle() {
    let root = planted_tree(
        "reexport",
        &[
            ("src/lib.rs", "pub mod m;\n"),
            (
                "src/m/mod.rs",
                "mod x;\nmod y;\npub use x::X;\npub use y::Y;\n",
            ),
            ("src/m/x.rs", "pub struct X;\n"),
            (
                "src/m/y.rs",
                "use super::X;\npub struct Y(pub crate::m::X);\n",
            ),
        ],
    );
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    // y names X through mod.rs: the edge goes to x.rs, where X is.
    assert!(g.edges.contains_key(&(m("m::y"), m("m::x"))));
    assert!(!g.edges.contains_key(&(m("m::y"), m("m"))));
    assert!(g.edges.contains_key(&(m("m"), m("m::y"))));
    assert!(cycles(&g).is_empty());
    // The same names defined in mod.rs itself are a cycle.
    let root = planted_tree(
        "defined",
        &[
            ("src/lib.rs", "pub mod m;\n"),
            ("src/m/mod.rs", "mod y;\npub use y::Y;\npub struct X;\n"),
            ("src/m/y.rs", "use super::X;\npub struct Y(pub X);\n"),
        ],
    );
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(cycles(&g), vec![vec![m("m"), m("m::y")]]);
    // Globs both ways (`pub use x::*` in mod.rs, `use super::*` in a child): the child
    // depends on the files of the names it uses, not on mod.rs.
    let root = planted_tree(
        "glob",
        &[
            ("src/lib.rs", "pub mod m;\n"),
            (
                "src/m/mod.rs",
                "mod x;\nmod y;\npub use x::*;\npub use y::*;\n",
            ),
            ("src/m/x.rs", "pub struct X;\n"),
            ("src/m/y.rs", "use super::*;\npub struct Y(pub X);\n"),
        ],
    );
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert!(g.edges.contains_key(&(m("m::y"), m("m::x"))));
    assert!(cycles(&g).is_empty(), "{:?}", g.edges);
    let root = planted_tree(
        "glob-defined",
        &[
            ("src/lib.rs", "pub mod m;\n"),
            ("src/m/mod.rs", "mod y;\npub use y::*;\npub struct X;\n"),
            ("src/m/y.rs", "use super::*;\npub struct Y(pub X);\n"),
        ],
    );
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(cycles(&g), vec![vec![m("m"), m("m::y")]]);
}

#[test]
fn x_acyclic_files_cfg_test_modules_are_not_edges() {
    fn tree(c: &str) -> Vec<(&str, &str)> {
        vec![
            ("src/lib.rs", "pub mod m;\n"),
            (
                "src/m/mod.rs",
                "mod c;\npub use c::C;\npub struct P;\n#[cfg(test)]\n#[path = \"m_tests.rs\"]\nmod more;\n",
            ),
            ("src/m/c.rs", c),
            ("src/m/m_tests.rs", "use super::c::C;\nuse crate::m::P;\n"),
        ]
    }
    let child = "pub struct C;\n#[cfg(test)]\nmod tests {\n    use super::*;\n    use crate::m::P;\n    fn f() { let _ = { crate::m::P }; }\n}\n";
    let root = planted_tree("cfgtest", &tree(child));
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert!(cycles(&g).is_empty(), "{:?}", g.edges);
    assert!(!g.files.contains_key(&m("m::m_tests")));
    assert_eq!(g.files.len(), 3);
    // Control: the same module without `#[cfg(test)]` is a cycle.
    let plain = child.replace("#[cfg(test)]\n", "");
    let root = planted_tree("cfgtest-control", &tree(&plain));
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(cycles(&g), vec![vec![m("m"), m("m::c")]]);
}

#[test]
fn x_acyclic_files_paths_in_comments_and_strings_are_not_edges() {
    fn tree(a: &str) -> Vec<(&str, &str)> {
        vec![
            ("src/lib.rs", "pub mod a;\npub mod b;\n"),
            ("src/a.rs", a),
            ("src/b.rs", "pub fn g() { let _ = crate::a::f(); }\n"),
        ]
    }
    let a = "// use crate::b::g;\n/* crate::b::g() /* nested */ crate::b */\n/// [`crate::b::g`]\npub fn f() -> (&'static str, &'static str, char) {\n    (\"crate::b::g\", r#\"use crate::b::g; \"#, '\"')\n}\nfn l<'a>(x: &'a str) -> &'a str { x }\n";
    let root = planted_tree("comments", &tree(a));
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert!(cycles(&g).is_empty(), "{:?}", g.edges);
    assert!(g.edges.contains_key(&(m("b"), m("a"))));
    // Control: code after the comments and literals is still read.
    let with_call = format!("{a}fn h() {{ crate::b::g() }}\n");
    let root = planted_tree("comments-control", &tree(&with_call));
    let g = file_graph(&root);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(cycles(&g), vec![vec![m("a"), m("b")]]);
}
