//! `flexarm bundle`: the page as one self-contained HTML file that opens from disk with no server
//! and no network — what the page's "Save for offline" makes — starting at a state string and
//! carrying a teacher's lesson. The files come from the built page (`www/`, with the wasm module
//! that `bash scripts/serve.sh` builds); which files, how each is rewritten and the file's layout
//! are the library's ([`flexarm::offline`]); this compresses the archive (gzip) and writes it.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::{ArgMatches, Command};
use flexarm::offline::{self, Bundle, OfflineStart};

use crate::cli::{self, option, usage_error, Res};

/// The built page, where it is in this repository.
const WWW: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/www");

pub fn command() -> Command {
    cli::command(
        "bundle",
        "Write the page as one HTML file that opens from disk — a USB stick, a course's file area, a message — with \
         no server or network (the page's \"Save for offline\")",
    )
    .arg(option("out", "FILE.html", "Where to write the file").required(true))
    .arg(option(
        "state",
        "STATE",
        "The state string the file opens at, as in the page's address (e.g. 'delta=0.01&pf=off&answers=hidden', \
         with 'paused=1&t=3' for a moment; default: the page's start)",
    ))
    .arg(option(
        "lesson",
        "FILE",
        "A teacher's lesson (Markdown, the format of docs/teaching.md) for the file to carry and open instead of \
         the built-in one",
    ))
    .arg(option(
        "www",
        "DIR",
        "The built page to bundle (default: this repository's www/, built by bash scripts/serve.sh)",
    ))
}

/// Reads one of the page's files; a missing wasm module says how to build it.
fn read(www: &Path, path: &str) -> Res<Vec<u8>> {
    let full = www.join(path);
    std::fs::read(&full).map_err(|e| {
        let hint = if path.starts_with("pkg/") {
            " — build the page's wasm module first (bash scripts/serve.sh builds it; or give --www DIR of a built page)"
        } else {
            ""
        };
        usage_error(format!("could not read {}: {e}{hint}", full.display()))
    })
}

pub fn run(m: &ArgMatches) -> Res<String> {
    let out = m.get_one::<String>("out").cloned().unwrap_or_default();
    let www = m.get_one::<String>("www").map_or_else(|| PathBuf::from(WWW), PathBuf::from);
    let lesson = match m.get_one::<String>("lesson") {
        None => None,
        Some(path) => {
            let bytes =
                std::fs::read(path).map_err(|e| usage_error(format!("could not read --lesson file '{path}': {e}")))?;
            let name = Path::new(path).file_name().map_or_else(|| path.clone(), |n| n.to_string_lossy().into_owned());
            Some((name, bytes))
        }
    };
    let state = m.get_one::<String>("state").map_or("", String::as_str);
    // The state alone first, so that a mistake is named with its flag (a lesson's names its file).
    OfflineStart::new(state, None).map_err(|e| usage_error(format!("--state: {e}")))?;
    let start = OfflineStart::new(state, lesson).map_err(|e| usage_error(e.to_string()))?;

    let mut bundle = Bundle::new();
    while let Some(path) = bundle.next_wanted().map(str::to_string) {
        let bytes = read(&www, &path)?;
        bundle.add(&path, bytes)?;
    }
    let archive = bundle.archive()?;
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    let compressed = gz
        .write_all(&archive)
        .and_then(|()| gz.finish())
        .map_err(|e| usage_error(format!("could not compress the page's files: {e}")))?;
    let html = bundle.html(&compressed, &start)?;
    cli::write_file("--out", &out, &html)?;
    Ok(format!(
        "wrote {out}: it opens at {}.\n{}\n",
        start.describe(),
        offline::size_text(html.len(), compressed.len())
    ))
}
