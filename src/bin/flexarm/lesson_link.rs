//! `flexarm lesson-link`: one homework link that carries a teacher's lesson to students inside the
//! page's address (issue 35): the file checked as the page checks it, compressed (raw deflate) and
//! encoded by the library ([`flexarm::classroom::link`]), as the page's "make a homework link"
//! writes it.

use std::io::Write;
use std::path::Path;

use clap::{ArgMatches, Command};
use flexarm::classroom::link;
use flexarm::classroom::progress::checked;

use crate::cli::{self, option, usage_error, Res};

pub fn command() -> Command {
    cli::command(
        "lesson-link",
        "Print one homework link that carries a teacher's lesson inside the page's address (after the #, which no \
         server sees): it opens the lesson's first step in student mode",
    )
    .arg(
        clap::Arg::new("file")
            .value_name("FILE")
            .required(true)
            .help("The lesson (Markdown, the format of docs/teaching.md)"),
    )
    .arg(option(
        "base",
        "URL",
        "The page's address the link starts with (e.g. https://example.org/flexarm/); default: none, so that the \
         printed text is what to put after it",
    ))
}

pub fn run(m: &ArgMatches) -> Res<String> {
    let path = m.get_one::<String>("file").cloned().unwrap_or_default();
    let bytes = std::fs::read(&path).map_err(|e| usage_error(format!("could not read the lesson '{path}': {e}")))?;
    // The page's checks, here: a link to a lesson the page would refuse helps no one.
    checked(&bytes).map_err(|e| usage_error(format!("{path}: {e}")))?;
    let name = Path::new(&path).file_name().map_or_else(|| path.clone(), |n| n.to_string_lossy().into_owned());
    let mut deflate = flate2::write::DeflateEncoder::new(Vec::new(), flate2::Compression::best());
    let compressed = deflate
        .write_all(&bytes)
        .and_then(|()| deflate.finish())
        .map_err(|e| usage_error(format!("could not compress the lesson: {e}")))?;
    let base = m.get_one::<String>("base").map_or("", String::as_str);
    let base = base.split(['?', '#']).next().unwrap_or_default();
    let url = link::lesson_link(base, &name, &compressed).map_err(|e| usage_error(e.to_string()))?;
    Ok(format!("{url}\n"))
}
