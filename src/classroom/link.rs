//! One homework link (issue 35): a teacher's lesson carried inside the page's address, in the
//! fragment (`#lesson=…&name=…`), which the browser never sends to a server. The lesson file's
//! bytes, compressed (raw deflate: `CompressionStream("deflate-raw")` in the page, flate2 in
//! `flexarm lesson-link`), base64url-encoded, with the file's name. The page reads the fragment
//! back, the browser unpacks it, and the lesson is then checked exactly as a file is
//! ([`super::Classroom::load_lesson`]'s checks, through [`super::LessonFiles`]).
//!
//! Only the encoding and the size limit are here; each host compresses with what it has.

use crate::error::{Error, ParseError};
use crate::session::query::{encode, split_query};

/// The fragment's key for the lesson's bytes, and for its file name.
pub const LESSON_KEY: &str = "lesson";
pub const NAME_KEY: &str = "name";

/// The longest fragment a link may carry, characters.
pub const MAX_FRAGMENT: usize = 8000;
/// Why: what a teacher is told when a lesson is too long for a link.
pub const WHY_MAX: &str = "HTTP (RFC 9110) asks software to handle addresses of at least 8000 characters, and \
                           some mail programs, chat tools and course sites cut longer ones; put the file beside the \
                           page and link it with lesson_src=, or hand out the offline file";

/// The query a homework link opens with: the lesson's first step in student mode (the verdict,
/// ρ and the maps hidden until each answer), in the full view.
pub const LINK_QUERY: &str = "mode=full&answers=hidden&lesson=1";

/// The fragment (without `#`) carrying a lesson file `name` whose bytes, compressed, are
/// `compressed`; an error naming the size and the reason when it is longer than
/// [`MAX_FRAGMENT`].
pub fn lesson_fragment(name: &str, compressed: &[u8]) -> Result<String, Error> {
    let fragment = format!("{LESSON_KEY}={}&{NAME_KEY}={}", base64url(compressed), encode(name));
    if fragment.len() > MAX_FRAGMENT {
        return Err(Error::Parse(ParseError {
            key: "lesson".into(),
            text: name.into(),
            expected: format!(
                "a lesson whose link is at most {MAX_FRAGMENT} characters (this one needs {}): {WHY_MAX}",
                fragment.len()
            ),
        }));
    }
    Ok(fragment)
}

/// The whole link: the page's address `base` (without query or fragment), [`LINK_QUERY`] and the
/// lesson's fragment.
pub fn lesson_link(base: &str, name: &str, compressed: &[u8]) -> Result<String, Error> {
    Ok(format!("{base}?{LINK_QUERY}#{}", lesson_fragment(name, compressed)?))
}

/// The lesson a fragment carries (`#` or not): its file name and compressed bytes; None when it
/// carries none; an error when it carries one that is not base64url.
pub fn read_lesson_fragment(fragment: &str) -> Result<Option<(String, Vec<u8>)>, Error> {
    let pairs = split_query(fragment.strip_prefix('#').unwrap_or(fragment));
    let value = |key: &str| pairs.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str());
    let Some(coded) = value(LESSON_KEY) else { return Ok(None) };
    let name = value(NAME_KEY).map(str::to_string);
    let bytes = from_base64url(coded).ok_or_else(|| {
        Error::Parse(ParseError {
            key: "lesson".into(),
            text: format!("{} characters after #lesson=", coded.len()),
            expected: "the lesson as a homework link writes it (base64url): the link may have been cut — ask for it \
                       again"
                .into(),
        })
    })?;
    Ok(Some((name.filter(|n| !n.is_empty()).unwrap_or_else(|| "lesson.md".into()), bytes)))
}

const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

/// base64url without padding (RFC 4648 §5): safe in a URL as it is.
pub fn base64url(bytes: &[u8]) -> String {
    encode_base64(bytes, ALPHABET, false)
}

/// base64 (RFC 4648) in `alphabet` (the standard one, §4, or the URL's, §5), padded with `=` to
/// whole groups of four if `pad`: the one encoder of the offline file and the homework link.
pub fn encode_base64(bytes: &[u8], alphabet: &[u8; 64], pad: bool) -> String {
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(alphabet[((n >> (18 - 6 * i)) & 63) as usize] as char);
            } else if pad {
                out.push('=');
            }
        }
    }
    out
}

/// The bytes of base64url text (padding optional), or None if it is not that.
pub fn from_base64url(text: &str) -> Option<Vec<u8>> {
    let text = text.trim_end_matches('=');
    if text.len() % 4 == 1 {
        return None;
    }
    let value = |c: u8| ALPHABET.iter().position(|&a| a == c).map(|v| v as u32);
    let mut out = Vec::with_capacity(text.len() * 3 / 4);
    for chunk in text.as_bytes().chunks(4) {
        let mut n = 0u32;
        for (i, &c) in chunk.iter().enumerate() {
            n |= value(c)? << (18 - 6 * i);
        }
        for i in 0..chunk.len() - 1 {
            out.push((n >> (16 - 8 * i)) as u8);
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64url_matches_rfc_4648_vectors_and_reads_back() {
        for (plain, coded) in
            [("", ""), ("f", "Zg"), ("fo", "Zm8"), ("foo", "Zm9v"), ("foob", "Zm9vYg"), ("foobar", "Zm9vYmFy")]
        {
            assert_eq!(base64url(plain.as_bytes()), coded);
            assert_eq!(from_base64url(coded).unwrap(), plain.as_bytes());
        }
        let all: Vec<u8> = (0..=255).collect();
        assert_eq!(from_base64url(&base64url(&all)).unwrap(), all);
        assert!(base64url(&[0xfb, 0xff]).chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_'));
        assert_eq!(from_base64url("Zg+/"), None);
        assert_eq!(from_base64url("Z"), None);
    }
}
