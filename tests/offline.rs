//! The offline file (issue 33): the page as one HTML file that opens from disk with no server.
//! Checked here natively: every module of the page travels and none still imports by a relative
//! path, nothing in the file asks the browser to fetch, the archive inside decodes back to the
//! files, and the file carries its start — the state, the lesson step, the moment, student mode
//! and a teacher's lesson — which the page reopens as it was. The browser side (opened from
//! file:// with the network off) is tests/e2e/offline.test.mjs.

use std::collections::BTreeSet;
use std::io::Read;
use std::path::Path;
use std::process::Command;

use flexarm::classroom::{Classroom, LessonFiles, LessonOrigin};
use flexarm::offline::source::{rewrite_imports, MODULE_PREFIX};
use flexarm::offline::{Bundle, OfflineStart, BOOT, ENTRY};

const WWW: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/www");
const HOMEWORK: &str = include_str!("../www/lessons/windows.md");
/// A lesson with a mistake in its step's `state:` (line 6).
const BAD_LESSON: &str = "# T\n\n## S\n\nSome prose.\nstate: delta=banana\n";

/// The wasm-pack output, which `cargo test` runs without: stand-ins (their content is not read).
fn stub(path: &str) -> Vec<u8> {
    match path {
        "pkg/flexarm.js" => b"export default async function init() {}\n".to_vec(),
        _ => vec![0, 97, 115, 109, 1, 0, 0, 0],
    }
}

/// A bundle of the repository's page, gathered as the CLI and the page gather it.
fn gathered() -> Bundle {
    let mut bundle = Bundle::new();
    while let Some(path) = bundle.next_wanted().map(str::to_string) {
        let bytes =
            if path.starts_with("pkg/") { stub(&path) } else { std::fs::read(Path::new(WWW).join(&path)).unwrap() };
        bundle.add(&path, bytes).unwrap_or_else(|e| panic!("{path}: {e}"));
    }
    bundle
}

/// The archive's files, read as js/offline.js reads them.
fn unpack(archive: &[u8]) -> Vec<(String, Vec<u8>)> {
    let n = u32::from_le_bytes(archive[..4].try_into().unwrap()) as usize;
    let header: Vec<(String, usize)> = serde_json::from_slice(&archive[4..4 + n]).unwrap();
    let mut at = 4 + n;
    let files = header
        .into_iter()
        .map(|(path, len)| {
            at += len;
            (path, archive[at - len..at].to_vec())
        })
        .collect();
    assert_eq!(at, archive.len(), "the archive has bytes no header entry names");
    files
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    use std::io::Write;
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    gz.write_all(bytes).unwrap();
    gz.finish().unwrap()
}

fn base64_decode(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        _ => 63,
    };
    let bytes: Vec<u8> = text.bytes().filter(|&c| c != b'=').map(value).collect();
    bytes
        .chunks(4)
        .flat_map(|c| {
            let n = c.iter().enumerate().fold(0u32, |n, (i, &v)| n | (u32::from(v) << (18 - 6 * i)));
            let b = n.to_be_bytes();
            b[1..c.len()].to_vec()
        })
        .collect()
}

/// The text between `<script id="ID" …>` and its `</script>`.
fn script_text<'a>(html: &'a str, id: &str) -> &'a str {
    let open = html.find(&format!("<script id=\"{id}\"")).unwrap_or_else(|| panic!("no #{id}"));
    let start = open + html[open..].find('>').unwrap() + 1;
    &html[start..start + html[start..].find("</script>").unwrap()]
}

#[test]
fn every_module_of_the_page_travels_and_none_imports_by_a_relative_path() {
    let files = unpack(&gathered().archive().unwrap());
    let carried: BTreeSet<String> = files.iter().map(|(p, _)| p.clone()).collect();
    // Every module in www/js but the tests and the offline file's own start-up script.
    for entry in std::fs::read_dir(Path::new(WWW).join("js")).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if name.ends_with(".js") && !name.ends_with(".test.js") && name != "offline.js" {
            assert!(carried.contains(&format!("js/{name}")), "js/{name} is not in the offline file");
        }
    }
    for path in
        ["pkg/flexarm.js", "pkg/flexarm_bg.wasm", "lessons/paper.md", "lessons/windows.md", "export/model_template.py"]
    {
        assert!(carried.contains(path), "{path} is not in the offline file");
    }
    // (The start-up script is not a module: it names the map's prefix only to write the map.)
    for (path, bytes) in files.iter().filter(|(p, _)| p.ends_with(".js") && p != BOOT) {
        let text = std::str::from_utf8(bytes).unwrap();
        // Nothing is left to rewrite: no import by a relative path.
        let (again, _) = rewrite_imports(path, text).unwrap();
        assert!(again == text, "{path} still imports by a relative path");
        // Every module it names is carried.
        for named in text.split(MODULE_PREFIX).skip(1) {
            let target = &named[..named.find(['\'', '"']).unwrap()];
            assert!(carried.contains(target), "{path} imports {target}, which the file does not carry");
        }
    }
    // The help page travels with its styles inside it.
    let help = std::str::from_utf8(&files.iter().find(|(p, _)| p == "help.html").unwrap().1).unwrap();
    assert!(help.contains("<style>") && !help.contains("rel=\"stylesheet\""));
    // Everything the page reads to make an offline file is carried: an offline file makes one too.
    for path in [ENTRY, BOOT, "style.css", "help.css"] {
        assert!(carried.contains(path), "{path} is not carried");
    }
}

#[test]
fn the_file_asks_the_browser_to_fetch_nothing_and_decodes_back_to_its_files() {
    let bundle = gathered();
    let archive = bundle.archive().unwrap();
    let start = OfflineStart::new("delta=0.01&pf=off&answers=hidden", None).unwrap();
    let html = bundle.html(&gzip(&archive), &start).unwrap();
    // No stylesheet link, no preload, no module script by path, no src= at all: from file:// each would fail.
    for refused in ["rel=\"stylesheet\"", "modulepreload", "rel=\"preload\"", "type=\"module\"", " src=\""] {
        assert!(!html.contains(refused), "the offline file still holds {refused}");
    }
    assert!(html.contains("<style>/* style.css */"));
    // The payload is the archive, gzip-compressed and base64-encoded.
    let payload = script_text(&html, "flexarm-files");
    let mut unzipped = Vec::new();
    flate2::read::GzDecoder::new(&base64_decode(payload.trim())[..]).read_to_end(&mut unzipped).unwrap();
    assert_eq!(unzipped, archive);
    assert!(html.contains(&format!("data-main=\"{MODULE_PREFIX}js/main.js\"")));
    // The start is JSON the page reads back.
    let start_json: serde_json::Value = serde_json::from_str(script_text(&html, "flexarm-start")).unwrap();
    assert_eq!(start_json["query"], "delta=0.01&pf=off&answers=hidden");
    assert!(start_json["lesson"].is_null());
    // The start-up script comes after both.
    assert!(html.rfind("flexarmOffline").unwrap() > html.find("id=\"flexarm-files\"").unwrap());
}

#[test]
fn a_teachers_lesson_text_cannot_end_its_script() {
    let lesson = HOMEWORK.replace("# ", "# </script><script>alert(1)</script> ");
    let start = OfflineStart::new("", Some(("hw.md".into(), lesson.clone().into_bytes()))).unwrap();
    let json = start.to_json();
    assert!(!json.contains("</script"));
    let back: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(back["lesson"]["text"].as_str().unwrap().replace("\r\n", "\n"), lesson.replace("\r\n", "\n"));
}

#[test]
fn a_start_is_checked_as_the_page_checks_it() {
    // A lesson opens at its first step unless the state names one.
    let s = OfflineStart::new("delta=0.02", Some(("windows.md".into(), HOMEWORK.as_bytes().to_vec()))).unwrap();
    assert_eq!(s.query, "delta=0.02&lesson=1");
    let s = OfflineStart::new("lesson=3", Some(("windows.md".into(), HOMEWORK.as_bytes().to_vec()))).unwrap();
    assert_eq!(s.query, "lesson=3");
    // Refused, with the reason: a bad value, a lesson by path, a lesson with a mistake.
    let e = OfflineStart::new("delta=-1", None).unwrap_err().to_string();
    assert!(e.contains("δ") || e.contains("delta"), "{e}");
    let e = OfflineStart::new("lesson_src=lessons/windows.md", None).unwrap_err().to_string();
    assert!(e.contains("--lesson FILE"), "{e}");
    let e = OfflineStart::new("", Some(("bad.md".into(), BAD_LESSON.as_bytes().to_vec()))).unwrap_err();
    assert!(e.to_string().starts_with("bad.md: lesson, line 6") && e.to_string().contains("banana"), "{e}");
}

#[test]
fn the_file_carries_the_lesson_step_the_moment_and_student_mode_and_reopens_them() {
    // A teacher's lesson fetched by path, at its second step, student mode, paused at t = 1 s.
    let files = LessonFiles {
        teacher: Some((LessonOrigin::Path("lessons/windows.md".into()), HOMEWORK.as_bytes().to_vec())),
        ..LessonFiles::default()
    };
    let (session, classroom, notices) =
        Classroom::open("lesson_src=lessons/windows.md&lesson=2&answers=hidden&paused=1&t=1", files);
    assert!(notices.is_empty(), "{notices:?}");
    let start = OfflineStart::of(&classroom, &session, true);
    assert!(!start.query.contains("lesson_src"), "{}", start.query);
    for part in ["lesson=2", "answers=hidden", "paused=1", "t=1"] {
        assert!(start.query.split('&').any(|p| p == part), "{part} missing from {}", start.query);
    }
    let carried = start.lesson.clone().expect("the teacher's lesson travels");
    assert_eq!(carried.name, "lessons/windows.md");
    let words = start.describe();
    assert!(
        words.contains("paused at t = 1 s") && words.contains("step 2") && words.contains("student mode"),
        "{words}"
    );

    // Opened from the file: the carried lesson at step 2, in student mode, paused at t = 1 s.
    let files = LessonFiles {
        teacher: Some((LessonOrigin::Carried(carried.name.clone()), carried.text.into_bytes())),
        offline: true,
        ..LessonFiles::default()
    };
    let (mut session, mut classroom, notices) = Classroom::open(&start.query, files);
    assert!(notices.is_empty(), "{notices:?}");
    let status = classroom.lesson_status(&session).expect("the lesson is open");
    assert_eq!((status.index, status.source.as_str()), (1, "lessons/windows.md"));
    assert!(classroom.student_mode(&session));
    assert!(classroom.take_start_paused());
    assert!((session.run(0).unwrap().closed_loop().time() - 1.0).abs() < 0.02);
    // Its links name the step, not a path the file cannot load.
    let state = classroom.state_string(&session);
    assert!(state.contains("lesson=2") && !state.contains("lesson_src"), "{state}");
    // Saved again, it carries the lesson on.
    classroom.follow(&mut session);
    assert_eq!(OfflineStart::of(&classroom, &session, false).lesson.map(|l| l.name), Some("lessons/windows.md".into()));
}

#[test]
fn an_offline_file_says_it_cannot_load_a_lesson_by_path() {
    let files = LessonFiles { offline: true, ..LessonFiles::default() };
    let (_, _, notices) = Classroom::open("lesson_src=lessons/mine.md", files);
    assert_eq!(notices.len(), 1);
    assert!(notices[0].text.contains("an offline file cannot load a lesson from a path"), "{}", notices[0].text);
    assert!(notices[0].text.contains("drop the file on the page"), "{}", notices[0].text);
}

fn flexarm(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_flexarm")).args(args).output().expect("the flexarm binary runs")
}

/// A copy of the page with stand-ins for the wasm-pack output.
fn built_page(dir: &Path) {
    let copy = |from: &Path, to: &Path| {
        std::fs::create_dir_all(to).unwrap();
        for entry in std::fs::read_dir(from).unwrap() {
            let entry = entry.unwrap();
            if entry.file_type().unwrap().is_file() {
                std::fs::copy(entry.path(), to.join(entry.file_name())).unwrap();
            }
        }
    };
    for sub in ["", "js", "lessons", "export"] {
        copy(&Path::new(WWW).join(sub), &dir.join(sub));
    }
    std::fs::create_dir_all(dir.join("pkg")).unwrap();
    for path in ["pkg/flexarm.js", "pkg/flexarm_bg.wasm"] {
        std::fs::write(dir.join(path), stub(path)).unwrap();
    }
}

#[test]
fn the_cli_writes_the_file_and_refuses_bad_input_in_one_line() {
    let dir = std::env::temp_dir().join(format!("flexarm-offline-test-{}", std::process::id()));
    let www = dir.join("www");
    built_page(&www);
    let (www_arg, out) = (www.to_string_lossy().into_owned(), dir.join("class.html").to_string_lossy().into_owned());
    let lesson = Path::new(WWW).join("lessons/windows.md").to_string_lossy().into_owned();
    let ok =
        flexarm(&["bundle", "--www", &www_arg, "--out", &out, "--state", "pf=off&answers=hidden", "--lesson", &lesson]);
    assert!(ok.status.success(), "{}", String::from_utf8_lossy(&ok.stderr));
    let said = String::from_utf8_lossy(&ok.stdout);
    assert!(said.contains("student mode") && said.contains("step 1") && said.contains(" MB"), "{said}");
    let html = std::fs::read_to_string(&out).unwrap();
    let start: serde_json::Value = serde_json::from_str(script_text(&html, "flexarm-start")).unwrap();
    assert_eq!(start["query"], "pf=off&answers=hidden&lesson=1");
    assert_eq!(start["lesson"]["name"], "windows.md");

    // Bad input: status 2, one line naming what is wrong.
    let missing_wasm = dir.join("bare");
    built_page(&missing_wasm);
    std::fs::remove_file(missing_wasm.join("pkg/flexarm_bg.wasm")).unwrap();
    let bare = missing_wasm.to_string_lossy().into_owned();
    let bad_lesson = dir.join("bad.md");
    std::fs::write(&bad_lesson, BAD_LESSON).unwrap();
    let bad_lesson = bad_lesson.to_string_lossy().into_owned();
    for (args, says) in [
        (vec!["bundle", "--www", &www_arg], "--out"),
        (vec!["bundle", "--www", &www_arg, "--out", &out, "--state", "delta=banana"], "delta"),
        (vec!["bundle", "--www", &www_arg, "--out", &out, "--lesson", &bad_lesson], "banana"),
        (vec!["bundle", "--www", &www_arg, "--out", &out, "--lesson", "/nonexistent/l.md"], "could not read --lesson"),
        (vec!["bundle", "--www", &bare, "--out", &out], "build the page's wasm module first"),
        (vec!["bundle", "--www", &www_arg, "--out", "/nonexistent/dir/f.html"], "could not write --out"),
    ] {
        let o = flexarm(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(says), "{args:?} should say {says}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_offline_file_makes_another_from_the_files_it_carries() {
    let first = unpack(&gathered().archive().unwrap());
    let mut again = Bundle::new();
    while let Some(path) = again.next_wanted().map(str::to_string) {
        let carried = first.iter().find(|(p, _)| *p == path).unwrap_or_else(|| panic!("{path} is not carried"));
        again.add(&path, carried.1.clone()).unwrap();
    }
    let second: BTreeSet<String> = unpack(&again.archive().unwrap()).into_iter().map(|(p, _)| p).collect();
    // The same files, but the help page's stylesheet: the help page carried has it inside.
    let first: BTreeSet<String> = first.into_iter().map(|(p, _)| p).filter(|p| p != "help.css").collect();
    assert_eq!(second, first);
}

#[test]
fn the_start_in_words_names_the_figure_and_student_mode_set_by_the_lesson() {
    let hidden = HOMEWORK.replacen("\n\n", "\n\nanswers: hidden\n\n", 1);
    let start = OfflineStart::new("preset=fig5.3", Some(("hw.md".into(), hidden.into_bytes()))).unwrap();
    let words = start.describe();
    assert!(words.starts_with("Fig. 5.3: δ = 0.01 s without preliminary feedback"), "{words}");
    assert!(words.contains("step 1") && words.ends_with("student mode"), "{words}");
    // Without it, and without answers=hidden, no student mode is claimed.
    let start = OfflineStart::new("preset=fig5.3", Some(("hw.md".into(), HOMEWORK.as_bytes().to_vec()))).unwrap();
    assert!(!start.describe().contains("student mode"));
}
