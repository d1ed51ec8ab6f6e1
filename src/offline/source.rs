//! The page's sources made fit to travel inside one file: a module's relative imports rewritten to
//! the names the offline file's import map gives its modules, and an HTML page's stylesheets
//! inlined and its preloads dropped (a file opened from disk may fetch nothing).

use crate::error::Error;

/// The prefix of a module's name in the offline file's import map: `@flexarm/js/dom.js`.
pub const MODULE_PREFIX: &str = "@flexarm/";

/// `spec` (`./x.js`, `../pkg/x.js`) resolved against the folder of the page-relative `from`
/// (`js/wasm.js`): `pkg/x.js`. A path that leaves the page's folder is refused.
pub fn resolve(from: &str, spec: &str) -> Result<String, Error> {
    let mut parts: Vec<&str> = from.split('/').collect();
    parts.pop(); // the file's own name
    for part in spec.split('/') {
        match part {
            "." | "" => {}
            ".." => {
                if parts.pop().is_none() {
                    return Err(Error::Refused(format!("{from}: the import '{spec}' leaves the page's folder")));
                }
            }
            name => parts.push(name),
        }
    }
    Ok(parts.join("/"))
}

/// True when `before` (the text before a string literal) ends in `from`, `import` or `import(`:
/// the literal is a module specifier.
fn follows_import(before: &str) -> bool {
    let b = before.trim_end();
    match b.strip_suffix('(') {
        Some(call) => ends_with_word(call.trim_end(), "import"),
        None => ends_with_word(b, "from") || ends_with_word(b, "import"),
    }
}

/// `text` ends with the word `word` (not the end of a longer name, nor a property: `x.from`).
fn ends_with_word(text: &str, word: &str) -> bool {
    text.strip_suffix(word)
        .is_some_and(|rest| !rest.ends_with(|c: char| c.is_alphanumeric() || c == '_' || c == '$' || c == '.'))
}

/// A module with its relative imports (static, re-exports and `import()`) rewritten to
/// `@flexarm/PATH`, and the page-relative paths it imports, in order of appearance (imports
/// rewritten before, by an offline file that makes another, are named and left as they are). Specifiers in
/// comments (a JSDoc `import('./x.js').T`) are rewritten too: harmless there, and they name
/// modules the page has anyway.
pub fn rewrite_imports(path: &str, text: &str) -> Result<(String, Vec<String>), Error> {
    let mut out = String::with_capacity(text.len() + 256);
    let mut imports = Vec::new();
    let mut copied = 0;
    let mut at = 0;
    while let Some(offset) = text[at..].find(['\'', '"']) {
        let open = at + offset;
        let quote = text.as_bytes()[open] as char;
        let body = &text[open + 1..];
        let relative = body.starts_with("./") || body.starts_with("../");
        let end = body.find([quote, '\n']).filter(|&e| body.as_bytes()[e] as char == quote);
        match end {
            // Already rewritten (a module carried by an offline file, which makes another): named.
            Some(len) if body.starts_with(MODULE_PREFIX) && follows_import(&text[..open]) => {
                imports.push(body[MODULE_PREFIX.len()..len].to_string());
                at = open + len + 2;
            }
            Some(len) if relative && follows_import(&text[..open]) => {
                let target = resolve(path, &body[..len])?;
                out.push_str(&text[copied..=open]);
                out.push_str(MODULE_PREFIX);
                out.push_str(&target);
                imports.push(target);
                copied = open + 1 + len;
                at = copied + 1;
            }
            // Skip a whole literal, so that a quote inside it starts nothing.
            Some(len) => at = open + len + 2,
            None => at = open + 1,
        }
    }
    out.push_str(&text[copied..]);
    Ok((out, imports))
}

/// The value of attribute `name` in a tag's text (`<link rel="x" href="y">`), double-quoted as
/// the page writes them.
fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = tag.find(&key)? + key.len();
    let len = tag[start..].find('"')?;
    Some(&tag[start..start + len])
}

/// The `<link …>` tags of a page: (start, end) byte ranges and the tag's text.
fn link_tags(html: &str) -> Vec<(usize, usize)> {
    let mut tags = Vec::new();
    let mut at = 0;
    while let Some(offset) = html[at..].find("<link ") {
        let start = at + offset;
        let Some(len) = html[start..].find('>') else { break };
        tags.push((start, start + len + 1));
        at = start + len + 1;
    }
    tags
}

/// The stylesheets a page links (`<link rel="stylesheet" href="…">`), page-relative, resolved
/// against the page's own path.
pub fn stylesheets(page: &str, html: &str) -> Result<Vec<String>, Error> {
    link_tags(html)
        .into_iter()
        .filter_map(|(s, e)| {
            let tag = &html[s..e];
            (attribute(tag, "rel") == Some("stylesheet")).then(|| attribute(tag, "href")).flatten()
        })
        .map(|href| resolve(page, &format!("./{href}")))
        .collect()
}

/// The page with each stylesheet link replaced by a `<style>` of that file (`css` gives its text)
/// and its `modulepreload` and `preload` links dropped (from disk they would only fail).
pub fn inline_styles<'a>(page: &str, html: &str, css: &dyn Fn(&str) -> Option<&'a str>) -> Result<String, Error> {
    let mut out = String::with_capacity(html.len() * 2);
    let mut copied = 0;
    for (s, e) in link_tags(html) {
        let tag = &html[s..e];
        let replacement = match attribute(tag, "rel") {
            Some("stylesheet") => {
                let href = attribute(tag, "href").unwrap_or("");
                let path = resolve(page, &format!("./{href}"))?;
                let text =
                    css(&path).ok_or_else(|| Error::Refused(format!("{page}: its stylesheet {path} is missing")))?;
                if text.contains("</style") {
                    return Err(Error::Refused(format!(
                        "{path} contains \"</style\", which would end its inlined copy"
                    )));
                }
                format!("<style>/* {path} */\n{text}</style>")
            }
            Some("modulepreload" | "preload") => String::new(),
            _ => continue,
        };
        // A dropped tag takes its line with it (its indentation and its newline).
        let s = if replacement.is_empty() { html[..s].trim_end_matches(' ').len() } else { s };
        let e = if replacement.is_empty() && html[e..].starts_with('\n') { e + 1 } else { e };
        out.push_str(&html[copied..s]);
        out.push_str(&replacement);
        copied = e;
    }
    out.push_str(&html[copied..]);
    Ok(out)
}

/// A byte range of a text.
pub type Span = (usize, usize);

/// The page's module scripts (`<script type="module" src="…"></script>`): the tag's byte range and
/// its page-relative source.
pub fn module_scripts(page: &str, html: &str) -> Result<Vec<(Span, String)>, Error> {
    const CLOSE: &str = "</script>";
    let mut found = Vec::new();
    let mut at = 0;
    while let Some(offset) = html[at..].find("<script ") {
        let start = at + offset;
        let Some(len) = html[start..].find(CLOSE) else { break };
        let end = start + len + CLOSE.len();
        let tag = &html[start..end];
        if attribute(tag, "type") == Some("module") {
            if let Some(src) = attribute(tag, "src") {
                found.push(((start, end), resolve(page, &format!("./{src}"))?));
            }
        }
        at = end;
    }
    Ok(found)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resolves_against_the_importing_folder() {
        assert_eq!(resolve("js/wasm.js", "../pkg/flexarm.js").unwrap(), "pkg/flexarm.js");
        assert_eq!(resolve("js/main.js", "./dom.js").unwrap(), "js/dom.js");
        assert_eq!(resolve("index.html", "./style.css").unwrap(), "style.css");
        assert!(resolve("js/a.js", "../../x.js").is_err());
    }

    #[test]
    fn rewrites_static_dynamic_and_side_effect_imports_only() {
        let src = "import { a, b } from './a.js';\nimport './side.js';\nexport { c } from \"../pkg/c.js\";\n\
                   const m = await import( '../pkg/c.js' );\nconst s = 'from ./not.js';\nconst u = new URL('./w.wasm', import.meta.url);\n\
                   x.from('./no.js'); const q = \"it's\"; import('./late.js');";
        let (out, imports) = rewrite_imports("js/main.js", src).unwrap();
        assert_eq!(imports, ["js/a.js", "js/side.js", "pkg/c.js", "pkg/c.js", "js/late.js"]);
        assert!(out.contains("from '@flexarm/js/a.js'"));
        assert!(out.contains("import '@flexarm/js/side.js'"));
        assert!(out.contains("from \"@flexarm/pkg/c.js\""));
        assert!(out.contains("import( '@flexarm/pkg/c.js' )"));
        assert!(out.contains("import('@flexarm/js/late.js')"));
        // Not specifiers: left alone.
        assert!(
            out.contains("'from ./not.js'") && out.contains("new URL('./w.wasm'") && out.contains("x.from('./no.js')")
        );
    }

    #[test]
    fn inlines_stylesheets_and_drops_preloads() {
        let html = "<head>\n  <link rel=\"icon\" href=\"data:,\">\n  <link rel=\"stylesheet\" href=\"style.css\">\n  \
                    <link rel=\"modulepreload\" href=\"js/main.js\">\n  <script type=\"module\" src=\"js/main.js\"></script>\n</head>";
        assert_eq!(stylesheets("index.html", html).unwrap(), ["style.css"]);
        let out = inline_styles("index.html", html, &|p| (p == "style.css").then_some("body { color: red }")).unwrap();
        assert!(out.contains("<style>/* style.css */\nbody { color: red }</style>"));
        assert!(out.contains("<link rel=\"icon\" href=\"data:,\">"));
        assert!(!out.contains("modulepreload"));
        let scripts = module_scripts("index.html", &out).unwrap();
        assert_eq!(scripts.len(), 1);
        assert_eq!(scripts[0].1, "js/main.js");
        assert!(inline_styles("index.html", html, &|_| None).is_err());
    }
}
