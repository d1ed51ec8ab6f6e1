//! One homework link (issue 35): `flexarm lesson-link` writes a link whose fragment carries the
//! lesson file byte for byte; opened (as the page opens it: the fragment read, unpacked and taken
//! as a teacher's lesson) it shows the lesson's first step in student mode; a lesson too long for
//! a link, or a link cut short, is refused with its reason.

use std::io::Read;
use std::process::Command;

use flexarm::classroom::link::{read_lesson_fragment, LINK_QUERY, MAX_FRAGMENT};
use flexarm::classroom::{Classroom, LessonFiles, LessonOrigin};

const HOMEWORK: &str = include_str!("../www/lessons/windows.md");

fn lesson_link(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_flexarm")).arg("lesson-link").args(args).output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn inflate(bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    flate2::read::DeflateDecoder::new(bytes).read_to_end(&mut out).unwrap();
    out
}

#[test]
fn the_link_carries_the_file_byte_for_byte_and_opens_it_in_student_mode() {
    let (ok, out, err) = lesson_link(&["www/lessons/windows.md", "--base", "https://example.org/flexarm/?delta=1#x"]);
    assert!(ok, "{err}");
    let link = out.trim();
    // The page's address without its query or fragment, then the link's own.
    let prefix = format!("https://example.org/flexarm/?{LINK_QUERY}#");
    assert!(link.starts_with(&prefix), "{link}");
    let fragment = &link[prefix.len() - 1..];
    assert!(fragment.len() <= MAX_FRAGMENT);
    println!("the homework link of lessons/windows.md (5 steps): {} characters", link.len());
    let (name, packed) = read_lesson_fragment(fragment).unwrap().expect("a lesson in the fragment");
    assert_eq!(name, "windows.md");
    let bytes = inflate(&packed);
    assert_eq!(bytes, HOMEWORK.as_bytes());
    // Opened as the page opens it: the link's query, the unpacked lesson as a teacher's.
    let files = LessonFiles { teacher: Some((LessonOrigin::Carried(name), bytes)), ..LessonFiles::default() };
    let (session, classroom, notices) = Classroom::open(LINK_QUERY, files);
    assert!(notices.is_empty(), "{notices:?}");
    let status = classroom.lesson_status(&session).expect("the lesson is open");
    assert_eq!((status.index, status.source.as_str()), (0, "windows.md"));
    assert!(classroom.student_mode(&session));
    // Its state (what the address keeps after the page writes it) still opens the lesson, in
    // student mode: a reload shows the same.
    let state = classroom.state_string(&session);
    assert!(state.split('&').any(|p| p == "lesson=1") && state.split('&').any(|p| p == "answers=hidden"), "{state}");
}

#[test]
fn a_lesson_too_long_for_a_link_and_a_cut_link_are_refused_with_their_reasons() {
    // The built-in lesson (16 steps) needs more than a link should carry.
    let (ok, _, err) = lesson_link(&["www/lessons/paper.md"]);
    assert!(!ok);
    assert!(
        err.contains("at most 8000 characters") && err.contains("RFC 9110") && err.contains("lesson_src="),
        "{err}"
    );
    // A lesson the page would refuse gets no link: the file's line is named.
    let dir = std::env::temp_dir().join(format!("flexarm-link-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.md");
    std::fs::write(&bad, "# A lesson\n\n## One step\nstate: banana=1\n").unwrap();
    let (ok, _, err) = lesson_link(&[bad.to_str().unwrap()]);
    assert!(!ok && err.contains("bad.md"), "{err}");
    // A link cut inside its base64: refused, and told to ask again; none at all: no lesson.
    let e = read_lesson_fragment("#lesson=Zg+&name=a.md").unwrap_err().to_string();
    assert!(e.contains("cut"), "{e}");
    assert_eq!(read_lesson_fragment("#t=3").unwrap(), None);
    assert_eq!(read_lesson_fragment("").unwrap(), None);
}

#[test]
fn an_embed_of_a_linked_lessons_step_carries_the_link_on() {
    let (_, out, _) = lesson_link(&["www/lessons/windows.md"]);
    let fragment = &out.trim()[out.find('#').unwrap()..];
    let (name, packed) = read_lesson_fragment(fragment).unwrap().unwrap();
    let files = LessonFiles {
        teacher: Some((LessonOrigin::Carried(name.clone()), inflate(&packed))),
        link: Some(fragment.to_string()),
        ..LessonFiles::default()
    };
    let (session, classroom, _) = Classroom::open(LINK_QUERY, files);
    let embed = classroom.embed(&session, "https://example.org/flexarm/index.html?x=1#y", "lesson=2").unwrap();
    assert!(embed.src.starts_with("https://example.org/flexarm/index.html?"), "{}", embed.src);
    assert!(embed.src.ends_with(fragment), "{}", embed.src);
    assert!(embed.src.contains("lesson=2") && embed.src.contains("embed=1"), "{}", embed.src);
    // The embedded page reads it back as the student's page does.
    let src_fragment = &embed.src[embed.src.find('#').unwrap()..];
    assert_eq!(read_lesson_fragment(src_fragment).unwrap().unwrap().0, name);
    // A lesson carried by an offline file (no link) or opened from disk still cannot be embedded.
    let files =
        LessonFiles { teacher: Some((LessonOrigin::Carried(name), inflate(&packed))), ..LessonFiles::default() };
    let (session, classroom, _) = Classroom::open(LINK_QUERY, files);
    let e = classroom.embed(&session, "https://example.org/", "lesson=2").unwrap_err().to_string();
    assert!(e.contains("make a homework link"), "{e}");
}

/// A lesson opened from a file moves into the address (the page writes the fragment there): the
/// URL then names its step, and its steps can be embedded; student mode kept for the lesson comes
/// back when the address lost `answers=hidden`.
#[test]
fn a_lesson_opened_from_a_file_travels_on_in_the_address_and_student_mode_is_kept_for_it() {
    let (_, out, _) = lesson_link(&["www/lessons/windows.md"]);
    let fragment = &out.trim()[out.find('#').unwrap() + 1..];
    let (session, classroom, _) = Classroom::open("", LessonFiles::default());
    let (mut session, mut classroom) = (session, classroom);
    classroom.load_lesson(&mut session, LessonOrigin::File("windows.md".into()), HOMEWORK.as_bytes()).unwrap();
    // From the disk: a link cannot bring it back, nor embed it.
    assert!(!classroom.state_string(&session).contains("lesson="));
    assert!(classroom.embed(&session, "https://example.org/", "lesson=2").is_err());
    classroom.carry_in_link(&mut session, fragment).unwrap();
    assert!(classroom.state_string(&session).contains("lesson=1"), "{}", classroom.state_string(&session));
    let embed = classroom.embed(&session, "https://example.org/", "lesson=2").unwrap();
    assert!(embed.src.ends_with(fragment), "{}", embed.src);
    // Only a lesson from a file moves (a second call finds it carried already).
    assert!(classroom.carry_in_link(&mut session, fragment).is_err());

    // Student mode for this lesson, kept by the browser: back on, nothing hidden shown; what the
    // student answered stays shown.
    assert!(!classroom.student_mode(&session));
    classroom.keep_student_mode(&mut session);
    assert!(classroom.student_mode(&session) && classroom.answers_hidden(&session));
    assert!(classroom.status(&session).lesson.unwrap().student_mode);
    assert!(classroom.state_string(&session).contains("answers=hidden"));
    classroom.lesson_answer(&mut session, 0).unwrap();
    assert!(!classroom.answers_hidden(&session), "answered: shown");
}
