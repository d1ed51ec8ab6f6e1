//! The offline file: the page as one self-contained HTML file that opens from disk — a USB stick,
//! a course's file area, a message — with no server and no network (`flexarm bundle`, and the
//! page's "Save for offline").
//!
//! A browser refuses ES modules and `fetch` from `file://`, so the file carries everything:
//! * the page (`index.html`) with its stylesheets inlined and its preloads dropped;
//! * an archive of the files the page reads as it runs — its modules, whose relative imports are
//!   rewritten to `@flexarm/PATH` (the file's start-up script, `www/js/offline.js`, maps those
//!   names to blob URLs with an import map), the simulation (`pkg/flexarm_bg.wasm`), the lessons,
//!   the Python template and the help page — gzip-compressed and base64-encoded;
//! * its start ([`OfflineStart`]): the state string the page opens at when the file's address
//!   holds none, and a teacher's lesson.
//!
//! Which files, how each is rewritten and the file's layout are decided here, once, for the CLI
//! (which reads `www/`) and the page (which fetches its own files, or reads them from the archive
//! it came in). Only the compression is each host's: flate2 natively, `CompressionStream` in the
//! browser. The archive: a little-endian u32, the length of a JSON header `[[path, bytes], …]`,
//! the header, then each file's bytes in the header's order.

pub mod source;
pub mod start;

use crate::error::Error;
pub use start::{CarriedLesson, OfflineStart};

/// The page, where the search for the files it needs starts.
pub const ENTRY: &str = "index.html";

/// The offline file's start-up script (a classic script, inlined at the end of the file's body):
/// unpacks the archive, maps the modules, starts the page.
pub const BOOT: &str = "js/offline.js";

/// The files the page reads by path as it runs (no import names them): the simulation, the
/// lessons (`lessons/windows.md` is `lesson_src=`'s example), the Python template and the help
/// page; and the file's start-up script.
pub const RESOURCES: [&str; 6] =
    ["pkg/flexarm_bg.wasm", "lessons/paper.md", "lessons/windows.md", "export/model_template.py", "help.html", BOOT];

/// The files of one offline file, gathered one by one: [`Bundle::next_wanted`] names the next file
/// the bundle needs, [`Bundle::add`] gives it (and learns what it imports).
#[derive(Clone, Debug)]
pub struct Bundle {
    /// The files given, in the order given (modules already rewritten).
    files: Vec<(String, Vec<u8>)>,
    /// Paths still wanted, next first.
    wanted: Vec<String>,
    /// Every path wanted or given.
    known: Vec<String>,
}

impl Default for Bundle {
    fn default() -> Self {
        Self::new()
    }
}

impl Bundle {
    /// A bundle that wants the page and the files it reads by path.
    pub fn new() -> Bundle {
        let mut b = Bundle { files: Vec::new(), wanted: Vec::new(), known: Vec::new() };
        b.want(ENTRY);
        for path in RESOURCES {
            b.want(path);
        }
        b
    }

    fn want(&mut self, path: &str) {
        if !self.known.iter().any(|k| k == path) {
            self.known.push(path.to_string());
            self.wanted.push(path.to_string());
        }
    }

    /// The next file the bundle needs, by its path relative to the page (None: it has them all).
    pub fn next_wanted(&self) -> Option<&str> {
        self.wanted.first().map(String::as_str)
    }

    /// Gives the bundle a wanted file's bytes. A module's relative imports are rewritten and the
    /// modules it imports become wanted; a page's stylesheets and module scripts become wanted.
    pub fn add(&mut self, path: &str, bytes: Vec<u8>) -> Result<(), Error> {
        let Some(i) = self.wanted.iter().position(|p| p == path) else {
            return Err(Error::Refused(format!("the offline file does not need {path}")));
        };
        self.wanted.remove(i);
        let text = |bytes: &[u8]| {
            String::from_utf8(bytes.to_vec()).map_err(|_| Error::Refused(format!("{path} is not UTF-8 text")))
        };
        let (bytes, needs) = if path == BOOT {
            let boot = text(&bytes)?;
            if boot.contains("</script") {
                return Err(Error::Refused(format!("{path} contains \"</script\", which would end its inlined copy")));
            }
            (bytes, Vec::new())
        } else if path.ends_with(".js") {
            let (rewritten, imports) = source::rewrite_imports(path, &text(&bytes)?)?;
            (rewritten.into_bytes(), imports)
        } else if path.ends_with(".html") {
            let page = text(&bytes)?;
            let mut needs = source::stylesheets(path, &page)?;
            needs.extend(source::module_scripts(path, &page)?.into_iter().map(|(_, src)| src));
            (bytes, needs)
        } else {
            (bytes, Vec::new())
        };
        for need in needs {
            self.want(&need);
        }
        self.files.push((path.to_string(), bytes));
        Ok(())
    }

    fn file(&self, path: &str) -> Option<&[u8]> {
        self.files.iter().find(|(p, _)| p == path).map(|(_, b)| b.as_slice())
    }

    fn text(&self, path: &str) -> Option<&str> {
        self.file(path).and_then(|b| core::str::from_utf8(b).ok())
    }

    fn complete(&self) -> Result<(), Error> {
        match self.next_wanted() {
            Some(path) => Err(Error::NotReady(if path == ENTRY {
                "the offline file needs the page first"
            } else {
                "the offline file still lacks some of the page's files"
            })),
            None => Ok(()),
        }
    }

    /// The archive of the files (uncompressed; the host compresses it with gzip): every file the
    /// bundle gathered — the page and its styles too, which the file also holds inlined, so that
    /// an offline file can make another — with the help page's styles inlined (it is shown from
    /// a blob URL).
    pub fn archive(&self) -> Result<Vec<u8>, Error> {
        self.complete()?;
        // Other pages (the help) with their styles inlined.
        let mut pages = Vec::new();
        for (path, _) in self.files.iter().filter(|(p, _)| p != ENTRY && p.ends_with(".html")) {
            pages.push(source::inline_styles(path, self.text(path).unwrap_or(""), &|p| self.text(p))?);
        }
        let mut pages = pages.iter();
        let mut entries: Vec<(&str, &[u8])> = Vec::new();
        for (path, bytes) in &self.files {
            let page = if path != ENTRY && path.ends_with(".html") { pages.next().map(String::as_bytes) } else { None };
            entries.push((path, page.unwrap_or(bytes)));
        }
        let header = format!(
            "[{}]",
            entries
                .iter()
                .map(|(p, b)| format!("[{},{}]", start::json_string(p), b.len()))
                .collect::<Vec<_>>()
                .join(",")
        );
        let mut out = Vec::with_capacity(4 + header.len() + entries.iter().map(|(_, b)| b.len()).sum::<usize>());
        out.extend_from_slice(&(header.len() as u32).to_le_bytes());
        out.extend_from_slice(header.as_bytes());
        for (_, b) in &entries {
            out.extend_from_slice(b);
        }
        Ok(out)
    }

    /// The offline file: the page with its styles inlined, its module script replaced by the
    /// start (`#flexarm-start`), the archive gzip-compressed by the host (`compressed`,
    /// base64 in `#flexarm-files`) and the start-up script, at the end of the body (the page's
    /// loading screen shows while it unpacks).
    pub fn html(&self, compressed: &[u8], start: &OfflineStart) -> Result<String, Error> {
        self.complete()?;
        let page = self.text(ENTRY).ok_or(Error::NotReady("the offline file needs the page first"))?;
        let boot = self.text(BOOT).ok_or(Error::NotReady("the offline file needs its start-up script"))?;
        let mut page = source::inline_styles(ENTRY, page, &|p| self.text(p))?;
        let scripts = source::module_scripts(ENTRY, &page)?;
        let [((s, e), main)] = scripts.as_slice() else {
            return Err(Error::Refused(format!("{ENTRY} must start the page with exactly one module script")));
        };
        let main = main.clone();
        page.replace_range(s..e, "");
        let Some(body_end) = page.rfind("</body>") else {
            return Err(Error::Refused(format!("{ENTRY} has no </body>")));
        };
        let tail = format!(
            "<script id=\"flexarm-start\" type=\"application/json\">{}</script>\n\
             <script id=\"flexarm-files\" type=\"application/octet-stream\" data-main=\"{}{main}\">{}</script>\n\
             <script>\n{boot}</script>\n",
            start.to_json(),
            source::MODULE_PREFIX,
            start::base64(compressed),
        );
        page.insert_str(body_end, &tail);
        Ok(page)
    }
}

/// What the page says of an offline file of `file_bytes` whose archive compressed to
/// `compressed_bytes`: its size, and against the gzip of what the served page loads (the same
/// files).
pub fn size_text(file_bytes: usize, compressed_bytes: usize) -> String {
    let mb = |b: usize| crate::plot::format::significant_trimmed(b as f64 / 1e6, 3);
    format!(
        "One HTML file of {} MB that opens from disk with no server or network: the page, its modules, the simulation and the lessons, gzip-compressed and base64-encoded ({}× their {} MB as gzip, about what the served page loads).",
        mb(file_bytes),
        crate::plot::format::significant_trimmed(file_bytes as f64 / compressed_bytes.max(1) as f64, 3),
        mb(compressed_bytes)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_start_up_script_that_would_end_its_own_script_tag_is_refused() {
        let mut b = Bundle::new();
        assert!(b.add(BOOT, b"x = '</script>';".to_vec()).is_err());
    }
}
