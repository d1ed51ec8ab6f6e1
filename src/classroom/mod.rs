//! The classroom around a session: the guided lesson and its steps ([`lesson`]), the answers a
//! student hands in ([`answers`]), student mode ([`student`]), a link's moment ([`moment`]), a
//! teacher's lesson carried inside a homework link ([`link`]) and
//! the links and embeds that carry a lesson step ([`embed`]). It works *on* a physics
//! [`Session`] — a lesson step sets its settings, a goal reads its runs — and tells it what to hide
//! ([`Session::set_hidden`]); the session knows nothing of lessons. The web handle holds one of
//! each (`web/classroom.rs` beside `web/session.rs`); a native test composes them the same way.
//!
//! Architecture invariant: the classroom changes the session only through its public methods
//! (settings applied whole, notes, the ghost), and re-derives what is hidden after every change
//! it makes ([`Classroom::follow`] after the session's own).

pub mod answers;
pub mod class;
pub mod embed;
pub mod lesson;
pub mod link;
pub mod moment;
pub mod progress;
pub mod room;
pub mod student;

pub use progress::LessonOrigin;
pub use room::{Classroom, ClassroomStatus, HiddenStatus, LessonFiles};
